// engine/lambert_lanes.h: Lambert's formula (area_light.h's lambert_polygon_integral) in the lanes
// of a vector, two ways, each with the scalar formula's bits (the same per-edge arithmetic in the
// same order, terms summed one by one in edge order; tests/lighting/area_light.cpp checks both):
//
//   lambert_polygon_integral_lanes   four EDGES of one point per vector (polygon_light_terms).
//   polygon_diffuse_lanes            POINTS in lanes: one polygon light's P (and the below_horizon
//                                    and inside flags) at kPointLanes points, clipping included,
//                                    for the per-point loop's batch (engine/shade_point.h).
//
// Why: per edge the formula is a cross product, a square root and two divisions in a chain. Edges
// in lanes issue one square root and two divisions per four edges but stay latency-bound (one
// point's sum waits on its sqrt -> division -> polynomial -> division); points in lanes make the
// edges of one point independent of each other, and the kernel throughput-bound
// (bench/lighting/results.md).
//
// Precision: double, as the scalar formula. Degenerate edges (|q x d| = 0) add nothing.
#pragma once

#include <shadetool/lighting/area_light.h>

namespace shadetool {
namespace lighting_engine {

// Inputs: a convex spherical polygon (count >= 0, q and d scaled below 2 as polygon_light_terms
// leaves them) in the upper hemisphere of the unit normal n. Output: P (steradians, no 1/pi).
double lambert_polygon_integral_lanes(const SphericalPolygon& poly, const Vec3d& n);

// Points per call of polygon_diffuse_lanes: two AVX-512 vectors of doubles (four AVX2 ones), so
// that two independent chains (sqrt -> division -> polynomial -> division) are in flight per
// edge; 8 and 32 measured slower (bench/lighting/results.md).
constexpr int kPointLanes = 16;

// kPointLanes points in world space, as structure of arrays: p, and n unit (a zero n is allowed;
// its lane's result is meaningless and the caller does not read it).
struct PointLanes {
  double px[kPointLanes], py[kPointLanes], pz[kPointLanes];
  double nx[kPointLanes], ny[kPointLanes], nz[kPointLanes];
};

// Per lane: what polygon_light_terms gives with a lobe of kind None (P, below_horizon, inside),
// bit for bit; `scalar` marks the lanes not computed here, which the caller must give to
// polygon_light_terms: a scaling exponent outside double's normal range (scalbn there), a non-
// finite direction, or a horizon crossing that is not one exit and one entry (rounding on a
// light almost in p's tangent plane).
struct PolygonLaneTerms {
  double P[kPointLanes];
  bool below_horizon[kPointLanes], inside[kPointLanes], scalar[kPointLanes];
};

// A convex polygon light (vertices in world space, count in [3, kMaxAreaVertices], emit_normal
// unit) at the points' lanes. The steps of polygon_light_terms and clip_to_hemisphere, per lane:
// the side of the light's plane, the directions q_i = v_i - p and edges d_i scaled by one power of
// two, the horizon test n.q_i >= 0, and Lambert's sum over the clipped polygon written as the
// original edges (an edge leaving the hemisphere cut at t = a/(a - b), one entering cut at the
// same t from the other end, an edge wholly below adds 0) plus the one edge along the horizon
// added right after the edge that leaves: the clipped polygon's edges in its own order.
void polygon_diffuse_lanes(const Vec3d* vertices, int count, const Vec3d& emit_normal, bool two_sided,
                           const PointLanes& points, PolygonLaneTerms& out);

}  // namespace lighting_engine
}  // namespace shadetool
