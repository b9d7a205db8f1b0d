// write_bench_files.h: writes a benchmark mesh and its exact normals to disk, with no dependency on
// lib/io (the generator must run before, and independently of, the reader it is used to measure).
//
//   write_binary_ply   `ply / binary_little_endian`, vertex x y z (float, or double with
//                      `double_positions`), face `list uchar int vertex_indices`
//   write_obj          `v x y z` with %.9g (round-trips a float exactly) or %.17g (double), and
//                      `f a b c` (1-based)
//   write_normals_f64  raw little-endian doubles, #V by 3, the exact unit normal of each vertex
//                      (at the double position; float rounding of a position on a unit-size surface
//                      moves its true normal by at most ~1e-5 degrees)
// Every writer throws std::runtime_error naming the path when the file cannot be written.
#pragma once

#include <string>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

namespace shadetool::bench {

void write_binary_ply(const Mesh& mesh, const std::string& path, bool double_positions);
void write_obj(const Mesh& mesh, const std::string& path, bool double_positions);
void write_normals_f64(const std::vector<Vec3d>& normals, const std::string& path);

}  // namespace shadetool::bench
