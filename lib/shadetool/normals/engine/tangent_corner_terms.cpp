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
  // The lanes as GCC vectors (8 floats; two halves on the baseline clone): the loop over members
  // is then lane-wise without relying on the vectoriser; selects (?: on a lane mask) skip the
  // members past a lane's count.
  typedef float F8 __attribute__((vector_size(32)));
  typedef float F8u __attribute__((vector_size(32), aligned(4), may_alias));  // a row, unaligned
  typedef int I8 __attribute__((vector_size(32)));
  static_assert(L == 8, "one F8 per row");
#define load(p) F8(*reinterpret_cast<const F8u*>(p))
  I8 members;
  std::memcpy(&members, count, sizeof members);
  const F8 zero = {0, 0, 0, 0, 0, 0, 0, 0}, half = zero + 0.5f;
  F8 osx = zero, osy = zero, osz = zero, otx = zero, oty = zero, otz = zero, ms = zero, mt = zero, sum = zero;
  I8 near = {-1, -1, -1, -1, -1, -1, -1, -1};  // all true
  const F8 s0x = load(terms), s0y = load(terms + B), s0z = load(terms + 2 * B);  // member 0's ps, pt
  const F8 t0x = load(terms + 3 * B), t0y = load(terms + 4 * B), t0z = load(terms + 5 * B);
  for (std::size_t j = 0; j < rows; ++j) {
    const float* c = terms + j * L;
    const F8 psx = load(c), psy = load(c + B), psz = load(c + 2 * B);
    const F8 ptx = load(c + 3 * B), pty = load(c + 4 * B), ptz = load(c + 5 * B), a = load(c + 6 * B);
    const F8 mag_s = load(mags + j * L), mag_t = load(mags + B + j * L);
    const I8 in = int(j) < members;
    osx = in ? osx + a * psx : osx;
    osy = in ? osy + a * psy : osy;
    osz = in ? osz + a * psz : osz;
    otx = in ? otx + a * ptx : otx;
    oty = in ? oty + a * pty : oty;
    otz = in ? otz + a * ptz : otz;
    ms = in ? ms + a * mag_s : ms;
    mt = in ? mt + a * mag_t : mt;
    sum = in ? sum + a : sum;
    if (j > 0) {  // member 0 is within 60 degrees of itself by definition
      const F8 ds = s0x * psx + s0y * psy + s0z * psz, dt = t0x * ptx + t0y * pty + t0z * ptz;
      near = near & ~(in & ~((ds > half) & (dt > half)));
    }
  }
#undef load
  float vosx[L], vosy[L], vosz[L], votx[L], voty[L], votz[L], vms[L], vmt[L], vsum[L];
  int vnear[L];
  std::memcpy(vosx, &osx, sizeof osx), std::memcpy(vosy, &osy, sizeof osy), std::memcpy(vosz, &osz, sizeof osz);
  std::memcpy(votx, &otx, sizeof otx), std::memcpy(voty, &oty, sizeof oty), std::memcpy(votz, &otz, sizeof otz);
  std::memcpy(vms, &ms, sizeof ms), std::memcpy(vmt, &mt, sizeof mt), std::memcpy(vsum, &sum, sizeof sum);
  std::memcpy(vnear, &near, sizeof near);
  for (std::size_t g = 0; g < L; ++g) {
    float* o = out;
    // Unit where not zero (tangents.cpp's normalize: the length's inverse, then products), into
    // rows row..row+2.
    auto unit_where_nonzero = [&](float x, float y, float z, std::size_t row) {
      const bool nz = (std::fabs(x) > FLT_MIN) | (std::fabs(y) > FLT_MIN) | (std::fabs(z) > FLT_MIN);
      const float len = std::sqrt(x * x + y * y + z * z);
      const bool unit = nz & (len > 0.0f);
      const float inv = 1.0f / len;  // used only where len > 0
      o[row * L + g] = unit ? inv * x : x;
      o[(row + 1) * L + g] = unit ? inv * y : y;
      o[(row + 2) * L + g] = unit ? inv * z : z;
    };
    unit_where_nonzero(vosx[g], vosy[g], vosz[g], 0);
    unit_where_nonzero(votx[g], voty[g], votz[g], 3);
    const bool positive = vsum[g] > 0.0f;
    o[6 * L + g] = positive ? vms[g] / vsum[g] : vms[g];  // divisor checked (selected)
    o[7 * L + g] = positive ? vmt[g] / vsum[g] : vmt[g];
    o[8 * L + g] = vnear[g] ? 1.0f : 0.0f;
  }
}

SHADETOOL_TANGENT_CLONES
void tangent_triangle_derivatives(std::size_t n, const float* __restrict in, float* __restrict out) {
  constexpr std::size_t B = kTangentCornerBlock;
  for (std::size_t i = 0; i < n; ++i) {
    const float sx = in[i], sy = in[B + i], sz = in[2 * B + i];
    const float tx = in[3 * B + i], ty = in[4 * B + i], tz = in[5 * B + i], a = in[6 * B + i];
    const bool area = std::fabs(a) > FLT_MIN;
    const float sign = a > 0.0f ? 1.0f : -1.0f;
    const float len_s = std::sqrt(sx * sx + sy * sy + sz * sz), len_t = std::sqrt(tx * tx + ty * ty + tz * tz);
    const bool unit_s = area & (std::fabs(len_s) > FLT_MIN), unit_t = area & (std::fabs(len_t) > FLT_MIN);
    const float rs = sign / (unit_s ? len_s : 1.0f), rt = sign / (unit_t ? len_t : 1.0f);  // divisors checked
    const float abs_area = area ? std::fabs(a) : 1.0f;                                      // divisor checked
    out[i] = unit_s ? rs * sx : 0.0f;
    out[B + i] = unit_s ? rs * sy : 0.0f;
    out[2 * B + i] = unit_s ? rs * sz : 0.0f;
    out[3 * B + i] = unit_t ? rt * tx : 0.0f;
    out[4 * B + i] = unit_t ? rt * ty : 0.0f;
    out[5 * B + i] = unit_t ? rt * tz : 0.0f;
    out[6 * B + i] = area ? len_s / abs_area : 0.0f;
    out[7 * B + i] = area ? len_t / abs_area : 0.0f;
  }
}

}  // namespace shadetool::normals_detail
