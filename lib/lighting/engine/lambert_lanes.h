// engine/lambert_lanes.h: Lambert's formula (area_light.h's lambert_polygon_integral) with four
// edges in the lanes of one vector: the same per-edge arithmetic in the same order, the edges'
// terms then summed one by one in edge order, so the result has the scalar formula's bits
// (tests/lighting/area_light.cpp checks it). Internal: not installed.
//
// Why: per edge the formula is a cross product, a square root and two divisions in a chain
// (bench/lighting/results.md: 35% of a rect light); four edges in one AVX2 vector issue one
// square root and two divisions instead of four of each.
//
// Inputs: a convex spherical polygon (count >= 0, q and d scaled below 2 as polygon_light_terms
// leaves them) in the upper hemisphere of the unit normal n. Output: P (steradians, no 1/pi).
// Precision: double, as the scalar formula. Degenerate edges (|q x d| = 0) add nothing.
#pragma once

#include <shadetool/lighting/area_light.h>

namespace shadetool {
namespace lighting_engine {

double lambert_polygon_integral_lanes(const SphericalPolygon& poly, const Vec3d& n);

}  // namespace lighting_engine
}  // namespace shadetool
