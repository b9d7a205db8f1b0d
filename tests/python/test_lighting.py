# bake_lighting, occlusion and render against the CLI on the same mesh and scene: the same values
# bit for bit (colours as the CLI stores them with --hdr, occlusion as PLY quality, images as the
# PFM's floats and the PNG's bytes).
import json
import struct
import zlib

import numpy as np
import pytest

import shadetool
from conftest import DATA, run_cli, same_bits

SCENES = ["studio.json", "sun.json", "area_sphere.json", "sky.json"]


@pytest.mark.parametrize("scene", SCENES)
@pytest.mark.parametrize("per", ["vertex", "face"])
@pytest.mark.parametrize("shadows", [False, True])
def test_bake_lighting_equals_the_cli_colours(tmp_path, scene, per, shadows):
    out = tmp_path / "cli.ply"
    extra = ["--shadows", "--samples", "4"] if shadows else []
    run_cli("bake-lighting", DATA / "torus_knot.ply", "-o", out, "--scene", DATA / "scenes" / scene, "--hdr",
            "--per", per, *extra)
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    rgb = shadetool.bake_lighting(mesh, scene=DATA / "scenes" / scene, per=per, shadows=shadows, samples=4)
    assert rgb.dtype == np.float64
    assert rgb.shape == ((mesh.num_vertices if per == "vertex" else mesh.num_faces), 3)
    back = shadetool.read_mesh(out)
    stored = back.vertex_colors if per == "vertex" else back.face_colors
    assert same_bits(rgb.astype(np.float32), stored)  # --hdr stores float(c)
    # The scene as a dict gives the same bits as the file.
    as_dict = json.loads((DATA / "scenes" / scene).read_text())
    assert same_bits(shadetool.bake_lighting(mesh, scene=as_dict, per=per, shadows=shadows, samples=4), rgb)


def test_bake_lighting_of_one_directional_light_is_lamberts_law(tetra):
    V, F = tetra
    N = np.array([[0, 0, 1.0]] * 4)
    scene = {"model": "lambert", "ambient": [0, 0, 0],
             "material": {"ambient": [0, 0, 0], "diffuse": [1, 1, 1]},
             "lights": [{"type": "directional", "direction": [0, np.sin(0.5), -np.cos(0.5)]}]}  # travelling towards -z
    rgb = shadetool.bake_lighting(V, F, N, scene)
    assert np.allclose(rgb, np.cos(0.5), rtol=0, atol=1e-15)  # OpenGL: diffuse * max(n . L, 0)


@pytest.mark.parametrize("per", ["vertex", "face"])
def test_occlusion_equals_the_cli_quality(tmp_path, per):
    out = tmp_path / "cli.ply"
    run_cli("occlusion", DATA / "torus_knot.ply", "-o", out, "--as", "quality", "--samples", "16", "--per", per)
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    open_fraction = shadetool.occlusion(mesh, samples=16, per=per)
    back = shadetool.read_mesh(out)
    assert same_bits(open_fraction, back.vertex_quality if per == "vertex" else back.face_quality)


def test_occlusion_of_a_convex_mesh_is_one_and_of_a_box_interior_below():
    mesh = shadetool.read_mesh(DATA / "icosphere.ply")
    assert np.all(shadetool.occlusion(mesh, samples=8) == 1.0)  # nothing above a convex surface
    inward = np.array(mesh.faces)[:, ::-1]
    inside = shadetool.occlusion(np.array(mesh.vertices), inward, samples=8)
    assert np.all(inside == 0.0)  # inside a closed sphere every ray hits


def read_pfm(path):
    data = path.read_bytes()
    header, rest = data.split(b"\n", 3)[:3], data.split(b"\n", 3)[3]
    assert header[0] == b"PF"
    w, h = map(int, header[1].split())
    scale = float(header[2])
    pixels = np.frombuffer(rest, dtype="<f4" if scale < 0 else ">f4").reshape(h, w, 3)
    return pixels[::-1]  # PFM stores the bottom row first


