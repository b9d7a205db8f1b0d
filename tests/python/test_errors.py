# Bad input is a Python exception with one clear message, never a crash: ValueError for a wrong
# shape, dtype or index (checked before any kernel runs), FileNotFoundError for a missing file.
import numpy as np
import pytest

import shadetool
from conftest import DATA

SCENE = {"lights": [{"type": "directional", "direction": [0, 0, 1]}]}


def all_calls(V, F):
    """Every function that takes (V, F), as zero-argument calls."""
    return [
        lambda: shadetool.face_normals(V, F),
        lambda: shadetool.vertex_normals(V, F),
        lambda: shadetool.corner_normals(V, F, crease_deg=30),
        lambda: shadetool.repair(V, F),
        lambda: shadetool.transform(V, F, None, np.eye(4)),
        lambda: shadetool.bake_lighting(V, F, None, SCENE),
        lambda: shadetool.occlusion(V, F, samples=4),
        lambda: shadetool.render(V, F, None, SCENE, width=8, height=8),
        lambda: shadetool.Mesh(V, F),
        lambda: shadetool.write_mesh("/tmp/never-written.ply", V, F),
    ]


@pytest.mark.parametrize(
    "V,F,message",
    [
        (np.zeros((4, 2)), [[0, 1, 2]], r"V: must have shape \(n, 3\), got \(4, 2\)"),
        (np.zeros(12), [[0, 1, 2]], r"V: must have shape \(n, 3\), got \(12,\)"),
        (np.zeros((4, 3), dtype=np.int64), [[0, 1, 2]], "V: dtype int64 not supported; expected float64 or float32"),
        (np.zeros((4, 3), dtype=np.float16), [[0, 1, 2]], "V: dtype float16 not supported"),
        (np.zeros((4, 3)), np.array([[0, 1, 4]]), r"F: 1 vertex index out of range \[0, 4\) \(first: face 0 corner 2 is 4\)"),
        (np.zeros((4, 3)), np.array([[0, 1, 2], [0, -1, 2]]), r"first: face 1 corner 1 is -1"),
        (np.zeros((4, 3)), np.array([[0, 1, 2]], dtype=np.uint64) * np.uint64(2**63), "out of range"),
        (np.zeros((4, 3)), np.array([[0.0, 1.0, 2.0]]), "F: dtype float64 not supported; expected an integer array"),
        (np.zeros((4, 3)), np.array([0, 1, 2]), r"F: must have shape \(m, k\)"),
        (np.zeros((4, 3)), (np.array([0, 1, 2]), np.array([1, 3])), r"offsets\): must start at 0, got 1"),
        (np.zeros((4, 3)), (np.array([0, 1, 2]), np.array([0, 2])), r"must end at len\(indices\) = 3, got 2"),
        (np.zeros((4, 3)), (np.array([0, 1, 2, 3]), np.array([0, 3, 1, 4])), "must be non-decreasing"),
        (np.zeros((4, 3)), (np.array([0, 1, 2]), np.array([0, 5])), r"offsets\): 1 offset outside \[0, 3\]"),
        (np.zeros((4, 3)), (np.array([0, 1, 9]), np.array([0, 3])), r"first: indices 2 is 9"),
        (np.zeros((4, 3)), None, "F: is required"),
        ("not an array", [[0, 1, 2]], r"V: must have shape \(n, 3\), got \(\)"),
    ],
)
def test_bad_arrays_raise_value_error_in_every_function(V, F, message):
    # Mesh(...) names its arguments vertices and faces.
    message = message.replace("V: ", "(V|vertices): ").replace("F: is required", "(F: is required|faces: is None)")
    message = message.replace("F: ", "(F|faces): ")
    for call in all_calls(V, F):
        with pytest.raises(ValueError, match=message):
            call()


