# A round trip with Open3D (python3-open3d): its TriangleMesh's arrays in, our normals out,
# checked against the analytic sphere, our CLI on the same arrays, and Open3D's own area-weighted
# normals; and our normals back into Open3D.
import numpy as np
import pytest

import shadetool
from conftest import angle_deg, run_cli, same_bits

o3d = pytest.importorskip("open3d")


@pytest.fixture(scope="module")
def o3d_sphere():
    return o3d.geometry.TriangleMesh.create_sphere(radius=2.0, resolution=30)


def test_open3d_arrays_in_our_normals_out(o3d_sphere, tmp_path):
    V = np.asarray(o3d_sphere.vertices)   # (n, 3) float64 view of Open3D's memory
    F = np.asarray(o3d_sphere.triangles)  # (m, 3) int32
    assert F.dtype == np.int32
    N = shadetool.vertex_normals(V, F, weight="max")
    # Analytic: a sphere's normal is the position over the radius (Max weighting is exact there).
    assert np.max(angle_deg(N, V)) < 1e-9
    # Our CLI on the same arrays (written by write_mesh) gives the same bits.
    src, out = tmp_path / "o3d.ply", tmp_path / "cli.ply"
    shadetool.write_mesh(src, V, F)
    run_cli("normals", src, "-o", out, "--weight", "max")
    assert same_bits(shadetool.read_mesh(out).vertex_normals, N)


def test_area_weighting_agrees_with_open3d_compute_vertex_normals(o3d_sphere):
    V, F = np.asarray(o3d_sphere.vertices), np.asarray(o3d_sphere.triangles)
    ours = shadetool.vertex_normals(V, F, weight="area")
    theirs_mesh = o3d.geometry.TriangleMesh(o3d_sphere)
    theirs_mesh.compute_vertex_normals()  # area-weighted: sum of unnormalised face normals
    theirs = np.asarray(theirs_mesh.vertex_normals)
    # Same formula, different summation order and cross products: rounding only.
    assert np.max(angle_deg(ours, theirs)) < 1e-9


def test_our_normals_go_back_into_open3d(o3d_sphere):
    V, F = np.asarray(o3d_sphere.vertices), np.asarray(o3d_sphere.triangles)
    N = shadetool.vertex_normals(V, F)
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(V), o3d.utility.Vector3iVector(F))
    mesh.vertex_normals = o3d.utility.Vector3dVector(N)
    assert mesh.has_vertex_normals() and same_bits(np.asarray(mesh.vertex_normals), N)
    # Open3D's arrays are views whose rows are not contiguous with anything of ours: still one read.
    face_n = shadetool.face_normals(np.asarray(mesh.vertices), np.asarray(mesh.triangles))
    mesh.compute_triangle_normals()
    assert np.max(angle_deg(face_n, np.asarray(mesh.triangle_normals))) < 1e-9
