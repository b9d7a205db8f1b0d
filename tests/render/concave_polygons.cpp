// Concave polygons of 5+ corners and concave quads are drawn inside their outline, as the glTF and
// STL writers write them (geometry/polygon_triangles.h), not as the fan from corner 0 (a quad: its
// 0-2 diagonal), which covers area outside a concave outline and turns triangles over (culled:
// holes inside it).
// Truth the renderer did not produce: each polygon's area by the shoelace formula and, per pixel
// centre, a crossing-number point-in-polygon test, both computed here.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/lighting/bake_lighting.h>
#include "geometry/polygon_outlines.h"
#include "render_test_util.h"

using namespace shadetool;
using namespace shadetool::render_testing;
using namespace shadetool_test;

namespace {


// Distance from (x, y) to the outline's nearest edge.
double outline_distance(const Outline& p, double x, double y) {
  double best = 1e300;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto &a = p[k], &b = p[(k + 1) % p.size()];
    const double ex = b[0] - a[0], ey = b[1] - a[1], len2 = ex * ex + ey * ey;
    double t = len2 > 0 ? ((x - a[0]) * ex + (y - a[1]) * ey) / len2 : 0.0;  // divisor checked
    t = std::min(1.0, std::max(0.0, t));
    best = std::min(best, std::hypot(x - a[0] - t * ex, y - a[1] - t * ey));
  }
  return best;
}

struct Drawn {
  std::size_t covered = 0;          // pixels drawn
  std::size_t wrong_far = 0;        // pixels > 1 px from the outline drawn iff outside (or not drawn inside)
  std::size_t lit_outside = 0;      // pixels outside the outline whose colour is not the background
  std::size_t lit_outside_far = 0;  // of those, more than 1 px from the outline
  std::size_t edge = 0;             // pixels within 1 px of the outline (where coverage may go either way)
  std::size_t exact_mismatch = 0;   // pixels whose coverage differs from the crossing test (any distance)
};

// The outline as one face z = 0, counter-clockwise seen from the camera (+z), flat-shaded and lit
// on a black background, back faces culled, one sample per pixel at its centre.
Drawn draw(const Outline& p, int side) {
  Mesh m;
  std::vector<std::uint32_t> face;
  for (const auto& q : p) {
    face.push_back(std::uint32_t(m.num_vertices()));
    m.add_vertex({q[0], q[1], 0});
  }
  m.add_face(face);
  Scene s = pixel_exact_scene(side);
  RenderOptions o;
  o.width = o.height = side;
  o.count_coverage = true;
  o.shading = RenderShading::Flat;
  const RenderResult r = render_mesh(m, s, o);
  Drawn d;
  for (int row = 0; row < side; ++row)
    for (int col = 0; col < side; ++col) {
      const double x = col + 0.5, y = side - row - 0.5;
      const std::uint32_t c = r.coverage[std::size_t(row) * side + col];
      const bool in = crossing_inside(p, x, y);
      const float* rgb = r.image.pixel(col, row);
      d.covered += c;
      d.exact_mismatch += (c == 1) != in;
      const bool near = outline_distance(p, x, y) <= 1.0;
      if (!in && (rgb[0] != 0 || rgb[1] != 0 || rgb[2] != 0)) {
        ++d.lit_outside;
        d.lit_outside_far += !near;
      }
      if (near) ++d.edge;
      else d.wrong_far += (c != (in ? 1u : 0u));
    }
  return d;
}

}  // namespace

