// Tests of io/engine/newell_normal.h: the normal a reader or writer supplies for a face the file
// gives none, by the one degenerate rule of geometry/degenerate_face.h.
#include <catch2/catch.hpp>

#include <cmath>

#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/io/engine/newell_normal.h>

using namespace shadetool;

namespace {

// Triangle (0,0,0), (1,0,0), (1/2, h, 0) turned about the x axis by 30 degrees, so the exact
// normal (0, -sin 30, cos 30) has two non-zero components and the area vector carries rounding.
Mesh sliver(double h) {
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  Mesh m;
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0.5, h * c, h * s});
  m.add_face({0, 1, 2});
  return m;
}

}  // namespace

TEST_CASE("newell_normal: zero exactly for the faces the one rule calls without area", "[io][newell]") {
  // sin of the apex angle ~ 4h: the rule's threshold 64 eps ~ 1.4e-14 lies near h = 3.6e-15.
  int degenerate = 0, regular = 0;
  for (double h = 1e-16; h < 1e-13; h *= 1.1) {
    const Mesh m = sliver(h);
    const Vec3d n = io::newell_normal(m, 0);
    const bool zero = n.x == 0 && n.y == 0 && n.z == 0;
    INFO("h = " << h);
    CHECK(zero == (face_area_kind(m, 0) != DegenerateKind::None));
    CHECK(zero == (face_degenerate_kind(m, 0) != DegenerateKind::None));
    degenerate += zero;
    regular += !zero;
  }
  CHECK(degenerate > 5);  // the range straddles the threshold
  CHECK(regular > 5);
}

TEST_CASE("newell_normal: the unit normal of a regular face, and zero for NaN or too few corners", "[io][newell]") {
  const Mesh m = sliver(0.5);
  const Vec3d n = io::newell_normal(m, 0);
  CHECK(n.x == Approx(0).margin(1e-15));
  CHECK(n.y == Approx(-0.5).margin(1e-15));
  CHECK(n.z == Approx(std::sqrt(3.0) / 2).margin(1e-15));
  Mesh bad;
  bad.add_vertex({0, 0, 0});
  bad.add_vertex({1, 0, 0});
  bad.add_vertex({NAN, 1, 0});
  bad.add_face({0, 1, 2});
  bad.add_face({0, 1});
  for (std::size_t f : {0u, 1u}) {
    const Vec3d z = io::newell_normal(bad, f);
    CHECK((z.x == 0 && z.y == 0 && z.z == 0));
  }
}
