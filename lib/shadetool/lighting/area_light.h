// area_light.h: what an area or sky light adds at a point (issue 16), exact where a closed form
// exists. The equation (man page, lighting_equation.h): per channel
//
//   ka * a  +  kd * L * P  +  ks * L * S
//   P = integral of max(n.w, 0) dw over the directions w in which p sees the light
//       (projected solid angle, steradians, no 1/pi)
//   S = integral of [n.w > 0] spec(w) dw, spec the model's lobe for light direction w:
//       Phong max(R.w, 0)^shininess, R = 2 (n.V) n - V the reflected view vector;
//       Blinn-Phong max(n.H(w), 0)^shininess, H(w) = normalize(w + V); Lambert none.
//
// Formulas (each function below names its source):
//   polygon P   Lambert's formula P = 1/2 |sum_i Theta_i (n . gamma_i)| over the edges of the
//               polygon's directions clipped to p's upper half-space (Arvo 1995, "Applications
//               of irradiance tensors", eq. 9; horizon clipping as in his section 5).
//   sphere P    the spherical cap of half-angle sigma (sin sigma = r/d) around the centre's
//               direction at angle theta from n; fully above the horizon pi sin^2(sigma) cos(theta),
//               crossing it Snyder's closed form (Snyder 1996, "Area light sources for real-time
//               graphics", MSR-TR-96-11; as written in Lagarde & de Rousiers 2014, eq. 18-19).
//   sky P       pi (1 + n.up) / 2 above, pi (1 - n.up) / 2 below.
//   Phong S     integer shininess: Arvo's (1995) recurrence for the axial moment
//               tau_k(A, w) = integral over A of (w.u)^k du (eq. 21 there, derived again in
//               area_light.cpp): exact. The sky's lit region is split into spherical triangles.
//   other S     Blinn-Phong, non-integer Phong, sphere lights: Gauss-Legendre quadrature of order
//               q per spherical triangle (sphere: per cap, q x 2q polar); error measured against the
//               closed form in bench/lighting (time against error) and bounded in the tests.
//
// Inputs are unit vectors (n, R, V, up) and directions from p; every routine is scale-free: a
// scene scaled by 1e-100 or 1e100 gives the same P and S (lengths are taken with core/vec3.h's
// overflow-safe length before anything is squared).
//
// Degenerate cases, on the line where they are handled:
//   p on the polygon's plane (edge-on, or touching it)   P = S = 0
//   p behind a one-sided polygon                         P = S = 0
//   light wholly below p's horizon                       P = S = 0 (reported: below_horizon)
//   p inside or on a sphere light (d <= r)               P = S = 0 (it emits outward)
//   an edge of zero length after clipping                contributes 0 (Theta = 0)
//
// Precision: double. Lambert's sum has at most 2 + #vertices terms; edge_angle(|a x b|, a.b)
// keeps each edge angle accurate to 1e-15 relative down to 1e-300 radians.
#pragma once

#include <cstddef>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Polygons have at most this many vertices (validated when the scene is read); clipping by two
// half-spaces adds at most two.
constexpr int kMaxAreaVertices = 64;
constexpr int kMaxClippedVertices = kMaxAreaVertices + 2;

// A convex spherical polygon as p sees it: vertex directions q_i (any positive length; only the
// direction counts) and edge vectors d_i = q_(i+1) - q_i taken from the light's own edges, not
// by subtracting nearly equal q's: a light 1e-6 wide keeps its digits (each edge's plane normal
// q_i x d_i and angle are then accurate to an ulp, and Lambert's sum cancels only as the true
// value does).
// Fixed storage of N vectors left uninitialised (Vec3d's members have initialisers, so a plain
// array would be zero-filled on every call, per polygon per point: the larger part of a rect
// light's cost; bench/lighting/results.md).
template <int N>
struct Vec3Buffer {
  Vec3Buffer() {}
  union {
    Vec3d v[N];
  };
  Vec3d& operator[](int i) { return v[i]; }
  const Vec3d& operator[](int i) const { return v[i]; }
};

struct SphericalPolygon {
  int count = 0;
  Vec3Buffer<kMaxClippedVertices> q;
  Vec3Buffer<kMaxClippedVertices> d;
};

// Sutherland-Hodgman on the sphere: `in` intersected with {w : axis.w >= 0}; out.count < 3: nothing
// left. The new edge along the horizon gets d = q_next - q (it is not small).
void clip_to_hemisphere(const SphericalPolygon& in, const Vec3d& axis, SphericalPolygon& out);

