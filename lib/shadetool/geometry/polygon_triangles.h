// polygon_triangles.h: the triangles of one polygon face, by ear clipping in the polygon's own
// plane, so that a concave polygon is covered once, inside its outline, with every triangle wound
// as the polygon is. The library's one rule for splitting a polygon of 5+ corners: the glTF and
// STL writers (quads too), render, the occlusion/shadow BVH, the least-squares fit and tangents.
// Render, the BVH and the fit keep a convex quad on its 0-2 diagonal (render and the fit shade it
// bilinearly) and split a concave one (quad_is_concave below) by polygon_triangles; tangents keep
// every quad whole (MikkTSpace chooses its diagonal).
//
// Inputs:  positions   #V by 3 (double)
//          corners     the face's n corner vertex indices (n >= 3), as the face lists them
// Output:  3 (n - 2) indices into `corners` (0..n-1), appended to `out`, one triangle per 3, each
//          in the polygon's winding. A convex polygon gives the fan from corner 0,
//          (0,1,2) (0,2,3) ..., exactly the triangles writers wrote before; a triangle gives (0,1,2).
// Method:  the polygon is projected on the coordinate plane its Newell normal
//          (geometry/face_area_vector.h) is most nearly perpendicular to, oriented so that the
//          polygon turns counter-clockwise; then ear clipping (Meisters, "Polygons have ears",
//          Amer. Math. Monthly 82, 1975): a corner whose turn is convex and whose triangle holds no
//          other remaining corner is cut off, searching from the second remaining corner each time
//          (which gives the fan on a convex polygon). A corner at the position of one of the
//          candidate triangle's corners (the two ends of a bridge to a hole, a repeated vertex) does
//          not block it. Only reflex corners (turn <= 0) are tested against a candidate (in a
//          simple polygon, when any corner lies in a candidate's triangle a reflex one does too),
//          found through a grid over the outline (the cells the candidate crosses): the same ears
//          in the same order as testing every corner, without its O(n) per ear on a polygon convex
//          up to rounding (bench/geometry/results.md). A convex polygon is recognised in O(n) and
//          given the fan directly. Precision: double (projected 2D cross products; the grid's cell
//          arithmetic only chooses which corners to test, with a cell of margin).
// Degenerate input: a polygon whose Newell normal is zero or not finite (no area, collinear, NaN)
//          has no plane to clip in: the fan from corner 0, as before. When no ear is found among
//          the remaining corners (a self-intersecting outline), the remaining corners are written as
//          the fan from the first of them: every corner and the triangle count are kept.
#pragma once

#include <cstdint>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

void polygon_triangles(const double* positions, const std::uint32_t* corners, std::uint32_t n,
                       std::vector<std::uint32_t>& out);

// quad_is_concave: whether a quad (corners 0..3) turns right at one of its corners in its own
// plane (the projection polygon_triangles clips in: Newell normal, dominant axis dropped, the
// outline counter-clockwise). The one test of a concave quad for render, the BVH and the fit:
//   true   a dart (one reflex corner) or a bowtie (two): its bilinear map folds, so it is not a
//          valid parametrisation; it is split by polygon_triangles, through its reflex corner (on
//          1-3 when the reflex corner is 1 or 3, where the 0-2 diagonal lies outside the quad, as
//          Blender flips it: is_quad_flip_v3_first_third_fast in its mesh tessellation; on 0-2 when
//          it is 0 or 2), which is what the glTF and STL writers write, and shaded linearly on each
//          triangle.
//   false  a convex quad, one with a straight corner (turn exactly 0), or one with no plane (Newell
//          normal zero or not finite): kept on its 0-2 diagonal with its bilinear map, as before.
// Inputs: positions #V by 3 (double), corners the quad's 4 vertex indices. Precision: double, the
// same projected 2D cross products as polygon_triangles (no division).
bool quad_is_concave(const double* positions, const std::uint32_t* corners);

}  // namespace shadetool
#pragma GCC visibility pop
