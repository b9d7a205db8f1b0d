# repair and transform against the CLI on the same meshes: the same file, byte for byte, and
# repair's report equal to `shadetool repair --report`'s JSON.
import json

import numpy as np
import pytest

import shadetool
from conftest import DATA, run_cli, same_bits


@pytest.mark.parametrize("name", ["inconsistent_winding.obj", "non_manifold.obj", "cube.obj", "icosphere.ply",
                                  "quad_sphere.obj", "dodecahedron.off"])
@pytest.mark.parametrize("remove_degenerate", [False, True])
def test_repair_writes_the_cli_file_and_report(tmp_path, name, remove_degenerate):
    cli_out, py_out, report = tmp_path / "cli.ply", tmp_path / "py.ply", tmp_path / "report.json"
    extra = ["--remove-degenerate"] if remove_degenerate else []
    run_cli("repair", DATA / name, "-o", cli_out, "--report", report, *extra)
    mesh = shadetool.read_mesh(DATA / name)
    F, N, rep = shadetool.repair(mesh, return_normals=True, remove_degenerate=remove_degenerate)
    assert F.dtype == np.uint32
    expected = json.loads(report.read_text())
    expected.pop("input", None)
    expected.pop("output", None)
    assert rep == expected
    mesh.faces = F
    mesh.vertex_normals = N
    shadetool.write_mesh(py_out, mesh)
    assert py_out.read_bytes() == cli_out.read_bytes()
    # Arrays in, the same faces out; the input Mesh is left as it was.
    F2, rep2 = shadetool.repair(np.array(mesh.vertices), np.array(shadetool.read_mesh(DATA / name).faces))
    assert same_bits(F2, F) and rep2["faces_flipped"] == rep["faces_flipped"]


def test_repair_turns_an_inside_out_tetrahedron_outward(tetra):
    V, F = tetra
    F_in = F[:, ::-1]  # every face reversed: the signed volume is negative
    F_out, report = shadetool.repair(V, F_in)
    assert report["faces_flipped"] == 4 and report["components_inverted"] == 1
    # Outward: every face normal points away from the centroid.
    centroid = V.mean(axis=0)
    N = shadetool.face_normals(V, F_out)
    assert np.all(np.sum(N * (V[F_out].mean(axis=1) - centroid), axis=1) > 0)


MATRICES = {
    "rotation": [0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3],
    "uniform-scale": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0],
    "mirror-shear": [-1, 0.5, 0, 0.25, 0, 2, 0, 0, 0, 0, 0.5, -1],
}


@pytest.mark.parametrize("kind", MATRICES)
@pytest.mark.parametrize("normals", ["transform", "recompute", "drop"])
def test_transform_writes_the_cli_file(tmp_path, kind, normals):
    with_normals, cli_out, py_out = tmp_path / "n.ply", tmp_path / "cli.ply", tmp_path / "py.ply"
    run_cli("normals", DATA / "torus_knot.ply", "-o", with_normals)
    values = MATRICES[kind]
    run_cli("transform", with_normals, "-o", cli_out, "--matrix", ",".join(map(str, values)), "--normals", normals)
    mesh = shadetool.read_mesh(with_normals)
    matrix = np.array(values, dtype=np.float64).reshape(3, 4)
    V, F, N = shadetool.transform(mesh, matrix=matrix, normals=normals)
    assert V.dtype == np.float64 and F.dtype == np.uint32
    assert (N is None) == (normals == "drop")
    mesh.vertices = V
    mesh.faces = F
    mesh.vertex_normals = N
    shadetool.write_mesh(py_out, mesh)
    assert py_out.read_bytes() == cli_out.read_bytes()
    # The same map as a 4 x 4 matrix, and from arrays, gives the same bits.
    m4 = np.vstack([matrix, [0, 0, 0, 1]])
    V2, F2, N2 = shadetool.transform(np.array(shadetool.read_mesh(with_normals).vertices),
                                     np.array(shadetool.read_mesh(with_normals).faces),
                                     np.array(shadetool.read_mesh(with_normals).vertex_normals), m4, normals=normals)
    assert same_bits(V2, V) and same_bits(F2, F) and (N is None or same_bits(N2, N))


def test_a_mirror_keeps_normals_outward(tetra):
    V, F = tetra
    N = shadetool.vertex_normals(V, F)
    V2, F2, N2 = shadetool.transform(V, F, N, np.diag([-1.0, 1.0, 1.0, 1.0]))
    assert np.array_equal(V2[:, 0], -V[:, 0])
    assert same_bits(F2, F[:, [0, 2, 1]].astype(np.uint32))  # winding reversed, first corner kept
    # The transformed normals equal normals recomputed from the mirrored mesh (angle-weighted).
    assert np.allclose(N2, shadetool.vertex_normals(V2, F2), atol=1e-15)
