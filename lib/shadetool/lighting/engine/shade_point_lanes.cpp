// engine/shade_point_lanes.cpp: see shade_point_lanes.h. The comments name the scalar lines of
// engine/shade_point.h and lighting_equation.h each step repeats. Compiled with -ffp-contract=off
// (CMakeLists.txt): a multiply and an add must stay two roundings, as in the scalar loop.
#include <shadetool/lighting/engine/shade_point_lanes.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SHADETOOL_POINT_LANES 1
#include <immintrin.h>
#endif

namespace shadetool {
namespace lighting_engine {

bool point_lanes_support(const PointLighting& lighting) {
  for (const SpaceLight& light : lighting.frame.lights) switch (light.type) {
      case LightType::Directional:
      case LightType::Point:
      case LightType::Spot:
        continue;
      case LightType::Ambient:  // folded into the base by plan_lighting: never here
      case LightType::Area:
      case LightType::Sky:
      case LightType::Environment:
        return false;
    }
  return true;
}

#if defined(SHADETOOL_POINT_LANES)

bool point_lanes_available() {
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
}

#define LANES_TARGET __attribute__((target("avx2,fma")))

namespace {

// An exponent the double-double power takes: an integer in [0, 2^20] (0: x^0 = 1, as std::pow).
bool integer_exponent(double e) { return e >= 0 && e <= 0x1p20 && e == std::floor(e); }

struct V3 {
  __m256d x, y, z;
};

LANES_TARGET inline __m256d bcast(double v) { return _mm256_set1_pd(v); }
LANES_TARGET inline __m256d add(__m256d a, __m256d b) { return _mm256_add_pd(a, b); }
LANES_TARGET inline __m256d sub(__m256d a, __m256d b) { return _mm256_sub_pd(a, b); }
LANES_TARGET inline __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
LANES_TARGET inline __m256d div(__m256d a, __m256d b) { return _mm256_div_pd(a, b); }
LANES_TARGET inline __m256d gt(__m256d a, __m256d b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
LANES_TARGET inline __m256d both(__m256d a, __m256d b) { return _mm256_and_pd(a, b); }
LANES_TARGET inline __m256d but_not(__m256d a, __m256d not_b) { return _mm256_andnot_pd(not_b, a); }
// mask ? a : b
LANES_TARGET inline __m256d select(__m256d mask, __m256d a, __m256d b) { return _mm256_blendv_pd(b, a, mask); }
LANES_TARGET inline int lanes(__m256d mask) { return __builtin_popcount(unsigned(_mm256_movemask_pd(mask))); }
// core/vec3.h's dot: a.x * b.x + a.y * b.y + a.z * b.z, left to right
LANES_TARGET inline __m256d dot(const V3& a, const V3& b) { return add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z)); }
LANES_TARGET inline V3 bcast(const Vec3d& v) { return {bcast(v.x), bcast(v.y), bcast(v.z)}; }
// lighting_equation.h's positive_part: x > 0 ? x : 0 (NaN -> 0)
LANES_TARGET inline __m256d positive_part(__m256d x) { return _mm256_and_pd(gt(x, _mm256_setzero_pd()), x); }
// color += k * s, per channel, in the lanes of mask
LANES_TARGET inline void add_scaled(V3& color, const V3& k, __m256d s, __m256d mask) {
  color.x = select(mask, add(color.x, mul(k.x, s)), color.x);
  color.y = select(mask, add(color.y, mul(k.y, s)), color.y);
  color.z = select(mask, add(color.z, mul(k.z, s)), color.z);
}

// (h, l) <- h + l renormalised (fast two-sum, |h| >= |l|).
LANES_TARGET inline void renormalise(__m256d& h, __m256d& l) {
  const __m256d s = add(h, l);
  l = sub(l, sub(s, h));
  h = s;
}

// lighting_equation.h's lighting_integer_power four at a time (the same operations, same order): x^e, e in [1, 2^20], in double-double: left-to-right binary exponentiation, each product's
// rounding error kept by an FMA (h*h - fl(h*h) is exact); l*l (below 2^-106 h^2) dropped.
LANES_TARGET inline __m256d integer_power(__m256d x, std::uint32_t e) {
  __m256d h = x, l = _mm256_setzero_pd();
  for (int bit = 30 - __builtin_clz(e); bit >= 0; --bit) {
    __m256d p = mul(h, h);
    __m256d err = _mm256_fmsub_pd(h, h, p);
    err = _mm256_fmadd_pd(add(h, h), l, err);
    h = p, l = err;
    renormalise(h, l);
    if ((e >> bit) & 1u) {
      p = mul(h, x);
      err = _mm256_fmsub_pd(h, x, p);
      err = _mm256_fmadd_pd(l, x, err);
      h = p, l = err;
      renormalise(h, l);
    }
  }
  return h;
}

// lighting_equation.h's pow(positive_part(x), exponent) in the lanes of `need` (others: any value).
LANES_TARGET inline __m256d power(__m256d x, double exponent, __m256d need) {
  x = positive_part(x);
  if (exponent == 0) return bcast(1.0);  // std::pow(x, 0) = 1 for every x
  __m256d r;
  int redo = 0;
  if (integer_exponent(exponent)) {
    r = integer_power(x, std::uint32_t(exponent));
    // results below 2^-900 (and x = 0): std::pow (the low part could have lost bits)
    redo = _mm256_movemask_pd(both(need, _mm256_cmp_pd(r, bcast(0x1p-900), _CMP_LT_OQ)));
  } else {
    r = x;
    redo = _mm256_movemask_pd(need);
  }
  if (redo) {
    alignas(32) double v[4], xs[4];
    _mm256_store_pd(v, r);
    _mm256_store_pd(xs, x);
    for (int k = 0; k < 4; ++k)
      if ((redo >> k) & 1) v[k] = std::pow(xs[k], exponent);
    r = _mm256_load_pd(v);
  }
  return r;
}

// Four points (lanes of `valid`). Returns the lanes left to the scalar loop.
LANES_TARGET inline __attribute__((always_inline)) int shade4(const PointLighting& lit, const V3& p, V3 n, __m256d valid, ShadeCounters& count, V3& color) {
  const __m256d zero = _mm256_setzero_pd(), one = bcast(1.0);
  const __m256d lo = bcast(0x1p-1000), hi = bcast(0x1p1000);
  const bool specular = lit.plan.specular, view = lit.plan.view;
  // n2 = g.conorm2(n); n_scale = 1 / sqrt(n2) where n2 > 0 and finite (else: scalar)
  const __m256d n2 = dot(n, n);
  __m256d ok = both(gt(n2, zero), _mm256_cmp_pd(n2, bcast(HUGE_VAL), _CMP_LT_OQ));
  const __m256d n_scale = div(one, _mm256_sqrt_pd(n2));
  V3 V{zero, zero, zero};
  __m256d v_unit = zero, n_dot_v = zero;
  if (view) {  // metric_normalize(eye - p) in [2^-1000, 2^1000] (else: scalar)
    const V3 e = bcast(lit.frame.eye);
    const V3 v{sub(e.x, p.x), sub(e.y, p.y), sub(e.z, p.z)};
    const __m256d d2 = dot(v, v);
    ok = both(ok, both(_mm256_cmp_pd(d2, lo, _CMP_GE_OQ), _mm256_cmp_pd(d2, hi, _CMP_LE_OQ)));
    const __m256d inv = div(one, _mm256_sqrt_pd(d2));
    V = {mul(v.x, inv), mul(v.y, inv), mul(v.z, inv)};
    v_unit = one;
    n_dot_v = mul(dot(n, V), n_scale);
    if (lit.two_sided) {  // n_dot_v < 0: n = -n, n_dot_v = -n_dot_v
      const __m256d flip = _mm256_cmp_pd(n_dot_v, zero, _CMP_LT_OQ);
      const __m256d sign = both(flip, bcast(-0.0));
      n = {_mm256_xor_pd(n.x, sign), _mm256_xor_pd(n.y, sign), _mm256_xor_pd(n.z, sign)};
      n_dot_v = _mm256_xor_pd(n_dot_v, sign);
    }
  }
  color = bcast(lit.plan.base);
  for (const SpaceLight& light : lit.frame.lights) {
    __m256d active = bcast(0.0);  // the lanes that go on to add_light_term
    __m256d att_spot = one, n_dot_l = zero;
    V3 L{zero, zero, zero};
    const __m256d all = _mm256_cmp_pd(zero, zero, _CMP_EQ_OQ);
    switch (light.type) {
      case LightType::Directional:
        L = bcast(light.to_light);
        n_dot_l = mul(dot(n, L), n_scale);
        active = light.has_ambient ? all : gt(n_dot_l, zero);
        count.back_facing += std::size_t(lanes(but_not(valid, active)));
        break;
      case LightType::Point:
      case LightType::Spot: {
        const V3 q = bcast(light.position);
        const V3 to_light{sub(q.x, p.x), sub(q.y, p.y), sub(q.z, p.z)};
        active = light.has_ambient ? all : gt(dot(n, to_light), zero);  // sign of n.L, no sqrt
        count.back_facing += std::size_t(lanes(but_not(valid, active)));
        const __m256d d2 = dot(to_light, to_light);  // metric_normalize in range (else: scalar)
        ok = both(ok, _mm256_or_pd(but_not(all, active),
                                   both(_mm256_cmp_pd(d2, lo, _CMP_GE_OQ), _mm256_cmp_pd(d2, hi, _CMP_LE_OQ))));
        const __m256d d = _mm256_sqrt_pd(d2);
        const __m256d inv = div(one, d);
        L = {mul(to_light.x, inv), mul(to_light.y, inv), mul(to_light.z, inv)};
        __m256d spot = one;
        if (light.cone) {
          const __m256d cos_t = _mm256_xor_pd(dot(L, bcast(light.axis_lowered)), bcast(-0.0));  // -dot
          const __m256d inside = _mm256_cmp_pd(cos_t, bcast(light.cos_cutoff), _CMP_NLT_UQ);  // !(cos_t < cos_cutoff)
          count.outside_cone += std::size_t(lanes(both(valid, but_not(active, inside))));
          active = both(active, inside);
          spot = power(cos_t, light.exponent, both(valid, active));  // spot_factor inside the cone
        }
        __m256d den = bcast(light.kc);  // attenuation_denominator
        if (light.kl != 0) den = add(den, mul(bcast(light.kl), d));
        if (light.kq != 0) den = add(den, mul(mul(bcast(light.kq), d), d));
        att_spot = div(spot, den);
        n_dot_l = mul(dot(n, L), n_scale);
        break;
      }
      case LightType::Ambient:
      case LightType::Area:
      case LightType::Sky:
      case LightType::Environment:
        return 0xf;  // not reached: point_lanes_support
    }
    count.vertex_light_evaluations += std::size_t(lanes(valid));
    const __m256d lit_lanes = both(active, gt(n_dot_l, zero));
    const bool with_specular = specular && light.has_specular;
    __m256d spec = zero;
    if (with_specular) {
      const __m256d l_dot_v = dot(L, V);
      __m256d base = zero;
      switch (lit.model) {
        case ShadingModel::BlinnPhong: {  // blinn_phong_n_dot_h
          const __m256d h2 = add(add(one, mul(bcast(2.0), l_dot_v)), v_unit);
          base = select(gt(h2, zero), div(add(n_dot_l, n_dot_v), _mm256_sqrt_pd(h2)), zero);
          break;
        }
        case ShadingModel::Phong:  // specular_phong's R.V
          base = sub(mul(mul(bcast(2.0), n_dot_l), n_dot_v), l_dot_v);
          break;
        case ShadingModel::Lambert:  // plan.specular is false
          break;
      }
      spec = power(base, lit.shininess, both(valid, lit_lanes));
    }
    // add_light_term (visibility 1)
    if (light.has_ambient) add_scaled(color, bcast(light.products.ambient), att_spot, active);
    add_scaled(color, bcast(light.products.diffuse), mul(att_spot, n_dot_l), lit_lanes);
    if (with_specular) add_scaled(color, bcast(light.products.specular), mul(att_spot, spec), lit_lanes);
  }
  const int scalar = _mm256_movemask_pd(but_not(valid, ok));
  count.points += std::size_t(lanes(valid)) - std::size_t(__builtin_popcount(unsigned(scalar)));
  return scalar;
}

}  // namespace

LANES_TARGET void shade_point_lanes(const PointLighting& lighting, const PointBlock& b, double* rgb_out,
                                    ShadeCounters& counters) {
  const __m256d all = _mm256_cmp_pd(_mm256_setzero_pd(), _mm256_setzero_pd(), _CMP_EQ_OQ);
  for (std::size_t i = 0; i < b.count; i += 4) {
    const std::size_t m = std::min<std::size_t>(4, b.count - i);
    V3 p, n;
    __m256d valid = all;
    if (m == 4) {
      p = {_mm256_loadu_pd(b.px + i), _mm256_loadu_pd(b.py + i), _mm256_loadu_pd(b.pz + i)};
      n = {_mm256_loadu_pd(b.nx + i), _mm256_loadu_pd(b.ny + i), _mm256_loadu_pd(b.nz + i)};
    } else {  // the tail, padded with its first point
      alignas(32) double in[6][4];
      const double* src[6] = {b.px + i, b.py + i, b.pz + i, b.nx + i, b.ny + i, b.nz + i};
      for (int a = 0; a < 6; ++a)
        for (std::size_t k = 0; k < 4; ++k) in[a][k] = src[a][k < m ? k : 0];
      p = {_mm256_load_pd(in[0]), _mm256_load_pd(in[1]), _mm256_load_pd(in[2])};
      n = {_mm256_load_pd(in[3]), _mm256_load_pd(in[4]), _mm256_load_pd(in[5])};
      const __m256i index = _mm256_set_epi64x(3, 2, 1, 0);
      valid = _mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(std::int64_t(m)), index));
    }
    ShadeCounters lane_counts;
    V3 color;
    const int redo = shade4(lighting, p, n, valid, lane_counts, color);
    if (redo != 0) {  // the quad again without the lanes the scalar loop takes (rare), for the counts
      lane_counts = ShadeCounters{};
      const __m256d keep = _mm256_castsi256_pd(_mm256_set_epi64x((redo & 8) ? 0 : -1, (redo & 4) ? 0 : -1,
                                                                 (redo & 2) ? 0 : -1, (redo & 1) ? 0 : -1));
      shade4(lighting, p, n, both(valid, keep), lane_counts, color);
    }
    counters += lane_counts;
    // (r0 g0 b0 r1 g1 b1 ...) from the three channel vectors
    alignas(32) double r[3][4];
    _mm256_store_pd(r[0], color.x);
    _mm256_store_pd(r[1], color.y);
    _mm256_store_pd(r[2], color.z);
    double* o = rgb_out + 3 * i;
    for (std::size_t k = 0; k < m; ++k) o[3 * k] = r[0][k], o[3 * k + 1] = r[1][k], o[3 * k + 2] = r[2][k];
    for (std::size_t k = 0; k < m; ++k)
      if ((redo >> k) & 1) {
        const Vec3d c = shade_point(lighting, {b.px[i + k], b.py[i + k], b.pz[i + k]},
                                    {b.nx[i + k], b.ny[i + k], b.nz[i + k]}, &counters);
        o[3 * k] = c.x, o[3 * k + 1] = c.y, o[3 * k + 2] = c.z;
      }
  }
}

LANES_TARGET void integer_power_lanes(const double* x, std::size_t count, std::uint32_t exponent, double* out) {
  for (std::size_t i = 0; i < count; i += 4) {
    alignas(32) double v[4] = {0, 0, 0, 0};
    const std::size_t m = std::min<std::size_t>(4, count - i);
    std::memcpy(v, x + i, m * sizeof(double));
    _mm256_store_pd(v, power(_mm256_load_pd(v), double(exponent), _mm256_cmp_pd(_mm256_setzero_pd(), _mm256_setzero_pd(), _CMP_EQ_OQ)));
    std::memcpy(out + i, v, m * sizeof(double));
  }
}

#else  // no vector path: shade_point_block takes the scalar loop

bool point_lanes_available() { return false; }
void shade_point_lanes(const PointLighting&, const PointBlock&, double*, ShadeCounters&) {}
void integer_power_lanes(const double*, std::size_t, std::uint32_t, double*) {}

#endif

}  // namespace lighting_engine
}  // namespace shadetool
