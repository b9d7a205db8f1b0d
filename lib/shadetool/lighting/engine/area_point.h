// engine/area_point.h: area and sky lights inside the per-point loop (engine/shade_point.h).
// The point, its normal and the specular lobe are brought to world space once per point (only
// when a scene has such lights), then lighting/area_light.h gives P and S and
// lighting_equation.h's add_light_term adds ka*a + kd*L*P + ks*L*S. Internal: not installed.
#pragma once

#include <shadetool/lighting/area_light.h>
#include <shadetool/lighting/lighting_equation.h>
#include <shadetool/lighting/shade_points.h>
#include <shadetool/lighting/shading_space.h>

namespace shadetool {
namespace lighting_engine {

// The lobe is made only for specular scenes (has_lobe): a WorldPoint is declared per point, and
// zero-filling a SpecularLobe there (rep stos) was a fifth of the per-point loop of a rect light.
struct WorldPoint {
  WorldPoint() {}
  Vec3d p{0, 0, 0};
  Vec3d n{0, 0, 0};       // unit, or zero (then only the ambient term is added)
  bool has_lobe = false;  // lobe constructed (world_point with specular); else it is not read
  union {
    SpecularLobe lobe;
  };
};

// p, n in the frame's space S (n any length, already flipped for two-sided); zero_normal when the
// loop found n zero or non-finite. Fills `out` in place, every field it reads (p, n, has_lobe), so a
// WorldPoint may be reused from point to point (a returned one was zero-filled twice per point).
// world_unit_scale > 0: S is world and n * world_unit_scale is already the unit normal with the
// bits unit(n) would give (the loop's 1 / sqrt(n.n) in the identity metric, n.n in
// [2^-1000, 2^1000]): used as it is, not normalised again (a square root and a division on the
// path of every area light).
void world_point(const ShadingFrame& frame, ShadingModel model, bool specular, double shininess, const Vec3d& p,
                 const Vec3d& n, bool zero_normal, WorldPoint& out, double world_unit_scale = 0);

// Adds one area or sky light's terms to color; counts skips. visibility (shadows; 1 without):
// the light's visible fraction; visibility_ground the sky's ground's (sky lights only).
void add_area_light(Vec3d& color, const SpaceLight& light, const WorldPoint& point, ShadeCounters& count,
                    double visibility = 1.0, double visibility_ground = 1.0);

// A polygon or sphere light's terms t at the point: its counters, and ka*a + kd*L*P (+ ks*L*S
// with_specular). A zero normal: the ambient term only (t is not read).
inline void add_area_terms(Vec3d& color, const SpaceLight& light, const WorldPoint& point, const AreaTerms& t,
                           bool with_specular, ShadeCounters& count, double visibility) {
  if (point.n == Vec3d{0, 0, 0}) {
    if (light.has_ambient) color += light.products.ambient;
    return;
  }
  count.below_horizon += t.below_horizon;
  count.inside_light += t.inside;
  add_light_term(color, light.products, 1.0, t.P, t.S, light.has_ambient, with_specular, visibility);
}

// Whether the per-point loop may compute this light's terms for a block of points at once: a
// polygon light whose S is not needed (a scene without specular, a light without a specular
// colour, or the Lambert model), so that P and the counters' flags are all there is.
bool batched_polygon_light(const SpaceLight& light, ShadingModel model, bool specular);

// The terms polygon_light_terms gives (without a lobe) for a batched light at count <= kPointLanes
// world points, bit for bit: the points in the lanes of vectors (engine/lambert_lanes.h), the few
// lanes it leaves by polygon_light_terms itself. Writes terms[i * stride], i < count, for
// add_area_terms; points with a zero normal get default terms (add_area_terms adds their ambient
// term only and does not read them).
void polygon_terms_batch(const SpaceLight& light, const WorldPoint* points, int count, AreaTerms* terms,
                         std::size_t stride);

}  // namespace lighting_engine
}  // namespace shadetool
