// lighting_equation.h: the colour of one point under one light, OpenGL 2.1 fixed-function
// lighting with a local viewer (The OpenGL Graphics System 2.1, section 2.14.1, "Lighting",
// equation 2.1 for the RGBA primary colour). The formulas only: the per-point loop that finds
// L, V and the distances in a shading space, skips what is zero and counts it is
// engine/shade_point.h; the per-point entry point is lighting/shade_point.h.
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
// Area, sky and environment lights (issue 16) add ka*a + kd*L*P + ks*L*S with P and S their
// projected solid angle and specular integral: lighting/area_light.h.
//
// Degenerate input, handled explicitly:
//   zero or non-finite normal        n.L = n.V = 0: only the emission and ambient terms remain
//   point at a light's position      L, the spot cosine and att are undefined: the light adds 0
//   light or eye at 1e-300 or 1e300  distances and directions scaled before squaring
//                                    (engine/metric.h); att terms with coefficient 0 left out
//   point at the eye                 V = 0: H = L (blinn-phong), R.V = 0 (phong), no two-sided flip
//   L = -V exactly (H = 0)           n.H = 0
//   0^0 (shininess or exponent 0)    1, as std::pow and OpenGL
//
// Precision: double throughout. Colours are linear and unclamped (clamping is encode_color.h's).
#pragma once

#include <cmath>
#include <cstdint>

#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// max(x, 0), inline (std::fmax is a libm call in GCC's -O2 code); NaN -> 0.
inline double positive_part(double x) { return x > 0 ? x : 0.0; }

// lighting_power(x, e) = max(x, 0)^e: the lighting equation's one power (a specular term's
// shininess, a spot's exponent), here and nowhere else; engine/shade_point_lanes.cpp computes the
// same bits four at a time. e = 0 gives 1 (0^0 = 1, as std::pow and OpenGL); NaN x gives 0^e.
// For an integer e in [1, 2^20] (every scene we have seen): left-to-right binary exponentiation in
// double-double, each product's rounding error recovered exactly by an FMA (Dekker 1971; Ogita,
// Rump and Oishi 2005), l*l (below 2^-106 h^2) dropped, rounded to double once at the end. The
// unrounded value is within about 2^-98 (relative) of x^e, so the result is x^e correctly rounded
// unless x^e lies that close to a midpoint between two doubles; glibc's pow is only within 0.52 ulp
// (it differs by one ulp in about 1 of 1,600 powers: tests/lighting/shade_point.cpp). std::fma is
// exact on every machine, so the bits do not depend on the CPU. Results below 2^-900 (the low part
// could be subnormal), x = 0, and other exponents: std::pow.
inline bool lighting_power_is_integer(double e) { return e >= 1 && e <= 0x1p20 && e == std::floor(e); }
// x^e for e >= 1 in double-double as above: lighting/lighting_power.cpp (one FMA instruction per
// product where the CPU has it, the C library's exact fma otherwise: the same bits either way).
double lighting_integer_power(double x, std::uint32_t e);
inline double lighting_power(double x, double e) {
  if (e == 0) return 1.0;
  x = positive_part(x);
  if (lighting_power_is_integer(e)) {
    const double r = lighting_integer_power(x, std::uint32_t(e));
    if (!(r < 0x1p-900)) return r;  // as the lanes' test: NaN (x = Inf) is kept
  }
  return std::pow(x, e);
}

// att_i's denominator kc + kl d + kq d^2 (all >= 0, not all zero, d > 0). A term whose
// coefficient is 0 is left out rather than computed as 0 * d: for d = Inf (a light beyond double's
// range) that product would be NaN, while the limit is the other terms' value. kq d^2 is formed as
// (kq d) d so that it overflows only when the true value does.
inline double attenuation_denominator(double kc, double kl, double kq, double d) {
  double s = kc;
  if (kl != 0) s += kl * d;
  if (kq != 0) s += (kq * d) * d;
  return s;
}

