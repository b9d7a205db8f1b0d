// degenerate_faces.h: how many faces are degenerate, by kind, for `shadetool info`.
//
// Inputs:  mesh  positions (V*3), face_start (F+1), corner_vertex (C)
// Outputs: DegenerateFaces, counted by the one rule of geometry/degenerate_face.h (the rule repair
//          removes by and normals skips by, so the three agree face for face; normals still use a
//          repeated-index face that has area):
//   repeated_index  faces that use one vertex index at more than one corner
//   zero_area       faces whose area vector vanishes to rounding (|N| <= 64 eps |a| |b|, a and b
//                   a triangle's two shortest edges; the Newell sum against its bound for a
//                   polygon), and faces with fewer than 3 corners (no area at all)
//   nonfinite       faces touching a NaN or Inf coordinate (or whose area overflows)
//   total           faces in at least one of repeated_index or zero_area
// Precision: double, the stored precision.
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::info {

struct DegenerateFaces {
  std::size_t repeated_index = 0;
  std::size_t zero_area = 0;
  std::size_t nonfinite = 0;
  std::size_t total = 0;
};

DegenerateFaces degenerate_faces(const Mesh& mesh);

}  // namespace shadetool::info
#pragma GCC visibility pop
