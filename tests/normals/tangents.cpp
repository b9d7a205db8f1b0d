// MikkTSpace tangents (normals/tangents.h) against closed forms and against the reference
// implementation (npm `mikktspace`, installed into the build tree on first use; skipped loudly when
// node or the registry is missing).
#include <catch2/catch.hpp>

#include <array>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <shadetool/core/error.h>
#include <shadetool/core/math_constants.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/tangents.h>
#include <shadetool/normals/update_mesh_normals.h>
#include "geometry/polygon_outlines.h"
#include "support/analytic_meshes.h"
#include "support/mesh_file_list.h"
#include "support/mikktspace_reference.h"
#include "support/run_process.h"

using namespace shadetool;

namespace {

// A flat grid in z = 0 with texture coordinates u = a x + b y, v = c x + d y (an affine map):
// dP/du, the exact tangent, is the first column of the inverse of [[a b] [c d]], and w is the
// sign of its determinant.
Mesh affine_grid(double a, double b, double c, double d, int n, bool quads) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      m.add_vertex({x, y, 0});
      m.texcoords.insert(m.texcoords.end(), {a * x + b * y, c * x + d * y});
    }
  auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (quads) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      else {
        m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
        m.add_face({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
      }
    }
  m.corner_texcoord_index = m.corner_vertex;
  m.vertex_normals.clear();
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.vertex_normals.insert(m.vertex_normals.end(), {0, 0, 1});
  return m;
}

// A torus (radii 1 and 0.35) as an n by n grid of triangles with its exact unit normals as vertex
// normals and texture coordinates split along the seams (support/analytic_meshes.h, the mesh
// bench/normals/bench_tangents.cpp times): positions, normals and texture coordinates shared
// between corners by index.
Mesh textured_torus(int n) {
  shadetool::testing::AnalyticMesh am = shadetool::testing::textured_torus(n);
  for (const Vec3d& e : am.exact_normals) am.mesh.vertex_normals.insert(am.mesh.vertex_normals.end(), {e.x, e.y, e.z});
  return std::move(am.mesh);
}

// The same mesh with nothing shared: every corner its own position, vertex normal and texture
// coordinate (copies of its values).
Mesh per_corner_copies(const Mesh& m) {
  Mesh c = m;
  c.positions.clear();
  c.vertex_normals.clear();
  c.texcoords.clear();
  for (std::size_t k = 0; k < m.num_corners(); ++k) {
    const std::uint32_t v = m.corner_vertex[k], t = m.corner_texcoord_index[k];
    c.add_vertex(m.position(v));
    c.vertex_normals.insert(c.vertex_normals.end(), m.vertex_normals.begin() + 3 * v, m.vertex_normals.begin() + 3 * v + 3);
    c.texcoords.insert(c.texcoords.end(), m.texcoords.begin() + 2 * t, m.texcoords.begin() + 2 * t + 2);
    c.corner_vertex[k] = c.corner_texcoord_index[k] = std::uint32_t(k);
  }
  return c;
}

// The reference's zero frame (tangents.h, zero_corners): every component within FLT_MIN of 0.
bool zero_frame(const float* e) { return std::fabs(e[0]) <= FLT_MIN && std::fabs(e[1]) <= FLT_MIN && std::fabs(e[2]) <= FLT_MIN; }

double angle_deg(const double* t, Vec3d e) {
  const Vec3d a{t[0], t[1], t[2]};
  const Vec3d x = cross(a, e);
  return std::atan2(std::sqrt(dot(x, x)), dot(a, e)) * 180.0 / kPi;
}

}  // namespace

