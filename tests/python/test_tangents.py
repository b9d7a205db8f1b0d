# shadetool.tangents: MikkTSpace frames against a closed form (an affine texture map on a plane:
# the tangent is dP/du, w the sign of the map) and against what `shadetool normals --tangents`
# writes to PLY (tx ty tz tw, the same frames).
import numpy as np
import pytest

import shadetool
from conftest import DATA, run_cli


def grid(n, a, b, c, d):
    xs = np.linspace(0.0, 1.0, n + 1)
    X, Y = np.meshgrid(xs, xs)
    V = np.stack([X.ravel(), Y.ravel(), np.zeros(X.size)], axis=1)
    UV = np.stack([a * V[:, 0] + b * V[:, 1], c * V[:, 0] + d * V[:, 1]], axis=1)
    F = []
    for j in range(n):
        for i in range(n):
            v = j * (n + 1) + i
            F += [[v, v + 1, v + n + 2], [v, v + n + 2, v + n + 1]]
    N = np.tile([0.0, 0.0, 1.0], (len(V), 1))
    return V, np.array(F, dtype=np.int32), N, UV


@pytest.mark.parametrize("m", [(1, 0, 0, 1), (2, 0.5, -0.25, 1), (-1, 0, 0, 1)])
def test_affine_map_gives_dpdu_and_the_maps_handedness(m):
    a, b, c, d = m
    V, F, N, UV = grid(3, a, b, c, d)
    T = shadetool.tangents(V, F, N, UV)
    assert T.shape == (len(F), 3, 4) and T.dtype == np.float64
    det = a * d - b * c
    e = np.array([d / det, -c / det, 0.0])
    e /= np.linalg.norm(e)
    assert np.all(T[..., 3] == np.sign(det))
    assert np.max(np.abs(T[..., :3] - e)) < 1e-6


def test_a_mesh_without_texture_coordinates_is_refused():
    mesh = shadetool.read_mesh(DATA / "cube.obj")
    with pytest.raises(ValueError):
        shadetool.tangents(mesh)


def test_the_cli_writes_the_same_frames_to_ply(tmp_path):
    out = tmp_path / "t.ply"
    run_cli("normals", DATA / "materials.obj", "--recompute", "--smoothing-groups", "ignore", "--tangents", "-o", out)
    written = shadetool.read_mesh(out)
    props = written.vertex_properties
    T = np.stack([props[k] for k in ("tx", "ty", "tz", "tw")], axis=1)
    mesh = shadetool.read_mesh(DATA / "materials.obj")
    mesh.clear_normals()
    mesh.vertex_normals = shadetool.vertex_normals(mesh)
    ours = shadetool.tangents(mesh).reshape(-1, 4)
    corner_vertex = written.face_indices
    assert np.array_equal(T[corner_vertex].astype(np.float32), ours.astype(np.float32))
