# `cmake --install --component python` puts the package (module, __init__.py, stubs, py.typed) under
# the prefix, in the interpreter's platform site-packages layout, importable from there.
import os
import subprocess
import sys
import sysconfig

import pytest

BUILD = os.environ.get("SHADETOOL_BUILD_DIR")


@pytest.mark.skipif(not BUILD, reason="needs SHADETOOL_BUILD_DIR (set by ctest)")
def test_install_component_python_is_importable_from_the_prefix(tmp_path):
    r = subprocess.run(["cmake", "--install", BUILD, "--prefix", str(tmp_path), "--component", "python"],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    installed = sorted(p.relative_to(tmp_path).as_posix() for p in tmp_path.rglob("*") if p.is_file())
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    names = sorted(p.rsplit("/", 1)[1] for p in installed)
    assert names == sorted(["__init__.py", "__init__.pyi", "py.typed", "_shadetool" + suffix]), installed
    assert all(p.rsplit("/", 2)[1] == "shadetool" for p in installed), installed
    site = (tmp_path / installed[0]).parent.parent
    assert site.name in ("dist-packages", "site-packages")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(site)
    r = subprocess.run([sys.executable, "-c", "import shadetool; print(shadetool.__file__)"], capture_output=True,
                       text=True, env=env, cwd=tmp_path)
    assert r.returncode == 0 and r.stdout.strip().startswith(str(site)), r.stderr