TEST_CASE("MikkTSpace: an affine texture map on a plane gives dP/du exactly, w the sign of the map", "[tangents]") {
  struct Map { double a, b, c, d; };
  for (const Map mp : {Map{1, 0, 0, 1}, Map{2, 0.5, -0.25, 1}, Map{-1, 0, 0, 1}, Map{0.3, 1, 1, 0}}) {
    const double det = mp.a * mp.d - mp.b * mp.c;
    const Vec3d dpdu = normalized_or(Vec3d{mp.d / det, -mp.c / det, 0}, Vec3d{});  // first column of the inverse
    for (bool quads : {false, true}) {
      const Mesh m = affine_grid(mp.a, mp.b, mp.c, mp.d, 4, quads);
      const TangentFrames t = mikktspace_tangents(m);
      REQUIRE(t.tangents.size() == 4 * m.num_corners());
      CHECK(t.fallback_corners == 0);
      CHECK(t.default_corners == 0);
      for (std::size_t c = 0; c < m.num_corners(); ++c) {
        CHECK(angle_deg(&t.tangents[4 * c], dpdu) < 1e-4);
        CHECK(t.tangents[4 * c + 3] == (det > 0 ? 1.0 : -1.0));
      }
    }
  }
}

TEST_CASE("MikkTSpace: a concave polygon of 5+ corners under an affine map gives dP/du and w = +1 at every corner",
          "[tangents][polygon_triangles]") {
  // Truth: u = x, v = y on the plane z = 0, normal +z: the tangent is (1, 0, 0) and the map keeps
  // orientation (w = +1) at every corner. An L hexagon (corner 0 at (2,1), notch (1,1)-(2,2)) and
  // a comb: the fan from corner 0 turns a triangle over (negative texture area), which flips the
  // handedness of the corners it alone holds.
  const std::vector<shadetool_test::Outline> outlines{shadetool_test::l_hexagon(), shadetool_test::comb()};
  for (const auto& p : outlines) {
    Mesh m;
    std::vector<std::uint32_t> face;
    for (const auto& q : p) {
      face.push_back(m.add_vertex({q[0], q[1], 0}));
      m.texcoords.insert(m.texcoords.end(), {q[0], q[1]});
      m.vertex_normals.insert(m.vertex_normals.end(), {0, 0, 1});
    }
    m.add_face(face);
    m.corner_texcoord_index = m.corner_vertex;
    const TangentFrames t = mikktspace_tangents(m);
    REQUIRE(t.tangents.size() == 4 * m.num_corners());
    std::size_t wrong = 0;
    for (std::size_t c = 0; c < m.num_corners(); ++c)
      wrong += !(angle_deg(&t.tangents[4 * c], {1, 0, 0}) < 1e-4) || t.tangents[4 * c + 3] != 1.0;
    CHECK(wrong == 0);
  }
}

TEST_CASE("MikkTSpace: a mirrored texture seam keeps each side's handedness", "[tangents]") {
  // Two triangles sharing an edge, the right one's u mirrored (u = 2 - x): separate frames, w -1 there.
  Mesh m;
  for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{1, 1, 0}, Vec3d{0, 1, 0}, Vec3d{2, 0, 0}, Vec3d{2, 1, 0}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.add_face({1, 4, 5});
  m.add_face({1, 5, 2});
  m.texcoords = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 1};  // vertex 4 -> u 0, vertex 5 -> u 0 (mirror)
  m.corner_texcoord_index = m.corner_vertex;
  m.vertex_normals.assign(3 * 6, 0);
  for (int v = 0; v < 6; ++v) m.vertex_normals[3 * v + 2] = 1;
  const TangentFrames t = mikktspace_tangents(m);
  for (std::size_t c = 0; c < 6; ++c) {
    CHECK(t.tangents[4 * c + 3] == 1.0);
    CHECK(angle_deg(&t.tangents[4 * c], {1, 0, 0}) < 1e-4);
  }
  for (std::size_t c = 6; c < 12; ++c) {
    CHECK(t.tangents[4 * c + 3] == -1.0);
    CHECK(angle_deg(&t.tangents[4 * c], {-1, 0, 0}) < 1e-4);
  }
}

