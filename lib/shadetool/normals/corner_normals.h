// corner_normals.h: one normal per face corner, smooth across gentle edges and split at creases.
//
// Inputs:  mesh          positions #V by 3, faces (triangles or polygons): a Mesh, or a MeshView
//                        of arrays held elsewhere (core/mesh_view.h; used in place, same bits)
//          crease_angle  radians; an edge is a crease when the angle between its two faces' unit
//                        normals exceeds crease_angle (0 = every non-flat edge splits; pi = no
//                        edge splits by angle). Boundary edges, non-manifold edges (3+ faces),
//                        edges whose two faces disagree in orientation and edges of degenerate
//                        faces are always creases.
//          weighting     how face normals are weighted within a smooth group (normals/weighting.h)
//          precision     accumulation precision
// Output:  normals       N by 3 pool of unit normals, one per (vertex, smooth group), in vertex
//                        order then by each group's first corner
//          corner_index  #C: index into `normals` for every corner (Mesh::corner_normal_index)
//          fallback_corners  corners whose group sum could not be normalised and got the
//                        documented fallback (never NaN)
//
// Around each vertex, two corners are in the same smooth group when they are linked by a chain of
// non-crease edges (union-find over the corners of the vertex); a group's normal is the
// normalised weighted sum of its corners' contributions, as in vertex_normals. This is
// libigl's per_corner_normals, OpenMesh's update_halfedge_normals and Blender's auto smooth,
// computed from flat arrays. With crease_angle >= pi on a closed manifold mesh every corner gets
// its vertex's vertex_normals result.
// Degenerate faces: their corners take the vertex's smooth normal (all valid contributions at
// the vertex, creases ignored), sharing the vertex's only group when it has one; a vertex with no
// valid face gets (0, 0, 1). A group whose sum cancels takes its first corner's face normal.
// Scale: as vertex_normals (a 2^k-scaled mesh gives bitwise the same normals; engine/mesh_scale.h).
// Crease test: interior_angle(|n1 x n2|, n1 . n2) <= crease_angle (geometry/interior_angle.h) on
// the unit face normals of face_normals.h; decided from n1 . n2 against cos(crease_angle) where
// that is at least 1e-5 from the threshold, which provably gives the angle comparison's verdict
// (corner_normals.cpp, CreaseTest), so an edge at exactly the threshold angle is smooth as before.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/core/mesh_view.h>
#include <shadetool/normals/weighting.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct CornerNormals {
  std::vector<double> normals;
  std::vector<std::uint32_t> corner_index;
  std::size_t fallback_corners = 0;
  std::size_t degenerate_faces = 0;  // faces that contributed nothing (as in vertex_normals)
};

CornerNormals corner_normals(const Mesh& mesh, double crease_angle, Weighting weighting = Weighting::Angle,
                             Precision precision = Precision::Double);
CornerNormals corner_normals(const MeshView& mesh, double crease_angle, Weighting weighting = Weighting::Angle,
                             Precision precision = Precision::Double);
// The same, with smoothing groups (normals/smoothing_groups.h): two faces join across an edge only
// when face_group gives them the same label and it is not 0 (0: a flat face); creases split further.
// Throws Error when face_group's size is not #F.
CornerNormals corner_normals(const Mesh& mesh, double crease_angle, const std::vector<std::uint32_t>& face_group,
                             Weighting weighting = Weighting::Angle, Precision precision = Precision::Double);

// corner_group_normals: one normal per group of corners that the caller chose (a file's smoothing
// groups, a stored normal pool), with the same weightings, kernels and summation order as
// corner_normals: a group's normal is the normalised weighted sum of its corners' contributions,
// added in ascending corner order.
// Inputs:  mesh          positions #V by 3, faces
//          corner_group  #C: the group of each corner, < num_groups, or kNoGroup (the corner
//                        contributes to nothing). Groups need not stay at one vertex.
//          num_groups    G
// Output:  normals       G by 3 unit normals; (0, 0, 0) for a failed group
//          failed        groups (ascending) whose sum is zero or not finite: no corner, only
//                        degenerate faces, or cancelling contributions. The caller gives them its
//                        fallback (they have no direction of their own).
//          degenerate_faces  faces that contributed nothing (geometry/degenerate_face.h)
// Throws Error when corner_group's size is not #C or a group is >= num_groups (and not kNoGroup).
constexpr std::uint32_t kNoGroup = 0xffffffffu;

struct GroupNormals {
  std::vector<double> normals;
  std::vector<std::uint32_t> failed;
  std::size_t degenerate_faces = 0;
};

GroupNormals corner_group_normals(const Mesh& mesh, const std::vector<std::uint32_t>& corner_group,
                                  std::size_t num_groups, Weighting weighting = Weighting::Angle,
                                  Precision precision = Precision::Double);

}  // namespace shadetool
#pragma GCC visibility pop
