// area_light.cpp: see area_light.h.
#include <shadetool/lighting/area_light.h>

#include <array>
#include <cmath>
#include <vector>

#include <shadetool/core/math_constants.h>

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
// (a x b points into the polygon), -1 clockwise; 0 when degenerate (zero area).
double orientation(const Vec3d* d, int count) {
  double s = 0;
  for (int i = 1; i + 1 < count; ++i) s += dot(d[0], cross(d[i], d[i + 1]));
  return s > 0 ? 1.0 : s < 0 ? -1.0 : 0.0;
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

// E_k = integral along the arc from a to b (unit, angle theta) of (w.u)^k ds, k = start, start+2,
// ...: h(s) = A cos s + B sin s, C^2 = A^2 + B^2, and
//   E_k = (k-1)/k C^2 E_{k-2} - [h^{k-1} h']_0^theta / k,  E_0 = theta, E_1 = A sin + B (1 - cos).
struct EdgeMoment {
  double A, B, hb, hb_prime, C2, theta;  // h(0) = A, h'(0) = B, h(theta), h'(theta)
  double E;                              // E_k at the current k
  double pow_a, pow_b;                   // A^(k-1), hb^(k-1) for the next step (k+2 needs ^(k+1))
};

}  // namespace

int clip_to_hemisphere(const Vec3d* in, int count, const Vec3d& axis, Vec3d* out) {
  int m = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3d& a = in[i];
    const Vec3d& b = in[(i + 1) % count];
    const double da = dot(axis, a), db = dot(axis, b);
    if (da >= 0) out[m++] = a;
    if ((da >= 0) != (db >= 0)) {
      // The chord a + t (b - a) projects onto the arc: its crossing of the plane axis.x = 0 is the
      // arc's. da - db != 0 (the signs differ).
      const double t = da / (da - db);
      out[m++] = normalized_or(a + (b - a) * t, a);
    }
  }
  return m;
}

double lambert_polygon_integral(const Vec3d* d, int count, const Vec3d& n) {
  double sum = 0;
  for (int i = 0; i < count; ++i) {
    const Vec3d c = cross(d[i], d[(i + 1) % count]);
    const double s = length(c);
    if (!(s > 0)) continue;  // a zero-length edge: Theta = 0
    sum += std::atan2(s, dot(d[i], d[(i + 1) % count])) * (dot(n, c) / s);  // divisor checked
  }
  return 0.5 * std::fabs(sum);
}

double polygon_solid_angle(const Vec3d* d, int count) {
  double omega = 0;
  for (int i = 1; i + 1 < count; ++i) {
    const Vec3d &a = d[0], &b = d[i], &c = d[i + 1];
    const double det = std::fabs(dot(a, cross(b, c)));
    omega += 2.0 * std::atan2(det, 1.0 + dot(a, b) + dot(b, c) + dot(c, a));
  }
  return omega;
}

