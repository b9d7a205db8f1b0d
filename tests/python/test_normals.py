# The normals functions against the CLI (the same bits in the same file), against analytic
# sphere and ellipsoid normals, and for every input layout the bindings accept.
import numpy as np
import pytest

import shadetool
from conftest import DATA, angle_deg, run_cli, same_bits, uv_ellipsoid

MESHES = ["icosphere.ply", "torus_knot.ply", "quad_sphere.obj", "dodecahedron.off", "non_manifold.obj"]


@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("weight", ["angle", "area", "uniform", "max"])
@pytest.mark.parametrize("precision", ["double", "float"])
def test_vertex_normals_write_the_cli_file_byte_for_byte(tmp_path, name, weight, precision):
    ext = "obj" if name.endswith(".obj") else "ply"
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("normals", DATA / name, "-o", cli_out, "--recompute", "--weight", weight, "--precision", precision)
    mesh = shadetool.read_mesh(DATA / name)
    N = shadetool.vertex_normals(mesh, weight=weight, precision=precision)
    assert N.shape == (mesh.num_vertices, 3) and N.dtype == np.float64
    mesh.clear_normals()
    mesh.vertex_normals = N
    shadetool.write_mesh(py_out, mesh)
    assert py_out.read_bytes() == cli_out.read_bytes()


@pytest.mark.parametrize("name", MESHES)
def test_face_normals_write_the_cli_file_byte_for_byte(tmp_path, name):
    cli_out, py_out = tmp_path / "cli.ply", tmp_path / "py.ply"
    run_cli("normals", DATA / name, "-o", cli_out, "--recompute", "--faces")
    mesh = shadetool.read_mesh(DATA / name)
    N = shadetool.face_normals(mesh)
    assert N.shape == (mesh.num_faces, 3)
    mesh.clear_normals()
    mesh.face_normals = N  # no degenerate face in these meshes, so no (0, 0, 1) fallback to apply
    shadetool.write_mesh(py_out, mesh)
    assert py_out.read_bytes() == cli_out.read_bytes()


@pytest.mark.parametrize("name", MESHES)
@pytest.mark.parametrize("crease", [0.0, 30.0, 180.0])
def test_corner_normals_equal_the_cli_per_corner(tmp_path, name, crease):
    cli_out = tmp_path / "cli.obj"  # OBJ keeps the pool and the per-corner indices (vn, f v//n)
    run_cli("normals", DATA / name, "-o", cli_out, "--recompute", "--crease", crease)
    mesh = shadetool.read_mesh(DATA / name)
    pool, index = shadetool.corner_normals(mesh, crease_deg=crease)
    back = shadetool.read_mesh(cli_out)
    ours = pool[np.ravel(index)]
    theirs = back.corner_normals[back.corner_normal_index]
    assert same_bits(ours, theirs)


def test_vertex_normals_from_arrays_equal_those_of_the_read_mesh():
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    V, F = np.array(mesh.vertices), np.array(mesh.faces)
    expected = shadetool.vertex_normals(mesh)
    assert same_bits(shadetool.vertex_normals(V, F), expected)
    assert same_bits(shadetool.vertex_normals(V, F.astype(np.int64)), expected)
    assert same_bits(shadetool.vertex_normals(V, F.astype(np.int32)), expected)
    # Non-contiguous views (every other column of a wider array, reversed rows) are converted
    # element by element (only C-contiguous float64 V and int32/uint32 F are read in place).
    wide = np.zeros((V.shape[0], 6))
    wide[:, ::2] = V
    assert same_bits(shadetool.vertex_normals(wide[:, ::2], F), expected)
    F_fortran = np.asfortranarray(F.astype(np.int64))
    assert same_bits(shadetool.vertex_normals(V, F_fortran), expected)
    # Negative strides: vertices in reverse order, faces (same order) renumbered to match.
    n = len(V)
    assert same_bits(shadetool.vertex_normals(V[::-1], n - 1 - F), expected[::-1])
    # Unaligned memory (an array inside a bytes buffer at an odd offset) is read element by element.
    raw = bytearray(V.nbytes + 1)
    unaligned = np.frombuffer(raw, dtype=np.float64, count=V.size, offset=1).reshape(-1, 3)
    unaligned[...] = V
    assert not unaligned.flags.aligned
    assert same_bits(shadetool.vertex_normals(unaligned, F), expected)
    # float32 positions are widened exactly: the same as widening them first.
    V32 = V.astype(np.float32)
    assert same_bits(shadetool.vertex_normals(V32, F), shadetool.vertex_normals(V32.astype(np.float64), F))
    # Python lists are accepted (numpy.asarray).
    assert same_bits(shadetool.vertex_normals(V.tolist(), F.tolist()), expected)