def test_bad_options_raise_value_error(tetra):
    V, F = tetra
    with pytest.raises(ValueError, match="weight: 'cotan' is not one of uniform, area, angle, max"):
        shadetool.vertex_normals(V, F, weight="cotan")
    with pytest.raises(ValueError, match="precision: 'half' is not one of double, float"):
        shadetool.vertex_normals(V, F, precision="half")
    with pytest.raises(ValueError, match="crease_deg is required"):
        shadetool.corner_normals(V, F)
    with pytest.raises(ValueError, match=r"crease_deg must be in \[0, 180\]"):
        shadetool.corner_normals(V, F, crease_deg=190)
    with pytest.raises(ValueError, match=r"crease_deg must be in \[0, 180\]"):
        shadetool.corner_normals(V, F, crease_deg=float("nan"))
    with pytest.raises(ValueError, match=r"matrix must have shape \(3, 4\) or \(4, 4\)"):
        shadetool.transform(V, F, None, np.eye(3))
    with pytest.raises(ValueError, match="last row"):
        shadetool.transform(V, F, None, [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1, 1]])
    with pytest.raises(ValueError, match="N: must have shape"):
        shadetool.transform(V, F, np.zeros((3, 3)), np.eye(4))
    with pytest.raises(ValueError, match="normals: 'keep' is not one of transform, recompute, drop"):
        shadetool.transform(V, F, None, np.eye(4), normals="keep")
    with pytest.raises(ValueError, match=r"scene: \$\.lights\[0\]\.type"):
        shadetool.bake_lighting(V, F, None, {"lights": [{"type": "laser"}]})
    with pytest.raises(ValueError, match="samples must be 1..16"):
        shadetool.render(V, F, None, SCENE, samples=17)
    with pytest.raises(ValueError, match="each side must be 1..16384 pixels"):
        shadetool.render(V, F, None, SCENE, width=0)
    with pytest.raises(ValueError, match="distance must be > 0"):
        shadetool.occlusion(V, F, distance=0.0)
    # Every enumerated option is parsed by the library's vocabulary: its message, the same names.
    with pytest.raises(ValueError, match="bake_lighting: model: 'toon' is not one of lambert, phong, blinn-phong"):
        shadetool.bake_lighting(V, F, None, SCENE, model="toon")
    with pytest.raises(ValueError, match="bake_lighting: space: 'screen' is not one of auto, world, camera, object"):
        shadetool.bake_lighting(V, F, None, SCENE, space="screen")
    with pytest.raises(ValueError, match="render: shading: 'toon' is not one of flat, gouraud, phong"):
        shadetool.render(V, F, None, SCENE, shading="toon")
    with pytest.raises(ValueError, match="Mesh.precision: 'half' is not one of double, float"):
        shadetool.Mesh(V, F).precision = "half"
    # The library's limits, relayed: shadow samples, threads, and a space asked of Phong (refused,
    # as `shadetool render --shading phong --space world` is; flat and gouraud take it).
    with pytest.raises(ValueError, match="bake_lighting: samples must be 1..1048576, got 0"):
        shadetool.bake_lighting(V, F, None, SCENE, shadows=True, samples=0)
    with pytest.raises(ValueError, match="render: threads must be 0..1024"):
        shadetool.render(V, F, None, SCENE, width=8, height=8, threads=2000)
    with pytest.raises(ValueError, match="render: space 'world' applies to flat and gouraud shading"):
        shadetool.render(V, F, None, SCENE, width=8, height=8, space="world")
    assert shadetool.render(V, F, None, SCENE, width=8, height=8, space="world", shading="flat").shape == (8, 8, 3)


def test_scene_dicts_pass_the_one_scene_check(tetra):
    """The Python door into a Scene is the JSON reader's, then validate_scene: messages name the path."""
    V, F = tetra
    with pytest.raises(ValueError, match=r"scene: \$\.lights\[0\]\.intensity: must be >= 0, got -1"):
        shadetool.bake_lighting(V, F, None, {"lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": -1}]})
    with pytest.raises(ValueError, match=r"scene: \$\.lights\[0\]\.intensity: color x intensity overflows"):
        shadetool.bake_lighting(
            V, F, None, {"lights": [{"type": "point", "position": [0, 0, 3], "color": [10, 1, 1], "intensity": 1e308}]})
    with pytest.raises(ValueError, match=r"scene: \$\.lights\[0\]\.intensity: must be a number, got a string"):
        shadetool.render(V, F, None, {"lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": "x"}]})
    with pytest.raises(ValueError, match="F: must be None when the first argument is a shadetool.Mesh"):
        shadetool.vertex_normals(shadetool.Mesh(V, F), F)


def test_non_finite_positions_are_refused_where_the_cli_refuses_them(tetra):
    V, F = tetra
    V = V.copy()
    V[2, 1] = np.nan
    for call in (lambda: shadetool.repair(V, F), lambda: shadetool.bake_lighting(V, F, None, SCENE),
                 lambda: shadetool.occlusion(V, F), lambda: shadetool.transform(V, F, None, np.eye(4))):
        with pytest.raises(ValueError, match="NaN or Inf"):
            call()
    with pytest.raises(ValueError, match="NaN"):
        shadetool.write_mesh("/tmp/never-written.ply", V, F)
    # The normals functions follow the CLI's rule too (`shadetool normals` refuses the same mesh):
    # ValueError naming the first bad vertex, not a made-up (0, 0, 1) (issue 28, item 8).
    V[3, 0] = np.inf
    for fn in (shadetool.vertex_normals, shadetool.face_normals):
        with pytest.raises(ValueError, match=r"2 vertices have NaN or Inf coordinates \(first: vertex 2\)"):
            fn(V, F)
    with pytest.raises(ValueError, match=r"first: vertex 2"):
        shadetool.corner_normals(V, F, crease_deg=30)
    with pytest.raises(ValueError, match=r"first: vertex 2"):
        shadetool.vertex_normals(shadetool.Mesh(V, F))


def test_missing_files_raise_file_not_found(tmp_path, tetra):
    V, F = tetra
    with pytest.raises(FileNotFoundError, match="no such file"):
        shadetool.read_mesh(tmp_path / "missing.ply")
    with pytest.raises(FileNotFoundError):
        shadetool.bake_lighting(V, F, None, str(tmp_path / "missing.json"))
    with pytest.raises(FileNotFoundError, match="does not exist"):
        shadetool.write_mesh(tmp_path / "no" / "dir.ply", V, F)
    assert not (tmp_path / "no").exists()


def test_bad_file_content_raises_value_error_with_the_readers_message(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
    with pytest.raises(ValueError, match=r"bad.obj:4: "):
        shadetool.read_mesh(bad)
    with pytest.raises(ValueError, match="unknown mesh format"):
        shadetool.read_mesh(DATA / "pose.txt")
