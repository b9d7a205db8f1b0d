// visibility_scene.h: one ray-casting BVH per mesh (Intel Embree 3), built once and shared by every
// thread that asks what a ray from a point can see (ambient_occlusion.h, shadow_visibility.h).
//
// Inputs:  mesh  positions #V by 3, faces (triangles or polygons; non-manifold is fine); must
//                outlive the scene with its corner_vertex unchanged (see Memory)
// Builds:  an Embree triangle scene of the mesh's non-degenerate faces. Degenerate faces by the
//          library's one rule, geometry/degenerate_face.h (fewer than 3 corners, repeated index,
//          area vector zero to rounding, non-finite corner) take no part; for the BVH only (the mesh is not
//          touched) convex quads are fanned (c0, c1, c2) (c0, c2, c3), as render rasterises them,
//          and concave quads (polygon_triangles.h quad_is_concave) and polygons of 5+ corners
//          split inside their outline by geometry/polygon_triangles.h, as render draws them and
//          the glTF/STL writers write them (a concave quad through its reflex corner; a convex
//          polygon: the same fan).
// Frame:   Embree intersects in float. The BVH holds  local = (p - centre) * 2^-e  rounded once to
//          float, where centre is the middle of the kept faces' bounding box (in double) and 2^e
//          is the smallest power of two >= its half extent: |local| <= 1. Centring makes a mesh
//          1e8 from the origin as precise as one at the origin; the power-of-two scale is exact and
//          puts the mesh where ray_offset.h's constants are designed to work (extent about 1), so
//          a 1e-3 mesh and a 1e6 mesh behave alike. Precision of the geometry: 2^-24 of the
//          mesh's half extent. A vertex's local point is its BVH vertex exactly (same rounding).
// Memory:  the float vertex buffer (owned here, shared with Embree: 12 B per vertex), the index
//          buffer and Embree's BVH. When every face is a non-degenerate triangle the index buffer
//          IS the mesh's corner_vertex array (shared with Embree, not copied: `shared_indices`),
//          so the mesh must outlive the scene and its corner_vertex must not change while the
//          scene exists; otherwise the kept faces, split, are copied here (12 B per triangle).
//          Then Embree's BVH in its compact layout (RTC_SCENE_FLAG_COMPACT, about
//          36 B per triangle; bench/visibility/results.md), built in robust mode
//          (RTC_SCENE_FLAG_ROBUST: watertight, no ray leaks between triangles sharing an edge);
//          bvh_bytes counts what Embree allocated through the device's memory monitor.
// Threads: Embree builds with TBB (the caller's arena and limits); queries are read-only.
// Errors:  throws Error when the mesh's extent overflows float after centring or Embree fails.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct VisibilitySceneStats {
  std::size_t faces_used = 0;           // faces in the BVH
  std::size_t triangles = 0;            // triangles after splitting polygons
  std::size_t degenerate_faces = 0;     // left out: too few corners, repeated index or zero area
  std::size_t nonfinite_faces = 0;      // left out: a NaN or Inf corner
  std::size_t bvh_bytes = 0;            // Embree's allocations for the scene (net, after build)
  std::size_t buffer_bytes = 0;         // owned here: float vertices, and indices when copied
  bool shared_indices = false;          // the mesh's corner_vertex is the index buffer (no copy)
  double build_ms = 0;
};

class VisibilityScene {
 public:
  explicit VisibilityScene(const Mesh& mesh);
  explicit VisibilityScene(Mesh&&) = delete;  // the scene may share the mesh's corner array: no temporaries
  ~VisibilityScene();
  VisibilityScene(VisibilityScene&&) noexcept;
  VisibilityScene& operator=(VisibilityScene&&) noexcept;
  VisibilityScene(const VisibilityScene&) = delete;
  VisibilityScene& operator=(const VisibilityScene&) = delete;

  const VisibilitySceneStats& stats() const { return stats_; }

  // The BVH's frame: local = (world - centre) * scale, scale a power of two.
  Vec3d centre() const { return centre_; }
  double scale() const { return scale_; }
  Vec3f to_local(const Vec3d& world) const;

  struct Impl;  // lib/shadetool/visibility/engine/embree_scene.h
  const Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
  VisibilitySceneStats stats_;
  Vec3d centre_{};
  double scale_ = 1;
};

}  // namespace shadetool
#pragma GCC visibility pop