// tangents.h, step 2: corners weld by their values (float ==: -0 equals +0, a value with a NaN
// equals nothing), the mesh's indices play no part; so sharing values by index or copying them
// per corner cannot change a bit. With a NaN shared by index (a position, a normal, a texture
// coordinate), its corners must stay apart as their copies do: welding them would join the groups
// around their neighbours.
TEST_CASE("MikkTSpace welds by value, not by index: shared and per-corner copies give the same bits, NaN included", "[tangents]") {
  for (bool with_nan : {false, true}) {
    Mesh shared = textured_torus(12);
    if (with_nan) {
      shared.positions[3 * 17 + 1] = std::nan("");
      shared.vertex_normals[3 * 60 + 2] = std::nan("");
      shared.texcoords[2 * 100] = std::nan("");
    }
    shared.positions[3 * 30] = -0.0;  // -0 and +0 are one value
    const Mesh copied = per_corner_copies(shared);
    const TangentFrames a = mikktspace_tangents(shared), b = mikktspace_tangents(copied);
    INFO("NaN values: " << with_nan);
    REQUIRE(a.tangents.size() == 4 * shared.num_corners());
    REQUIRE(b.tangents.size() == a.tangents.size());
    CHECK(std::memcmp(a.tangents.data(), b.tangents.data(), 8 * a.tangents.size()) == 0);
    CHECK(a.default_corners == b.default_corners);
    CHECK(a.fallback_corners == b.fallback_corners);
  }
}

// tangents.h, zero_corners: where the reference's frame is the zero vector, a unit tangent
// perpendicular to the normal with the reference's w. The case in closed form: one triangle in
// z = 0 with u = x, v = y (dP/du = +x, positive texture area: w = +1) and every vertex normal along
// +x, so dP/du projected onto the normal's plane is exactly zero (testplate.glb from trimesh's
// models has two such corners; a zero TANGENT fails the Khronos validator).
TEST_CASE("MikkTSpace: a frame the reference leaves zero becomes a unit tangent perpendicular to the normal", "[tangents]") {
  Mesh m;
  for (Vec3d p : {Vec3d{0, 0, 0}, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}}) m.add_vertex(p);
  m.add_face({0, 1, 2});
  m.texcoords = {0, 0, 1, 0, 0, 1};
  m.texcoord_dims = 2;
  m.corner_texcoord_index = m.corner_vertex;
  m.vertex_normals = {1, 0, 0, 1, 0, 0, 1, 0, 0};
  const TangentFrames t = mikktspace_tangents(m);
  CHECK(t.zero_corners == 3);
  CHECK(t.fallback_corners == 0);
  for (std::size_t c = 0; c < 3; ++c) {
    const Vec3d x{t.tangents[4 * c], t.tangents[4 * c + 1], t.tangents[4 * c + 2]};
    CHECK(std::fabs(x.x) < 1e-12);                   // perpendicular to the normal (+x)
    CHECK(std::fabs(dot(x, x) - 1) < 1e-12);          // unit
    CHECK(t.tangents[4 * c + 3] == 1.0);              // the reference's handedness
  }
  // A normal tilted off +x by a little: the projection is small but not zero, so the reference's
  // frame (its normalised projection) stands and nothing is counted.
  m.vertex_normals = {1, 0, 1e-3, 1, 0, 1e-3, 1, 0, 1e-3};
  const TangentFrames u = mikktspace_tangents(m);
  CHECK(u.zero_corners == 0);
}

