// lighting/lighting_power.cpp: lighting_equation.h's lighting_integer_power, x^e in double-double
// (formula, paper, precision and degenerate cases on its declaration). Built twice (target_clones):
// with the FMA instruction where the CPU has it, else calling the C library's fma, which is exact
// too: the same bits on every CPU. This file is compiled with -ffp-contract=off (CMakeLists.txt):
// p = h * h must stay rounded, apart from the error term the FMA recovers.
// engine/shade_point_lanes.cpp computes the same operations in the same order four at a time.
#include <shadetool/lighting/lighting_equation.h>

#include <cmath>
#include <cstdint>

namespace shadetool {

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target_clones("fma", "default")))
#endif
double lighting_integer_power(double x, std::uint32_t e) {
  double h = x, l = 0;  // x^e = h + l, |l| <= ulp(h) / 2
  for (int bit = 30 - __builtin_clz(e); bit >= 0; --bit) {
    double p = h * h;
    double err = std::fma(h, h, -p);  // exact: h * h - fl(h * h)
    err = std::fma(h + h, l, err);    // + 2 h l (l * l, below 2^-106 h^2, dropped)
    double s = p + err;               // fast two-sum, |p| >= |err|
    l = err - (s - p), h = s;
    if ((e >> bit) & 1u) {
      p = h * x;
      err = std::fma(h, x, -p);  // exact: h * x - fl(h * x)
      err = std::fma(l, x, err);
      s = p + err;
      l = err - (s - p), h = s;
    }
  }
  return h;
}

}  // namespace shadetool