// The angle between two vectors a, b from s = |a x b| >= 0 and c = a.b: atan2(s, c) in [0, pi],
// to 1e-15 relative (checked against std::atan2 in tests/lighting/area_light.cpp). One division and
// an 11-term odd Taylor polynomial: the ratio min/max of (s, |c|) is reduced to |x| <= tan(pi/16)
// around 0, pi/8 or pi/4 (x = (num - t_k den) / (den + t_k num), t_k = tan(k pi/8)), where the
// series' first omitted term x^23/23 is below 2e-17 of x. s = c = 0 gives 0.
// Lambert's formula needs one per edge; glibc's atan2 was a quarter of a rect light's time.
// Inline and branch-free (selects only, an Estrin-ordered polynomial), so that the edges of a
// polygon overlap in the pipeline and a loop over edges vectorises (engine/lambert_lanes.h).
inline double edge_angle(double s, double c) {
  const double ac = c < 0 ? -c : c;
  const bool swap = s > ac;  // reduce to num / den in [0, 1]: theta' = atan(num / den) in [0, pi/4]
  const double num = swap ? ac : s, den = swap ? s : ac;
  const bool zero = !(den > 0);  // s = c = 0: a zero-length vector (NaN: 0 as well); selected at the end
  // Nearest of 0, pi/8, pi/4 (boundaries tan(pi/16), tan(3 pi/16)): |x| <= tan(pi/16) = 0.1989.
  const bool k1 = num >= 0.19891236737965800 * den, k2 = num >= 0.66817863791929890 * den;
  const double tk = k2 ? 1.0 : k1 ? 0.41421356237309503 : 0.0;              // tan(pi/8) rounded
  const double base = k2 ? kQuarterPi : k1 ? kPi / 8 : 0.0;  // pi/8 exact: pi scaled by 2^-3
  // den + tk num >= den > 0, or 1 where the result is the 0 selected below: divisor checked
  const double x = (num - tk * den) / (zero ? 1.0 : den + tk * num);
  const double y = x * x, y2 = y * y, y4 = y2 * y2, y8 = y4 * y4;
  // atan(x) = x - x y (1/3 - y/5 + y^2/7 - ... + y^9/21): the bracket by Estrin's scheme.
  constexpr double c3 = -1.0 / 3, c5 = 1.0 / 5, c7 = -1.0 / 7, c9 = 1.0 / 9, c11 = -1.0 / 11, c13 = 1.0 / 13,
                   c15 = -1.0 / 15, c17 = 1.0 / 17, c19 = -1.0 / 19, c21 = 1.0 / 21;
  const double q0 = c3 + c5 * y, q1 = c7 + c9 * y, q2 = c11 + c13 * y, q3 = c15 + c17 * y, q4 = c19 + c21 * y;
  const double p = (q0 + q1 * y2) + (q2 + q3 * y2) * y4 + q4 * y8;
  const double a = base + (x + x * (y * p));  // atan(t_k) = theta_k to 2e-17 (t1's rounding)
  const double b = swap ? kHalfPi - a : a;
  const double theta = c < 0 ? kPi - b : b;
  return zero ? 0.0 : theta;
}

// Lambert's formula: the projected solid angle about n of a convex spherical polygon lying in
// n's upper hemisphere (clip first), either orientation. q and d with components below 2^500
// (polygon_light_terms scales them below 2): |q x d|^2 is formed directly.
double lambert_polygon_integral(const SphericalPolygon& poly, const Vec3d& n);

// Solid angle of a convex spherical polygon (fan of Van Oosterom-Strackee triangles).
double polygon_solid_angle(const SphericalPolygon& poly);

// Arvo's axial moment tau_k = integral over the convex spherical polygon of (w.u)^k du, k >= 0
// an integer, w unit; either orientation. O(k * count). The recurrence subtracts terms of the
// polygon's angular size delta to get a result of size delta^2, losing about 1e-16 / delta^2
// relative: polygon_specular_integral uses it for solid angles >= 1e-4 (error <= 1e-12) and an
// order-8 Gauss rule below (error below (k delta)^16 / 16!: < 1e-13 for k delta < 1).
// solid_angle: the polygon's, when the caller has it (< 0: computed here).
double polygon_axial_moment(const SphericalPolygon& poly, const Vec3d& w, int k, double solid_angle = -1);

// Snyder's projected solid angle of a sphere seen at angle theta from n under half-angle sigma,
// given cos(theta) and sin^2(sigma) in (0, 1).
double sphere_projected_solid_angle(double cos_theta, double sin2_sigma);

// The sky's two projected solid angles (n.up = cos of the angle between n and up).
struct SkyProjection {
  double sky, ground;
};
SkyProjection sky_projected_solid_angles(double n_dot_up);

// The specular lobe of one point, for S.
enum class LobeKind { None, Phong, BlinnPhong };
struct SpecularLobe {
  LobeKind kind = LobeKind::None;
  double shininess = 0;
  Vec3d reflected{0, 0, 0};  // Phong: R = 2 (n.V) n - V, unit (zero at the eye)
  Vec3d view{0, 0, 0};       // Blinn-Phong: V, unit (zero at the eye: H = w)
  Vec3d normal{0, 0, 0};     // Blinn-Phong: n, unit
  int quadrature_order = 16; // q for the quadrature paths
};

// spec(w) of the lobe (without the [n.w > 0] factor).
double lobe_value(const SpecularLobe& lobe, const Vec3d& w);

// S over a convex spherical polygon already clipped to n's upper hemisphere: Arvo's closed form
// for Phong with an integer shininess, quadrature otherwise. small_by_quadrature: a polygon below
// 1e-4 sr takes an order-8 Gauss rule instead of the recurrence (see polygon_axial_moment); the
// sky's pieces of a hemisphere do not need it.
double polygon_specular_integral(const SphericalPolygon& poly, const SpecularLobe& lobe, bool small_by_quadrature = true);

// P and S of one light at p (world space; n unit).
struct AreaTerms {
  double P = 0, S = 0;
  bool below_horizon = false;  // nothing of the light above p's horizon: skipped
  bool inside = false;         // p on the polygon's plane or inside the sphere: the light adds 0
};

// A convex polygon light: vertices (world), emit_normal the unit normal of the emitting side.
AreaTerms polygon_light_terms(const Vec3d* vertices, int count, const Vec3d& emit_normal, bool two_sided,
                              const Vec3d& p, const Vec3d& n, const SpecularLobe& lobe);

// A sphere light of centre c and radius r > 0.
AreaTerms sphere_light_terms(const Vec3d& center, double radius, const Vec3d& p, const Vec3d& n,
                             const SpecularLobe& lobe);

// The sky: P and S for the sky (above the horizon of up) and for the ground (below).
struct SkyTerms {
  double P_sky = 0, P_ground = 0, S_sky = 0, S_ground = 0;
};
SkyTerms sky_light_terms(const Vec3d& up, const Vec3d& n, const SpecularLobe& lobe);

}  // namespace shadetool
#pragma GCC visibility pop