TEST_CASE("MikkTSpace: faces without texture coordinates get a tangent perpendicular to the normal", "[tangents]") {
  Mesh m = affine_grid(1, 0, 0, 1, 1, false);
  m.corner_texcoord_index[4] = kNoTexcoord;  // second triangle
  const Vec3d n = normalized_or(Vec3d{1, 2, 3}, Vec3d{});
  for (int v = 0; v < 4; ++v) set3(m.vertex_normals, v, n);
  const TangentFrames t = mikktspace_tangents(m);
  CHECK(t.fallback_corners == 3);
  for (std::size_t c = 3; c < 6; ++c) {
    const Vec3d x{t.tangents[4 * c], t.tangents[4 * c + 1], t.tangents[4 * c + 2]};
    CHECK(std::fabs(dot(x, n)) < 1e-12);
    CHECK(std::fabs(dot(x, x) - 1) < 1e-12);
  }
  Mesh bare = m;
  bare.corner_texcoord_index.clear();
  CHECK_THROWS_AS(mikktspace_tangents(bare), shadetool::Error);
}

// Step 1 has two paths: when every face is a taken triangle the weld writes the triangles' welded
// vertices itself; otherwise make_triangles collects them. A face without texture coordinates is no
// part of the reference's input, so adding one (which sends the mesh down the other path) must
// leave every other corner's frame bit for bit as it was.
TEST_CASE("MikkTSpace: a face it does not take changes no other corner's frame (both triangle paths)", "[tangents]") {
  for (bool with_nan : {false, true}) {
    Mesh all_taken = textured_torus(10);
    if (with_nan) {
      all_taken.positions[3 * 17 + 1] = std::nan("");
      all_taken.texcoords[2 * 40] = std::nan("");
    }
    all_taken.positions[3 * 8 + 2] = 0.0;  // a flattened vertex: degenerate and thin triangles nearby
    all_taken.positions[3 * 9] = all_taken.positions[3 * 10];  // and two vertices at one place
    all_taken.positions[3 * 9 + 1] = all_taken.positions[3 * 10 + 1];
    all_taken.positions[3 * 9 + 2] = all_taken.positions[3 * 10 + 2];
    Mesh one_untaken = all_taken;
    one_untaken.add_face({0, 1, 2});
    for (int k = 0; k < 3; ++k) one_untaken.corner_texcoord_index.push_back(kNoTexcoord);
    const TangentFrames a = mikktspace_tangents(all_taken), b = mikktspace_tangents(one_untaken);
    INFO("NaN values: " << with_nan);
    REQUIRE(a.tangents.size() == 4 * all_taken.num_corners());
    REQUIRE(b.tangents.size() == a.tangents.size() + 12);
    CHECK(std::memcmp(a.tangents.data(), b.tangents.data(), 8 * a.tangents.size()) == 0);
    CHECK(a.default_corners == b.default_corners);
    CHECK(b.fallback_corners == a.fallback_corners + 3);
  }
}

namespace {

// Every triangle with all corners textured, as the reference's unindexed input; the same floats
// mikktspace_tangents rounds its input to.
struct Unindexed {
  std::vector<float> data;             // 8 per corner
  std::vector<std::uint32_t> corner;   // the mesh corner of each
};

Unindexed unindexed(const Mesh& m) {
  Unindexed u;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    bool ok = true;
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) ok = ok && m.corner_texcoord_index[c] != kNoTexcoord;
    if (!ok) continue;
    for (std::uint32_t c = m.face_start[f]; c < m.face_start[f + 1]; ++c) {
      const Vec3d p = m.position(m.corner_vertex[c]);
      const Vec3d n = m.has_corner_normals() ? get3(m.corner_normals, m.corner_normal_index[c]) : get3(m.vertex_normals, m.corner_vertex[c]);
      const std::size_t t = std::size_t(m.corner_texcoord_index[c]) * m.texcoord_dims;
      for (double x : {p.x, p.y, p.z, n.x, n.y, n.z, m.texcoords[t], m.texcoords[t + 1]}) u.data.push_back(float(x));
      u.corner.push_back(c);
    }
  }
  return u;
}

