// tangents.h: per-corner tangent frames by MikkTSpace (Mikkelsen 2008, "Simulation of wrinkled
// surfaces revisited", and the reference implementation's description, mikktspace.h/.c), the
// frame Blender, Substance, xNormal, Unreal and glTF 2.0 (3.7.2.1, TANGENT) bake normal maps in.
//
// Inputs:  mesh   positions #V by 3; faces (triangles, quads, polygons); normals: corner normals
//                 (corner_normal_index) when present, else vertex normals, else face normals;
//                 texture coordinates per corner (corner_texcoord_index, the first two of
//                 texcoord_dims components: u, v with v up, OBJ's and Blender's convention).
// Output:  tangents  #C by 4: xyz a unit vector (float values widened to double), w = +1 or -1,
//                    the handedness: bitangent = w * cross(normal, tangent).
//          fallback_corners  corners of faces the algorithm cannot take (a corner without a texture
//                    coordinate, or fewer than 3 corners): tangent = any unit vector
//                    perpendicular to the corner's normal (Duff et al. 2017), w = +1.
//          default_corners   corners the algorithm reached with no frame of its own (a degenerate
//                    triangle with no healthy neighbour at that vertex, or a triangle with zero
//                    texture area in no group): the reference's default, (1, 0, 0), w = -1.
//          zero_corners      corners whose frame in the reference is the zero vector (the sum of
//                    their group's derivatives projected onto the normal is zero within FLT_MIN:
//                    texture coordinates constant over the vertex's faces, or derivatives that
//                    cancel): zero is not a tangent (glTF 2.0 requires TANGENT of unit length, the
//                    Khronos validator reports it), so any unit vector perpendicular to the
//                    corner's normal (as fallback_corners), w the reference's.
//
// The algorithm, step by step as the reference (tangents.cpp names each step):
//  1. triangles: a quad is split along its shorter diagonal in texture space (ties: in space; still
//     tied: 0-2); a polygon of 5+ corners, which the reference skips, by geometry/
//     polygon_triangles.h (inside its outline, as render draws it; a convex polygon: the fan from
//     its first corner; Blender triangulates such polygons before calling MikkTSpace).
//  2. welding: corners with bitwise-equal (as float ==) position, normal and texture coordinate
//     are one vertex; the mesh's own indices play no part.
//  3. degenerate triangles (two equal positions) are set aside; a quad with one of them is marked.
//  4. per triangle: the texture-space derivatives vOs = t31y d1 - t21y d2, vOt = -t31x d1 + t21x d2
//     (Mikkelsen, eq. 18 and 19), unit, with the sign of the signed texture area (orientation);
//     a triangle with zero texture area (or zero derivative) groups with any neighbour; a quad
//     whose two triangles disagree in orientation takes the larger one's.
//  5. neighbours: triangles sharing a welded edge in opposite directions.
//  6. groups: around each welded vertex, the triangles linked through neighbours that share the
//     group's orientation (depth first, left neighbour first).
//  7. per group and triangle: the sub-group of members whose projected derivatives are not
//     antiparallel (the reference's angular threshold, 180 degrees) plus the triangle's own quad;
//     each distinct sub-group's frame is the angle-weighted sum of its members' derivatives
//     projected onto the vertex normal; the two triangles of a quad average at shared corners.
//  8. degenerate triangles copy the frame of the first healthy corner at the same welded vertex;
//     in a quad with one degenerate triangle, the missing corner copies the coincident corner's.
// Precision: float throughout, in the reference's order of operations (positions, normals and
// texture coordinates rounded to float first): its decisions (welding, orientation, which
// triangles group) are exact float comparisons, and a normal map baked with them shades correctly
// only with the same decisions. Checked against the reference (npm `mikktspace`, the gltf-rs port
// of mikktspace.c) on every mesh with texture coordinates in data/ and the corpus.
// Degenerate input: as above; no NaN is produced from finite input (every division checks its
// divisor as the reference does, FLT_MIN).
// Throws Error when the mesh has no texture coordinates or no normals.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct TangentFrames {
  std::vector<double> tangents;  // #C by 4
  std::size_t fallback_corners = 0;
  std::size_t default_corners = 0;
  std::size_t zero_corners = 0;
};

TangentFrames mikktspace_tangents(const Mesh& mesh);

// A unit vector perpendicular to the unit vector n (Duff et al. 2017, "Building an orthonormal
// basis, revisited", branchless); (1, 0, 0) when n is not finite or not near unit length.
Vec3d perpendicular_unit(const Vec3d& n);

// The note a command prints when zero_corners > 0 (one wording for the CLI, glTF and Python).
std::string tangent_zero_corners_note(std::size_t zero_corners);

}  // namespace shadetool
#pragma GCC visibility pop
