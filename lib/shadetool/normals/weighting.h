// weighting.h: the four weightings of face normals into vertex (and corner) normals, the
// accumulation precision, and what one face corner adds to its vertex's normal, under each of the four
// weightings, as four small scalar functions side by side (as OpenMesh's calc_vertex_normal_fast,
// _correct, _loop). Every path of the normals kernels computes these formulas; the vectorised
// triangle kernels (normals/engine/triangle_blocks.h) are tested against them
// (tests/normals/weighting.cpp).
//
// The corner: face area vector N = 2 A n (geometry/face_area_vector.h), |N| = len > 0 (the face is
// not degenerate by geometry/degenerate_face.h: a degenerate face contributes nothing, under every
// weighting), edges a = p_next - p and b = p_prev - p from the corner's vertex p.
//   n = unit_normal(N, len)                          N / |N|, multiplied by 1/|N| (divisor: len > 0)
//   Uniform  uniform_contribution(n)          = n    Gouraud 1971: every face counts once
//   Area     area_contribution(N)             = N    weight 2A: OpenMesh update_normals, libigl AREA
//   Angle    angle_contribution(n, theta)     = theta n   Thuermer & Wuethrich 1998; theta the
//            corner's interior angle (geometry/interior_angle.h; a triangle's third angle is
//            pi minus the other two; a polygon's reflex corner counts 2 pi - theta)
//   Max      max_contribution(v, s, d, out)   = v s / d   Max 1999, eq. 6: n sin(theta) / (|a| |b|)
//            = n |a x b| / (|a|^2 |b|^2), exact on a sphere. Triangle: |a x b| = |N| at every
//            corner, so v = N, s = 1; polygon: v = n, s = |(a x b) . n|; d = |a|^2 |b|^2.
//            Degenerate corner: d zero (a zero-length edge) or the result not finite (d
//            underflows): no contribution (returns false).
// Precision: double throughout; the kernels round each contribution once to the accumulation type.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <shadetool/core/vec3.h>
#include <shadetool/geometry/face_area_vector.h>  // SHADETOOL_INLINE

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class Weighting {
  Uniform,  // mean of unit face normals (Gouraud 1971)
  Area,     // sum of unnormalised face normals: weight = face area
  Angle,    // unit face normal times the interior angle at the vertex (Thuermer & Wuethrich 1998)
  Max,      // sin(angle) / (|e1| |e2|) (Max 1999), exact when the neighbours lie on a sphere
};

// The modes of Blender's Weighted Normal modifier (MOD_weighted_normal.cc), which rank a vertex's
// faces by a value and divide each rank's weight by the strength again (normals/ranked_normals.h):
enum class RankedWeighting {
  FaceArea,       // value: the face's area (Blender's "Face Area")
  CornerAngle,    // value: the corner's interior angle ("Corner Angle")
  FaceAreaAngle,  // value: area times angle ("Face Area And Angle", Unity's "area and angle weighted" ranked)
};
// Their --weight names (core/vocabulary.h, weighting.cpp), beside Weighting's: "face-area",
// "corner-angle", "face-area-angle". find_: nullopt for a name that is not one of them.
std::optional<RankedWeighting> find_ranked_weighting(std::string_view text);
const char* ranked_weighting_name(RankedWeighting weighting);
std::vector<std::string> ranked_weighting_names();

// Precision the kernels accumulate in (inputs and outputs are double arrays either way).
enum class Precision { Double, Float };

// Their vocabularies (core/vocabulary.h, weighting.cpp): "uniform", "area", "angle", "max"
// (--weight) and "double", "float" (--precision).
Weighting parse_weighting(std::string_view text, const std::string& what);
const char* weighting_name(Weighting weighting);
std::vector<std::string> weighting_names();
Precision parse_precision(std::string_view text, const std::string& what);
const char* precision_name(Precision precision);
std::vector<std::string> precision_names();


SHADETOOL_INLINE Vec3d unit_normal(const Vec3d& N, double len) { return N * (1.0 / len); }  // len > 0: checked by the caller

SHADETOOL_INLINE Vec3d uniform_contribution(const Vec3d& n) { return n; }

SHADETOOL_INLINE Vec3d area_contribution(const Vec3d& N) { return N; }

SHADETOOL_INLINE Vec3d angle_contribution(const Vec3d& n, double theta) { return n * theta; }

SHADETOOL_INLINE bool max_contribution(const Vec3d& v, double s, double d, Vec3d& out) {
  if (!(d > 0.0)) return false;
  out = v * (s / d);  // divisor checked
  return is_finite(out);
}

}  // namespace shadetool
#pragma GCC visibility pop
