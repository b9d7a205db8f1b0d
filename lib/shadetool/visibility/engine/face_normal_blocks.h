// face_normal_blocks.h: the library's face normals (normals/face_normals.h, double) for one block
// of consecutive faces at a time, so that a caller that reads each face's normal once (ambient
// occlusion per face) holds B rows instead of #F (machinery: at 1M triangles the #F rows are
// 24 MB, as much as two thirds of Embree's BVH).
//
// Inputs:  mesh        positions #V by 3, faces; outlives the call, unchanged
//          begin, end  the block: faces [begin, end)
//          starts      scratch for a polygon mesh's block face starts (reused between calls)
// Output:  (end - begin) by 3 unit normals, row f - begin for face f; (0, 0, 0) for a face without
//          area, as face_normals gives.
// Why these are face_normals(mesh)'s rows, bit for bit: a face's normal depends only on its own
//          corners' positions; the block is a view of the same positions (all #V of them, not
//          copied) and of the block's corners, so the one mesh-wide input, the power-of-two scale
//          of meshes outside [2^-32, 2^32) (normals/engine/mesh_scale.h: sampled over the
//          positions), is the mesh's own too. A triangle mesh's block is a triangle view (corner
//          3f, as the kernels read the whole mesh when C = 3F); a polygon mesh's block gets its
//          face starts rebased to its first corner.
// Memory:  24 B per block face for the result, 4 B per block face for polygon starts. (A mesh
//          outside the kernels' range is scaled into a copy of its positions per block: correct,
//          and slow only for such meshes.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/face_normals.h>

namespace shadetool::visibility_engine {

inline std::vector<double> face_normal_block(const Mesh& mesh, std::size_t begin, std::size_t end,
                                             std::vector<std::uint32_t>& starts) {
  const std::size_t n = end - begin;
  if (mesh.all_triangles())  // C = 3F: the kernels read face f at corner 3f, as for the whole mesh
    return face_normals(MeshView::triangles(mesh.positions.data(), mesh.num_vertices(),
                                            mesh.corner_vertex.data() + 3 * begin, n));
  const std::uint32_t first = mesh.face_start[begin];
  starts.resize(n + 1);
  for (std::size_t f = 0; f <= n; ++f) starts[f] = mesh.face_start[begin + f] - first;
  return face_normals(MeshView::polygons(mesh.positions.data(), mesh.num_vertices(), mesh.corner_vertex.data() + first,
                                         starts.data(), n));
}

}  // namespace shadetool::visibility_engine
