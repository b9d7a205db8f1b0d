// mesh_info.h: everything `shadetool info` reports about a mesh, computed in one call.
//
// Inputs:  mesh  any Mesh as read (polygons, non-manifold parts, NaN/Inf values allowed)
// Outputs: MeshInfo
//   counts         vertices, faces, corners; faces by size (3: triangles, 4: quads, ...)
//   bbox           over the vertices with finite coordinates (has_bbox = false if there are none)
//   attributes     which optional arrays are present
//   topology       edges, boundary / non-manifold / inconsistently wound edges, non-manifold
//                  vertices (see edge_topology.h), connected components (connected_components.h)
//   defects        degenerate faces (geometry/degenerate_faces.h, the count repair reports), unreferenced vertices, vertices with NaN
//                  or Inf coordinates, NaN/Inf values among normals, texcoords and colours
// Nothing is modified; the mesh may be invalid in every way listed above, but its indices must be
// in range (readers guarantee that).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/vec3.h>
#include <shadetool/geometry/degenerate_faces.h>
#include <shadetool/info/edge_topology.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::info {

struct MeshInfo {
  std::size_t vertices = 0, faces = 0, corners = 0;
  std::vector<std::pair<std::size_t, std::size_t>> faces_by_size;  // (size, count), by size
  std::size_t triangles = 0, quads = 0, polygons = 0;              // polygons: more than 4 sides

  bool has_bbox = false;
  Vec3d bbox_min, bbox_max;

  bool vertex_normals = false, corner_normals = false, face_normals = false;
  bool vertex_colors = false, face_colors = false, texcoords = false;
  std::size_t corner_normal_pool = 0, texcoord_pool = 0;
  bool vertex_quality = false, face_quality = false;
  std::vector<std::string> vertex_properties, face_properties;  // names of Mesh's extra scalars
  int color_channels = 0;  // 0 when no colours
  bool double_precision = false;

  EdgeTopology topology;
  std::size_t components = 0;

  DegenerateFaces degenerate;
  std::size_t unreferenced_vertices = 0;
  std::size_t nonfinite_vertices = 0;  // vertices with a NaN or Inf coordinate
  std::size_t nonfinite_unreferenced_vertices = 0;  // of those, the ones no face uses (repair
                                                   // --remove-unreferenced removes them)
  std::size_t nonfinite_values = 0;    // NaN/Inf values in normals, texcoords and colours

  // Closed 2-manifold: every edge has exactly two sides, every vertex one fan, no degenerate face.
  bool closed_manifold() const {
    return faces > 0 && topology.boundary_edges == 0 && topology.non_manifold_edges == 0 &&
           topology.non_manifold_vertices == 0;
  }
};

MeshInfo mesh_info(const Mesh& mesh);

}  // namespace shadetool::info
#pragma GCC visibility pop
