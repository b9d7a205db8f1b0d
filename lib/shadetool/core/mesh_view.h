// mesh_view.h: a mesh's positions and faces as borrowed arrays (pointers and counts), so that a
// caller holding them in its own memory (NumPy arrays, another library's buffers) computes on them
// in place instead of copying them into a Mesh. The normals kernels take a view; a Mesh converts to
// one, so both run the same code.
//
// Shapes (as core/mesh.h; V = #vertices, F = #faces, C = #corners):
//   positions      V*3 doubles   x y z per vertex, contiguous (row-major (V, 3))
//   corner_vertex  C uint32      vertex index of each corner
//   face_start     F+1 uint32    face f uses corners [face_start[f], face_start[f+1]), from 0 to C;
//                  or null: every face is a triangle, face f = corners 3f, 3f+1, 3f+2 (C = 3F)
// Contract (the maker's, checked once where the view is made, not by the kernels): every index
// < V, face_start non-decreasing from 0 to C, C < 2^32. The arrays outlive the view and do not
// change while a computation reads them. A view owns nothing and copies nothing.
// A Mesh converts to a view implicitly (a function taking `const MeshView&` takes a Mesh); the
// view of a temporary Mesh is refused at compile time (it would dangle).
#pragma once

#include <cstddef>
#include <cstdint>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct MeshView {
  const double* positions = nullptr;
  const std::uint32_t* corner_vertex = nullptr;
  const std::uint32_t* face_start = nullptr;  // null: triangles, face f = corners 3f .. 3f+2
  std::size_t vertex_count = 0, face_count = 0, corner_count = 0;

  MeshView() = default;
  MeshView(const Mesh& mesh)  // NOLINT(google-explicit-constructor): a Mesh is a view of itself
      : positions(mesh.positions.data()), corner_vertex(mesh.corner_vertex.data()),
        face_start(mesh.face_start.data()), vertex_count(mesh.num_vertices()), face_count(mesh.num_faces()),
        corner_count(mesh.num_corners()) {}
  MeshView(Mesh&&) = delete;

  // Triangles (F, 3) in place: positions (V, 3), triangles (F, 3) vertex indices.
  static MeshView triangles(const double* positions, std::size_t V, const std::uint32_t* triangles, std::size_t F) {
    MeshView view;
    view.positions = positions;
    view.corner_vertex = triangles;
    view.vertex_count = V;
    view.face_count = F;
    view.corner_count = 3 * F;
    return view;
  }
  // Faces of any sizes: corner_vertex (C), face_start (F + 1).
  static MeshView polygons(const double* positions, std::size_t V, const std::uint32_t* corner_vertex,
                           const std::uint32_t* face_start, std::size_t F) {
    MeshView view;
    view.positions = positions;
    view.corner_vertex = corner_vertex;
    view.face_start = face_start;
    view.vertex_count = V;
    view.face_count = F;
    view.corner_count = face_start[F];
    return view;
  }

  std::size_t num_vertices() const { return vertex_count; }
  std::size_t num_faces() const { return face_count; }
  std::size_t num_corners() const { return corner_count; }
  std::uint32_t face_begin(std::size_t f) const { return face_start ? face_start[f] : std::uint32_t(3 * f); }
  std::uint32_t face_end(std::size_t f) const { return face_start ? face_start[f + 1] : std::uint32_t(3 * f + 3); }
  std::uint32_t face_size(std::size_t f) const { return face_end(f) - face_begin(f); }

  // True when the kernels take the triangle path (corner = 3f + k): C = 3F, as Mesh::all_triangles.
  bool all_triangles() const { return corner_count == 3 * face_count; }

  Vec3d position(std::size_t v) const { return {positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]}; }
};

}  // namespace shadetool
#pragma GCC visibility pop
