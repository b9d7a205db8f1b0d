// tangent_corner_terms.cpp: see tangent_corner_terms.h (what, and why the clones agree bitwise).
#include <shadetool/normals/engine/tangent_corner_terms.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace shadetool::normals_detail {

// One clone each for AVX-512, AVX2 and the baseline, as triangle_blocks.cpp (built with
// -fno-math-errno -fno-trapping-math, CMakeLists.txt: a sqrt that may set errno stops GCC from
// vectorising; the values are the same).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define SHADETOOL_TANGENT_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define SHADETOOL_TANGENT_CLONES
#endif

namespace {

// project_unit of tangent_corner_terms.h, lane-wise: every value computed, then selected.
inline __attribute__((always_inline)) void project_unit(float vx, float vy, float vz, float nx, float ny, float nz,
                                                        float& px, float& py, float& pz) {
  const float d = nx * vx + ny * vy + nz * vz;
  px = vx - d * nx;
  py = vy - d * ny;
  pz = vz - d * nz;
  const bool not_zero = (std::fabs(px) > FLT_MIN) | (std::fabs(py) > FLT_MIN) | (std::fabs(pz) > FLT_MIN);
  const float len = std::sqrt(px * px + py * py + pz * pz);
  const float inv = 1.0f / len;  // used only where len > 0 (selected below)
  const bool unit = not_zero & (len > 0.0f);
  px = unit ? inv * px : px;
  py = unit ? inv * py : py;
  pz = unit ? inv * pz : pz;
}

// arc_cosine of tangent_corner_terms.h (fdlibm's e_acos.c), every branch computed, then selected.
inline __attribute__((always_inline)) double arc_cosine(double x) {
  constexpr double pio2_hi = 1.57079632679489655800e+00, pio2_lo = 6.12323399573676603587e-17;
  constexpr double pi = 3.14159265358979311600e+00;
  constexpr double pS0 = 1.66666666666666657415e-01, pS1 = -3.25565818622400915405e-01,
                   pS2 = 2.01212532134862925881e-01, pS3 = -4.00555345006794114027e-02,
                   pS4 = 7.91534994289814532176e-04, pS5 = 3.47933107596021167570e-05;
  constexpr double qS1 = -2.40339491173441421878e+00, qS2 = 2.02094576023350569471e+00,
                   qS3 = -6.88283971605453293030e-01, qS4 = 7.70381505559019352791e-02;
  const double ax = std::fabs(x);
  const bool middle = ax < 0.5;
  const double z = middle ? x * x : (1.0 - ax) * 0.5;
  const double p = z * (pS0 + z * (pS1 + z * (pS2 + z * (pS3 + z * (pS4 + z * pS5)))));
  const double q = 1.0 + z * (qS1 + z * (qS2 + z * (qS3 + z * qS4)));  // in [0.4, 1]: no zero
  const double r = p / q;
  const double s = std::sqrt(z);
  // |x| < 0.5: pi/2 - asin(x).
  const double a_middle = pio2_hi - (x - (pio2_lo - x * r));
  // x <= -0.5: pi - 2 asin(sqrt(z)).
  const double a_negative = pi - 2.0 * (s + (r * s - pio2_lo));
  // x >= 0.5: 2 asin(sqrt(z)), sqrt(z) = df + c with df its high 32 bits.
  std::uint64_t bits;
  std::memcpy(&bits, &s, sizeof bits);
  bits &= 0xffffffff00000000ull;
  double df;
  std::memcpy(&df, &bits, sizeof df);
  const double sum = s + df;
  const double c = sum > 0.0 ? (z - df * df) / sum : 0.0;  // x = 1: z = s = 0, c = 0; else divisor > 0
  const double a_positive = 2.0 * (df + (r * s + c));
  return middle ? a_middle : x < 0.0 ? a_negative : a_positive;
}

}  // namespace

SHADETOOL_TANGENT_CLONES
void tangent_corner_terms(std::size_t n, const float* __restrict in, float* __restrict out) {
  constexpr std::size_t B = kTangentCornerBlock;
  const float *nx = in, *ny = in + B, *nz = in + 2 * B;
  const float *osx = in + 3 * B, *osy = in + 4 * B, *osz = in + 5 * B;
  const float *otx = in + 6 * B, *oty = in + 7 * B, *otz = in + 8 * B;
  const float *e1x = in + 9 * B, *e1y = in + 10 * B, *e1z = in + 11 * B;
  const float *e2x = in + 12 * B, *e2y = in + 13 * B, *e2z = in + 14 * B;
  float *psx = out, *psy = out + B, *psz = out + 2 * B, *ptx = out + 3 * B, *pty = out + 4 * B, *ptz = out + 5 * B;
  float cosine[B];
  float* angle = out + 6 * B;
  for (std::size_t i = 0; i < n; ++i) {
    float sx, sy, sz, tx, ty, tz, ax, ay, az, bx, by, bz;
    project_unit(osx[i], osy[i], osz[i], nx[i], ny[i], nz[i], sx, sy, sz);
    project_unit(otx[i], oty[i], otz[i], nx[i], ny[i], nz[i], tx, ty, tz);
    project_unit(e1x[i], e1y[i], e1z[i], nx[i], ny[i], nz[i], ax, ay, az);
    project_unit(e2x[i], e2y[i], e2z[i], nx[i], ny[i], nz[i], bx, by, bz);
    psx[i] = sx, psy[i] = sy, psz[i] = sz;
    ptx[i] = tx, pty[i] = ty, ptz[i] = tz;
    cosine[i] = std::min(1.0f, std::max(-1.0f, ax * bx + ay * by + az * bz));
  }
  for (std::size_t i = 0; i < n; ++i) angle[i] = float(arc_cosine(double(cosine[i])));
}

