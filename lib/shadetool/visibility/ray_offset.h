// ray_offset.h: where a ray leaving a surface starts, so that it does not hit the surface it
// leaves (self-intersection), with an offset that scales with the coordinates' magnitude.
//
// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems
// (2019), ch. 6, listing 6-1: the point p is moved along the geometric normal n by int_scale = 256
// units in the last place of each coordinate (integer arithmetic on the float's bits, so the
// offset is relative: ulp(p) grows with |p|), except near the origin (|p_i| < 1/32), where ulps
// become tiny and a fixed float_scale * n_i = n_i / 65536 is added instead. The constants bound
// the error of computing p (by barycentric interpolation or, here, rounding a double vertex to
// float) and of Embree's float intersection test, for points in a frame of extent about 1:
// VisibilityScene builds its BVH in such a frame (the mesh's box centred and scaled by a power of
// two), so the near-origin branch is relative to the mesh's size as well.
//
// Inputs:  p  the point on the surface, in the BVH's float frame
//          n  unit normal on the side the ray leaves from (flip it for rays going below)
// Output:  the ray origin
// Precision: float, the precision Embree intersects in. Degenerate input: n = 0 leaves p as is
// (the caller gives a usable normal: see shadow_visibility.h for points without one).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::visibility {

constexpr float kOffsetOrigin = 1.0f / 32.0f;       // below this |p_i|, add a fixed offset
constexpr float kOffsetFloatScale = 1.0f / 65536.0f;  // that fixed offset per unit of n_i
constexpr float kOffsetIntScale = 256.0f;            // ulps per unit of n_i elsewhere

inline float offset_coordinate(float p, float n) {
  if (std::fabs(p) < kOffsetOrigin) return p + kOffsetFloatScale * n;
  const std::int32_t of = static_cast<std::int32_t>(kOffsetIntScale * n);  // |of| <= 256
  std::int32_t bits;
  std::memcpy(&bits, &p, sizeof bits);
  bits += (p < 0) ? -of : of;  // moves p away from or toward 0 by |of| ulps, following n's sign
  float q;
  std::memcpy(&q, &bits, sizeof q);
  return q;
}

inline Vec3f offset_ray_origin(const Vec3f& p, const Vec3f& n) {
  return {offset_coordinate(p.x, n.x), offset_coordinate(p.y, n.y), offset_coordinate(p.z, n.z)};
}

}  // namespace shadetool::visibility
#pragma GCC visibility pop
