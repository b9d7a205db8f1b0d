#!/usr/bin/env python3
"""Writes the hostile-input corpus tests/bad_inputs/files/ and its manifest expected.tsv.

Every file is one way a mesh file can be wrong. The manifest says, per file, what every
subcommand must do with it (tests/bad_inputs/bad_inputs.cpp runs them all):

  read       the reader refuses it: every subcommand (info too) prints ONE line on stderr,
             `shadetool: FILE[:LINE]: ...` containing FRAGMENT (or one of the alternatives
             FRAGMENT|FRAGMENT2, where readers are allowed to find either problem first), exits 1, writes no output, leaves
             the input and an existing output file as they were.
  nonfinite  the file is well formed but holds NaN or Inf positions: `info` reads it and reports
             it (exit 0, FRAGMENT in its report); every command that computes refuses it as
             `read` does, with a message containing "NaN or Inf".
  nonfinite_normals  positions fine, some stored normal NaN or Inf: `info` reports it (FRAGMENT),
             `repair` fixes it (exit 0, an output with no NaN or Inf), every other command
             refuses it as `read` does (its output would carry the NaN), naming "NaN or Inf" or
             "invalid".

Cases made at run time (a directory, unreadable permissions, a missing output directory, output
path = input path) are in bad_inputs.cpp, not here. Run: python3 tests/bad_inputs/make_corpus.py
"""
import os, random, struct

here = os.path.dirname(os.path.abspath(__file__))
out_dir = os.path.join(here, 'files')
entries = []  # (file, class, fragment, why)


def case(name, data, cls, fragment, why):
    if isinstance(data, str):
        data = data.encode('latin-1')
    with open(os.path.join(out_dir, name), 'wb') as f:
        f.write(data)
    entries.append((name, cls, fragment, why))


os.makedirs(out_dir, exist_ok=True)
for old in os.listdir(out_dir):
    os.remove(os.path.join(out_dir, old))
rng = random.Random(20260123)  # fixed seed: the corpus is reproducible byte for byte
garbage = bytes(rng.randrange(256) for _ in range(4000))
TRI_V = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n'

# ---------------------------------------------------------------- OBJ
case('obj_empty.obj', '', 'read', 'file is empty', 'zero bytes')
case('obj_garbage.obj', garbage, 'read', 'not a text mesh', 'random bytes (with NULs): not a text file')
case('obj_text_garbage.obj', 'hello world\nthis is no mesh\n' + ''.join(chr(32 + rng.randrange(95)) for _ in range(2000)),
     'read', 'not an OBJ file', 'printable text with no OBJ keyword')
case('obj_index_out_of_range.obj', TRI_V + 'f 1 2 4\n', 'read', 'vertex index 4 out of range', 'index past the last vertex')
case('obj_negative_past_start.obj', TRI_V + 'f -1 -2 -4\n', 'read', 'vertex index -4 out of range',
     'relative index reaching before the first vertex')
case('obj_index_zero.obj', TRI_V + 'f 0 1 2\n', 'read', 'index 0 is invalid', 'OBJ indices start at 1')
case('obj_index_2pow40.obj', TRI_V + 'f 1 2 1099511627776\n', 'read', 'out of range', 'index 2^40')
case('obj_index_overflow.obj', TRI_V + 'f 1 2 99999999999999999999999\n', 'read', 'malformed face index',
     'index beyond int64')
case('obj_face_vt_not_a_number.obj', TRI_V + 'vt 0 0\nf 1/ 2/x 3\n', 'read', "malformed face index '2/x'",
     'a vt field that is not a number (an empty one is absent; an `f` of 2 vertices is skipped, not refused)')
case('obj_malformed_number.obj', 'v 0 0 0\nv 1.5x 0 0\nv 0 1 0\nf 1 2 3\n', 'read', "malformed number '1.5x'",
     'trailing junk after a number')