double polygon_axial_moment(const Vec3d* d, int count, const Vec3d& w, int k) {
  // tau_k = (k-1)/(k+1) tau_{k-2} + 1/(k+1) sum_i (w.gamma_i) E_i,{k-1}
  // (Laplace-Beltrami of (w.u)^k and Stokes; gamma_i the unit normal of edge i's great circle
  // pointing into the polygon), tau_0 = solid angle, tau_{-1} = 0.
  const double o = orientation(d, count);
  if (o == 0) return 0;
  EdgeMoment edges[kMaxClippedVertices];
  Vec3d gamma[kMaxClippedVertices];
  int m = 0;
  const bool odd = k % 2 == 1;
  for (int i = 0; i < count; ++i) {
    const Vec3d &a = d[i], &b = d[(i + 1) % count];
    const Vec3d c = cross(a, b);
    const double s = length(c);
    if (!(s > 0)) continue;  // zero-length edge: no contribution
    const Vec3d g = c * (1.0 / s);
    const Vec3d t = cross(g, a);  // unit tangent at a toward b
    EdgeMoment e;
    e.theta = std::atan2(s, dot(a, b));
    e.A = dot(w, a);
    e.B = dot(w, t);
    e.hb = dot(w, b);
    e.hb_prime = -e.A * std::sin(e.theta) + e.B * std::cos(e.theta);
    e.C2 = e.A * e.A + e.B * e.B;
    // E at k-1 = 0 (k odd) or 1 (k even)
    e.E = odd ? e.theta : e.A * std::sin(e.theta) + e.B * (1 - std::cos(e.theta));
    e.pow_a = odd ? e.A : e.A * e.A;       // A^(j-1) for the next E_j, j = k0 + 2
    e.pow_b = odd ? e.hb : e.hb * e.hb;
    gamma[m] = g * o;
    edges[m++] = e;
  }
  double tau = odd ? 0.0 : polygon_solid_angle(d, count);
  for (int j = odd ? 1 : 2; j <= k; j += 2) {  // tau_j from tau_{j-2} and E_{j-1}
    double sum = 0;
    for (int i = 0; i < m; ++i) sum += dot(w, gamma[i]) * edges[i].E;
    tau = (j - 1.0) / (j + 1.0) * tau + sum / (j + 1.0);
    if (j + 2 > k) break;
    const int next = j + 1;  // E_{next} from E_{next-2}
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

double polygon_specular_integral(const Vec3d* d, int count, const Vec3d& n, const SpecularLobe& lobe) {
  switch (lobe.kind) {
    case LobeKind::None: return 0;
    case LobeKind::Phong: {
      if (lobe.shininess == 0) return polygon_solid_angle(d, count);  // max(R.w,0)^0 = 1 (0^0 = 1)
      Vec3d clipped[kMaxClippedVertices];
      const int m = clip_to_hemisphere(d, count, lobe.reflected, clipped);  // R = 0 (at the eye): all kept
      if (m < 3) return 0;
      if (lobe.reflected == Vec3d{0, 0, 0}) return 0;  // R.w = 0 everywhere: 0^s = 0 for s > 0
      const double k = std::round(lobe.shininess);
      if (k == lobe.shininess && k <= 4096) return polygon_axial_moment(clipped, m, lobe.reflected, int(k));
      double s = 0;
      for (int i = 1; i + 1 < m; ++i)
        s += triangle_quadrature(clipped[0], clipped[i], clipped[i + 1], lobe.quadrature_order,
                                 [&](const Vec3d& w) { return lobe_value(lobe, w); });
      return s;
    }
    case LobeKind::BlinnPhong: {
      (void)n;  // d is already inside n's hemisphere; lobe.normal is n
      double s = 0;
      for (int i = 1; i + 1 < count; ++i)
        s += triangle_quadrature(d[0], d[i], d[i + 1], lobe.quadrature_order,
                                 [&](const Vec3d& w) { return lobe_value(lobe, w); });
      return s;
    }
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
  Vec3d dirs[kMaxAreaVertices];
  for (int i = 0; i < count; ++i) dirs[i] = normalized_or(vertices[i] - p, Vec3d{0, 0, 0});  // p off the plane: != 0
  Vec3d clipped[kMaxClippedVertices];
  const int m = clip_to_hemisphere(dirs, count, n, clipped);
  if (m < 3) {
    t.below_horizon = true;
    return t;
  }
  t.P = lambert_polygon_integral(clipped, m, n);
  t.S = polygon_specular_integral(clipped, m, n, lobe);
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
  // S: polar Gauss-Legendre over the cap (theta in [0, sigma], q nodes, weight sin theta) times
  // 2q equispaced azimuths (exact for trigonometric polynomials of degree < 2q), with [n.w > 0].
  const SpecularLobe& b = lobe;
  const Vec3d e1 = normalized_or(std::fabs(c.x) < 0.9 ? cross(c, Vec3d{1, 0, 0}) : cross(c, Vec3d{0, 1, 0}), Vec3d{0, 0, 1});
  const Vec3d e2 = cross(c, e1);
  const double cos_sigma = std::sqrt(std::fmax(0.0, 1 - sin2));
  const double one_minus_cos_sigma = sin2 / (1 + cos_sigma);  // no cancellation for small lights
  const int q = lobe.quadrature_order;
  const GaussRule& g = gauss_legendre(q);
  double s = 0;
  for (int i = 0; i < q; ++i) {
    // theta through u = 1 - cos(theta) in [0, 1 - cos sigma] (dw = du dphi): smooth in u.
    const double one_minus_cos = one_minus_cos_sigma * g.x[i];
    const double ct = 1 - one_minus_cos;
    const double st = std::sqrt(std::fmax(0.0, one_minus_cos * (2 - one_minus_cos)));
    double ring = 0;
    for (int j = 0; j < 2 * q; ++j) {
      const double phi = kPi * j / q;
      const Vec3d w = c * ct + (e1 * std::cos(phi) + e2 * std::sin(phi)) * st;
      if (dot(n, w) > 0) ring += lobe_value(b, w);
    }
    s += g.w[i] * ring * (kPi / q);
  }
  t.S = s * one_minus_cos_sigma;
  return t;
}

SkyTerms sky_light_terms(const Vec3d& up, const Vec3d& n, const SpecularLobe& lobe) {
  SkyTerms t;
  const SkyProjection P = sky_projected_solid_angles(dot(n, up));
  t.P_sky = P.sky;
  t.P_ground = P.ground;
  if (lobe.kind == LobeKind::None) return t;
  // Each hemisphere as four spherical triangles (pole, e_i, e_i+1), clipped to n's hemisphere.
  const Vec3d e1 = normalized_or(std::fabs(up.x) < 0.9 ? cross(up, Vec3d{1, 0, 0}) : cross(up, Vec3d{0, 1, 0}), Vec3d{0, 0, 1});
  const Vec3d e2 = cross(up, e1);
  const Vec3d ring[4] = {e1, e2, -e1, -e2};
  for (int half = 0; half < 2; ++half) {
    const Vec3d pole = half == 0 ? up : -up;
    double s = 0;
    for (int i = 0; i < 4; ++i) {
      const Vec3d tri[3] = {pole, ring[i], ring[(i + 1) % 4]};
      Vec3d clipped[kMaxClippedVertices];
      const int m = clip_to_hemisphere(tri, 3, n, clipped);
      if (m >= 3) s += polygon_specular_integral(clipped, m, n, lobe);
    }
    (half == 0 ? t.S_sky : t.S_ground) = s;
  }
  return t;
}

}  // namespace shadetool
