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
// engine/shade_batched.h calls the equation in two halves (kPrepareOnly, then with a PointBatch)
// so that polygon lights' terms are computed in between for a block of points at once
// (engine/lambert_lanes.h); the plain loop's instance has neither and is the code it always was.
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

// What the equation's first steps make of a point (the normal's scale, V, the two-sided flip): kept
// by the batched loop (engine/shade_batched.h) between its two calls of shade_point_in_space.
struct PreparedPoint {
  Vec3d n{0, 0, 0};  // zero for a zero or non-finite normal, flipped for two-sided lighting
  double n2 = 0, n_scale = 0;
  Vec3d V_lowered{0, 0, 0};
  double v_unit = 0, n_dot_v = 0;
};

// A batch of points made by engine/shade_batched.h for some polygon lights: the point prepared
// and in world space, and for each light j with batched[j] its terms[j].
struct PointBatch {
  const PreparedPoint* prepared = nullptr;
  const WorldPoint* world = nullptr;
  const bool* batched = nullptr;
  const AreaTerms* terms = nullptr;
};

// The point in world space for area and sky lights (engine/area_point.h's world_point), from the
// normal n as the loop below leaves it (zero, or flipped for two-sided lighting), n2 = |n|^2_G^-1
// before that and n_scale = 1 / |n|.
template <class Metric>
SHADETOOL_ALWAYS_INLINE void make_world_point(const ShadingFrame& frame, const EquationSetup& eq, const Vec3d& p,
                                              const Vec3d& n, double n2, double n_scale, WorldPoint& world) {
  // In world space with the identity metric, n * n_scale is unit(n) bit for bit (the same
  // 1 / sqrt(n.n) as engine/metric.h's rule inside [2^-1000, 2^1000]): not redone.
  const bool world_unit =
      std::is_same<Metric, IdentityMetric>::value && frame.space_is_world && n2 >= 0x1p-1000 && n2 <= 0x1p1000;
  world_point(frame, eq.model, eq.specular, eq.shininess, p, n, n_scale == 0, world, world_unit ? n_scale : 0.0);
}

// The colour at p (in the frame's space) with normal n (in the frame's space, any length).
// Always inlined into the per-point loop (see bench/lighting/results.md for why).
// kShadows: visibility points at this point's row of ShadeOptions::visibility (2 values per
// frame light: the light's visible fraction, and for a sky its ground's); without shadows it is
// unused and every light's visibility is the constant 1 (the same code and bits as before).
// The batched loop (engine/shade_batched.h) calls it twice per point: kPrepareOnly, the first steps
// only (counted here), into *prepared_out and *world_out; then with batch, the lights only, the
// first steps taken from batch->prepared. Without either, the code is the plain loop's.
template <bool kEarlyTests, bool kShadows, class Metric, bool kPrepareOnly = false>
SHADETOOL_ALWAYS_INLINE Vec3d shade_point_in_space(const Metric& g, const ShadingFrame& frame,
                                                   const EquationSetup& eq, const Vec3d& p, Vec3d n,
                                                   ShadeCounters& count, const double* visibility = nullptr,
                                                   const PointBatch* batch = nullptr,
                                                   PreparedPoint* prepared_out = nullptr,
                                                   WorldPoint* world_out = nullptr) {
  Vec3d color = eq.base;
  double n2 = 0;
  double n_scale = 0;  // 1 / |n|_{G^-1}; 0 leaves only the ambient terms
  Vec3d V_lowered{0, 0, 0};
  double v_unit = 0;  // |V|^2: 1, or 0 at the eye
  double n_dot_v = 0;
  if (batch) {
    const PreparedPoint& pp = *batch->prepared;
    n = pp.n, n2 = pp.n2, n_scale = pp.n_scale;
    V_lowered = pp.V_lowered, v_unit = pp.v_unit, n_dot_v = pp.n_dot_v;
  } else {
    ++count.points;
    n2 = g.conorm2(n);
    if (n2 > 0 && std::isfinite(n2)) {
      n_scale = 1.0 / std::sqrt(n2);
    } else {
      n = {0, 0, 0};
      ++count.zero_normals;
    }
    if (eq.view) {
      const UnitAndLength eye_dir = metric_normalize(g, frame.eye - p);
      if (eye_dir.length > 0) {
        const Vec3d V = eye_dir.unit;
        V_lowered = g.lower(V);
        v_unit = 1;
        n_dot_v = dot(n, V) * n_scale;
      }
      if (eq.two_sided && n_dot_v < 0) {
        n = -n;
        n_dot_v = -n_dot_v;
      }
    }
  }
  if (kPrepareOnly) {
    *prepared_out = {n, n2, n_scale, V_lowered, v_unit, n_dot_v};
    make_world_point<Metric>(frame, eq, p, n, n2, n_scale, *world_out);
    return color;
  }

  WorldPoint world;  // area and sky lights: p, n and the lobe in world space, made at the first one
  bool world_ready = false;
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
        if (batch) {
          if (batch->batched[j])
            add_area_terms(color, light, *batch->world, batch->terms[j], false, count, vis);
          else
            add_area_light(color, light, *batch->world, count, vis, vis_ground);
          continue;
        }
        if (!world_ready) {
          make_world_point<Metric>(frame, eq, p, n, n2, n_scale, world);
          world_ready = true;
        }
        add_area_light(color, light, world, count, vis, vis_ground);
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

}  // namespace lighting_engine
}  // namespace shadetool
