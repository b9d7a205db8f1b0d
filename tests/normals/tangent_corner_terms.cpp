// The vector pass of MikkTSpace (normals/engine/tangent_corner_terms.h) against the reference's
// scalar arithmetic written out here from mikktspace.c (EvalTspace: vsub, vscale, vdot,
// NormalizeSafe, the clamped cosine, (float) acos of it in double, here glibc's), bit for bit, on
// random, tiny, zero and non-finite inputs and every block length.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <shadetool/normals/engine/tangent_corner_terms.h>

using shadetool::normals_detail::kTangentCornerBlock;
using shadetool::normals_detail::tangent_corner_terms;
using shadetool::normals_detail::tangent_triangle_derivatives;

namespace {

struct V3 {
  float x, y, z;
};
float vdot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 vsub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 vscale(float s, V3 v) { return {s * v.x, s * v.y, s * v.z}; }
bool not_zero(float x) { return std::fabs(x) > FLT_MIN; }
// mikktspace.c: NormalizeSafe(vsub(v, vscale(vdot(n, v), n))) where VNotZero, else the vector as is.
V3 project_unit(V3 v, V3 n) {
  V3 p = vsub(v, vscale(vdot(n, v), n));
  if (not_zero(p.x) || not_zero(p.y) || not_zero(p.z)) {
    const float len = std::sqrt(vdot(p, p));
    if (len > 0) p = vscale(1.0f / len, p);
  }
  return p;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0 || (a != a && b != b); }

}  // namespace

TEST_CASE("MikkTSpace's corner terms: the vector pass gives the scalar arithmetic's bits", "[tangents]") {
  constexpr std::size_t B = kTangentCornerBlock;
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float specials[] = {0.0f, -0.0f, 1e-39f, -1e-39f, 1e-20f, 1.0f, NAN, INFINITY};
  std::size_t checked = 0;
  for (int round = 0; round < 200; ++round) {
    const std::size_t n = 1 + std::size_t(round) % B;
    std::vector<float> in(15 * B), out(7 * B);
    for (std::size_t i = 0; i < n; ++i) {
      V3 nn{u(rng), u(rng), u(rng)};
      const float len = std::sqrt(vdot(nn, nn));
      nn = len > 0 ? vscale(1.0f / len, nn) : V3{0, 0, 1};
      float v[15] = {nn.x, nn.y, nn.z};
      for (int r = 3; r < 15; ++r) v[r] = u(rng);
      // Some lanes: a derivative or an edge along the normal (zero projection), tiny, or special.
      if (rng() % 4 == 0) { v[3] = nn.x; v[4] = nn.y; v[5] = nn.z; }
      if (rng() % 4 == 0) { v[9] = 2 * nn.x; v[10] = 2 * nn.y; v[11] = 2 * nn.z; }
      if (rng() % 3 == 0) v[3 + rng() % 12] = specials[rng() % 8];
      if (rng() % 5 == 0) for (int r = 12; r < 15; ++r) v[r] = 1e-30f * v[r];
      for (int r = 0; r < 15; ++r) in[r * B + i] = v[r];
    }
    tangent_corner_terms(n, in.data(), out.data());
    for (std::size_t i = 0; i < n; ++i) {
      auto row = [&](int r) { return V3{in[r * B + i], in[(r + 1) * B + i], in[(r + 2) * B + i]}; };
      const V3 nn = row(0);
      const V3 ps = project_unit(row(3), nn), pt = project_unit(row(6), nn);
      const V3 a = project_unit(row(9), nn), b = project_unit(row(12), nn);
      const float c = std::min(1.0f, std::max(-1.0f, vdot(a, b)));
      const float expected[7] = {ps.x, ps.y, ps.z, pt.x, pt.y, pt.z, float(std::acos(double(c)))};
      for (int r = 0; r < 7; ++r) {
        INFO("round " << round << " lane " << i << " output row " << r);
        CHECK(same_bits(out[r * B + i], expected[r]));
      }
      ++checked;
    }
  }
  CHECK(checked > 5000);
}