case('obj_v_two_values.obj', 'v 0 0\n', 'read', 'v has 2 values', 'a vertex with two coordinates')
case('obj_texcoord_out_of_range.obj', TRI_V + 'vt 0 0\nf 1/1 2/2 3/1\n', 'read', 'texcoord index 2 out of range',
     'vt index past the last vt')
case('obj_normal_out_of_range.obj', TRI_V + 'vn 0 0 1\nf 1//1 2//1 3//-2\n', 'read', 'normal index -2 out of range',
     'relative vn index before the first vn')
case('obj_malformed_face_token.obj', TRI_V + 'vt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n', 'read', 'malformed face index', 'four slashes')
case('obj_very_long_line.obj', TRI_V + 'f 1 2 3 ' + '7' * 300_000 + '\n', 'read', 'malformed face index',
     'a 300 kB line: the message must not echo it')
case('obj_nan.obj', 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n', 'nonfinite', 'NaN/Inf                1 vertices',
     'a NaN coordinate')
case('obj_inf.obj', 'v 0 0 0\nv 1 -inf 0\nv 0 1 0\nf 1 2 3\n', 'nonfinite', 'NaN/Inf                1 vertices',
     'an Inf coordinate')
case('obj_overflow_to_inf.obj', 'v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n', 'nonfinite',
     'NaN/Inf                1 vertices', 'a literal beyond double: read as Inf')

# ---------------------------------------------------------------- PLY
def ply_header(fmt='ascii', nv=3, nf=1, extra_v='', face_prop='property list uchar int vertex_indices\n'):
    return ('ply\nformat %s 1.0\nelement vertex %s\nproperty float x\nproperty float y\nproperty float z\n%s'
            'element face %s\n%send_header\n' % (fmt, nv, extra_v, nf, face_prop))

TRI_ASCII = '0 0 0\n1 0 0\n0 1 0\n'
le_tet_v = struct.pack('<12f', 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
le_tet_f = b''.join(struct.pack('<B3i', 3, *f) for f in ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)))
be_tet_v = struct.pack('>12f', 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
be_tet_f = b''.join(struct.pack('>B3i', 3, *f) for f in ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)))
LE, BE = 'binary_little_endian', 'binary_big_endian'

case('ply_empty.ply', '', 'read', 'file is empty', 'zero bytes')
case('ply_garbage.ply', garbage, 'read', 'not a PLY file', 'random bytes')
case('ply_garbage_after_magic.ply', b'ply\n' + garbage, 'read', 'ply_garbage_after_magic.ply:',
     'the magic line, then random bytes')
case('ply_header_only.ply', ply_header(), 'read', 'header claims 3 vertex elements', 'header, no body')
case('ply_no_end_header.ply', 'ply\nformat ascii 1.0\nelement vertex 0\n', 'read', 'no end_header',
     'header never ends')
case('ply_no_format.ply', 'ply\nelement vertex 0\nend_header\n', 'read', 'no format line', 'format line missing')
case('ply_unknown_format.ply', ply_header('binary_middle_endian') + TRI_ASCII, 'read', "unknown PLY format",
     'an encoding that does not exist')
case('ply_binary_truncated_vertices.ply', ply_header(LE, 4, 4).encode() + le_tet_v[:30], 'read',
     'header claims 4 vertex elements', 'binary LE cut inside the vertices')
case('ply_binary_truncated_faces.ply', ply_header(LE, 4, 4).encode() + le_tet_v + le_tet_f[:-3], 'read',
     'truncated', 'binary LE cut inside the last face')
case('ply_binary_be_truncated.ply', ply_header(BE, 4, 4).encode() + be_tet_v + be_tet_f[:20], 'read',
     'ply_binary_be_truncated.ply', 'binary BE cut after the first face')
case('ply_huge_vertex_count.ply', ply_header(LE, 1099511627776, 4).encode() + le_tet_v + le_tet_f, 'read',
     'header claims 1099511627776 vertex elements|too many vertices', '2^40 vertices claimed: must not allocate')
