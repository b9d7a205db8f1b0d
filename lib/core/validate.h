// validate.h: refusing input a command cannot use, with one clear line.
//
// Readers accept NaN/Inf coordinates (so that `shadetool info` can report them); commands that
// compute with positions call require_finite_positions first.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

#include "core/error.h"
#include "core/mesh.h"

namespace shadetool {

// Throws Error `NAME: K vertices have NaN or Inf coordinates (first: vertex I)` if any.
inline void require_finite_positions(const Mesh& mesh, const std::string& name) {
  std::size_t bad = 0, first = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = &mesh.positions[3 * v];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
      if (bad++ == 0) first = v;
    }
  }
  if (bad > 0)
    fail(name, 0, std::to_string(bad) + (bad == 1 ? " vertex has" : " vertices have") +
                      " NaN or Inf coordinates (first: vertex " + std::to_string(first) + ")");
}

// Throws Error `NAME: mesh is empty (no faces)` for a mesh with no faces.
inline void require_faces(const Mesh& mesh, const std::string& name) {
  if (mesh.num_faces() == 0) fail(name, 0, "mesh is empty (no faces)");
}

}  // namespace shadetool
