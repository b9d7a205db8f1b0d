# The Python package as users install and combine it (issue 28, items 7 and 9):
#  - `pip install .` (pyproject.toml -> lib/python/build_backend.py) into a virtual environment
#    installs a package that imports, carries its stubs and py.typed, and that mypy type-checks
#    against (a wrong argument type is reported, a right call is not);
#  - `import open3d` before or after `import shadetool` leaves glTF reading intact (Open3D carries
#    its own tinygltf; ours is compiled in with hidden symbols).
import ast
import os
import subprocess
import sys
import textwrap
import venv

import pytest

from conftest import DATA, SOURCE_DIR

BUILD = os.environ.get("SHADETOOL_BUILD_DIR")


def _python_env():
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PIP_REQUIRE_VIRTUALENV")}


@pytest.mark.parametrize("order", ["open3d, shadetool", "shadetool, open3d"])
def test_gltf_with_an_external_buffer_reads_whatever_was_imported_first(order):
    pytest.importorskip("open3d")
    code = textwrap.dedent(f"""
        import {order}
        import shadetool
        m = shadetool.read_mesh({str(DATA / 'scene.gltf')!r})
        print(m.num_faces)
    """)
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert int(r.stdout) > 0


@pytest.mark.skipif(not BUILD, reason="needs SHADETOOL_BUILD_DIR (set by ctest)")
def test_pip_install_builds_a_typed_package_mypy_checks(tmp_path):
    try:
        import pip  # noqa: F401
    except ImportError:
        pytest.skip("no pip for this interpreter (python3-pip)")
    env_dir = tmp_path / "venv"
    try:
        venv.EnvBuilder(system_site_packages=True, with_pip=False).create(env_dir)
    except Exception as e:  # python3-venv missing
        pytest.skip(f"cannot create a virtual environment: {e}")
    py = env_dir / "bin" / "python"
    env = _python_env()
    # The ctest build tree is reused (only the module's target is built), so the test does not
    # build the library a second time; without SHADETOOL_CMAKE_BUILD_DIR the backend configures
    # build/wheel itself.
    env["SHADETOOL_CMAKE_BUILD_DIR"] = BUILD
    # The virtual environment has no pip of its own: the interpreter's pip installs into it.
    r = subprocess.run([sys.executable, "-m", "pip", "--python", str(py), "install", "--no-build-isolation",
                        "--no-index", "--no-deps", str(SOURCE_DIR)], capture_output=True, text=True, env=env,
                       cwd=tmp_path)
    if r.returncode != 0 and "no such option: --python" in r.stderr:
        pytest.skip("pip older than 22.3 has no --python")
    assert r.returncode == 0, r.stdout + r.stderr
    r = subprocess.run([str(py), "-c", "import shadetool, pathlib; p = pathlib.Path(shadetool.__file__).parent; "
                        "print(p); print(sorted(x.name for x in p.iterdir() if x.suffix != '.pyc' and x.name != '__pycache__'))"],
                       capture_output=True, text=True, env=_python_env(), cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    where, listing = r.stdout.splitlines()
    names = ast.literal_eval(listing)
    assert where.startswith(str(env_dir)), where
    assert "py.typed" in names and "__init__.pyi" in names and any(n.startswith("_shadetool.") for n in names), names

    # mypy (Debian's `mypy`) run by the environment's interpreter finds the installed stubs.
    try:
        subprocess.run(["mypy", "--version"], capture_output=True, check=True)
    except (OSError, subprocess.CalledProcessError):
        pytest.skip("no mypy (Debian package mypy)")
    good = tmp_path / "good.py"
    good.write_text("import numpy as np\nimport shadetool\n"
                    "V = np.zeros((3, 3))\nF = np.array([[0, 1, 2]], dtype=np.int32)\n"
                    "N = shadetool.vertex_normals(V, F, weight='angle')\n"
                    "m: shadetool.Mesh = shadetool.read_mesh('x.obj')\n")
    bad = tmp_path / "bad.py"
    bad.write_text("import shadetool\nshadetool.vertex_normals(1, 2, weight='heaviest')\n")
    args = ["mypy", "--python-executable", str(py), "--no-incremental", "--cache-dir", str(tmp_path / "mc")]
    r = subprocess.run(args + [str(good)], capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    r = subprocess.run(args + [str(bad)], capture_output=True, text=True, cwd=tmp_path)
    assert r.returncode == 1 and "vertex_normals" in r.stdout, r.stdout + r.stderr
