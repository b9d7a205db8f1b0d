// engine/shade_point_lanes.h: shade_point (engine/shade_point.h's loop in world space, identity
// metric, early tests on, no shadows) for four points at a time in the lanes of an AVX2 vector,
// for lighting/shade_point.h's shade_point_block. Internal: not installed.
//
// Every operation is the scalar loop's, in the same order, without fused multiply-adds (this file
// is compiled with -ffp-contract=off), and the skips are masks: so each lane's colour is the
// scalar loop's bit for bit, with one exception, the powers (the specular max(n.H, 0)^shininess
// and the spot's cos^exponent). Where the exponent is an integer e in [1, 2^20] the power is
// integer_power_lanes below; other exponents call std::pow per lane (the scalar loop's bits).
//
// integer_power_lanes: x^e by binary exponentiation in double-double arithmetic (each product's
// rounding error recovered exactly with an FMA, Dekker 1971 / Ogita, Rump and Oishi 2005), rounded
// to double once at the end: relative error of the unrounded value below about 2^-98, so the
// result is x^e correctly rounded unless x^e lies within 2^-98 (relative) of a midpoint between
// two doubles. glibc's pow is within 0.52 ulp: it is not always correctly rounded, so the two can
// differ by one ulp of the power, rarely (tests/lighting/shade_point.cpp measures how often and
// checks that where they differ ours is the nearer to x^e computed in long double). Results below
// 2^-900 (the double-double's low part could be subnormal) and x = 0 go to std::pow.
//
// Lanes the vector path does not take (the scalar loop's rarely taken branches: a zero or
// non-finite normal, a point at the eye or a light or a distance outside [2^-500, 2^500], see
// engine/metric.h) are given to the scalar shade_point, point by point.
//
// Precision: double, as the scalar loop.
#pragma once

#include <cstddef>
#include <cstdint>

#include <shadetool/lighting/shade_point.h>

namespace shadetool {
namespace lighting_engine {

// Whether the vector path exists here: built for x86-64 and the CPU has AVX2 and FMA.
bool point_lanes_available();

// Whether every light of `lighting` is one the vector path handles (directional, point, spot).
bool point_lanes_support(const PointLighting& lighting);

// Points [0, count) of `block` (point_lanes_available() and point_lanes_support(lighting) hold)
// into rgb_out (#count by 3), counted into counters as the scalar loop counts; the lanes the vector
// path does not take are given to shade_point here.
void shade_point_lanes(const PointLighting& lighting, const PointBlock& block, double* rgb_out,
                       ShadeCounters& counters);

// x[i]^exponent for i in [0, count) as described above (point_lanes_available() holds). Exposed
// for the test that checks it against std::pow and long double.
void integer_power_lanes(const double* x, std::size_t count, std::uint32_t exponent, double* out);

}  // namespace lighting_engine
}  // namespace shadetool
