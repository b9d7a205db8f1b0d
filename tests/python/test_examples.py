# examples/python_normals.py runs as its docstring says and writes what it claims; the stub file
# names every public function of the module.
import ast
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

import shadetool
from conftest import SOURCE_DIR, same_bits


def test_python_normals_example_writes_a_torus_with_its_normals(tmp_path):
    out = tmp_path / "torus.ply"
    r = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "python_normals.py"), str(out)],
                       capture_output=True, text=True, env=dict(os.environ))
    assert r.returncode == 0, r.stderr
    assert "normals vs analytic: max 0.0" in r.stdout  # under 0.1 degree on the 96 x 48 torus
    mesh = shadetool.read_mesh(out)
    assert mesh.num_faces == 9216 and mesh.vertex_colors is not None
    assert same_bits(mesh.vertex_normals, shadetool.vertex_normals(np.array(mesh.vertices), np.array(mesh.faces)))


def test_the_stub_declares_every_public_name():
    stub = Path(shadetool.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text())
    declared = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(shadetool) if not name.startswith("_")}
    assert public <= declared, public - declared


def test_the_readme_python_block_runs_verbatim(tmp_path):
    # The README's Python example (the first ```python block after "## Python"), run as written
    # from a folder where data/ is the source tree's, so its out.ply lands in tmp_path.
    readme = (SOURCE_DIR / "README.md").read_text()
    section = readme[readme.index("\n## Python"):]
    block = section[section.index("```python\n") + len("```python\n"):]
    block = block[:block.index("```")]
    (tmp_path / "data").symlink_to(SOURCE_DIR / "data")
    r = subprocess.run([sys.executable, "-c", block], capture_output=True, text=True, cwd=tmp_path,
                       env=dict(os.environ))
    assert r.returncode == 0, r.stderr
    assert shadetool.read_mesh(tmp_path / "out.ply").num_faces > 0