// The angle's arc cosine (fdlibm's method, tangent_corner_terms.h) is glibc's acos rounded to float
// for every float cosine: a cosine near each c of a sweep over [-1, 1] (every 4099th float, the
// ends, and around +-0.5, where the method changes branch) from edges e1 = x and e2 = (c, s, 0) in
// the plane of N = z; the expected angle is glibc's acos of the cosine the scalar arithmetic
// gives for them. (All 2130706434 floats in [-1, 1] were checked once, tangent_corner_terms.h.)
TEST_CASE("MikkTSpace's corner angle: the pass's arc cosine equals float(acos(double)) across [-1, 1]", "[tangents]") {
  constexpr std::size_t B = kTangentCornerBlock;
  std::vector<float> cosines = {1.0f, -1.0f, 0.0f, -0.0f, 0.5f, -0.5f, std::nextafter(0.5f, 0.0f), std::nextafter(-0.5f, 0.0f),
                                std::nextafter(1.0f, 0.0f), std::nextafter(-1.0f, 0.0f), 1e-30f, -1e-30f};
  for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 4099) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    cosines.push_back(f);
    cosines.push_back(-f);
  }
  std::size_t mismatches = 0;
  std::vector<float> in(15 * B, 0.0f), out(7 * B);
  for (std::size_t begin = 0; begin < cosines.size(); begin += B) {
    const std::size_t n = std::min(B, cosines.size() - begin);
    for (std::size_t i = 0; i < n; ++i) {
      const float c = cosines[begin + i];
      const float s = std::sqrt(std::max(0.0f, 1.0f - c * c));
      const float v[15] = {0, 0, 1, 1, 0, 0, 0, 1, 0, 1, 0, 0, c, s, 0};
      for (int r = 0; r < 15; ++r) in[r * B + i] = v[r];
    }
    tangent_corner_terms(n, in.data(), out.data());
    for (std::size_t i = 0; i < n; ++i) {
      auto row = [&](int r) { return V3{in[r * B + i], in[(r + 1) * B + i], in[(r + 2) * B + i]}; };
      const V3 a = project_unit(row(9), row(0)), b = project_unit(row(12), row(0));
      const float c = std::min(1.0f, std::max(-1.0f, vdot(a, b)));
      if (!same_bits(out[6 * B + i], float(std::acos(double(c))))) ++mismatches;
    }
  }
  INFO(cosines.size() << " cosines");
  CHECK(mismatches == 0);
  CHECK(cosines.size() > 500000);
}

// The lane pass's frames (tangent_lane_frames) against mikktspace.c's EvalTspace sums written out
// here: per group, in member order, res.vOs = vadd(res.vOs, vscale(fAngle, vOs)) and so on, then
// Normalize where VNotZero, the magnitudes divided by fAngleSum where it is > 0; and the 60-degree
// test against the first member, all bit for bit, on random groups of 0 to 8 members with random,
// tiny, zero and non-finite terms.
using shadetool::normals_detail::kTangentLanes;
using shadetool::normals_detail::tangent_lane_frames;

TEST_CASE("MikkTSpace's group frames: the lane pass gives the scalar sums' bits", "[tangents]") {
  constexpr std::size_t B = kTangentCornerBlock, L = kTangentLanes;
  std::mt19937 rng(31);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), angle(0.0f, 3.2f);
  const float specials[] = {0.0f, -0.0f, 1e-39f, -1e-39f, 1e-20f, 1.0f, NAN, INFINITY};
  std::size_t checked = 0, near_seen = 0, far_seen = 0;
  for (int round = 0; round < 2000; ++round) {
    std::vector<float> terms(7 * B), mags(2 * B), out(9 * L);
    int count[L];
    std::size_t rows = 0;
    for (std::size_t g = 0; g < L; ++g) count[g] = int(rng() % (B / L + 1)), rows = std::max(rows, std::size_t(count[g]));
    // Nearly parallel members in most rounds (the common, surely whole case), random ones else.
    const bool parallel = round % 3 != 0;
    for (std::size_t c = 0; c < rows * L; ++c) {
      const V3 s{1 + 0.2f * u(rng), 0.2f * u(rng), 0.2f * u(rng)}, t{0.2f * u(rng), 1 + 0.2f * u(rng), 0.2f * u(rng)};
      const V3 ps = parallel ? vscale(1.0f / std::sqrt(vdot(s, s)), s) : V3{u(rng), u(rng), u(rng)};
      const V3 pt = parallel ? vscale(1.0f / std::sqrt(vdot(t, t)), t) : V3{u(rng), u(rng), u(rng)};
      float v[9] = {ps.x, ps.y, ps.z, pt.x, pt.y, pt.z, angle(rng), 10 * angle(rng), 10 * angle(rng)};
      if (rng() % 50 == 0) v[rng() % 9] = specials[rng() % 8];
      if (rng() % 50 == 0) v[6] = 0.0f;
      for (int r = 0; r < 7; ++r) terms[r * B + c] = v[r];
      mags[c] = v[7], mags[B + c] = v[8];
    }
    tangent_lane_frames(rows, count, terms.data(), mags.data(), out.data());
    for (std::size_t g = 0; g < L; ++g) {
      if (count[g] == 0) continue;
      auto at = [&](int r, std::size_t j) { return terms[r * B + j * L + g]; };
      V3 os{0, 0, 0}, ot{0, 0, 0};
      float ms = 0, mt = 0, sum = 0;
      bool near = true;
      for (std::size_t j = 0; j < std::size_t(count[g]); ++j) {
        const float a = at(6, j);
        const V3 ps{at(0, j), at(1, j), at(2, j)}, pt{at(3, j), at(4, j), at(5, j)};
        const V3 sa = vscale(a, ps), ta = vscale(a, pt);
        os = {os.x + sa.x, os.y + sa.y, os.z + sa.z};
        ot = {ot.x + ta.x, ot.y + ta.y, ot.z + ta.z};
        ms += a * mags[j * L + g];
        mt += a * mags[B + j * L + g];
        sum += a;
        const V3 ps0{at(0, 0), at(1, 0), at(2, 0)}, pt0{at(3, 0), at(4, 0), at(5, 0)};
        if (j > 0) near = near && vdot(ps0, ps) > 0.5f && vdot(pt0, pt) > 0.5f;
      }
      auto normalize_safe = [](V3 v) {
        if (!(not_zero(v.x) || not_zero(v.y) || not_zero(v.z))) return v;
        const float len = std::sqrt(vdot(v, v));
        return len > 0 ? vscale(1.0f / len, v) : v;
      };
      os = normalize_safe(os);
      ot = normalize_safe(ot);
      if (sum > 0) ms /= sum, mt /= sum;
      const float expected[9] = {os.x, os.y, os.z, ot.x, ot.y, ot.z, ms, mt, near ? 1.0f : 0.0f};
      for (int r = 0; r < 9; ++r) {
        INFO("round " << round << " lane " << g << " members " << count[g] << " output row " << r);
        CHECK(same_bits(out[r * L + g], expected[r]));
      }
      (near ? near_seen : far_seen) += 1;
      ++checked;
    }
  }
  CHECK(checked > 10000);
  CHECK(near_seen > 1000);  // both answers of the 60-degree test occur
  CHECK(far_seen > 1000);
}

