// Tests of geometry/degenerate_faces: the one count of degenerate faces (info's and repair's):
// repeated indices, exactly zero area, NaN corners.
#include <cmath>

#include <catch2/catch.hpp>

#include <shadetool/geometry/degenerate_faces.h>
#include <shadetool/info/mesh_info.h>

using namespace shadetool;

TEST_CASE("degenerate faces: repeated index, collinear corners, NaN corners; a NaN face counts in the total",
          "[degenerate]") {
  Mesh m;
  for (auto p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{2, 0, 0}, Vec3d{0, 1, 0}, Vec3d{NAN, 0, 0}, Vec3d{1e-200, 1e-200, 0}})
    m.add_vertex(p);
  m.add_face({0, 1, 3});        // regular, area 1/2
  m.add_face({0, 1, 1});        // repeated index
  m.add_face({0, 1, 2});        // collinear: area exactly 0
  m.add_face({0, 1, 2, 3, 0});  // pentagon repeating vertex 0
  m.add_face({0, 1, 4});        // NaN corner
  m.add_face({0, 2, 3, 1});     // quad whose Newell area (1 - 0) is non-zero: (0,0,0),(2,0,0),(0,1,0),(1,0,0)
  m.add_face({0, 1, 5});        // tiny but non-zero area: 1e-200 * 1 / 2 is representable
  const DegenerateFaces d = degenerate_faces(m);
  CHECK(d.repeated_index == 2);
  CHECK(d.zero_area == 1);
  CHECK(d.non_finite == 1);
  CHECK(d.too_few_corners == 0);
  // The face with a NaN corner has no area and no winding: it is degenerate, and info and repair
  // count it alike (info's own count used to leave it out of its total: 3 there, 4 in repair).
  CHECK(d.count() == 4);
  CHECK(info::mesh_info(m).degenerate.count() == 4);
}

TEST_CASE("degenerate faces: a long face with a repeated index far apart", "[degenerate]") {
  Mesh m;
  std::vector<std::uint32_t> f;
  for (int i = 0; i < 20; ++i) {
    m.add_vertex({std::cos(i * 0.3), std::sin(i * 0.3), 0});
    f.push_back(std::uint32_t(i));
  }
  m.add_face(f);
  CHECK(degenerate_faces(m).count() == 0);
  f.push_back(3);
  m.add_face(f);
  CHECK(degenerate_faces(m).repeated_index == 1);
}
