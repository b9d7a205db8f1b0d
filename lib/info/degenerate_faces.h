// degenerate_faces.h: faces with a repeated vertex index or with zero area.
//
// Inputs:  mesh  positions (V*3), face_start (F+1), corner_vertex (C)
// Outputs: DegenerateFaces
//   repeated_index  faces that use one vertex index at more than one corner
//   zero_area       faces (without a repeated index) whose area vector is exactly zero: the Newell
//                   sum  A = 1/2 sum_i p_i x p_{i+1}  (taken relative to the first corner, which
//                   makes it exact for collinear integer points and translation-invariant) is
//                   (0,0,0) in double. NaN/Inf corners make a face neither zero-area nor regular:
//                   they are counted in `nonfinite`.
//   nonfinite       faces touching a vertex with a NaN or Inf coordinate
//   total           faces in at least one of repeated_index or zero_area
// Precision: double, the stored precision; no tolerance (exactly zero), so a sliver that is
// merely thin is not reported.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>

namespace shadetool::info {

struct DegenerateFaces {
  std::size_t repeated_index = 0;
  std::size_t zero_area = 0;
  std::size_t nonfinite = 0;
  std::size_t total = 0;
};

DegenerateFaces degenerate_faces(const Mesh& mesh);

// The rule above for one face f, for passes that must leave degenerate faces out (the visibility
// BVH): None, or the first of RepeatedIndex, NonFinite, ZeroArea that applies. `scratch` is reused
// storage for faces of more than 8 corners.
enum class FaceDegeneracy { None, RepeatedIndex, NonFinite, ZeroArea };
FaceDegeneracy face_degeneracy(const Mesh& mesh, std::size_t f, std::vector<std::uint32_t>& scratch);

}  // namespace shadetool::info
