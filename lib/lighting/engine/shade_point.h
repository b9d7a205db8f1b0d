// engine/shade_point.h: the per-point loop around lighting_equation.h, in a shading space with
// metric G (engine/metric.h): the normal's length, V, and per light L, the distance, attenuation
// and spot factor; then lighting_equation.h's add_light_term. Internal: not installed.
//
// Order of work per light (what is skipped is counted in ShadeCounters):
//   1. sign of n.(position - p), no square root: back-facing lights without an ambient term stop.
//   2. distance, then the spot-cone test: points outside the cone stop.
//   3. attenuation, spot exponent (pow), diffuse, specular (pow).
// kEarlyTests = false (SkipOptions::early_tests off, for bench/lighting and the tests that prove
// the skips change no bit) computes every step for every light and adds the zeros.
//
// Every switch over LightType here is exhaustive (no default): a new kind fails to compile
// (-Wswitch) until it has its own branch. Ambient lights never reach this loop (plan_lighting
// folds them into the constant base); area and sky lights go to engine/area_point.h.
//
// Two steps per point: prepare_point (the normal's scale, V, the two-sided flip) and
// shade_prepared_point (the lights); shade_point_in_space is both. shade_points.cpp's batched
// loop runs them apart, so that polygon lights' terms are computed in between for a block of
// points at once (PointBatch; engine/lambert_lanes.h).
#pragma once

#include <cmath>
#include <type_traits>

#include <shadetool/lighting/lighting_equation.h>
#include <shadetool/lighting/shade_points.h>
#include <shadetool/lighting/shading_space.h>
#include <shadetool/lighting/engine/area_point.h>
#include <shadetool/lighting/engine/metric.h>

