// Tests of the error rate visibility/sample_sequence.h promises: for the open fraction under a disc
// (a visibility integrand, discontinuous along the disc's silhouette) the RMS error over scrambles
// of the shuffled, Owen-scrambled Sobol points falls as N^(-3/4) (He & Wang 2015 for d = 2), not
// as N^(-1/2) like independent samples. Truth: Lambert's polygon form factor, not the code.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/sample_sequence.h>
#include <shadetool/visibility/visibility_scene.h>
#include "visibility_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// The point under the disc, off its axis: seen from the axis the silhouette is a circle about the
// normal, which the concentric map turns into an axis-aligned square (an easier integrand, rate
// N^-1); off the axis it is a general curve.
const Vec3d kPoint{0.45, 0.2, 0};

// RMS error of the open fraction at kPoint over `seeds` scrambles with N samples.
double rms_error(const VisibilityScene& scene, double truth, std::uint32_t n, std::size_t seeds) {
  std::vector<double> points(3 * seeds, 0.0), normals(3 * seeds, 0.0);
  std::vector<std::uint64_t> ids(seeds);
  for (std::size_t i = 0; i < seeds; ++i) {
    points[3 * i] = kPoint.x, points[3 * i + 1] = kPoint.y, points[3 * i + 2] = kPoint.z;
    normals[3 * i + 2] = 1, ids[i] = 1000 + i;
  }
  AmbientOcclusionOptions o;
  o.samples = n;
  const AmbientOcclusion ao = ambient_occlusion_at_points(scene, points, normals, ids, o);
  double sum = 0;
  for (float v : ao.open_fraction) sum += (v - truth) * (v - truth);
  return std::sqrt(sum / double(seeds));
}

}  // namespace

TEST_CASE("Occlusion error under a disc falls as N^-3/4, faster than independent sampling", "[visibility][rate]") {
  Mesh m = plane_grid(8.0, 2, true);
  const auto disc = disc_polygon(1.3, 1.0, 512);
  add_polygon(m, disc);
  const VisibilityScene scene(m);
  const double truth = 1 - polygon_form_factor(kPoint, {0, 0, 1}, disc);
  const std::size_t seeds = 400;
  const std::uint32_t ns[] = {16, 64, 256, 1024, 4096};
  std::vector<double> rms;
  for (const std::uint32_t n : ns) rms.push_back(rms_error(scene, truth, n, seeds));
  // Least-squares slope of log RMS against log N.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < rms.size(); ++i) {
    const double x = std::log(double(ns[i])), y = std::log(rms[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double k = double(rms.size());
  const double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
  for (std::size_t i = 0; i < rms.size(); ++i) {
    const double independent = std::sqrt(truth * (1 - truth) / ns[i]);  // sd of plain Monte Carlo
    INFO("N " << ns[i] << " rms " << rms[i] << " independent " << independent << " slope " << slope);
    // The bound: RMS <= C N^(-3/4) with C the 16-sample constant and 30% slack for the finite
    // number of seeds (400 scrambles: the RMS itself is known to about 7%).
    REQUIRE(rms[i] <= 1.3 * rms[0] * std::pow(double(ns[i]) / ns[0], -0.75));
    if (ns[i] >= 256) REQUIRE(rms[i] < 0.5 * independent);
  }
  INFO("slope " << slope);
  REQUIRE(slope < -0.68);
  REQUIRE(slope > -1.0);  // no faster than the theory allows: the error is real, not zero
}

TEST_CASE("The first 2^m scrambled Sobol points form a (0,m,2)-net for any seed", "[visibility][rate]") {
  // Every elementary interval of area 2^-m (2^a by 2^(m-a) cells) holds exactly one point.
  for (const std::uint32_t seed : {0u, 1u, 77u, 0xdeadbeefu}) {
    for (int mexp = 0; mexp <= 8; ++mexp) {
      const std::uint32_t n = 1u << mexp;
      for (int a = 0; a <= mexp; ++a) {
        std::vector<int> count(n, 0);
        for (std::uint32_t i = 0; i < n; ++i) {
          const visibility::UnitSquarePoint p = visibility::scrambled_sobol_2d(i, visibility::point_seed(seed, 0));
          const std::uint32_t cx = std::uint32_t(p.u * double(1u << a)), cy = std::uint32_t(p.v * double(1u << (mexp - a)));
          ++count[(cx << (mexp - a)) | cy];
        }
        for (int c : count) REQUIRE(c == 1);
      }
    }
  }
}

TEST_CASE("The cosine map covers the hemisphere with density cos/pi", "[visibility][rate]") {
  // Fraction of directions within polar angle t of the axis is sin^2 t (cosine-weighted), checked
  // on 4096 net points against the formula, and every direction is a unit vector with z >= 0.
  const std::uint32_t n = 4096;
  const double angles[] = {0.3, 0.7, 1.0, 1.3};
  for (const double t : angles) {
    std::uint32_t inside = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const visibility::UnitSquarePoint p = visibility::scrambled_sobol_2d(i, 99);
      const Vec3d w = visibility::cosine_hemisphere(p.u, p.v);
      REQUIRE(w.z >= 0);
      REQUIRE(std::fabs(dot(w, w) - 1) < 1e-12);
      inside += w.z > std::cos(t) ? 1 : 0;
    }
    REQUIRE(double(inside) / n == Approx(std::sin(t) * std::sin(t)).margin(2e-3));
  }
}
