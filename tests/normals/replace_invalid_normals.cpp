// Tests of normals/replace_invalid_normals: a normal with no direction is replaced by the one
// computed from the faces; every valid normal is kept bit for bit (issue 27 item 14).
#include <catch2/catch.hpp>

#include <cstring>
#include <limits>

#include <shadetool/normals/replace_invalid_normals.h>

using namespace shadetool;

namespace {

// Two triangles in the plane z = 0 wound to face +z, and a vertex (4) no face uses.
Mesh square() {
  Mesh m;
  for (const Vec3d& p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{1, 1, 0}, Vec3d{0, 1, 0}, Vec3d{5, 5, 5}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  return m;
}

}  // namespace

TEST_CASE("replace_invalid_normals: zero, NaN and Inf vertex normals get the face normal (+z here); valid ones keep "
          "their bits; an isolated vertex the fallback", "[replace_invalid_normals]") {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  Mesh m = square();
  m.vertex_normals = {0, 0, 0,  nan, 0, 1,  0.1, 0.2, 0.9,  0, inf, 0,  0, 0, 0};
  const InvalidNormalsReplaced r = replace_invalid_normals(m);
  CHECK(r.vertex == 4);
  CHECK(r.total() == 4);
  for (std::size_t v : {0u, 1u, 3u}) CHECK(get3(m.vertex_normals, v) == Vec3d{0, 0, 1});  // the plane's normal, exactly
  CHECK(get3(m.vertex_normals, 2) == Vec3d{0.1, 0.2, 0.9});                              // valid, not unit: kept
  CHECK(get3(m.vertex_normals, 4) == Vec3d{kFallbackNormal[0], kFallbackNormal[1], kFallbackNormal[2]});
  CHECK(invalid_normals_note(r) == "4 input normals had no direction (zero, NaN or Inf): replaced by the computed ones (4 vertex)");
}

TEST_CASE("replace_invalid_normals: a zero OBJ vn (assimp's spider.obj) is replaced by its corners' normal; "
          "a face normal by the face's", "[replace_invalid_normals]") {
  Mesh m = square();
  m.corner_normals = {0, 0, 1, 0, 0, 0};
  m.corner_normal_index = {0, 0, 1, 0, 0, 0};
  m.face_normals = {0, 0, 0, 0, 0, 1};
  const std::vector<double> before = m.corner_normals;
  const InvalidNormalsReplaced r = replace_invalid_normals(m);
  CHECK(r.corner == 1);
  CHECK(r.face == 1);
  CHECK(get3(m.corner_normals, 1) == Vec3d{0, 0, 1});
  CHECK(std::memcmp(m.corner_normals.data(), before.data(), 3 * sizeof(double)) == 0);
  CHECK(get3(m.face_normals, 0) == Vec3d{0, 0, 1});
  CHECK(invalid_normals_note(r) == "2 input normals had no direction (zero, NaN or Inf): replaced by the computed ones (1 corner, 1 face)");
}

TEST_CASE("replace_invalid_normals: valid normals, or none, change nothing", "[replace_invalid_normals]") {
  Mesh m = square();
  CHECK(replace_invalid_normals(m).total() == 0);
  CHECK(!m.has_vertex_normals());
  m.vertex_normals = {0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 1, 0, 0};  // against the faces, but a direction
  const std::vector<double> before = m.vertex_normals;
  CHECK(replace_invalid_normals(m).total() == 0);
  CHECK(m.vertex_normals == before);
  CHECK(invalid_normals_note({}).empty());
}