namespace shadetool {
namespace lighting_engine {

// What the per-point evaluation needs besides the frame.
struct EquationSetup {
  ShadingModel model = ShadingModel::BlinnPhong;
  bool specular = false;     // plan.specular
  bool view = false;         // plan.view
  bool two_sided = false;
  double shininess = 0;
  Vec3d base{0, 0, 0};       // plan.base
};

#if defined(__GNUC__)
#define SHADETOOL_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SHADETOOL_ALWAYS_INLINE inline
#endif

// What the light loop reads of a point besides p: its normal (flipped for two-sided lighting),
// the normal's scale and the view vector, all in the frame's space S.
struct PreparedPoint {
  Vec3d n{0, 0, 0};          // zero for a zero or non-finite normal
  double n2 = 0;             // |n|^2_{G^-1} as given
  double n_scale = 0;        // 1 / |n|_{G^-1}; 0 leaves only the ambient terms
  Vec3d V_lowered{0, 0, 0};  // G V, V unit toward the eye (zero at the eye or without plan.view)
  double v_unit = 0;         // |V|^2: 1, or 0 at the eye
  double n_dot_v = 0;
};

// p (in S) and n (in S, any length): counts the point (and a zero normal).
template <class Metric>
SHADETOOL_ALWAYS_INLINE PreparedPoint prepare_point(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq,
                                                    const Vec3d& p, const Vec3d& n, ShadeCounters& count) {
  ++count.points;
  PreparedPoint r;
  r.n = n;
  r.n2 = g.conorm2(n);
  if (r.n2 > 0 && std::isfinite(r.n2)) {
    r.n_scale = 1.0 / std::sqrt(r.n2);
  } else {
    r.n = {0, 0, 0};
    ++count.zero_normals;
  }
  if (eq.view) {
    const UnitAndLength eye_dir = metric_normalize(g, frame.eye - p);
    if (eye_dir.length > 0) {
      r.V_lowered = g.lower(eye_dir.unit);
      r.v_unit = 1;
      r.n_dot_v = dot(r.n, eye_dir.unit) * r.n_scale;
    }
    if (eq.two_sided && r.n_dot_v < 0) {
      r.n = -r.n;
      r.n_dot_v = -r.n_dot_v;
    }
  }
  return r;
}

// The point in world space for area and sky lights (engine/area_point.h's world_point).
template <class Metric>
SHADETOOL_ALWAYS_INLINE void make_world_point(const ShadingFrame& frame, const EquationSetup& eq, const Vec3d& p,
                                              const PreparedPoint& pp, WorldPoint& world) {
  // In world space with the identity metric, n * n_scale is unit(n) bit for bit (the same
  // 1 / sqrt(n.n) as engine/metric.h's rule inside [2^-1000, 2^1000]): not redone.
  const bool world_unit = std::is_same<Metric, IdentityMetric>::value && frame.space_is_world && pp.n2 >= 0x1p-1000 &&
                          pp.n2 <= 0x1p1000;
  world_point(frame, eq.model, eq.specular, eq.shininess, p, pp.n, pp.n_scale == 0, world,
              world_unit ? pp.n_scale : 0.0);
}

// A batch of points made by the per-point loop (shade_points.cpp) for some polygon lights: the
// point's world point, made already, and for each light j with batched[j] its terms[j].
struct PointBatch {
  const WorldPoint* world = nullptr;
  const bool* batched = nullptr;
  const AreaTerms* terms = nullptr;
};

// The colour at p (in the frame's space) prepared by prepare_point.
// Always inlined into the per-point loop (see bench/lighting/results.md for why).
// kShadows: visibility points at this point's row of ShadeOptions::visibility (2 values per
// frame light: the light's visible fraction, and for a sky its ground's); without shadows it is
// unused and every light's visibility is the constant 1 (the same code and bits as before).
// batch (optional): polygon lights' terms computed for a block of points at once.
template <bool kEarlyTests, bool kShadows, class Metric>
SHADETOOL_ALWAYS_INLINE Vec3d shade_prepared_point(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq,
                                                   const Vec3d& p, const PreparedPoint& pp, ShadeCounters& count,
                                                   const double* visibility = nullptr,
                                                   const PointBatch* batch = nullptr) {
  Vec3d color = eq.base;
  const Vec3d n = pp.n;  // copies, not references: values the compiler keeps in registers
  const double n_scale = pp.n_scale;
  const Vec3d V_lowered = pp.V_lowered;
  const double v_unit = pp.v_unit, n_dot_v = pp.n_dot_v;

  WorldPoint local_world;  // area and sky lights: p, n and the lobe in world space, made at the first one
  const WorldPoint* world = batch ? batch->world : nullptr;
  for (std::size_t j = 0; j < frame.lights.size(); ++j) {
    const SpaceLight& light = frame.lights[j];
    const double vis = kShadows ? visibility[2 * j] : 1.0;
    const double vis_ground = kShadows ? visibility[2 * j + 1] : 1.0;
    ++count.vertex_light_evaluations;
    const bool with_ambient = light.has_ambient || !kEarlyTests;
    Vec3d L;             // unit (in G) toward the light
    double n_dot_l = 0;  // unit-normal n . L
    double att_spot = 1;
    switch (light.type) {
      case LightType::Ambient:  // folded into eq.base by plan_lighting; never in frame.lights
        continue;
      case LightType::Directional:
        L = light.to_light;
        n_dot_l = dot(n, L) * n_scale;
        if (kEarlyTests && !(n_dot_l > 0) && !light.has_ambient) {
          ++count.back_facing;
          continue;
        }
        break;
      case LightType::Point:
      case LightType::Spot: {
        const Vec3d to_light = light.position - p;
        if (kEarlyTests && !(dot(n, to_light) > 0) && !light.has_ambient) {  // sign of n.L, no sqrt
          ++count.back_facing;
          continue;
        }
        const UnitAndLength light_dir = metric_normalize(g, to_light);
        const double d = light_dir.length;
        if (!(d > 0)) {  // the point is at the light: L and att undefined, the light adds nothing
          ++count.at_light;
          continue;
        }
        L = light_dir.unit;
        double spot = 1;
        if (light.cone) {
          const double cos_t = -dot(L, light.axis_lowered);
          if (kEarlyTests && cos_t < light.cos_cutoff) {
            ++count.outside_cone;
            continue;
          }
          spot = spot_factor(cos_t, light.cos_cutoff, light.exponent);
        }
        // kc, kl, kq >= 0, not all zero, and d > 0: the denominator is positive.
        att_spot = spot / attenuation_denominator(light.kc, light.kl, light.kq, d);
        n_dot_l = dot(n, L) * n_scale;
        break;
      }
      case LightType::Sky:
        if (!(eq.specular && light.has_specular)) {  // diffuse only: P from n.up in this space, no world map
          if (n_scale == 0) {  // zero normal: the ambient term only
            if (light.has_ambient) color += light.products.ambient;
            continue;
          }
          if (kShadows && (vis < 1 || vis_ground < 1)) ++count.shadowed;
          const SkyProjection P = sky_projected_solid_angles(dot(n, light.to_light) * n_scale);
          add_light_term(color, light.products, 1.0, P.sky, 0.0, light.has_ambient, false, vis);
          add_light_term(color, light.ground_products, 1.0, P.ground, 0.0, false, false, vis_ground);
          continue;
        }
        [[fallthrough]];
      case LightType::Area:  // P and S in world space (area_light.h, environment_map.h)
      case LightType::Environment:
        if (kShadows && (vis < 1 || vis_ground < 1)) ++count.shadowed;
        if (!world) {
          make_world_point<Metric>(frame, eq, p, pp, local_world);
          world = &local_world;
        }
        if (batch && batch->batched[j])
          add_area_terms(color, light, *world, batch->terms[j], false, count, vis);
        else
          add_area_light(color, light, *world, count, vis, vis_ground);
        continue;
    }

    if (kShadows && vis < 1 && n_dot_l > 0) ++count.shadowed;
    const bool with_specular = eq.specular && light.has_specular;
    double spec = 0;
    if (with_specular && (n_dot_l > 0 || !kEarlyTests)) {
      const double l_dot_v = dot(L, V_lowered);
      spec = eq.model == ShadingModel::BlinnPhong ? specular_blinn_phong(n_dot_l, n_dot_v, l_dot_v, v_unit, eq.shininess)
                                                  : specular_phong(n_dot_l, n_dot_v, l_dot_v, eq.shininess);
    }
    add_light_term(color, light.products, att_spot, n_dot_l, spec, with_ambient, with_specular, vis);
  }
  return color;
}

// The colour at p (in the frame's space) with normal n (in the frame's space, any length).
template <bool kEarlyTests, bool kShadows, class Metric>
SHADETOOL_ALWAYS_INLINE Vec3d shade_point_in_space(const Metric& g, const ShadingFrame& frame,
                                                   const EquationSetup& eq, const Vec3d& p, const Vec3d& n,
                                                   ShadeCounters& count, const double* visibility = nullptr) {
  const PreparedPoint pp = prepare_point(g, frame, eq, p, n, count);
  return shade_prepared_point<kEarlyTests, kShadows>(g, frame, eq, p, pp, count, visibility);
}

}  // namespace lighting_engine
}  // namespace shadetool