// Polygons as fans (the reference takes triangles only); everything else kept.
Mesh fan_triangles(const Mesh& m) {
  Mesh t = m;
  t.face_start = {0};
  t.corner_vertex.clear();
  t.corner_texcoord_index.clear();
  t.corner_normal_index.clear();
  t.face_normals.clear();
  t.face_colors.clear();
  t.face_quality.clear();
  t.face_properties.clear();
  t.face_group_run.clear();
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    const std::uint32_t b = m.face_start[f];
    for (std::uint32_t k = 1; k + 1 < m.face_size(f); ++k)
      for (std::uint32_t c : {b, b + k, b + k + 1}) {
        t.corner_vertex.push_back(m.corner_vertex[c]);
        t.corner_texcoord_index.push_back(m.corner_texcoord_index[c]);
        if (m.has_corner_normals()) t.corner_normal_index.push_back(m.corner_normal_index[c]);
        if (t.corner_vertex.size() % 3 == 0) t.face_start.push_back(std::uint32_t(t.corner_vertex.size()));
      }
  }
  return t;
}

std::vector<std::string> textured_meshes() {
  return shadetool::testing::data_and_corpus_mesh_files({".obj", ".ply", ".glb", ".gltf", ".off"});
}

}  // namespace

// Every textured mesh in data/ and the corpus: the same w at every corner, directions within 1e-3 degrees.
TEST_CASE("MikkTSpace equals the reference (npm mikktspace) on real files", "[tangents][reference]") {
  const std::string ref = shadetool_test::mikktspace_reference_dir();
  if (ref.empty()) {
    WARN("SKIPPED: the MikkTSpace reference (node + npm install mikktspace failed: no node or no registry)");
    return;
  }
  std::size_t meshes = 0, corners = 0;
  double overall_worst = 0;
  for (const std::string& path : textured_meshes()) {
    Mesh m;
    try {
      m = read_mesh(path);
    } catch (const shadetool::Error&) {
      continue;  // files the readers refuse are other tests' business
    }
    if (!m.has_texcoords() || m.texcoord_dims < 2) continue;
    if (!m.has_vertex_normals() && !m.has_corner_normals()) {
      NormalsRequest r;
      update_mesh_normals(m, r);
    }
    m = fan_triangles(m);
    const Unindexed u = unindexed(m);
    if (u.corner.empty()) continue;
    std::string error;
    const std::vector<float> expected = shadetool_test::mikktspace_reference(u.data, "tangents_ref", error);
    INFO(path << ": " << error);
    REQUIRE(expected.size() == 4 * u.corner.size());
    const TangentFrames t = mikktspace_tangents(m);
    std::size_t w_differs = 0, direction_differs = 0, zero_frames = 0;
    double worst = 0;
    for (std::size_t i = 0; i < u.corner.size(); ++i) {
      const double* ours = &t.tangents[4 * std::size_t(u.corner[i])];
      if (ours[3] != double(expected[4 * i + 3])) ++w_differs;
      if (zero_frame(&expected[4 * i])) {  // tangents.h, zero_corners: unit instead of zero
        ++zero_frames;
        if (!(std::fabs(ours[0] * ours[0] + ours[1] * ours[1] + ours[2] * ours[2] - 1) < 1e-9)) ++direction_differs;
        continue;
      }
      const double a = angle_deg(ours, {expected[4 * i], expected[4 * i + 1], expected[4 * i + 2]});
      worst = std::max(worst, a);
      if (!(a <= 1e-3)) ++direction_differs;
    }
    INFO(path << ": " << u.corner.size() << " corners, worst direction " << worst << " degrees");
    CHECK(w_differs == 0);
    CHECK(direction_differs == 0);
    CHECK(t.zero_corners == zero_frames);
    ++meshes;
    corners += u.corner.size();
    overall_worst = std::max(overall_worst, worst);
  }
  WARN("MikkTSpace reference: " << meshes << " textured meshes, " << corners << " corners, worst direction "
                                << overall_worst << " degrees");
  CHECK(meshes >= 1);
}

