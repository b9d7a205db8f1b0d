// vertex_normals_plan.h: what vertex_normals' parallel sum needs from a mesh's connectivity,
// computed once and reused by every later call on the same connectivity (as OpenMesh builds its
// half-edge topology once and update_normals reuses it).
//
// Input:   mesh   faces (face_start, corner_vertex) and the vertex count; positions are not read
//                 (a Mesh or a MeshView, core/mesh_view.h)
// Holds:   the chunks of faces that threads sum in parallel and which vertices lie on chunk
//          borders (accumulate_by_vertex.h): 1 bit per vertex, and each chunk's border faces.
//          Building costs two passes over the corners; without a plan, the angle and Max calls
//          of vertex_normals pay the first again each time and the others sum serially
//          (figures: bench/normals/results/notes.md).
// Use:     VertexNormalsPlan plan(mesh);  ... vertex_normals(mesh, plan, weighting, precision, out);
//          Valid while the mesh's faces and vertex count stay as they were (positions may change:
//          that is the case it serves, e.g. animation or repeated updates). vertex_normals checks
//          the counts (Error when they differ); same counts with different faces is the caller's
//          error (the result would then be wrong, as with a stale OpenMesh topology).
// Results: bitwise the same with or without a plan, for any thread count (the plan only decides
//          how the work is split; accumulate_by_vertex.h explains why the sums do not depend on it).
// Threads: the plan is made for the concurrency of the arena that builds it (one chunk per
//          thread) and is correct under any other.
#pragma once

#include <cstddef>
#include <memory>

#include <shadetool/core/mesh_view.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

namespace normals_detail {
struct ChunkPlan;
}

class VertexNormalsPlan {
 public:
  VertexNormalsPlan() = default;  // empty: fits no mesh with faces
  explicit VertexNormalsPlan(const MeshView& mesh);

  // Whether the plan was built for a mesh with these counts (vertices, faces, corners).
  bool fits(const MeshView& mesh) const;
  const normals_detail::ChunkPlan& chunks() const { return *chunks_; }

 private:
  std::size_t vertices_ = 0, faces_ = 0, corners_ = 0;
  std::shared_ptr<const normals_detail::ChunkPlan> chunks_;
};

}  // namespace shadetool
#pragma GCC visibility pop