def test_polygons_as_indices_and_offsets_equal_the_k_gon_array():
    mesh = shadetool.read_mesh(DATA / "quad_sphere.obj")
    V, Q = np.array(mesh.vertices), np.array(mesh.faces)
    assert Q.shape[1] == 4
    offsets = np.arange(0, 4 * len(Q) + 1, 4, dtype=np.int64)
    for fn in (shadetool.vertex_normals, shadetool.face_normals):
        assert same_bits(fn(V, (Q.ravel(), offsets)), fn(V, Q))
    pool_a, index_a = shadetool.corner_normals(V, (Q.ravel(), offsets), crease_deg=30)
    pool_b, index_b = shadetool.corner_normals(V, Q, crease_deg=30)
    assert same_bits(pool_a, pool_b) and index_a.shape == (Q.size,) and index_b.shape == Q.shape
    assert same_bits(index_a, index_b.ravel())
    # Mixed sizes: a triangle and a quad.
    V2 = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]], dtype=np.float64)
    N = shadetool.face_normals(V2, (np.array([1, 4, 2, 0, 1, 2, 3]), np.array([0, 3, 7])))
    assert same_bits(N, np.array([[0, 0, 1.0], [0, 0, 1.0]]))


def test_max_weighting_is_exact_on_a_sphere():
    V, F = uv_ellipsoid((1.0, 1.0, 1.0), 24, 48)
    N = shadetool.vertex_normals(V, F, weight="max")
    # Max 1999: exact when the neighbours lie on a sphere (up to rounding).
    assert np.max(angle_deg(N, V)) < 1e-9
    assert np.allclose(np.linalg.norm(N, axis=1), 1.0, atol=1e-15)


# Measured orders on this tessellation (worst vertex): angle and max second order (errors / 4 per
# halving of h: 2.0, 0.52, 0.13 deg for angle), area and uniform first order (/ 2: 1.0, 0.48, 0.24 deg
# for area), the known behaviour of the weightings on asymmetric one-rings.
@pytest.mark.parametrize("weight,ratio", [("angle", 3.5), ("max", 3.5), ("area", 1.9), ("uniform", 1.9)])
def test_ellipsoid_normals_converge_to_the_analytic_gradient(weight, ratio):
    radii = np.array([3.0, 2.0, 1.0])
    errors = []
    for n in (16, 32, 64):
        V, F = uv_ellipsoid(radii, n, 2 * n)
        N = shadetool.vertex_normals(V, F, weight=weight)
        truth = V / radii**2  # gradient of x^2/a^2 + y^2/b^2 + z^2/c^2
        errors.append(np.max(angle_deg(N, truth)))
    assert errors[1] < errors[0] / ratio and errors[2] < errors[1] / ratio, errors
    assert errors[2] < 0.3, errors


def test_face_normals_of_an_analytic_tetrahedron(tetra):
    V, F = tetra
    expected = np.array([[0, 0, -1], [0, -1, 0], [-1, 0, 0], [1, 1, 1]]) / np.array([[1], [1], [1], [np.sqrt(3)]])
    assert np.allclose(shadetool.face_normals(V, F), expected, atol=1e-15)


def test_degenerate_and_isolated_input_never_gives_nan():
    V = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [5, 5, 5]], dtype=np.float64)  # collinear + isolated
    F = np.array([[0, 1, 2]])
    assert np.array_equal(shadetool.face_normals(V, F), [[0, 0, 0]])
    N = shadetool.vertex_normals(V, F)
    assert np.all(np.isfinite(N)) and np.array_equal(N[3], [0, 0, 1])
    empty = shadetool.vertex_normals(np.zeros((0, 3)), np.zeros((0, 3), dtype=np.int32))
    assert empty.shape == (0, 3)


def test_results_are_writable_arrays_owned_by_numpy(tetra):
    V, F = tetra
    N = shadetool.vertex_normals(V, F)
    N[0] = 7  # the result's memory is the array's own
    assert N.flags.writeable and N.flags.c_contiguous