// spot_i for a point with cos_t = (-L).axis: cos_t^exponent inside the cone, 0 outside
// (cos_t < cos(cutoff)). 0^0 = 1 as OpenGL; a negative cos_t inside a cutoff of 90 gives 0^e.
inline double spot_factor(double cos_t, double cos_cutoff, double exponent) {
  const double spot = lighting_power(cos_t, exponent);
  return cos_t < cos_cutoff ? 0.0 : spot;
}

// spec_i, Blinn-Phong: max(n.H, 0)^shininess with n.H = (n.L + n.V) / |L + V| and
// |L + V|^2 = 1 + 2 L.G V + |V|^2 (v_unit = |V|^2: 1, or 0 at the eye, where H = L).
// L = -V exactly (|L + V| = 0): n.H = 0.
inline double blinn_phong_n_dot_h(double n_dot_l, double n_dot_v, double l_dot_v, double v_unit) {
  const double h2 = 1.0 + 2.0 * l_dot_v + v_unit;
  return h2 > 0 ? (n_dot_l + n_dot_v) / std::sqrt(h2) : 0.0;  // divisor checked
}
inline double specular_blinn_phong(double n_dot_l, double n_dot_v, double l_dot_v, double v_unit, double shininess) {
  return lighting_power(blinn_phong_n_dot_h(n_dot_l, n_dot_v, l_dot_v, v_unit), shininess);
}

// spec_i, Phong: max(R.V, 0)^shininess with R.V = 2 (n.L)(n.V) - L.V (R never formed).
inline double specular_phong(double n_dot_l, double n_dot_v, double l_dot_v, double shininess) {
  const double r_dot_v = 2.0 * n_dot_l * n_dot_v - l_dot_v;
  return lighting_power(r_dot_v, shininess);
}

// The material-times-light colours of light i: ka*a_i, kd*d_i, ks*s_i.
struct LightProducts {
  Vec3d ambient{0, 0, 0};
  Vec3d diffuse{0, 0, 0};
  Vec3d specular{0, 0, 0};
};

// Light i's term of equation 2.1, added to `color` in the order ambient, diffuse, specular (the
// order fixes the rounding):
//   att_spot * ( ka*a_i + max(n.L, 0) kd*d_i + [n.L > 0] spec ks*s_i )
// with_ambient / with_specular: false leaves that term out where its colour product is zero
// (att_spot * 0 would be NaN where att_spot overflows). Nothing is added but the ambient term
// when n.L <= 0. visibility in [0, 1] (shadows: the fraction of the light the point sees)
// scales att_spot for the diffuse and specular terms only; ambient is not shadowed. A wholly
// shadowed light (visibility 0) adds nothing more (0 * an overflowed att_spot would be NaN).
// Without shadows the callers pass the constant 1: att_spot * 1.0 is exact, and the compiler
// folds both the product and the test away, so that path is the same bits and the same code.
inline void add_light_term(Vec3d& color, const LightProducts& k, double att_spot, double n_dot_l, double spec,
                           bool with_ambient, bool with_specular, double visibility = 1.0) {
  if (with_ambient) color += k.ambient * att_spot;
  if (!(n_dot_l > 0) || !(visibility > 0)) return;
  const double a = att_spot * visibility;
  color += k.diffuse * (a * n_dot_l);
  if (with_specular) color += k.specular * (a * spec);
}

// The same term for a light whose P and S are colours (an environment map: per channel, the
// radiance is inside the integrals): ka*a_i + kd*P + ks*S, P and S scaled by visibility. P and S
// >= 0 (the caller clamps an approximation's negative lobes).
inline void add_light_term_rgb(Vec3d& color, const LightProducts& k, const Vec3d& P, const Vec3d& S,
                               bool with_ambient, bool with_specular, double visibility = 1.0) {
  if (with_ambient) color += k.ambient;
  if (!(visibility > 0)) return;
  color += Vec3d{k.diffuse.x * P.x, k.diffuse.y * P.y, k.diffuse.z * P.z} * visibility;
  if (with_specular) color += Vec3d{k.specular.x * S.x, k.specular.y * S.y, k.specular.z * S.z} * visibility;
}

}  // namespace shadetool
#pragma GCC visibility pop
