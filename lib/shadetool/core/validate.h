// validate.h: refusing input a command cannot use, with one clear line.
//
// Readers accept NaN/Inf coordinates (so that `shadetool info` can report them); commands that
// compute with positions call require_finite_positions first.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Throws Error `NAME: K vertices have NaN or Inf coordinates (first: vertex I)` if any, followed by
// `; no face uses them: `shadetool repair --remove-unreferenced` removes them` when no face uses
// any of them, `; K of them used by no face (...)` when some face uses some. The one rule for the
// command line and for Python (which holds a MeshView of the caller's arrays). The check is one
// pass over the positions split over the threads (validate.cpp).
void require_finite_positions(const MeshView& mesh, const std::string& name);
inline void require_finite_positions(const Mesh& mesh, const std::string& name) {
  require_finite_positions(MeshView(mesh), name);
}

// Throws Error `NAME: K normals have NaN or Inf components (first: KIND normal I); HINT` if any
// stored normal (vertex, corner pool, face) is not finite: for commands that would otherwise pass
// them through to their output (no output holds NaN or Inf the user did not ask to keep).
inline void require_finite_normals(const Mesh& mesh, const std::string& name, const std::string& hint) {
  std::size_t bad = 0;
  std::string first;
  auto scan = [&](const std::vector<double>& a, const char* kind) {
    for (std::size_t i = 0; i + 2 < a.size(); i += 3)
      if (!(std::isfinite(a[i]) && std::isfinite(a[i + 1]) && std::isfinite(a[i + 2])))
        if (bad++ == 0) first = std::string(kind) + " normal " + std::to_string(i / 3);
  };
  scan(mesh.vertex_normals, "vertex");
  scan(mesh.corner_normals, "corner");
  scan(mesh.face_normals, "face");
  if (bad > 0)
    fail(name, 0, std::to_string(bad) + (bad == 1 ? " normal has" : " normals have") + " NaN or Inf components (first: " +
                      first + "); " + hint);
}

// Throws Error `NAME: mesh is empty (no faces)` for a mesh with no faces.
inline void require_faces(const Mesh& mesh, const std::string& name) {
  if (mesh.num_faces() == 0) fail(name, 0, "mesh is empty (no faces)");
}

}  // namespace shadetool
#pragma GCC visibility pop
