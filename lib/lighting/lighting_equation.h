// lighting_equation.h: the colour of one point, OpenGL 2.1 fixed-function lighting with a local
// viewer (The OpenGL Graphics System 2.1, section 2.14.1, "Lighting", equation 2.1 for the RGBA
// primary colour), evaluated in any shading space (lighting/shading_space.h).
//
// For a point p with unit normal n and V = normalize(eye - p), all in world terms:
//
//   c = e + ka * a_global + sum_i att_i spot_i ( ka*a_i + max(n.L_i, 0) kd*d_i
//                                                + [n.L_i > 0] spec_i ks*s_i )
//
//   L_i     normalize(-direction) for directional lights, normalize(position - p) otherwise
//   att_i   1 / (kc + kl d + kq d^2), d = |position - p| (world units); 1 for directional
//   spot_i  1 for non-spots and cutoff 180 (OpenGL: "no cone"); else, with
//           cos_t = (-L_i).normalize(axis): 0 if cos_t < cos(cutoff), else cos_t^exponent
//   spec_i  blinn-phong max(n.H, 0)^shininess, H = normalize(L_i + V)  (OpenGL's h_i)
//           phong       max(R.V, 0)^shininess, R = 2 (n.L_i) n - L_i
//   two_sided: where n.V < 0, n -> -n.
//
// In a space with metric G (shading_space.h) the pairings n.L, n.V, n.H are plain dot products of
// the space's coordinates scaled by 1/|n|_{G^-1}, lengths are G-lengths, and with unit L, V:
//   |L + V|^2 = 2 (1 + L.G V),   n.H = (n.L + n.V) / |L + V|,   R.V = 2 (n.L)(n.V) - L.G V
// (the last is the identity R.V = 2 (n.L)(n.V) - L.V for unit n), so neither H nor R is formed.
//
// Order of work per light (what is skipped is counted in ShadeCounters):
//   1. sign of n.(position - p), no square root: back-facing lights without an ambient term stop.
//   2. distance, then the spot-cone test: points outside the cone stop.
//   3. attenuation, spot exponent (pow), diffuse, specular (pow).
//
// Degenerate input, handled explicitly:
//   zero or non-finite normal        n.L = n.V = 0: only the emission and ambient terms remain
//   point at a light's position      L, the spot cosine and att are undefined: the light adds 0
//   light or eye at 1e-300 or 1e300  distances and directions scaled before squaring
//                                    (metric_normalize); att terms with coefficient 0 left out
//   point at the eye                 V = 0: H = L (blinn-phong), R.V = 0 (phong), no two-sided flip
//   L = -V exactly (H = 0)           n.H = 0
//   0^0 (shininess or exponent 0)    1, as std::pow and OpenGL
//
// Precision: double throughout. Colours are linear and unclamped (clamping is encode_color.h's).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <shadetool/lighting/shading_space.h>

namespace shadetool {

struct ShadeCounters {
  std::size_t points = 0;
  std::size_t vertex_light_evaluations = 0;  // (point, light) pairs entered
  std::size_t back_facing = 0;               // pairs stopped at step 1 (no sqrt, att, pow)
  std::size_t outside_cone = 0;              // pairs stopped at step 2
  std::size_t at_light = 0;                  // point exactly at a light's position
  std::size_t zero_normals = 0;              // points with a zero or non-finite normal