namespace {

// Triangles over few vertices, each vertex with its own texture coordinate (continuous values: no
// zero texture area, so no triangle groups with any) and angle-free unit normals: edges shared by
// 1 to 5 triangles in either direction, vertices where separate fans meet, mirrored triangles
// beside unmirrored ones. Seeded: the same soups every run.
Mesh vertex_uv_soup(unsigned seed) {
  std::srand(seed);
  auto uniform = [] { return double(std::rand()) / RAND_MAX * 2 - 1; };
  Mesh m;
  const int V = 4 + std::rand() % 8, T = 2 + std::rand() % 24;
  for (int v = 0; v < V; ++v) {
    m.add_vertex({uniform(), uniform(), uniform()});
    const Vec3d n = normalized_or(Vec3d{uniform(), uniform(), 2.0}, Vec3d{0, 0, 1});
    m.vertex_normals.insert(m.vertex_normals.end(), {n.x, n.y, n.z});
    m.texcoords.insert(m.texcoords.end(), {uniform(), uniform()});
  }
  for (int t = 0; t < T; ++t) {
    std::uint32_t a = std::rand() % V, b = std::rand() % V, c = std::rand() % V;
    if (a == b || b == c || a == c) continue;
    for (std::uint32_t x : {a, b, c}) m.corner_vertex.push_back(x), m.corner_texcoord_index.push_back(x);
    m.face_start.push_back(std::uint32_t(m.corner_vertex.size()));
  }
  return m;
}

}  // namespace

namespace {

// Our tangents on `meshes` against the reference's, in one reference run (each mesh moved 10 units
// further along x than the one before: nothing welds across meshes): the same w at every corner,
// directions within 1e-3 degrees. Skips loudly without the reference.
void check_against_reference(std::vector<Mesh> meshes, const std::string& name) {
  const std::string ref = shadetool_test::mikktspace_reference_dir();
  if (ref.empty()) {
    WARN("SKIPPED: the MikkTSpace reference (node + npm install mikktspace failed: no node or no registry)");
    return;
  }
  std::vector<float> data;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    Mesh& m = meshes[i];
    for (std::size_t v = 0; v < m.num_vertices(); ++v) m.positions[3 * v] += 10.0 * double(i + 1);
    const Unindexed u = unindexed(m);
    REQUIRE(u.corner.size() == m.num_corners());  // every corner textured, triangles only
    data.insert(data.end(), u.data.begin(), u.data.end());
  }
  std::string error;
  const std::vector<float> expected = shadetool_test::mikktspace_reference(data, name + "_ref", error);
  INFO(error);
  REQUIRE(expected.size() == data.size() / 2);
  std::size_t at = 0, corners = 0, w_differs = 0, direction_differs = 0;
  double worst = 0;
  for (const Mesh& m : meshes) {
    const TangentFrames t = mikktspace_tangents(m);
    for (std::size_t c = 0; c < m.num_corners(); ++c, ++at) {
      const double* ours = &t.tangents[4 * c];
      if (ours[3] != double(expected[4 * at + 3])) ++w_differs;
      if (zero_frame(&expected[4 * at])) {  // tangents.h, zero_corners: unit instead of zero
        if (!(std::fabs(ours[0] * ours[0] + ours[1] * ours[1] + ours[2] * ours[2] - 1) < 1e-9)) ++direction_differs;
        continue;
      }
      const double a = angle_deg(ours, {expected[4 * at], expected[4 * at + 1], expected[4 * at + 2]});
      worst = std::max(worst, a);
      if (!(a <= 1e-3)) ++direction_differs;
    }
    corners += m.num_corners();
  }
  WARN("MikkTSpace reference, " << name << ": " << meshes.size() << " meshes, " << corners
                                << " corners, worst direction " << worst << " degrees");
  CHECK(w_differs == 0);
  CHECK(direction_differs == 0);
}