// mikktspace.c, InitTriInfo's per-triangle branch, written out: the derivatives made unit with the
// orientation's sign where their length is not zero, the magnitudes over the absolute area, all
// left zero where the area is zero.
TEST_CASE("MikkTSpace's triangle derivatives: the vector pass gives the reference's scalar bits", "[tangents]") {
  constexpr std::size_t B = kTangentCornerBlock;
  std::mt19937 rng(2929);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float specials[] = {0.0f, -0.0f, 1e-39f, -1e-39f, 1e-20f, 1e20f, NAN, INFINITY, -INFINITY, FLT_MIN};
  std::size_t checked = 0, zero_area = 0, zero_length = 0;
  for (int round = 0; round < 400; ++round) {
    const std::size_t n = 1 + std::size_t(round) % B;
    std::vector<float> in(7 * B), out(8 * B);
    for (std::size_t i = 0; i < n; ++i) {
      float v[7];
      for (float& x : v) x = u(rng);
      if (rng() % 4 == 0) v[6] = specials[rng() % 10];                       // area: zero, tiny, huge, non-finite
      if (rng() % 4 == 0) v[rng() % 2 ? 0 : 3] = v[rng() % 2 ? 1 : 4] = v[rng() % 2 ? 2 : 5] = 0.0f;  // a zero derivative (some components)
      if (rng() % 4 == 0) v[rng() % 6] = specials[rng() % 10];
      if (rng() % 6 == 0) for (int r = 0; r < 3; ++r) v[r] *= 1e-25f;        // a length that underflows
      for (int r = 0; r < 7; ++r) in[r * B + i] = v[r];
    }
    tangent_triangle_derivatives(n, in.data(), out.data());
    for (std::size_t i = 0; i < n; ++i) {
      const V3 os{in[i], in[B + i], in[2 * B + i]}, ot{in[3 * B + i], in[4 * B + i], in[5 * B + i]};
      const float area = in[6 * B + i];
      V3 us{0, 0, 0}, ut{0, 0, 0};
      float mag_s = 0, mag_t = 0;
      if (not_zero(area)) {
        const float abs_area = std::fabs(area), len_s = std::sqrt(vdot(os, os)), len_t = std::sqrt(vdot(ot, ot));
        const float sign = area > 0 ? 1.0f : -1.0f;
        if (not_zero(len_s)) us = vscale(sign / len_s, os);
        else ++zero_length;
        if (not_zero(len_t)) ut = vscale(sign / len_t, ot);
        mag_s = len_s / abs_area;
        mag_t = len_t / abs_area;
      } else {
        ++zero_area;
      }
      const float expected[8] = {us.x, us.y, us.z, ut.x, ut.y, ut.z, mag_s, mag_t};
      for (int r = 0; r < 8; ++r) {
        INFO("round " << round << " lane " << i << " output row " << r);
        CHECK(same_bits(out[r * B + i], expected[r]));
      }
      ++checked;
    }
  }
  CHECK(checked > 10000);
  CHECK(zero_area > 500);   // the early return taken often
  CHECK(zero_length > 100);  // the length test too
}