case('ply_huge_vertex_count_ascii.ply', ply_header('ascii', 1099511627776, 1) + TRI_ASCII + '3 0 1 2\n', 'read',
     'header claims 1099511627776 vertex elements|too many vertices', '2^40 vertices claimed, ascii')
case('ply_huge_face_count.ply', ply_header(LE, 4, 4294967295).encode() + le_tet_v + le_tet_f, 'read',
     'header claims 4294967295 face elements', '2^32-1 faces claimed')
case('ply_huge_list_count.ply', ply_header(LE, 4, 1, face_prop='property list uint int vertex_indices\n').encode()
     + le_tet_v + struct.pack('<I3i', 4294967295, 0, 1, 2), 'read', 'truncated',
     'a face claiming 2^32-1 indices')
case('ply_more_data_than_declared.ply', ply_header('ascii', 3, 1) + TRI_ASCII + '3 0 1 2\n3 0 2 1\n', 'read',
     'more data than the header declares', 'counts that lie: a face too many')
case('ply_less_data_than_declared.ply', ply_header('ascii', 4, 1) + TRI_ASCII + '3 0 1 2\n', 'read',
     'ply_less_data_than_declared.ply', 'counts that lie: a vertex too few')
case('ply_binary_extra_bytes.ply', ply_header(LE, 4, 4).encode() + le_tet_v + le_tet_f + b'\x01\x02\x03\x04', 'read',
     'bytes after the last element', 'binary counts that lie: bytes left over')
case('ply_index_out_of_range.ply', ply_header(LE, 4, 1).encode() + le_tet_v + struct.pack('<B3i', 3, 0, 1, 7),
     'read', 'vertex index 7 out of range', 'binary index past the last vertex')
case('ply_negative_index.ply', ply_header('ascii') + TRI_ASCII + '3 0 -1 2\n', 'read', 'vertex index -1 out of range',
     'negative index')
case('ply_short_face_index_out_of_range.ply', ply_header('ascii', 3, 2) + TRI_ASCII + '3 0 1 2\n2 0 7\n', 'read',
     'vertex index 7 out of range', 'a 2-gon (skipped) naming a vertex past the last: still refused')
case('ply_negative_list_count.ply', ply_header('ascii', face_prop='property list char int vertex_indices\n')
     + TRI_ASCII + '-3 0 1 2\n', 'read', 'negative list count', 'a signed list count below zero')
case('ply_float_list_count.ply', ply_header('ascii', face_prop='property list float int vertex_indices\n')
     + TRI_ASCII + '3 0 1 2\n', 'read', 'bad list count type', 'a float list count type')
case('ply_unknown_type.ply', ply_header('ascii', extra_v='property float128 w\n') + TRI_ASCII + '3 0 1 2\n', 'read',
     "unknown property type 'float128'", 'a type that does not exist')
case('ply_property_before_element.ply', 'ply\nformat ascii 1.0\nproperty float x\nend_header\n', 'read',
     'property before any element', 'a property outside any element')
case('ply_negative_count.ply', ply_header('ascii', -3, 1) + TRI_ASCII + '3 0 1 2\n', 'read',
     "malformed element count '-3'", 'a negative element count')
case('ply_malformed_number.ply', ply_header('ascii') + '0 0 0\n1 0 zz\n0 1 0\n3 0 1 2\n', 'read',
     "malformed number 'zz'", 'a word where a number goes')
case('ply_no_xyz.ply', 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n', 'read',
     'no x, y and z', 'a vertex element without y and z')
case('ply_no_vertex_indices.ply', ply_header('ascii', face_prop='property int flags\n') + TRI_ASCII + '0\n', 'read',
     'no vertex_indices', 'a face element without its index list')
case('ply_long_header_line.ply', 'ply\nformat ascii 1.0\n' + 'x' * 200_000 + '\nend_header\n', 'read',
     'no vertex in the file', 'a 200 kB header line without a keyword (a comment, issue 21 item 7) and no element')
