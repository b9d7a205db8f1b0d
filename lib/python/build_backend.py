"""build_backend.py: the PEP 517 backend behind `pip install .` (pyproject.toml).

It builds the package with the project's own CMake, for the interpreter that runs pip, and packs
what CMake put in BUILD/python/shadetool/ (the extension _shadetool, __init__.py, __init__.pyi,
py.typed) into a wheel. No setuptools: a wheel is a zip with three metadata files (PEP 427).

BUILD is $SHADETOOL_CMAKE_BUILD_DIR when set (an already configured build tree is reused as it is:
only the module's target is built), else build/wheel below the source tree, configured Release
with tests off. $SHADETOOL_CMAKE_ARGS adds configure arguments; $CMAKE_BUILD_PARALLEL_LEVEL the jobs.
"""
import base64
import hashlib
import os
import shlex
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

_SOURCE = Path(__file__).resolve().parents[2]
_NAME = "shadetool"


def _version():
    for line in (_SOURCE / "pyproject.toml").read_text().splitlines():
        if line.startswith("version"):
            return line.split("=", 1)[1].strip().strip('"')
    raise RuntimeError("pyproject.toml has no version")


def _tag():
    impl = "cp%d%d" % sys.version_info[:2]
    abi = impl + getattr(sys, "abiflags", "")
    plat = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return "%s-%s-%s" % (impl, abi, plat)


def _metadata():
    return (
        "Metadata-Version: 2.1\nName: %s\nVersion: %s\n"
        "Summary: Mesh normals, repair, transforms, baked lighting, occlusion and rendering on NumPy arrays\n"
        "Requires-Python: >=3.8\nRequires-Dist: numpy\n" % (_NAME, _version()))


def _run(cmd):
    print("build_backend:", " ".join(shlex.quote(str(c)) for c in cmd), file=sys.stderr, flush=True)
    subprocess.run([str(c) for c in cmd], check=True, stdout=sys.stderr)


def _build_package():
    build = Path(os.environ.get("SHADETOOL_CMAKE_BUILD_DIR") or _SOURCE / "build" / "wheel").resolve()
    if not (build / "CMakeCache.txt").exists():
        _run(["cmake", "-S", _SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DSHADETOOL_BUILD_TESTS=OFF",
              "-DSHADETOOL_PYTHON=ON", "-DPython3_EXECUTABLE=" + sys.executable,
              *shlex.split(os.environ.get("SHADETOOL_CMAKE_ARGS", ""))])
    _run(["cmake", "--build", build, "--target", "shadetool_python", "-j", os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")])
    package = build / "python" / _NAME
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not (package / ("_shadetool" + suffix)).exists():
        raise RuntimeError("%s has no _shadetool%s: the build is for another interpreter than %s"
                           % (package, suffix, sys.executable))
    return package


def _record_line(path, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return "%s,sha256=%s,%d" % (path, digest, len(data))


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    package = _build_package()
    version = _version()
    dist_info = "%s-%s.dist-info" % (_NAME, version)
    name = "%s-%s-%s.whl" % (_NAME, version, _tag())
    files = []
    for path in sorted(package.iterdir()):
        if path.is_file() and not path.name.endswith(".pyc"):
            files.append(("%s/%s" % (_NAME, path.name), path.read_bytes()))
    files.append((dist_info + "/METADATA", _metadata().encode()))
    files.append((dist_info + "/WHEEL", ("Wheel-Version: 1.0\nGenerator: shadetool build_backend\n"
                                         "Root-Is-Purelib: false\nTag: %s\n" % _tag()).encode()))
    record = [_record_line(p, d) for p, d in files] + [dist_info + "/RECORD,,"]
    files.append((dist_info + "/RECORD", ("\n".join(record) + "\n").encode()))
    with zipfile.ZipFile(Path(wheel_directory) / name, "w", zipfile.ZIP_DEFLATED) as z:
        for path, data in files:
            info = zipfile.ZipInfo(path, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if path.endswith(".so") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
    return name


def get_requires_for_build_wheel(config_settings=None):
    return []
