# The normals functions read C-contiguous float64 V and int32/uint32 F in place (a view of the
# caller's memory, core/mesh_view.h): the same bits as the copying path (a shadetool.Mesh, int64
# faces, strided positions), the caller's arrays left exactly as they were, read-only and
# foreign-byte-order arrays accepted, and every index still checked.
import numpy as np
import pytest

import shadetool
from conftest import DATA, same_bits


def snapshot(*arrays):
    return [(a.tobytes(), a.dtype, a.shape, a.strides, a.flags.writeable) for a in arrays]


def strided(V):
    """The same positions at other strides (every other column of a wider array): always copied."""
    wide = np.zeros((V.shape[0], 6))
    wide[:, ::2] = V
    return wide[:, ::2]


def calls(V, F):
    """Every normals result on (V, F), as a list of arrays."""
    out = [shadetool.face_normals(V, F), shadetool.face_normals(V, F, precision="float")]
    for weight in ("angle", "area", "uniform", "max"):
        for precision in ("double", "float"):
            out.append(shadetool.vertex_normals(V, F, weight=weight, precision=precision))
    for crease in (0.0, 30.0):
        out.extend(shadetool.corner_normals(V, F, crease_deg=crease))
    return out


def all_same_bits(a, b):
    return len(a) == len(b) and all(same_bits(x, y) for x, y in zip(a, b))


@pytest.mark.parametrize("name", ["torus_knot.ply", "icosphere.ply", "non_manifold.obj"])
@pytest.mark.parametrize("index_dtype", [np.int32, np.uint32])
def test_in_place_triangles_give_the_bits_of_the_copying_path_and_leave_the_arrays_untouched(name, index_dtype):
    mesh = shadetool.read_mesh(DATA / name)
    V = np.ascontiguousarray(mesh.vertices, dtype=np.float64)
    F = np.ascontiguousarray(mesh.faces, dtype=index_dtype)
    assert F.shape[1] == 3 and V.flags.c_contiguous and F.flags.c_contiguous
    before = snapshot(V, F)
    expected = calls(mesh, None)  # the library's own Mesh: no view of NumPy memory
    assert all_same_bits(calls(V, F), expected)
    assert all_same_bits(calls(strided(V), F.astype(np.int64)), expected)  # both arrays converted
    assert snapshot(V, F) == before


def test_read_only_arrays_are_read_in_place():
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    V = np.array(mesh.vertices, dtype=np.float64)
    F = np.array(mesh.faces, dtype=np.int32)
    V.flags.writeable = False
    F.flags.writeable = False
    assert all_same_bits(calls(V, F), calls(mesh, None))
    assert not V.flags.writeable and not F.flags.writeable


def test_in_place_quads_and_polygon_offsets_give_the_bits_of_the_mesh():
    mesh = shadetool.read_mesh(DATA / "quad_sphere.obj")
    V = np.array(mesh.vertices, dtype=np.float64)
    Q = np.array(mesh.faces, dtype=np.int32)
    assert Q.shape[1] == 4
    offsets = np.arange(0, Q.size + 1, 4, dtype=np.int32)
    indices = Q.ravel()
    before = snapshot(V, Q, offsets)
    expected = calls(mesh, None)
    assert all_same_bits(calls(V, Q), expected)
    got = calls(V, (indices, offsets))
    # corner_index comes back flat for (indices, offsets): compare it raveled.
    assert all(same_bits(np.ravel(x), np.ravel(y)) for x, y in zip(got, expected))
    assert snapshot(V, Q, offsets) == before


def test_foreign_byte_order_arrays_are_converted_not_misread():
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    V = np.array(mesh.vertices, dtype=np.float64)
    F = np.array(mesh.faces, dtype=np.int32)
    swapped_V, swapped_F = V.astype(V.dtype.newbyteorder()), F.astype(F.dtype.newbyteorder())
    assert np.array_equal(swapped_V, V) and np.array_equal(swapped_F, F)
    assert all_same_bits(calls(swapped_V, swapped_F), calls(V, F))


@pytest.mark.parametrize("index_dtype", [np.int32, np.uint32])
@pytest.mark.parametrize("bad_index", [-1, 4])
def test_in_place_indices_are_still_checked(index_dtype, bad_index):
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    if index_dtype == np.uint32 and bad_index < 0:
        bad_index = 2**32 - 1
    F = np.array([[0, 1, 2], [0, 2, 3], [0, 3, bad_index]], dtype=index_dtype)
    for fn in (shadetool.face_normals, shadetool.vertex_normals):
        with pytest.raises(ValueError, match=r"out of range \[0, 4\) \(first: face 2 corner 2"):
            fn(V, F)
    with pytest.raises(ValueError, match=r"offsets"):
        shadetool.vertex_normals(V, (F.ravel(), np.array([0, 3, 2, 9], dtype=index_dtype)))


def test_results_outlive_the_arrays_they_were_computed_from():
    mesh = shadetool.read_mesh(DATA / "icosphere.ply")
    V = np.array(mesh.vertices, dtype=np.float64)
    F = np.array(mesh.faces, dtype=np.int32)
    N = shadetool.vertex_normals(V, F)
    expected = N.copy()
    V[:] = np.nan  # the result is its own memory, not a view of V
    del V, F
    assert same_bits(N, expected)


def test_faces_of_fewer_than_3_corners_are_refused_as_the_readers_refuse_them():
    # A quad and a 2-corner face total 6 corners = 3 per face: taken as two triangles, the second
    # would get the normal of (3, 0, 4) (it did before this check). The file readers refuse such
    # faces; so do the arrays.
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    for fn in (shadetool.face_normals, shadetool.vertex_normals):
        with pytest.raises(ValueError, match=r"offsets\): face 1 has 2 corners \(a face needs at least 3\)"):
            fn(V, (np.array([0, 1, 2, 3, 0, 4], dtype=np.int32), np.array([0, 4, 6], dtype=np.int32)))
        with pytest.raises(ValueError, match=r"must have shape \(m, k\) \(k >= 3"):
            fn(V, np.array([[0, 1], [1, 2]], dtype=np.int32))
