// area_light.cpp: see area_light.h.
#include <shadetool/lighting/area_light.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/engine/lambert_lanes.h>

namespace shadetool {

namespace {

// Gauss-Legendre nodes and weights on [0, 1] for order q in [1, 64], by Newton on P_q (once).
struct GaussRule {
  std::vector<double> x, w;
};
const GaussRule& gauss_legendre(int q) {
  static const std::array<GaussRule, 65> rules = [] {
    std::array<GaussRule, 65> r;
    for (int n = 1; n <= 64; ++n) {
      for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double dp = 1;
        for (int it = 0; it < 100; ++it) {
          double p0 = 1, p1 = z;  // P_0, P_1
          for (int k = 2; k <= n; ++k) {
            const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
            p0 = p1;
            p1 = p2;
          }
          if (n == 1) p0 = 1, p1 = z;
          dp = n * (z * p1 - p0) / (z * z - 1);  // |z| < 1 for every node
          const double dz = p1 / dp;
          z -= dz;
          if (std::fabs(dz) < 1e-16) break;
        }
        r[n].x.push_back(0.5 * (1 - z));
        r[n].w.push_back(1.0 / ((1 - z * z) * dp * dp));  // 2 / ((1-z^2) P'^2), halved for [0, 1]
      }
    }
    return r;
  }();
  return rules[q < 1 ? 1 : q > 64 ? 64 : q];
}

// Orientation of a convex spherical polygon: +1 counter-clockwise seen from outside the sphere
// (q_i x d_i points into the polygon), -1 clockwise; 0 when degenerate (zero area). The fan's
// triple products q_0 . (q_i x q_(i+1)) = q_0 . (s_i x s_(i+1)) with s_i = q_i - q_0 summed from
// edges (no cancellation).
double orientation(const SphericalPolygon& P) {
  double sum = 0;
  Vec3d s{0, 0, 0};
  for (int i = 1; i + 1 < P.count; ++i) {
    s += P.d[i - 1];
    sum += dot(P.q[0], cross(s, s + P.d[i]));
  }
  return sum > 0 ? 1.0 : sum < 0 ? -1.0 : 0.0;
}

// Integral over the spherical triangle (a, b, c) of f, by the central projection of the flat
// triangle: w = x / |x|, dw = |x . N| / |x|^3 dA, collapsed (Duffy) Gauss-Legendre q x q.
template <class F>
double triangle_quadrature(const Vec3d& a, const Vec3d& b, const Vec3d& c, int q, const F& f) {
  const GaussRule& g = gauss_legendre(q);
  const Vec3d e1 = b - a, e2 = c - a;
  const Vec3d N = cross(e1, e2);
  double sum = 0;
  for (int i = 0; i < q; ++i) {
    const double u = g.x[i];
    for (int j = 0; j < q; ++j) {
      const double v = g.x[j] * (1 - u);
      const Vec3d x = a + e1 * u + e2 * v;
      const double r = length(x);
      if (!(r > 0)) continue;  // the chord passes through the centre only for antipodal vertices
      const Vec3d w = x * (1.0 / r);
      sum += g.w[i] * g.w[j] * (1 - u) * f(w) * std::fabs(dot(w, N)) / (r * r);
    }
  }
  return sum;
}

// A unit vector perpendicular to unit `axis`, toward `toward` when it is not parallel: built from
// the two vectors only (no world axis), so a rotated scene gets the rotated quadrature points.
Vec3d frame_axis(const Vec3d& axis, const Vec3d& toward) {
  const Vec3d t = toward - axis * dot(axis, toward);
  if (length(t) > 1e-8) return normalized_or(t, Vec3d{0, 0, 0});
  const Vec3d any = std::fabs(axis.x) < 0.6 ? Vec3d{1, 0, 0} : std::fabs(axis.y) < 0.6 ? Vec3d{0, 1, 0} : Vec3d{0, 0, 1};
  return normalized_or(any - axis * dot(axis, any), Vec3d{0, 0, 1});
}

// E_k = integral along the arc from a to b (unit, angle theta) of (w.u)^k ds, k = start, start+2,
// ...: h(s) = A cos s + B sin s, C^2 = A^2 + B^2, and
//   E_k = (k-1)/k C^2 E_{k-2} - [h^{k-1} h']_0^theta / k,  E_0 = theta, E_1 = A sin + B (1 - cos).
struct EdgeMoment {
  double A, B, hb, hb_prime, C2, theta;  // h(0) = A, h'(0) = B, h(theta), h'(theta)
  double E;                              // E_k at the current k
  double pow_a, pow_b;                   // A^(k-1), hb^(k-1) for the next step (k+2 needs ^(k+1))
};

// ilogb and ldexp for the normal range, from the bits (glibc's are calls, a visible part of a rect
// light's time: bench/lighting/results.md).
int binary_exponent(double x) {  // x > 0 finite; subnormals give -1023 (the caller's slow path)
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return int((bits >> 52) & 0x7ff) - 1023;
}
double power_of_two(int e) {  // e in [-1022, 1023]
  const std::uint64_t bits = std::uint64_t(e + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

}  // namespace

void clip_to_hemisphere(const SphericalPolygon& in, const Vec3d& axis, SphericalPolygon& out) {
  int m = 0;
  bool horizon[kMaxClippedVertices];  // out vertex m starts an edge along the horizon
  for (int i = 0; i < in.count; ++i) {
    const int j = i + 1 < in.count ? i + 1 : 0;  // not %: an integer division per edge
    const Vec3d &a = in.q[i], &b = in.q[j];
    const double da = dot(axis, a), db = dot(axis, b);
    const bool a_in = da >= 0, b_in = db >= 0;
    if (a_in && b_in) {
      out.q[m] = a, out.d[m] = in.d[i], horizon[m++] = false;
    } else if (a_in != b_in) {
      // The edge a + t d crosses the plane axis.x = 0 at t = da / (da - db) (the signs differ).
      const double t = da / (da - db);
      const Vec3d x = a + in.d[i] * t;
      if (a_in) {
        out.q[m] = a, out.d[m] = in.d[i] * t, horizon[m++] = false;
        out.q[m] = x, horizon[m++] = true;  // leaves along the horizon
      } else {
        out.q[m] = x, out.d[m] = in.d[i] * (1 - t), horizon[m++] = false;
      }
    }
  }
  for (int i = 0; i < m; ++i)
    if (horizon[i]) out.d[i] = out.q[i + 1 < m ? i + 1 : 0] - out.q[i];
  out.count = m;
}

double lambert_polygon_integral(const SphericalPolygon& P, const Vec3d& n) {
  double sum = 0;
  for (int i = 0; i < P.count; ++i) {
    const Vec3d c = cross(P.q[i], P.d[i]);  // = q_i x q_(i+1): the edge's plane normal
    const double s = std::sqrt(dot(c, c));  // q, d scaled to components below 2 (polygon_light_terms)
    if (!(s > 0)) continue;  // a zero-length edge: Theta = 0
    const double theta = edge_angle(s, dot(P.q[i], P.q[i]) + dot(P.q[i], P.d[i]));  // q_i . q_(i+1)
    sum += theta * (dot(n, c) / s);  // divisor checked
  }
  return 0.5 * std::fabs(sum);
}

double polygon_solid_angle(const SphericalPolygon& P) {
  // tan(Omega_t / 2) = |a.(b x c)| / (|a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a|) per fan triangle
  const Vec3d& a = P.q[0];
  const double la = std::sqrt(dot(a, a));  // scaled below 2 or unit, as above
  double omega = 0;
  Vec3d s{0, 0, 0};
  for (int i = 1; i + 1 < P.count; ++i) {
    s += P.d[i - 1];
    const Vec3d &b = P.q[i], c = P.q[i + 1];
    const double det = std::fabs(dot(a, cross(s, s + P.d[i])));
    const double lb = std::sqrt(dot(b, b)), lc = std::sqrt(dot(c, c));
    omega += 2.0 * edge_angle(det, la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la);
  }
  return omega;
}

double polygon_axial_moment(const SphericalPolygon& P, const Vec3d& w, int k, double solid_angle) {
  // tau_k = (k-1)/(k+1) tau_(k-2) + 1/(k+1) sum_i (w.gamma_i) E_i,(k-1)
  // (the Laplace-Beltrami operator of (w.u)^k and Stokes over the polygon; gamma_i the unit
  // normal of edge i's great circle pointing into the polygon), tau_0 = solid angle, tau_-1 = 0.
  const double o = orientation(P);
  if (o == 0) return 0;
  EdgeMoment edges[kMaxClippedVertices];
  Vec3Buffer<kMaxClippedVertices> gamma;
  int m = 0;
  const bool odd = k % 2 == 1;
  for (int i = 0; i < P.count; ++i) {
    // q and d are scaled below 2 (polygon_light_terms) or unit (the sky): squares are safe.
    const Vec3d c = cross(P.q[i], P.d[i]);
    const Vec3d qb = P.q[i] + P.d[i];
    const double s = std::sqrt(dot(c, c)), la = std::sqrt(dot(P.q[i], P.q[i])), lb = std::sqrt(dot(qb, qb));
    if (!(s > 0) || !(la > 0) || !(lb > 0)) continue;  // zero-length edge: no contribution
    const Vec3d g = c * (1.0 / s);
    const Vec3d a = P.q[i] * (1.0 / la);
    const Vec3d b = qb * (1.0 / lb);
    const Vec3d t = cross(g, a);  // unit tangent at a toward b
    EdgeMoment e;
    const double qq = dot(P.q[i], P.q[i]) + dot(P.q[i], P.d[i]);  // |q_i| |q_(i+1)| cos(theta)
    e.theta = edge_angle(s, qq);
    const double r = la * lb;  // |q_i| |q_(i+1)| > 0
    const double sin_t = s / r, cos_t = qq / r;
    // 1 - cos(theta) = sin^2 / (1 + cos) without cancellation for small edges; 2 when theta ~ pi
    const double one_minus_cos = cos_t > -0.5 ? sin_t * sin_t / (1 + cos_t) : 1 - cos_t;
    e.A = dot(w, a);
    e.B = dot(w, t);
    e.hb = dot(w, b);
    e.hb_prime = -e.A * sin_t + e.B * cos_t;
    e.C2 = e.A * e.A + e.B * e.B;
    e.E = odd ? e.theta : e.A * sin_t + e.B * one_minus_cos;  // E_0 or E_1
    e.pow_a = odd ? e.A : e.A * e.A;  // A^(j-1), hb^(j-1) for the next E_j, j = k0 + 2
    e.pow_b = odd ? e.hb : e.hb * e.hb;
    gamma[m] = g * o;
    edges[m++] = e;
  }
  double tau = odd ? 0.0 : solid_angle < 0 ? polygon_solid_angle(P) : solid_angle;
  for (int j = odd ? 1 : 2; j <= k; j += 2) {  // tau_j from tau_(j-2) and E_(j-1)
    double sum = 0;
    for (int i = 0; i < m; ++i) sum += dot(w, gamma[i]) * edges[i].E;
    tau = (j - 1.0) / (j + 1.0) * tau + sum / (j + 1.0);
    if (j + 2 > k) break;
    const int next = j + 1;  // E_next = (next-1)/next C^2 E_(next-2) - [h^(next-1) h']_0^theta / next
    for (int i = 0; i < m; ++i) {
      EdgeMoment& e = edges[i];
      e.E = (next - 1.0) / next * e.C2 * e.E - (e.pow_b * e.hb_prime - e.pow_a * e.B) / next;
      e.pow_a *= e.A * e.A;
      e.pow_b *= e.hb * e.hb;
    }
  }
  return tau;
}

double sphere_projected_solid_angle(double cos_theta, double sin2_sigma) {
  if (cos_theta * cos_theta > sin2_sigma) return kPi * sin2_sigma * (cos_theta > 0 ? cos_theta : 0.0);
  // The cap crosses the horizon (Snyder 1996; Lagarde & de Rousiers 2014, eq. 19):
  //   P = (cos t acos(y) - x sin t sqrt(1 - y^2)) sin^2 s + atan(sin t sqrt(1 - y^2) / x),
  //   x = cot s, y = -x cot t. Here cos^2 t <= sin^2 s < 1, so sin t > 0 and |y| <= 1.
  const double sin_theta = std::sqrt(std::fmax(0.0, 1 - cos_theta * cos_theta));
  const double x = std::sqrt(1 / sin2_sigma - 1);  // sin2_sigma in (0, 1): x > 0
  const double y = std::fmax(-1.0, std::fmin(1.0, -x * cos_theta / sin_theta));  // sin_theta > 0
  const double s = sin_theta * std::sqrt(1 - y * y);
  const double P = (cos_theta * std::acos(y) - x * s) * sin2_sigma + std::atan(s / x);  // x > 0
  return P > 0 ? P : 0.0;
}

SkyProjection sky_projected_solid_angles(double n_dot_up) {
  return {kPi * (1 + n_dot_up) / 2, kPi * (1 - n_dot_up) / 2};
}

double lobe_value(const SpecularLobe& lobe, const Vec3d& w) {
  switch (lobe.kind) {
    case LobeKind::None: return 0;
    case LobeKind::Phong: {
      const double r = dot(lobe.reflected, w);
      return std::pow(r > 0 ? r : 0.0, lobe.shininess);
    }
    case LobeKind::BlinnPhong: {
      const Vec3d h = w + lobe.view;  // |H| unnormalised; n.H = n.h / |h|
      const double l = length(h);
      const double c = l > 0 ? dot(lobe.normal, h) / l : 0.0;  // divisor checked; w = -V: 0
      return std::pow(c > 0 ? c : 0.0, lobe.shininess);
    }
  }
  return 0;
}

namespace {

// The fan of spherical triangles (q_0, q_i, q_(i+1)), each by triangle_quadrature of order q.
double polygon_quadrature(const SphericalPolygon& P, int q, const SpecularLobe& lobe) {
  const Vec3d a = normalized_or(P.q[0], Vec3d{0, 0, 0});
  double s = 0;
  for (int i = 1; i + 1 < P.count; ++i)
    s += triangle_quadrature(a, normalized_or(P.q[i], a), normalized_or(P.q[i + 1], a), q,
                             [&](const Vec3d& w) { return lobe_value(lobe, w); });
  return s;
}

}  // namespace

double polygon_specular_integral(const SphericalPolygon& P, const SpecularLobe& lobe, bool small_by_quadrature) {
  switch (lobe.kind) {
    case LobeKind::None: return 0;
    case LobeKind::Phong: {
      if (lobe.shininess == 0) return polygon_solid_angle(P);  // max(R.w,0)^0 = 1 (0^0 = 1)
      if (lobe.reflected == Vec3d{0, 0, 0}) return 0;         // at the eye: R.w = 0, 0^s = 0
      SphericalPolygon clipped;
      clip_to_hemisphere(P, lobe.reflected, clipped);
      if (clipped.count < 3) return 0;
      const double k = std::round(lobe.shininess);
      if (k == lobe.shininess && k <= 4096) {
        if (!small_by_quadrature) return polygon_axial_moment(clipped, lobe.reflected, int(k));
        const double omega = polygon_solid_angle(clipped);
        if (omega >= 1e-4) return polygon_axial_moment(clipped, lobe.reflected, int(k), omega);
        return polygon_quadrature(clipped, 8, lobe);  // small: see polygon_axial_moment
      }
      return polygon_quadrature(clipped, lobe.quadrature_order, lobe);
    }
    case LobeKind::BlinnPhong: return polygon_quadrature(P, lobe.quadrature_order, lobe);
  }
  return 0;
}

AreaTerms polygon_light_terms(const Vec3d* vertices, int count, const Vec3d& emit_normal, bool two_sided,
                              const Vec3d& p, const Vec3d& n, const SpecularLobe& lobe) {
  AreaTerms t;
  const double side = dot(emit_normal, p - vertices[0]);
  if (!(side > 0) && !(two_sided && side < 0)) {  // behind a one-sided light, or on its plane
    t.inside = side == 0;
    return t;
  }
  // Directions from p scaled by one power of two (exact) so that no product overflows.
  SphericalPolygon P;
  P.count = count;
  double big = 0;
  for (int i = 0; i < count; ++i) {
    P.q[i] = vertices[i] - p;
    P.d[i] = vertices[i + 1 < count ? i + 1 : 0] - vertices[i];
    const double m = std::fabs(P.q[i].x) > std::fabs(P.q[i].y) ? std::fabs(P.q[i].x) : std::fabs(P.q[i].y);
    const double mz = std::fabs(P.q[i].z) > m ? std::fabs(P.q[i].z) : m;
    big = mz > big ? mz : big;  // inline max: std::fmax is a libm call here
  }
  // 2^-e with big in [2^e, 2^(e+1)): every q then has components below 2, so |q x d|^2 and |q|^2
  // neither overflow nor (for any edge longer than 1e-150 of the distance) underflow. The factor
  // is exact; scalbn only where 2^-e itself is out of double's range.
  const int e = big > 0 && std::isfinite(big) ? binary_exponent(big) : 0;
  if (e > -1022 && e < 1023) {
    const double f = power_of_two(-e);
    for (int i = 0; i < count; ++i) P.q[i] = P.q[i] * f, P.d[i] = P.d[i] * f;
  } else {
    for (int i = 0; i < count; ++i) {
      P.q[i] = {std::scalbn(P.q[i].x, -e), std::scalbn(P.q[i].y, -e), std::scalbn(P.q[i].z, -e)};
      P.d[i] = {std::scalbn(P.d[i].x, -e), std::scalbn(P.d[i].y, -e), std::scalbn(P.d[i].z, -e)};
    }
  }
  // Wholly above p's horizon (the common case): no clipped copy. Wholly below: what
  // clip_to_hemisphere would find (no vertex with n.q >= 0: nothing left), without clipping.
  int n_above = 0;
  for (int i = 0; i < count; ++i) n_above += dot(n, P.q[i]) >= 0;
  if (n_above == 0) {
    t.below_horizon = true;
    return t;
  }
  // P: lambert_polygon_integral's bits, four edges at a time (engine/lambert_lanes.h).
  if (n_above == count) {
    t.P = lighting_engine::lambert_polygon_integral_lanes(P, n);
    t.S = polygon_specular_integral(P, lobe);
    return t;
  }
  SphericalPolygon clipped;
  clip_to_hemisphere(P, n, clipped);
  if (clipped.count < 3) {
    t.below_horizon = true;
    return t;
  }
  t.P = lighting_engine::lambert_polygon_integral_lanes(clipped, n);
  t.S = polygon_specular_integral(clipped, lobe);
  return t;
}

AreaTerms sphere_light_terms(const Vec3d& center, double radius, const Vec3d& p, const Vec3d& n,
                             const SpecularLobe& lobe) {
  AreaTerms t;
  const Vec3d to_c = center - p;
  const double d = length(to_c);
  if (!(d > radius)) {  // inside or on the sphere: it emits outward, p sees none of it
    t.inside = true;
    return t;
  }
  const Vec3d c = to_c * (1.0 / d);  // d > radius > 0
  const double sin_sigma = radius / d;
  const double sin2 = sin_sigma * sin_sigma;
  const double cos_theta = dot(n, c);
  if (cos_theta <= -sin_sigma) {  // the whole cap below the horizon
    t.below_horizon = true;
    return t;
  }
  t.P = sphere_projected_solid_angle(cos_theta, sin2);
  if (lobe.kind == LobeKind::None) return t;
  // S: polar Gauss-Legendre over the cap in u = 1 - cos(theta) (dw = du dphi), with the horizon
  // cut done exactly per ring: with e1 toward n (n.e2 = 0), n.w > 0 on the ring at theta iff
  // cos(phi) > -cos(theta) (n.c) / (sin(theta) (n.e1)), an arc |phi| < phi_max integrated by
  // Gauss-Legendre too. The ring integral has a square-root kink where the ring touches the
  // horizon (theta* = asin|n.c|): the u range is split there. Error measured in bench/lighting.
  const SpecularLobe& b = lobe;
  const Vec3d e1 = frame_axis(c, n);  // toward n
  const Vec3d e2 = cross(c, e1);
  const double n_c = dot(n, c), n_e1 = dot(n, e1);
  const double cos_sigma = std::sqrt(std::fmax(0.0, 1 - sin2));
  const double one_minus_cos_sigma = sin2 / (1 + cos_sigma);  // no cancellation for small lights
  const double n_c2 = n_c * n_c;
  const double u_star = n_c2 < sin2 ? n_c2 / (1 + std::sqrt(1 - n_c2)) : one_minus_cos_sigma;  // 1 - cos(theta*)
  const int q = lobe.quadrature_order;
  const GaussRule& g = gauss_legendre(q);
  const GaussRule& gp = gauss_legendre(2 * q > 64 ? 64 : 2 * q);
  double s = 0;
  const double bounds[3] = {0, u_star, one_minus_cos_sigma};
  for (int piece = 0; piece < 2; ++piece) {
    const double u0 = bounds[piece], du = bounds[piece + 1] - u0;
    if (!(du > 0)) continue;
    for (int i = 0; i < q; ++i) {
      const double one_minus_cos = u0 + du * g.x[i];
      const double ct = 1 - one_minus_cos;
      const double st = std::sqrt(std::fmax(0.0, one_minus_cos * (2 - one_minus_cos)));
      double phi_max = kPi;  // the whole ring above the horizon
      const double denom = st * n_e1;
      if (denom > 0) {
        const double x = -ct * n_c / denom;
        phi_max = x >= 1 ? 0.0 : x <= -1 ? kPi : std::acos(x);
      } else if (!(ct * n_c > 0)) {
        phi_max = 0;
      }
      if (!(phi_max > 0)) continue;
      double ring = 0;
      for (std::size_t j = 0; j < gp.x.size(); ++j) {
        const double phi = phi_max * (2 * gp.x[j] - 1);
        const Vec3d w = c * ct + (e1 * std::cos(phi) + e2 * std::sin(phi)) * st;
        ring += gp.w[j] * lobe_value(b, w);
      }
      s += g.w[i] * du * ring * (2 * phi_max);
    }
  }
  t.S = s;
  return t;
}

SkyTerms sky_light_terms(const Vec3d& up, const Vec3d& n, const SpecularLobe& lobe) {
  SkyTerms t;
  const SkyProjection P = sky_projected_solid_angles(dot(n, up));
  t.P_sky = P.sky;
  t.P_ground = P.ground;
  if (lobe.kind == LobeKind::None) return t;
  // Each hemisphere as four spherical triangles (pole, e_i, e_i+1), clipped to n's hemisphere.
  const Vec3d e1 = frame_axis(up, n);
  const Vec3d e2 = cross(up, e1);
  const Vec3d ring[4] = {e1, e2, -e1, -e2};
  for (int half = 0; half < 2; ++half) {
    const Vec3d pole = half == 0 ? up : -up;
    double s = 0;
    for (int i = 0; i < 4; ++i) {
      SphericalPolygon tri;
      tri.count = 3;
      tri.q[0] = pole, tri.q[1] = ring[i], tri.q[2] = ring[(i + 1) % 4];
      for (int k = 0; k < 3; ++k) tri.d[k] = tri.q[(k + 1) % 3] - tri.q[k];
      SphericalPolygon clipped;
      clip_to_hemisphere(tri, n, clipped);
      // Pieces of a hemisphere: a small one's error is small in absolute terms, which is what
      // counts here (its relative loss matters only for a light that is small as a whole).
      if (clipped.count >= 3) s += polygon_specular_integral(clipped, lobe, false);
    }
    (half == 0 ? t.S_sky : t.S_ground) = s;
  }
  return t;
}

}  // namespace shadetool
