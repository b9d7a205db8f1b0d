# shadetool: the Python package. Everything is the compiled module's (`_shadetool`, built from
# lib/python/*.cpp by CMake); this file only re-exports it under the package's name, so that the
# package can carry its type stubs (`__init__.pyi`) and the PEP 561 marker `py.typed`.
from ._shadetool import *  # noqa: F401,F403
from ._shadetool import __doc__, __version__  # noqa: F401


def _adopt():
    # Classes and functions say they live in `shadetool` (their repr, help() and pickling), not in
    # the private extension module.
    from . import _shadetool
    for name in dir(_shadetool):
        obj = getattr(_shadetool, name)
        if not name.startswith("_") and getattr(obj, "__module__", None) == _shadetool.__name__:
            try:
                obj.__module__ = __name__
            except (AttributeError, TypeError):
                pass


_adopt()
del _adopt