case('ply_nan_binary.ply', ply_header(LE, 4, 4).encode() + struct.pack('<12f', 0, 0, 0, float('nan'), 0, 0, 0, 1, 0,
     0, 0, 1) + le_tet_f, 'nonfinite', 'NaN/Inf                1 vertices', 'a NaN coordinate in binary')
case('ply_inf_ascii.ply', ply_header('ascii') + '0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n', 'nonfinite',
     'NaN/Inf                1 vertices', 'an Inf coordinate in ascii')

# ---------------------------------------------------------------- OFF
TRI_OFF = '0 0 0\n1 0 0\n0 1 0\n'
case('off_empty.off', '', 'read', 'file is empty', 'zero bytes')
case('off_garbage.off', garbage, 'read', 'off_garbage.off:', 'random bytes')
case('off_not_off.off', 'PFF\n3 1 0\n' + TRI_OFF + '3 0 1 2\n', 'read', 'not an OFF file', 'a wrong keyword')
case('off_only_comments.off', '# nothing here\n\n# at all\n', 'read', 'no OFF header', 'comments only')
case('off_header_only.off', 'OFF\n3 1 0\n', 'read', 'header claims 3 vertices and 1 faces', 'counts, no body')
case('off_huge_counts.off', 'OFF\n1099511627776 1099511627776 0\n' + TRI_OFF + '3 0 1 2\n', 'read',
     'header claims 1099511627776 vertices', '2^40 vertices and faces claimed')
case('off_fewer_vertices_than_declared.off', 'OFF\n4 1 0\n' + TRI_OFF + '3 0 1 2\n', 'read',
     'off_fewer_vertices_than_declared.off:', 'counts that lie: a vertex too few')
case('off_more_data_than_declared.off', 'OFF\n3 1 0\n' + TRI_OFF + '3 0 1 2\n3 0 2 1\n', 'read',
     'more data than the header declares', 'counts that lie: a face too many')
case('off_index_out_of_range.off', 'OFF\n3 1 0\n' + TRI_OFF + '3 0 1 3\n', 'read', 'vertex index 3 out of range',
     'index past the last vertex')
case('off_negative_index.off', 'OFF\n3 1 0\n' + TRI_OFF + '3 0 -1 2\n', 'read', 'vertex index -1 out of range',
     'negative index')
case('off_face_size_lies.off', 'OFF\n3 1 0\n' + TRI_OFF + '5 0 1 2\n', 'read', 'off_face_size_lies.off:6',
     'a face whose size says 5 but lists 3')
case('off_short_face_index_out_of_range.off', 'OFF\n3 2 0\n' + TRI_OFF + '3 0 1 2\n2 0 5\n', 'read',
     'vertex index 5 out of range', 'a 2-gon (skipped) naming a vertex past the last: still refused')
case('off_malformed_count.off', 'OFF\n3 x 0\n' + TRI_OFF + '3 0 1 2\n', 'read', "malformed count 'x'",
     'a word for a count')
case('off_binary.off', 'OFF BINARY\n', 'read', 'binary OFF: byte 11: the body ends before the counts', 'a binary OFF with no body')
case('off_vertex_two_values.off', 'OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n', 'read', 'vertex line has 2 values',
     'a vertex with two coordinates')
case('off_very_long_line.off', 'OFF\n3 1 0\n' + TRI_OFF + '3 0 1 2 ' + '9' * 300_000 + '\n', 'read',
     'off_very_long_line.off:6', 'a 300 kB face line: the message must not echo it')
case('off_inf.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\ninf 1 0\n3 0 1 2\n', 'nonfinite', 'NaN/Inf                1 vertices',
     'an Inf coordinate')

# ---------------------------------------------------------------- STL
def stl_binary(tris, count=None, header=b'hostile'):
    data = header.ljust(80, b' ') + struct.pack('<I', len(tris) if count is None else count)
    for n, a, b, c in tris:
        data += struct.pack('<12f', *n, *a, *b, *c) + b'\0\0'
    return data