SHADETOOL_TANGENT_CLONES
void tangent_lane_frames(std::size_t rows, const int* __restrict count, const float* __restrict terms,
                         const float* __restrict mags, float* __restrict out) {
  constexpr std::size_t B = kTangentCornerBlock, L = kTangentLanes;
  float osx[L], osy[L], osz[L], otx[L], oty[L], otz[L], ms[L], mt[L], sum[L], near[L];
  for (std::size_t g = 0; g < L; ++g)
    osx[g] = osy[g] = osz[g] = otx[g] = oty[g] = otz[g] = ms[g] = mt[g] = sum[g] = 0.0f, near[g] = 1.0f;
  for (std::size_t j = 0; j < rows; ++j)
    for (std::size_t g = 0; g < L; ++g) {
      const std::size_t c = j * L + g;
      const bool in = int(j) < count[g];
      const float angle = terms[6 * B + c];
      const float psx = terms[c], psy = terms[B + c], psz = terms[2 * B + c];
      const float ptx = terms[3 * B + c], pty = terms[4 * B + c], ptz = terms[5 * B + c];
      osx[g] = in ? osx[g] + angle * psx : osx[g];
      osy[g] = in ? osy[g] + angle * psy : osy[g];
      osz[g] = in ? osz[g] + angle * psz : osz[g];
      otx[g] = in ? otx[g] + angle * ptx : otx[g];
      oty[g] = in ? oty[g] + angle * pty : oty[g];
      otz[g] = in ? otz[g] + angle * ptz : otz[g];
      ms[g] = in ? ms[g] + angle * mags[c] : ms[g];
      mt[g] = in ? mt[g] + angle * mags[B + c] : mt[g];
      sum[g] = in ? sum[g] + angle : sum[g];
      // Within 60 degrees of member 0 (column g): its own dot with itself passes or not alike.
      const float ds = terms[g] * psx + terms[B + g] * psy + terms[2 * B + g] * psz;
      const float dt = terms[3 * B + g] * ptx + terms[4 * B + g] * pty + terms[5 * B + g] * ptz;
      const bool ok = j == 0 || ((ds > 0.5f) & (dt > 0.5f));
      near[g] = (in & !ok) ? 0.0f : near[g];
    }
  for (std::size_t g = 0; g < L; ++g) {
    float* o = out;
    // Unit where not zero (tangents.cpp's normalize: the length's inverse, then products).
    const bool s_nz = (std::fabs(osx[g]) > FLT_MIN) | (std::fabs(osy[g]) > FLT_MIN) | (std::fabs(osz[g]) > FLT_MIN);
    const float s_len = std::sqrt(osx[g] * osx[g] + osy[g] * osy[g] + osz[g] * osz[g]);
    const bool s_unit = s_nz & (s_len > 0.0f);
    const float s_inv = 1.0f / s_len;  // used only where s_len > 0
    o[0 * L + g] = s_unit ? s_inv * osx[g] : osx[g];
    o[1 * L + g] = s_unit ? s_inv * osy[g] : osy[g];
    o[2 * L + g] = s_unit ? s_inv * osz[g] : osz[g];
    const bool t_nz = (std::fabs(otx[g]) > FLT_MIN) | (std::fabs(oty[g]) > FLT_MIN) | (std::fabs(otz[g]) > FLT_MIN);
    const float t_len = std::sqrt(otx[g] * otx[g] + oty[g] * oty[g] + otz[g] * otz[g]);
    const bool t_unit = t_nz & (t_len > 0.0f);
    const float t_inv = 1.0f / t_len;  // used only where t_len > 0
    o[3 * L + g] = t_unit ? t_inv * otx[g] : otx[g];
    o[4 * L + g] = t_unit ? t_inv * oty[g] : oty[g];
    o[5 * L + g] = t_unit ? t_inv * otz[g] : otz[g];
    const bool positive = sum[g] > 0.0f;
    o[6 * L + g] = positive ? ms[g] / sum[g] : ms[g];  // divisor checked (selected)
    o[7 * L + g] = positive ? mt[g] / sum[g] : mt[g];
    o[8 * L + g] = near[g];
  }
}

}  // namespace shadetool::normals_detail