  ShadeCounters& operator+=(const ShadeCounters& o) {
    points += o.points;
    vertex_light_evaluations += o.vertex_light_evaluations;
    back_facing += o.back_facing;
    outside_cone += o.outside_cone;
    at_light += o.at_light;
    zero_normals += o.zero_normals;
    return *this;
  }
};

// Metric policies: lengths of vectors (norm2), G v (lower) and lengths of normals (conorm2).
struct IdentityMetric {
  double norm2(const Vec3d& v) const { return dot(v, v); }
  Vec3d lower(const Vec3d& v) const { return v; }
  double conorm2(const Vec3d& n) const { return dot(n, n); }
};
struct ScaledMetric {
  double s2, inv_s2;
  double norm2(const Vec3d& v) const { return s2 * dot(v, v); }
  Vec3d lower(const Vec3d& v) const { return v * s2; }
  double conorm2(const Vec3d& n) const { return inv_s2 * dot(n, n); }
};
struct GeneralMetric {  // G = B^T B, never formed (it would square cond(B))
  Mat3d B, B_transpose, B_inverse_transpose;
  double norm2(const Vec3d& v) const { return squared_length(B * v); }
  Vec3d lower(const Vec3d& v) const { return B_transpose * (B * v); }
  double conorm2(const Vec3d& n) const { return squared_length(B_inverse_transpose * n); }
};

// What the per-point evaluation needs besides the frame.
struct EquationSetup {
  ShadingModel model = ShadingModel::BlinnPhong;
  bool specular = false;     // plan.specular
  bool view = false;         // plan.view
  bool two_sided = false;
  bool early_tests = true;   // SkipOptions::early_tests
  double shininess = 0;
  Vec3d base{0, 0, 0};       // plan.base
};

#if defined(__GNUC__)
#define SHADETOOL_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SHADETOOL_ALWAYS_INLINE inline
#endif

// max(x, 0), inline (std::fmax is a libm call in GCC's -O2 code); NaN -> 0.
inline double positive_part(double x) { return x > 0 ? x : 0.0; }

// v / |v|_G and |v|_G for any finite v, without underflow or overflow of |v|^2: when the plain
// squared length lies in [2^-1000, 2^1000] (every distance between 1e-150 and 1e150 in world
// units: all usual scenes) it is used directly; otherwise v is first scaled by the power of two
// 2^-e that brings its largest component near 1 (exact: only the exponent changes), the unit
// vector is taken from the scaled copy and the length scaled back. v = 0 gives length 0 and a
// zero unit vector; a length beyond double's range gives Inf with a correct unit vector.
struct UnitAndLength {
  Vec3d unit;
  double length;
};
template <class Metric>
inline UnitAndLength metric_normalize(const Metric& g, const Vec3d& v) {
  constexpr double lo = 0x1p-1000, hi = 0x1p1000;
  const double d2 = g.norm2(v);
  if (d2 >= lo && d2 <= hi) {
    const double d = std::sqrt(d2);
    return {v * (1.0 / d), d};  // d >= 2^-500 > 0
  }
  const double m = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
  if (!(m > 0) || !std::isfinite(m)) return {{0, 0, 0}, m > 0 ? m : 0.0};
  const int e = std::ilogb(m);
  const Vec3d u{std::scalbn(v.x, -e), std::scalbn(v.y, -e), std::scalbn(v.z, -e)};
  const double du = std::sqrt(g.norm2(u));  // u has a component in [1, 2): du > 0 for regular G
  if (!(du > 0) || !std::isfinite(du)) return {{0, 0, 0}, 0.0};
  return {u * (1.0 / du), std::scalbn(du, e)};
}

// Attenuation denominator kc + kl d + kq d^2 (all >= 0, not all zero, d > 0). A term whose
// coefficient is 0 is left out rather than computed as 0 * d: for d = Inf (a light beyond double's
// range) that product would be NaN, while the limit is the other terms' value. kq d^2 is formed as
// (kq d) d so that it overflows only when the true value does.
inline double attenuation_denominator(double kc, double kl, double kq, double d) {
  double s = kc;
  if (kl != 0) s += kl * d;
  if (kq != 0) s += (kq * d) * d;
  return s;
}

// The colour at p (in the frame's space) with normal n (in the frame's space, any length).
// Always inlined into the per-point loop: GCC otherwise keeps a call per point for the
// General metric (measured: 35% of the time of a one-light lambert bake).
template <class Metric>
SHADETOOL_ALWAYS_INLINE Vec3d shade_point_in_space(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq,
                                  const Vec3d& p, Vec3d n, ShadeCounters& count) {
  ++count.points;
  Vec3d color = eq.base;

  const double n2 = g.conorm2(n);
  double n_scale = 0;  // 1 / |n|_{G^-1}; 0 leaves only the ambient terms
  if (n2 > 0 && std::isfinite(n2)) {
    n_scale = 1.0 / std::sqrt(n2);
  } else {
    n = {0, 0, 0};
    ++count.zero_normals;
  }

  Vec3d V{0, 0, 0}, V_lowered{0, 0, 0};
  double v_unit = 0;  // |V|^2: 1, or 0 at the eye
  double n_dot_v = 0;
  if (eq.view) {
    const Vec3d to_eye = frame.eye - p;
    const UnitAndLength eye_dir = metric_normalize(g, to_eye);
    if (eye_dir.length > 0) {
      V = eye_dir.unit;
      V_lowered = g.lower(V);
      v_unit = 1;
      n_dot_v = dot(n, V) * n_scale;
    }
    if (eq.two_sided && n_dot_v < 0) {
      n = -n;
      n_dot_v = -n_dot_v;
    }
  }

  for (const SpaceLight& light : frame.lights) {
    ++count.vertex_light_evaluations;
    Vec3d L;             // unit (in G) toward the light
    double n_dot_l;      // unit-normal n . L
    double factor = 1;   // att * spot
    if (light.type == LightType::Directional) {
      L = light.to_light;
      n_dot_l = dot(n, L) * n_scale;
      if (eq.early_tests && !(n_dot_l > 0) && !light.has_ambient) {
        ++count.back_facing;
        continue;
      }
    } else {
      const Vec3d to_light = light.position - p;
      const double n_dot_raw = dot(n, to_light);  // same sign as n.L, no square root yet
      if (eq.early_tests && !(n_dot_raw > 0) && !light.has_ambient) {
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
        const bool inside = !(cos_t < light.cos_cutoff);
        if (!inside && eq.early_tests) {
          ++count.outside_cone;
          continue;
        }
        spot = light.exponent == 0 ? 1.0 : std::pow(positive_part(cos_t), light.exponent);
        if (!inside) spot = 0;
      }
      // kc, kl, kq >= 0, not all zero, and d > 0: the denominator is positive.
      factor = spot / attenuation_denominator(light.kc, light.kl, light.kq, d);
      n_dot_l = dot(n, L) * n_scale;
    }

    if (light.has_ambient || !eq.early_tests) color += light.ambient * factor;
    const bool lit = n_dot_l > 0;
    if (!lit && eq.early_tests) continue;
    color += light.diffuse * (factor * positive_part(n_dot_l));

    if (eq.specular && light.has_specular) {
      const double l_dot_v = dot(L, V_lowered);
      double s;
      if (eq.model == ShadingModel::BlinnPhong) {
        const double h2 = 1.0 + 2.0 * l_dot_v + v_unit;  // |L + V|^2 with |L| = 1, |V|^2 = v_unit
        const double n_dot_h = h2 > 0 ? (n_dot_l + n_dot_v) / std::sqrt(h2) : 0.0;
        s = std::pow(positive_part(n_dot_h), eq.shininess);
      } else {  // Phong
        const double r_dot_v = 2.0 * n_dot_l * n_dot_v - l_dot_v;
        s = std::pow(positive_part(r_dot_v), eq.shininess);
      }
      if (lit) color += light.specular * (factor * s);
    }
  }
  return color;
}

}  // namespace shadetool
