// engine/shade_batched.h: shade_points' per-point loop with polygon lights batched
// (engine/area_point.h's batched_polygon_light): per block of kPointLanes points, each point
// brought to world space (the equation's own first steps, engine/shade_point.h, counting
// nothing), then each batched light's terms for the whole block in vector lanes
// (engine/lambert_lanes.h), then each point's equation, which adds them. Other lights, and
// everything else, as the plain loop: the same colours and counters, bit for bit
// (tests/lighting/shade_points.cpp). Internal: not installed.
//
// In a file of its own (shade_batched.cpp, instantiated there for the three metrics and the four
// loop flags): beside the plain loop in shade_points.cpp, the extra instances of the
// always-inlined equation changed GCC's inlining there and slowed point lights
// (bench/lighting/results.md).
#pragma once

#include <cstddef>

#include <shadetool/lighting/engine/shade_point.h>

namespace shadetool {
namespace lighting_engine {

// Points [begin, end) as shade_points.cpp's shade_range: into the space (map_points: positions
// too), then the equation; visibility: ShadeOptions::visibility (kShadows) or null.
template <bool kEarlyTests, bool kShadows, class Metric>
ShadeCounters shade_range_batched(const Metric& g, const ShadingFrame& frame, const EquationSetup& eq, bool map_points,
                                  const double* points, const double* normals, const double* visibility, double* out,
                                  std::size_t begin, std::size_t end);

}  // namespace lighting_engine
}  // namespace shadetool
