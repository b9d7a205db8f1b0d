# shadetool.Mesh: views without copies that never dangle, round trips through files, the
# documentation (help) and threads (the GIL is released while the library computes).
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import shadetool
from conftest import DATA, same_bits


def test_attributes_are_views_of_the_mesh(tetra):
    V, F = tetra
    mesh = shadetool.Mesh(V, F.astype(np.int64))
    assert mesh.precision == "double" and mesh.faces.dtype == np.uint32 and mesh.vertices.dtype == np.float64
    view = mesh.vertices
    view[0, 0] = 5.0  # writes into the mesh
    assert mesh.vertices[0, 0] == 5.0
    assert np.shares_memory(mesh.vertices, mesh.vertices)


def test_views_stay_valid_after_assignment_and_deletion(tetra):
    V, F = tetra
    mesh = shadetool.Mesh(V, F)
    old_faces = mesh.faces
    mesh.faces = F[:, ::-1]  # copy on write: the old view keeps the old arrays
    assert same_bits(old_faces, F.astype(np.uint32))
    assert same_bits(mesh.faces, F[:, ::-1].astype(np.uint32))
    positions = mesh.vertices
    del mesh
    assert same_bits(positions, V)  # the view keeps the mesh alive


def test_float32_vertices_are_remembered_and_written_as_float(tmp_path, tetra):
    V, F = tetra
    mesh = shadetool.Mesh(V.astype(np.float32), F)
    assert mesh.precision == "float"
    shadetool.write_mesh(tmp_path / "t.ply", mesh)
    back = shadetool.read_mesh(tmp_path / "t.ply")
    assert back.precision == "float" and same_bits(back.vertices, V)


@pytest.mark.parametrize("ext", ["ply", "obj", "off", "stl"])
def test_round_trip_through_every_format(tmp_path, ext):
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    N = shadetool.vertex_normals(mesh)
    path = tmp_path / f"k.{ext}"
    shadetool.write_mesh(path, np.array(mesh.vertices), np.array(mesh.faces), vertex_normals=N)
    back = shadetool.read_mesh(path)
    assert back.num_faces == mesh.num_faces
    if ext != "stl":  # STL holds facets, not shared vertices or vertex normals
        assert np.array_equal(back.faces, mesh.faces)
        assert np.max(np.abs(back.vertices - mesh.vertices)) < 1e-6


def test_polygon_mesh_exposes_indices_and_offsets():
    mesh = shadetool.read_mesh(DATA / "dodecahedron.off")
    assert mesh.faces.shape == (12, 5)
    assert mesh.face_offsets[-1] == len(mesh.face_indices) == 60
    mixed = shadetool.Mesh(np.zeros((5, 3)), (np.array([0, 1, 2, 0, 2, 3, 4]), np.array([0, 3, 7])))
    with pytest.raises(ValueError, match="faces of different sizes; use face_indices and face_offsets"):
        mixed.faces


def test_help_documents_shapes_and_dtypes():
    doc = shadetool.vertex_normals.__doc__
    assert "(n, 3) float64" in doc and "weight" in doc and "int32" in doc
    r = subprocess.run([sys.executable, "-c", "import shadetool; help(shadetool)"], capture_output=True, text=True,
                       env={"PYTHONPATH": shadetool.__file__.rsplit("/", 2)[0], "PAGER": "cat"})
    assert r.returncode == 0 and "vertex_normals" in r.stdout and "FileNotFoundError" in r.stdout


def test_the_gil_is_released_while_computing():
    # While a thread is inside vertex_normals (a 1.9M-triangle mesh), the main thread keeps running
    # Python: it records time stamps inside the call's window, which it could not do if the call held
    # the GIL. Two threads at once give the same bits as one.
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    V0, F0 = np.array(mesh.vertices), np.array(mesh.faces).astype(np.int64)
    copies = 200
    V = np.concatenate([V0 + 3.0 * k for k in range(copies)])
    F = np.concatenate([F0 + len(V0) * k for k in range(copies)])
    expected = shadetool.vertex_normals(V, F)
    windows, results = [], [None, None]

    def work(i):
        for _ in range(3):
            t0 = time.perf_counter()
            results[i] = shadetool.vertex_normals(V, F)
            windows.append((t0, time.perf_counter()))

    workers = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    stamps = []
    for w in workers:
        w.start()
    while any(w.is_alive() for w in workers):
        stamps.append(time.perf_counter())
    for w in workers:
        w.join()
    assert all(same_bits(r, expected) for r in results)
    stamps = np.array(stamps)

    def largest_gap(a, b):  # the longest time in [a, b] the main thread did not run
        t = np.concatenate([[a], stamps[(stamps > a) & (stamps < b)], [b]])
        return np.max(np.diff(t)) / (b - a)

    # Holding the GIL would leave one gap as long as the call itself (fraction ~1) in every window;
    # a thread descheduled on the loaded machine may miss a slice, so one window suffices.
    gaps = [largest_gap(a, b) for a, b in windows]
    assert min(gaps) < 0.5, gaps


def test_ply_scanner_properties_and_comments_are_read_and_written_back(tmp_path):
    # A scanner's PLY (written here by hand): a per-vertex confidence (float), an intensity
    # (ushort), a face flag (uchar) and a MeshLab texture comment survive read -> write -> read.
    src = tmp_path / "scan.ply"
    src.write_text(
        "ply\nformat ascii 1.0\ncomment TextureFile scan.png\n"
        "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property float confidence\nproperty ushort intensity\n"
        "element face 1\nproperty list uchar int vertex_indices\nproperty uchar flags\nend_header\n"
        "0 0 0 0.5 65535\n1 0 0 0.25 7\n0 1 0 1 0\n3 0 1 2 9\n")
    mesh = shadetool.read_mesh(str(src))
    assert sorted(mesh.vertex_properties) == ["confidence", "intensity"]
    assert mesh.vertex_properties["intensity"].tolist() == [65535, 7, 0]
    assert mesh.face_properties["flags"].tolist() == [9]
    assert mesh.comments == ["comment TextureFile scan.png"]
    out = tmp_path / "out.ply"
    shadetool.write_mesh(str(out), mesh)
    back = shadetool.read_mesh(str(out))
    assert back.vertex_properties["confidence"].tolist() == [0.5, 0.25, 1.0]
    assert back.face_properties["flags"].tolist() == [9]
    assert back.comments == ["comment written by shadetool", "comment TextureFile scan.png"]
    header = out.read_bytes().split(b"end_header")[0].decode()
    assert "property ushort intensity" in header and "property uchar flags" in header