two = [((0, 0, 1), (0, 0, 0), (1, 0, 0), (0, 1, 0)), ((0, 0, 1), (1, 0, 0), (1, 1, 0), (0, 1, 0))]
FACET = 'facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n'
case('stl_empty.stl', '', 'read', 'file is empty', 'zero bytes')
case('stl_short_garbage.stl', garbage[:40], 'read', 'not an STL file', '40 random bytes')
case('stl_garbage.stl', garbage, 'read', 'truncated or not STL', 'random bytes')
case('stl_binary_truncated.stl', stl_binary(two)[:-30], 'read', 'binary STL header says 2 triangles',
     'binary cut inside the second triangle')
case('stl_binary_huge_count.stl', stl_binary(two, count=0xFFFFFFFF), 'read', 'header says 4294967295 triangles',
     '2^32-1 triangles claimed: must not allocate')
case('stl_binary_count_too_small.stl', stl_binary(two, count=1), 'read', 'header says 1 triangles',
     'counts that lie: a triangle more than declared')
case('stl_header_only.stl', stl_binary([], count=5), 'read', 'header says 5 triangles', 'header, no triangles')
case('stl_ascii_truncated.stl', 'solid t\n' + FACET + 'facet normal 0 0 1\nouter loop\nvertex 0 0', 'read',
     'file ends inside a facet', 'ascii cut inside a vertex')
case('stl_ascii_no_endsolid.stl', 'solid t\n' + FACET, 'read', 'no endsolid', 'ascii without endsolid')
case('stl_ascii_malformed_number.stl', 'solid t\n' + FACET.replace('vertex 1 0 0', 'vertex 1 0 0,5') + 'endsolid\n',
     'read', "malformed number '0,5'", 'a decimal comma')
case('stl_ascii_two_vertices.stl', 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n'
     'endfacet\nendsolid\n', 'read', 'facet has 2 vertices', 'a 2-gon facet')
case('stl_ascii_bad_keyword.stl', 'solid t\nfacet normal 0 0 1\nouter lop\n', 'read', "expected 'loop'",
     'a misspelt keyword')
case('stl_binary_nan.stl', stl_binary([((0, 0, 1), (0, 0, 0), (float('nan'), 0, 0), (0, 1, 0))]), 'nonfinite',
     'NaN/Inf                1 vertices', 'a NaN coordinate in binary')

# ---------------------------------------------------------------- NaN/Inf normals
case('obj_nan_normal.obj', TRI_V + 'vn 0 0 1\nvn nan 0 1\nf 1//1 2//2 3//1\n', 'nonfinite_normals',
     '1 attribute values', 'a NaN vn')
case('ply_inf_vertex_normal.ply', ply_header('ascii', extra_v='property float nx\nproperty float ny\nproperty float nz\n')
     + '0 0 0 0 0 1\n1 0 0 0 inf 1\n0 1 0 0 0 1\n3 0 1 2\n', 'nonfinite_normals', 'NaN/Inf                0 vertices, 1 attribute values',
     'an Inf vertex normal component')
# (A NaN/Inf STL facet normal is no bad input: the reader replaces it by its triangle's own, as a
# zero one, with a note; OpenSCAD writes `facet normal nan nan nan` on slivers. tests/io/stl_format.cpp.)
case('off_nan_vertex_normal.off', 'NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 nan 0 1\n0 1 0 0 0 1\n3 0 1 2\n',
     'nonfinite_normals', 'NaN/Inf                0 vertices, 1 attribute values', 'a NaN normal in NOFF')

# ---------------------------------------------------------------- names
case('unknown_extension.xyz', 'v 0 0 0\n', 'read', "unknown mesh format 'xyz'", 'an extension no reader has')
case('no_extension', 'v 0 0 0\n', 'read', 'no file extension', 'no extension at all')

with open(os.path.join(here, 'expected.tsv'), 'w') as f:
    f.write('# file\tclass\tfragment\twhy  (written by make_corpus.py; see its docstring)\n')
    for e in entries:
        f.write('\t'.join(e) + '\n')
print(len(entries), 'files in', out_dir)