// n triangles around an apex (vertex 0) over a ring of n (closed) or n + 1 (open) vertices, texture
// coordinates and normals per vertex (continuous: one orientation, one group at the apex); with
// `mirrored`, triangle 0's ring corners take their own texture coordinates, mirrored through the
// apex's (that triangle flips orientation and shares no edge with the others); with `second`, a
// second ring below the apex the same way (two fans that meet only at the apex).
Mesh apex_fan(int n, bool closed, bool mirrored, bool second) {
  Mesh m;
  m.add_vertex({0, 0, 0.5});
  m.vertex_normals = {0, 0, 1};
  m.texcoords = {0.5, 0.5};
  auto ring = [&](double z, double turn) {
    const auto first = std::uint32_t(m.num_vertices());
    const int count = closed ? n : n + 1;
    for (int i = 0; i < count; ++i) {
      const double a = 2 * kPi * (i + turn) / (closed ? n : n + 1.5);
      m.add_vertex({std::cos(a), std::sin(a), z});
      const Vec3d nn = normalized_or(Vec3d{std::cos(a), std::sin(a), 1.0}, Vec3d{0, 0, 1});
      m.vertex_normals.insert(m.vertex_normals.end(), {nn.x, nn.y, nn.z});
      m.texcoords.insert(m.texcoords.end(), {0.5 + 0.4 * std::cos(a), 0.5 + 0.4 * std::sin(a)});
    }
    for (int i = 0; i < n; ++i) {
      const std::uint32_t b = first + std::uint32_t(i), c = first + std::uint32_t(closed ? (i + 1) % n : i + 1);
      for (std::uint32_t v : {0u, b, c}) m.corner_vertex.push_back(v), m.corner_texcoord_index.push_back(v);
      m.face_start.push_back(std::uint32_t(m.corner_vertex.size()));
    }
  };
  ring(0.0, 0.0);
  if (mirrored)
    for (std::size_t c : {1, 2}) {
      const std::uint32_t t = m.corner_texcoord_index[c];
      m.texcoords.insert(m.texcoords.end(), {1.0 - m.texcoords[2 * t], m.texcoords[2 * t + 1]});
      m.corner_texcoord_index[c] = std::uint32_t(m.texcoords.size() / 2 - 1);
    }
  if (second) ring(1.0, 0.5);
  return m;
}

}  // namespace

// tangents.h, steps 5 and 6: which triangles are neighbours (the first unpaired edge in the opposite
// direction, in triangle order) and which of them group at a vertex decide every frame; on
// non-manifold edges, fans that touch at one vertex and mixed orientations the reference's order
// is the only truth. tangents.cpp decides them vertex by vertex when no triangle groups with any:
// this checks those decisions against the reference on 300 such soups.
TEST_CASE("MikkTSpace equals the reference (npm mikktspace) on non-manifold, mirrored triangle soups", "[tangents][reference]") {
  std::vector<Mesh> soups;
  for (unsigned s = 1; s <= 300; ++s) {
    Mesh m = vertex_uv_soup(s);
    if (m.num_faces() > 0) soups.push_back(std::move(m));  // else every random triangle had a repeated vertex
  }
  check_against_reference(std::move(soups), "soups");
}

// tangents.cpp takes a vertex whose triangles all group together (one orientation, one ring or
// one fan) of up to 8 corners through a shortcut (OneGroupFrames), the rest through the general
// search: this checks both sides of each of its conditions against the reference: rings and open
// fans of 3 to 12 triangles around one apex (8 and 9: the size limit), one of them mirrored (two
// orientations), two rings meeting at the apex (two groups).
TEST_CASE("MikkTSpace equals the reference (npm mikktspace) on rings and fans around one vertex", "[tangents][reference]") {
  std::vector<Mesh> fans;
  for (int n = 3; n <= 12; ++n)
    for (bool closed : {true, false})
      for (bool mirrored : {false, true})
        for (bool second : {false, true}) fans.push_back(apex_fan(n, closed, mirrored, second));
  check_against_reference(std::move(fans), "fans");
}
