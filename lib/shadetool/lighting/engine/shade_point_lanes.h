// engine/shade_point_lanes.h: shade_point (engine/shade_point.h's loop in world space, identity
// metric, early tests on, no shadows) for four points at a time in the lanes of an AVX2 vector,
// for lighting/shade_point.h's shade_point_block. Internal: not installed.
//
// Every operation is the scalar loop's, in the same order, without fused multiply-adds (this file
// is compiled with -ffp-contract=off), and the skips are masks: so each lane's colour is the
// scalar loop's bit for bit, the powers (the specular max(n.H, 0)^shininess and the spot's
// cos^exponent) included: integer_power_lanes below is lighting_equation.h's lighting_power
// (double-double binary exponentiation for an integer exponent in [1, 2^20], correctly rounded;
// its formula, paper and degenerate cases are there) four at a time, with the same operations in
// the same order; other exponents, and results below 2^-900, call std::pow per lane as it does.
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
// for the test that checks it against lighting_power, bit for bit.
void integer_power_lanes(const double* x, std::size_t count, std::uint32_t exponent, double* out);

}  // namespace lighting_engine
}  // namespace shadetool