TEST_CASE("render: a concave polygon covers its outline's area once and nothing outside it", "[render][polygon_triangles]") {
  // Axis-aligned outlines with integer corners: no pixel centre (x.5) lies on an edge, so the
  // coverage must be the crossing test pixel for pixel and its count the shoelace area exactly.
  SECTION("an L hexagon starting where the fan turns a triangle over and crosses the notch") {
    Outline L;  // 3 squares of 16 px: (1,1) to (2,2) is the notch, corner 0 at (2,1)
    for (const auto& q : l_hexagon()) L.push_back({8 + 16 * q[0], 8 + 16 * q[1]});
    REQUIRE(shoelace_area(L) == 768.0);
    const Drawn d = draw(L, 48);
    CHECK(d.covered == 768);
    CHECK(d.exact_mismatch == 0);
    CHECK(d.lit_outside == 0);
  }
  SECTION("a comb of three teeth, corner 0 at a reflex corner") {
    Outline teeth;  // base 0..5 x 0..1, teeth at x in [0,1], [2,3], [4,5] up to y = 2; area 8 squares of 8 px
    for (const auto& q : comb()) teeth.push_back({4 + 8 * q[0], 4 + 8 * q[1]});
    REQUIRE(shoelace_area(teeth) == 512.0);
    const Drawn d = draw(teeth, 48);
    CHECK(d.covered == 512);
    CHECK(d.exact_mismatch == 0);
    CHECK(d.lit_outside == 0);
  }
  SECTION("a concave quad (a dart) from each of its corners: through its reflex corner, not on 0-2") {
    // Dart (4,4) (44,24) (4,44) (17,24), reflex at (17,24). Its slanted edges have slopes +-1/2 and
    // +-20/13, so no pixel centre (x.5, y.5) lies on one: the coverage must be the crossing test
    // pixel for pixel. On 0-2 with the reflex corner at 1 or 3, the triangle (0,1,2) covers the
    // notch (lit outside) and (0,2,3) is turned over.
    const Outline dart{{4, 4}, {44, 24}, {4, 44}, {17, 24}};
    const double area = shoelace_area(dart);  // (4*24 - 44*4) + (44*44 - 4*24) + (4*24 - 17*44) + (17*4 - 4*24) over 2 = 540
    REQUIRE(area == 540.0);
    for (std::size_t r = 0; r < 4; ++r) {
      Outline q;
      for (std::size_t k = 0; k < 4; ++k) q.push_back(dart[(r + k) % 4]);  // reflex corner at 3, 2, 1, 0
      const Drawn d = draw(q, 48);
      INFO("reflex corner at " << (3 + 4 - r) % 4);
      CHECK(d.exact_mismatch == 0);
      CHECK(d.lit_outside == 0);
      CHECK(std::fabs(double(d.covered) - area) <= double(d.edge));
    }
  }
  SECTION("a five-pointed star starting at an inner corner (slanted edges: exact away from them)") {
    Outline star;
    for (int k = 1; k <= 10; ++k) {
      const double r = k % 2 ? 8.0 : 22.0, a = kPi / 2 + k * kPi / 5;
      star.push_back({24.3 + r * std::cos(a), 23.7 + r * std::sin(a)});
    }
    const double area = shoelace_area(star);  // 5 * 22 * 8 * sin 36 deg
    REQUIRE(area == Approx(5 * 22.0 * 8.0 * std::sin(kPi / 5)));
    const Drawn d = draw(star, 48);
    CHECK(d.wrong_far == 0);
    CHECK(d.lit_outside_far == 0);
    CHECK(std::fabs(double(d.covered) - area) <= double(d.edge));
    CHECK(double(d.covered) > 0.9 * area);
  }
}

TEST_CASE("render: a concave quad is shaded linearly on each triangle through its reflex corner (Gouraud)", "[render][polygon_triangles]") {
  // The dart of the coverage test with a different normal at each corner, Gouraud-shaded,
  // orthographic (screen-affine = affine on the face): every covered pixel's colour must be the
  // linear interpolation of the corners' baked colours over the triangle (k, k+1, k+2) or
  // (k, k+2, k+3) through the reflex corner k that holds the pixel centre, the barycentric
  // coordinates computed here. The bilinear map of corners 0..3 (which folds on a dart) blends the
  // four colours otherwise.
  const Outline dart{{4, 4}, {44, 24}, {4, 44}, {17, 24}};
  const double normals[4][3] = {{0.3, 0, 1}, {-0.2, 0.4, 1}, {0, -0.5, 1}, {0.6, 0.5, 1}};
  for (std::size_t r = 0; r < 4; ++r) {
    Mesh m;
    Outline q;
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t c = (r + k) % 4;
      q.push_back(dart[c]);
      m.add_vertex({dart[c][0], dart[c][1], 0});
      const double* n = normals[c];
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);  // > 1 (n.z = 1)
      m.vertex_normals.insert(m.vertex_normals.end(), {n[0] / len, n[1] / len, n[2] / len});
    }
    m.add_face({0, 1, 2, 3});
    const std::size_t reflex = (3 + 4 - r) % 4;
    const Scene s = pixel_exact_scene(48);
    RenderOptions o;
    o.width = o.height = 48;
    o.count_coverage = true;
    o.shading = RenderShading::Gouraud;
    o.clamp_vertex_colors = false;
    const RenderResult img = render_mesh(m, s, o);
    const std::vector<double> baked = bake_lighting(m, s, ShadingFrequency::PerVertex).rgb;
    std::size_t checked = 0, wrong = 0;
    for (int row = 0; row < 48; ++row)
      for (int col = 0; col < 48; ++col) {
        if (img.coverage[std::size_t(row) * 48 + col] == 0) continue;
        const double x = col + 0.5, y = 48 - row - 0.5;
        for (std::size_t t = 0; t < 2; ++t) {
          const std::size_t v[3] = {reflex, (reflex + 1 + t) % 4, (reflex + 2 + t) % 4};
          const auto &a = q[v[0]], &b = q[v[1]], &c = q[v[2]];
          const double d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);  // > 0: the dart's triangles turn left
          const double l1 = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / d;  // divisor: d != 0 (a triangle of the dart)
          const double l2 = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / d;
          const double l0 = 1 - l1 - l2;
          if (l0 < 0 || l1 < 0 || l2 < 0) continue;  // not in this triangle
          ++checked;
          const float* px = img.image.pixel(col, row);
          for (int ch = 0; ch < 3; ++ch) {
            const double want = l0 * baked[3 * v[0] + ch] + l1 * baked[3 * v[1] + ch] + l2 * baked[3 * v[2] + ch];
            wrong += !(std::fabs(px[ch] - want) <= 1e-5);
          }
          break;
        }
      }
    INFO("reflex corner at " << reflex);
    CHECK(checked > 500);  // every covered pixel lies in one of the two triangles (540 in all)
    CHECK(wrong == 0);
  }
}
