// math_constants.h: π and its power-of-two multiples, once for the whole library.
//
// Each is the double nearest the real number (π/2, π/4 and 2π are π scaled by powers of two,
// so exact multiples of kPi). kRadiansPerDegree = π/180 rounded once; degrees are converted at
// the command line and in scene files only (radians inside).
#pragma once

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

constexpr double kPi = 3.14159265358979323846264338327950288;
constexpr double kTwoPi = 2 * kPi;
constexpr double kHalfPi = kPi / 2;
constexpr double kQuarterPi = kPi / 4;
constexpr double kRadiansPerDegree = kPi / 180;

}  // namespace shadetool
#pragma GCC visibility pop