def read_png_rgb8(path):
    """A non-interlaced 8-bit RGB PNG (what the renderer writes), decoded with zlib and the five filters."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, color, interlace) == (8, 2, 0)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = 3 * w
    out = np.zeros((h, stride), dtype=np.int32)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        prev = out[y - 1] if y > 0 else np.zeros(stride, dtype=np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            if f == 0: pred = 0
            elif f == 1: pred = a
            elif f == 2: pred = b
            elif f == 3: pred = (a + b) // 2
            else:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + pred) & 255
        out[y] = cur
    return out.reshape(h, w, 3).astype(np.uint8)


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_render_equals_the_cli_image(tmp_path, shading):
    pfm, png = tmp_path / "cli.pfm", tmp_path / "cli.png"
    scene = DATA / "scenes" / "studio.json"
    args = ["--scene", scene, "--size", "40,30", "--shading", shading, "--samples", "2"]
    run_cli("render", DATA / "torus_knot.ply", "-o", pfm, "--hdr", *args)
    run_cli("render", DATA / "torus_knot.ply", "-o", png, *args)
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    hdr = shadetool.render(mesh, scene=scene, width=40, height=30, shading=shading, samples=2, hdr=True)
    assert hdr.shape == (30, 40, 3) and hdr.dtype == np.float32
    assert same_bits(hdr, read_pfm(pfm))
    ldr = shadetool.render(mesh, scene=scene, width=40, height=30, shading=shading, samples=2)
    assert ldr.dtype == np.uint8 and same_bits(ldr, read_png_rgb8(png))
    assert np.count_nonzero(ldr) > 0


FLAT_SCENE = {"model": "lambert", "ambient": [0, 0, 0],
              "material": {"ambient": [0, 0, 0], "diffuse": [0.5, 0.25, 1]},
              "lights": [{"type": "directional", "direction": [0, 0, -1]}]}


def test_bake_lighting_uint8_is_srgb_by_default_and_linear_on_request(tmp_path):
    # issue 28, item 1: one convention with the CLI. kd = (0.5, 0.25, 1) lit straight on; IEC
    # 61966-2-1 by hand: 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536 -> 188; 0.25 -> 0.53710 -> 137.
    V = np.array([[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    N = np.array([[0, 0, 1.0]] * 4)
    assert np.all(shadetool.bake_lighting(V, F, N, FLAT_SCENE, uint8=True) == [188, 137, 255])
    assert np.all(shadetool.bake_lighting(V, F, N, FLAT_SCENE, uint8=True, linear=True) == [128, 64, 255])
    assert shadetool.bake_lighting(V, F, N, FLAT_SCENE, uint8=True).dtype == np.uint8
    assert np.allclose(shadetool.bake_lighting(V, F, N, FLAT_SCENE), [0.5, 0.25, 1], rtol=0, atol=1e-15)  # float: linear


@pytest.mark.parametrize("linear", [False, True])
def test_uint8_colours_equal_the_cli_bytes(tmp_path, linear):
    flag = ["--linear"] if linear else []
    mesh = shadetool.read_mesh(DATA / "torus_knot.ply")
    run_cli("bake-lighting", DATA / "torus_knot.ply", "-o", tmp_path / "lit.ply", "--scene",
            DATA / "scenes" / "studio.json", *flag)
    stored = np.rint(np.asarray(shadetool.read_mesh(tmp_path / "lit.ply").vertex_colors) * 255)
    rgb = shadetool.bake_lighting(mesh, scene=DATA / "scenes" / "studio.json", uint8=True, linear=linear)
    assert np.array_equal(rgb.astype(np.int64), stored.astype(np.int64))
    run_cli("occlusion", DATA / "torus_knot.ply", "-o", tmp_path / "ao.ply", "--samples", "16", *flag)
    grey = np.rint(np.asarray(shadetool.read_mesh(tmp_path / "ao.ply").vertex_colors)[:, 0] * 255)
    ao = shadetool.occlusion(mesh, samples=16, uint8=True, linear=linear)
    assert ao.dtype == np.uint8
    assert np.array_equal(ao.astype(np.int64), grey.astype(np.int64))
