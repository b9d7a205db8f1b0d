// tangent_corner_terms.cpp: see tangent_corner_terms.h (what, and why the clones agree bitwise).
#include <shadetool/normals/engine/tangent_corner_terms.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

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
  float* cosine = out + 6 * B;
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
}

}  // namespace shadetool::normals_detail
