#!/usr/bin/env python3
"""Writes the small valid seed files of fuzz/corpus/ (one per format variant the readers accept).

Run from anywhere: python3 fuzz/corpus/make_seeds.py. Crash inputs found by fuzzing are added
next to these by hand (named crash-*), and to tests/bad_inputs/ with their expected message.
"""
import os, struct

here = os.path.dirname(os.path.abspath(__file__))

def put(target, name, data):
    d = os.path.join(here, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), 'wb') as f:
        f.write(data.encode() if isinstance(data, str) else data)

# ---- OBJ
put('fuzz_read_obj', 'tri_vt_vn.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nf 1/1/1 2/2/1 3/3/1\n')
put('fuzz_read_obj', 'quad_negative.obj', 'o q\ng g1\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\ns 1\nusemtl m\nf -4 -3 -2 -1\n')
put('fuzz_read_obj', 'colors_w.obj', 'mtllib x.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0 0.5\nv 0 1 0 1\nf 1//1 2//1 3//1\nvn 0 0 1\n'
    .replace('f 1//1 2//1 3//1\nvn 0 0 1\n', 'vn 0 0 1\nf 1//1 2//1 3//1\n'))
put('fuzz_read_obj', 'crlf_comments.obj', '# c\r\nv 0 0 0 \r\nv 1 0 0\r\n\r\nv 0 1 0\r\nf 1 2 3 # tail\r\nxyz unknown\r\n')
# This seed was the fuzzer's first crash (on main before the io fixes landed): the first face
# corner's vt index was lost by the lazy per-corner allocation, leaving index 2^32-1.
put('fuzz_read_obj', 'double_digits.obj', 'v 0.1234567890123 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5\nf 1/1 2/1 3/1\n')

# ---- PLY
head = 'ply\nformat {fmt} 1.0\ncomment seed\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
put('fuzz_read_ply', 'ascii_tri.ply', head.format(fmt='ascii') +
    'element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n')
put('fuzz_read_ply', 'ascii_rich.ply', 'ply\nformat ascii 1.0\nobj_info x\nelement vertex 4\nproperty double x\nproperty double y\n'
    'property double z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\n'
    'property uchar blue\nproperty uchar alpha\nproperty float u\nproperty float v\nelement face 1\n'
    'property list uchar uint vertex_index\nproperty list uchar float texcoord\nproperty float red\nproperty float green\n'
    'property float blue\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n'
    '0 0 0 0 0 1 255 0 0 255 0 0\n1 0 0 0 0 1 0 255 0 255 1 0\n1 1 0 0 0 1 0 0 255 255 1 1\n0 1 0 0 0 1 9 9 9 9 0 1\n'
    '4 0 1 2 3 8 0 0 1 0 1 1 0 1 0.5 0.5 0.5\n0 1\n')
verts = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
for fmt, e in (('binary_little_endian', '<'), ('binary_big_endian', '>')):
    body = b''.join(struct.pack(e + 'fff', *v) for v in verts)
    body += b''.join(struct.pack(e + 'Biii', 3, *f) for f in faces)
    put('fuzz_read_ply', fmt + '.ply', (head.replace('vertex 3', 'vertex 4').format(fmt=fmt) +
        'element face 4\nproperty list uchar int vertex_indices\nend_header\n').encode() + body)
body = b''.join(struct.pack('<ddd', *v) + bytes([10, 20, 30]) for v in verts)
body += b''.join(struct.pack('<Hhhhh', 3, *f, 7) for f in faces)  # ushort count, short indices, extra short
body += struct.pack('<B', 2) + struct.pack('<ff', 1, 2)          # one 'material' element with a list
put('fuzz_read_ply', 'binary_types.ply', ('ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\n'
    'property double y\nproperty double z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n'
    'element face 4\nproperty list ushort short vertex_indices\nproperty short flags\n'
    'element material 1\nproperty list uchar float values\nend_header\n').encode() + body)

# ---- OFF
put('fuzz_read_off', 'tet.off', 'OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n')
put('fuzz_read_off', 'counts_next_line.off', '# comment\nOFF\n\n3 1 0\n0 0 0\n1 0 0 # c\n0 1 0\n3 0 1 2 255 0 0\n')
put('fuzz_read_off', 'coff.off', 'COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n')
put('fuzz_read_off', 'noff.off', 'NOFF\n4 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n4 0 1 2 3 0.5 0.5 0.5 1\n')
put('fuzz_read_off', 'stcnoff.off', 'STCNOFF\n3 1 0\n0 0 0 0 0 1 255 0 0 0 0\n1 0 0 0 0 1 0 255 0 1 0\n0 1 0 0 0 1 0 0 255 0 1\n3 0 1 2\n')
put('fuzz_read_off', 'no_keyword.off', '3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n')

# ---- STL
put('fuzz_read_stl', 'ascii.stl', 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n'
    'endfacet\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n')
tris = [((0, 0, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0)), ((0, 0, 1), (1, 0, 0), (1, 1, 0), (0, 1, 0))]
data = b'seed binary stl'.ljust(80, b' ') + struct.pack('<I', len(tris))
for t in tris:
    data += b''.join(struct.pack('<fff', *v) for v in t) + b'\0\0'
put('fuzz_read_stl', 'binary.stl', data)
data = b'solid but binary'.ljust(80, b' ') + struct.pack('<I', len(tris))
for t in tris:
    data += b''.join(struct.pack('<fff', *v) for v in t) + b'\0\0'
put('fuzz_read_stl', 'binary_solid_header.stl', data)
