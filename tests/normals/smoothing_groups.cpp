// OBJ smoothing groups honoured when normals are computed (normals/smoothing_groups.h,
// update_mesh_normals.h): hand-built files whose normals are known without the code.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <shadetool/core/math_constants.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/smoothing_groups.h>
#include <shadetool/normals/update_mesh_normals.h>

using namespace shadetool;

namespace {

// Two unit squares meeting at a right angle along the edge x = 0, z in [0, 1]: the floor (y = 0,
// normal +y) and the wall (x = 0, normal +x), each with the smoothing statement given.
Mesh hinge(const std::string& floor_s, const std::string& wall_s, const std::string& tail = "") {
  const std::string obj = "v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nv 0 1 0\nv 0 1 1\n" + floor_s +
                          "\nf 1 2 3 4\n" + wall_s + "\nf 1 5 6 2\n" + tail;
  return read_mesh_from_memory(obj, Format::Obj, "hinge.obj");
}

Vec3d corner_normal(const Mesh& m, std::size_t c) {
  return m.has_corner_normals() ? get3(m.corner_normals, m.corner_normal_index[c]) : get3(m.vertex_normals, m.corner_vertex[c]);
}

bool near(Vec3d a, Vec3d b) { return std::fabs(a.x - b.x) < 1e-12 && std::fabs(a.y - b.y) < 1e-12 && std::fabs(a.z - b.z) < 1e-12; }

const Vec3d kFloor{0, 1, 0}, kWall{1, 0, 0};
const Vec3d kBisector{std::sqrt(0.5), std::sqrt(0.5), 0};

}  // namespace

TEST_CASE("Smoothing groups: faces in different groups never share a normal", "[smoothing_groups]") {
  Mesh m = hinge("s 1", "s 2");
  const FaceSmoothingGroups g = face_smoothing_groups(m);
  CHECK(g.groups == std::vector<std::uint32_t>{1, 2});
  const NormalsReport r = update_mesh_normals(m, NormalsRequest{});
  CHECK(r.honoured_groups);
  for (std::uint32_t c = 0; c < 4; ++c) CHECK(near(corner_normal(m, c), kFloor));
  for (std::uint32_t c = 4; c < 8; ++c) CHECK(near(corner_normal(m, c), kWall));
}

TEST_CASE("Smoothing groups: one group smooths across the hinge (angle-weighted: the bisector); --crease splits it", "[smoothing_groups]") {
  Mesh m = hinge("s 1", "s 1");
  // Only one group and no flat face: nothing to honour, vertex normals as without groups.
  CHECK_FALSE(face_smoothing_groups(m).matter());
  update_mesh_normals(m, NormalsRequest{});
  CHECK(near(get3(m.vertex_normals, 0), kBisector));  // both faces' corners at vertex 0 are right angles
  // A flat triangle elsewhere makes the groups matter; the hinge, in one group, is smooth ...
  const std::string flat_elsewhere = "v 9 9 9\nv 9 9 10\nv 10 9 9\ns off\nf 7 8 9\n";
  Mesh one = hinge("s 1", "s 1", flat_elsewhere);
  CHECK(update_mesh_normals(one, NormalsRequest{}).honoured_groups);
  for (std::uint32_t c : {0u, 4u}) CHECK(near(corner_normal(one, c), kBisector));
  // ... and --crease 45 splits it at its 90 degree edge.
  Mesh a = hinge("s 1", "s 1", flat_elsewhere);
  NormalsRequest creased;
  creased.kind = NormalKind::Corner;
  creased.crease_angle = 45 * kRadiansPerDegree;
  update_mesh_normals(a, creased);
  for (std::uint32_t c = 0; c < 4; ++c) CHECK(near(corner_normal(a, c), kFloor));  // split at the 90 degree edge
  for (std::uint32_t c = 4; c < 8; ++c) CHECK(near(corner_normal(a, c), kWall));
}

TEST_CASE("Smoothing groups: s off and s 0 faces are flat; faces before the first s too", "[smoothing_groups]") {
  for (const char* off : {"s off", "s 0", ""}) {
    Mesh m = hinge(off, "s 3");
    const NormalsReport r = update_mesh_normals(m, NormalsRequest{});
    CHECK(r.flat_faces == 1);
    CHECK(r.smoothing_groups == 1);
    for (std::uint32_t c = 0; c < 4; ++c) CHECK(near(corner_normal(m, c), kFloor));
    for (std::uint32_t c = 4; c < 8; ++c) CHECK(near(corner_normal(m, c), kWall));
  }
}

TEST_CASE("Smoothing groups: ignore smooths across them, as before", "[smoothing_groups]") {
  Mesh m = hinge("s 1", "s 2");
  NormalsRequest r;
  r.smoothing_groups = SmoothingGroups::Ignore;
  update_mesh_normals(m, r);
  CHECK_FALSE(m.has_corner_normals());
  CHECK(near(get3(m.vertex_normals, 0), kBisector));
}

TEST_CASE("Smoothing groups: a file without s statements has none", "[smoothing_groups]") {
  Mesh m = hinge("g a", "g b");
  CHECK(face_smoothing_groups(m).groups.empty());
}
