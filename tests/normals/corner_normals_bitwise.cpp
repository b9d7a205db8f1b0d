// corner_normals and face_normals against frozen copies of their code before issue 31's rewrite
// (tests/support/corner_normals_reference.h): the same normals, corner indices and counts, bit for
// bit, on every mesh file in data/ and the corpus, on random meshes whose crease threshold is set
// to exactly an edge's own angle (and the doubles either side of it), and on the awkward cases:
// non-manifold and boundary edges, inconsistent orientation, degenerate faces, polygons, fans
// larger than the small-fan path, smoothing groups, float precision, tiny and huge scales.
#include <catch2/catch.hpp>


#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include <shadetool/core/error.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/engine/crease_paths.h>
#include <shadetool/normals/face_normals.h>
#include "normals_test_util.h"
#include "support/corner_normals_reference.h"
#include "support/mesh_file_list.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

const Weighting kAll[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
constexpr double kDeg = kPi / 180;

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// The first difference between the new and the frozen result, or "" when they agree bit for bit.
std::string difference(const CornerNormals& n, const CornerNormals& r) {
  if (n.corner_index != r.corner_index) return "corner_index";
  if (!same_bits(n.normals, r.normals)) return "normals";
  if (n.fallback_corners != r.fallback_corners) return "fallback_corners";
  if (n.degenerate_faces != r.degenerate_faces) return "degenerate_faces";
  return "";
}

// corner_normals against the frozen copy for one (mesh, angle, weighting, precision[, groups]);
// without smoothing groups also each of its two paths forced (normals/engine/crease_paths.h: the
// one-thread path without its probe, on every mesh where it applies, whatever the thread count).
void check_same(const Mesh& m, double angle, Weighting w, Precision p, const std::string& what,
                const std::vector<std::uint32_t>* groups = nullptr) {
  using normals_detail::CreasePath;
  const CornerNormals now = groups ? corner_normals(m, angle, *groups, w, p) : corner_normals(m, angle, w, p);
  const CornerNormals old = reference_crease::corner_normals_reference(MeshView(m), angle, w, p, groups ? groups->data() : nullptr);
  INFO(what << ", crease " << angle << " rad, weighting " << weighting_name(w) << ", " << precision_name(p));
  CHECK(difference(now, old) == "");
  if (groups) return;
  for (CreasePath path : {CreasePath::General, CreasePath::OneThread}) {
    INFO((path == CreasePath::General ? "general path" : "one-thread path"));
    CHECK(difference(normals_detail::corner_normals_by(MeshView(m), angle, w, p, path), old) == "");
  }
}

void check_face_normals(const Mesh& m, const std::string& what) {
  for (Precision p : {Precision::Double, Precision::Float}) {
    INFO(what << ", " << precision_name(p));
    CHECK(same_bits(face_normals(m, p), reference_crease::face_normals_reference(MeshView(m), p)));
  }
}

// Every mesh file under data/ and the corpus (/work/shared/corpus beside the tree, as tangents.cpp).
std::vector<std::string> mesh_files() {
  return shadetool::testing::data_and_corpus_mesh_files({".obj", ".ply", ".glb", ".gltf", ".off", ".stl"});
}

// A random height field: an n x n grid of points with random heights (angles between neighbouring
// faces anywhere from 0 to ~170 degrees), triangulated with random diagonals.
Mesh random_terrain(int n, double roughness, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.add_vertex({double(i), double(j), roughness * U(rng)});
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (rng() & 1) { m.add_face({a, b, c}); m.add_face({a, c, d}); }
      else { m.add_face({a, b, d}); m.add_face({b, c, d}); }
    }
  m.precision = ValuePrecision::Double;
  return m;
}

// The crease test's angle of every interior edge of a triangle mesh, as corner_normals computes it
// (interior_angle of the unit face normals; geometry/interior_angle.h).
std::vector<double> edge_angles(const Mesh& m, Precision p) {
  const std::vector<double> fn = face_normals(m, p);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> faces;
  for (std::size_t f = 0; f < m.num_faces(); ++f)
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t a = m.corner_vertex[3 * f + k], b = m.corner_vertex[3 * f + (k + 1) % 3];
      faces[{std::min(a, b), std::max(a, b)}].push_back(std::uint32_t(f));
    }
  std::vector<double> out;
  for (auto& [edge, fs] : faces) {
    if (fs.size() != 2) continue;
    const Vec3d na = get3(fn, fs[0]), nb = get3(fn, fs[1]), x = cross(na, nb);
    out.push_back(interior_angle(std::sqrt(dot(x, x)), dot(na, nb)));
  }
  return out;
}

// Two apexes over one base ring of `sides` points in z = 0: the top apex (vertex 0) at height top,
// base points at radius r_even / r_odd by the parity of their index (vertices 1..sides), the bottom
// apex (vertex sides + 1) at height bottom; the top fan wound counter-clockwise seen from above,
// the bottom fan the other way.
Mesh double_cone(int sides, double top, double r_even, double r_odd, double bottom) {
  Mesh m;
  m.add_vertex({0, 0, top});
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * kPi * i / sides, r = (i % 2) ? r_odd : r_even;
    m.add_vertex({r * std::cos(a), r * std::sin(a), 0});
  }
  m.add_vertex({0, 0, bottom});
  for (int i = 0; i < sides; ++i) {
    const std::uint32_t a = 1 + std::uint32_t(i), b = 1 + std::uint32_t((i + 1) % sides);
    m.add_face({0, a, b});
    m.add_face({std::uint32_t(sides + 1), b, a});
  }
  return m;
}

}  // namespace

TEST_CASE("corner_normals equals the frozen pre-issue-31 crease path bit for bit on every file in data/ and the corpus",
          "[corner_normals][reference]") {
  std::size_t meshes = 0;
  for (const std::string& path : mesh_files()) {
    Mesh m;
    try {
      m = read_mesh(path);
    } catch (const shadetool::Error&) {
      continue;  // files the readers refuse are other tests' business
    }
    if (m.num_faces() == 0) continue;
    ++meshes;
    check_face_normals(m, path);
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float}) check_same(m, 30 * kDeg, w, p, path);
    for (double angle : {0.0, 1 * kDeg, 60 * kDeg, 89.9 * kDeg, 180 * kDeg}) check_same(m, angle, Weighting::Angle, Precision::Double, path);
  }
  INFO("meshes read: " << meshes);
  CHECK(meshes >= 10);  // data/ alone holds more than ten
}

TEST_CASE("corner_normals: a crease threshold equal to an edge's own angle gives the old verdicts exactly",
          "[corner_normals][reference]") {
  // Terrains of three roughnesses: gentle (angles near 0: the band near cos = 1), moderate, wild.
  for (double roughness : {0.02, 0.4, 3.0})
    for (Precision p : {Precision::Double, Precision::Float}) {
      const Mesh m = random_terrain(12, roughness, 5u + std::uint32_t(roughness * 100));
      const std::vector<double> angles = edge_angles(m, p);
      REQUIRE(angles.size() > 300);
      for (std::size_t i = 0; i < angles.size(); i += 7) {
        const double a = angles[i];
        for (double t : {a, std::nextafter(a, -1.0), std::nextafter(a, 10.0)})
          check_same(m, t, Weighting::Angle, p, "terrain roughness " + std::to_string(roughness));
      }
      check_face_normals(m, "terrain");
    }
}

TEST_CASE("corner_normals: thresholds outside [0, pi], and on both sides of pi and 0, give the old verdicts",
          "[corner_normals][reference]") {
  const Mesh m = random_terrain(10, 3.0, 99);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (double t : {-1.0, -0.0, 0.0, 1e-300, 1e-9, kPi / 2, std::nextafter(kPi, 0.0), kPi, std::nextafter(kPi, 4.0), 4.0,
                   2 * kPi, 7.0, inf, -inf, nan})
    for (Weighting w : kAll) check_same(m, t, w, Precision::Double, "terrain, edge thresholds");
}

TEST_CASE("corner_normals: non-manifold, boundary, inconsistent, degenerate, polygon and large-fan meshes as before",
          "[corner_normals][reference]") {
  std::vector<std::pair<std::string, Mesh>> cases;
  {  // three triangles on one edge (non-manifold), a boundary, an isolated vertex
    Mesh m;
    for (Vec3d p : {Vec3d{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0.1}, {0.5, 0.2, 1}, {5, 5, 5}}) m.add_vertex(p);
    m.add_face({0, 1, 2});
    m.add_face({1, 0, 3});
    m.add_face({0, 1, 4});
    cases.emplace_back("non-manifold fin", m);
  }
  {  // a square of two triangles whose second is reversed (orientations disagree)
    Mesh m;
    for (Vec3d p : {Vec3d{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}}) m.add_vertex(p);
    m.add_face({0, 1, 2});
    m.add_face({0, 2, 3});
    m.add_face({0, 3, 2});
    cases.emplace_back("inconsistent", m);
  }
  {  // degenerate faces: a repeated index, collinear corners, a zero-area sliver, a NaN corner
    Mesh m = random_terrain(6, 0.5, 3);
    const std::uint32_t v0 = 0, v1 = 1, v2 = 2, n = std::uint32_t(m.num_vertices());
    m.add_vertex({0.5, 0, 0});  // on the edge 0-1: collinear with it
    m.add_vertex({std::numeric_limits<double>::quiet_NaN(), 0, 0});
    m.add_face({v0, v0, v2});
    m.add_face({v0, n, v1});
    m.add_face({v1, n + 1, v2});
    m.add_face({7, 8, 15});
    m.add_face({8, 7, 15});  // a two-sided pair: sums that cancel
    cases.emplace_back("degenerate", m);
  }
  {  // polygons: quads, a pentagon, a polygon with a repeated vertex
    Mesh m;
    for (Vec3d p : {Vec3d{0, 0, 0}, {1, 0, 0}, {2, 0, 0.5}, {0, 1, 0}, {1, 1, 0.2}, {2, 1, 1}, {0, 2, 0.3}, {1, 2, 0.9}, {2, 2, 0}})
      m.add_vertex(p);
    m.add_face({0, 1, 4, 3});
    m.add_face({1, 2, 5, 4});
    m.add_face({3, 4, 7, 6});
    m.add_face({4, 5, 8, 7});
    m.add_face({0, 3, 6, 7, 4});
    m.add_face({2, 1, 2, 5, 8});
    cases.emplace_back("polygons", m);
  }
  for (int sides : {31, 32, 33, 200}) {  // cones: the apex fan crosses kSmallFan; a ridge every other side
    Mesh m = double_cone(sides, 1.0, 1.6, 1.0, -0.2);
    m.add_face({0, 1, 2});  // one non-manifold fin at the apex
    cases.emplace_back("cone " + std::to_string(sides), m);
  }
  for (auto& [name, m] : cases) {
    m.precision = ValuePrecision::Double;
    check_face_normals(m, name);
    for (Weighting w : kAll)
      for (Precision p : {Precision::Double, Precision::Float})
        for (double angle : {0.0, 20 * kDeg, 30 * kDeg, 75 * kDeg, 180 * kDeg}) check_same(m, angle, w, p, name);
  }
}

TEST_CASE("corner_normals: smoothing groups, tiny and huge scales, irregular spheres as before", "[corner_normals][reference]") {
  Mesh terrain = random_terrain(16, 0.6, 17);
  std::vector<std::uint32_t> groups(terrain.num_faces());
  for (std::size_t f = 0; f < groups.size(); ++f) groups[f] = std::uint32_t((f / 7) % 4);  // 0: flat faces
  for (Weighting w : kAll) check_same(terrain, 40 * kDeg, w, Precision::Double, "terrain, smoothing groups", &groups);
  for (double scale : {std::ldexp(1.0, -80), 1e-30, 1e30, std::ldexp(1.0, 90)}) {
    Mesh m = terrain;
    for (double& x : m.positions) x *= scale;
    check_face_normals(m, "scaled terrain");
    for (Weighting w : kAll) check_same(m, 30 * kDeg, w, Precision::Double, "scaled terrain");
  }
  const Mesh sphere = irregular(uv_sphere(96, 48, 0.15, 11), 13).mesh;
  check_face_normals(sphere, "irregular sphere");
  for (Weighting w : kAll)
    for (Precision p : {Precision::Double, Precision::Float}) check_same(sphere, 30 * kDeg, w, p, "irregular sphere");
  check_same(sphere, 2 * kDeg, Weighting::Angle, Precision::Double, "irregular sphere");
}

TEST_CASE("corner_normals: the in-order (1 thread) and parallel (2 threads) groupings both equal the frozen copy",
          "[corner_normals][reference][parallel]") {
  // 40401 vertices: above kSerialBelow, so 2 threads split the grouping and the row pass into
  // parallel ranges; 1 thread runs each as one range.
  const Mesh m = random_terrain(200, 0.4, 23);
  REQUIRE(m.num_vertices() > 32768);
  const CornerNormals old = reference_crease::corner_normals_reference(MeshView(m), 30 * kDeg, Weighting::Angle, Precision::Double);
  for (int threads : {1, 2}) {
    CornerNormals now;
    tbb::task_arena(threads).execute([&] { now = corner_normals(m, 30 * kDeg, Weighting::Angle); });
    INFO(threads << " threads");
    CHECK(difference(now, old) == "");
  }
}

namespace {

// A pyramid fan around the apex 0 at height h over a regular base of `sides` points (radius 1,
// alternate points pulled in by `pinch` so that neighbouring faces differ), closed underneath by
// a second apex. Every apex face is tilted from the axis by about atan(1 / h).
Mesh pyramid_fan(int sides, double h, double pinch) {
  Mesh m = double_cone(sides, h, 1.0, 1.0 - pinch, -1.0);
  m.precision = ValuePrecision::Double;
  return m;
}

}  // namespace

TEST_CASE("corner_normals: the smooth-cone shortcut and the ring paths never change a verdict (apex fans of 3-18 "
          "corners, open, pinched, flipped, two fans on one vertex; thresholds swept through every edge's angle)",
          "[corner_normals][reference]") {
  // Fans across closed_triangle_ring8 (<= 8 corners), closed_smooth_ring (<= 16) and link_small_fan;
  // steep apexes (faces far apart: the cone test fails, CreaseTest decides) and flat ones (the cone
  // holds for large thresholds, topology alone decides).
  for (int sides = 3; sides <= 18; ++sides)
    for (double h : {0.05, 0.4, 3.0}) {
      std::vector<std::pair<std::string, Mesh>> cases;
      const Mesh closed = pyramid_fan(sides, h, 0.3);
      cases.emplace_back("closed", closed);
      {  // one apex face removed: an open fan (two boundary edges at the apex)
        Mesh m = closed;
        m.corner_vertex.erase(m.corner_vertex.begin(), m.corner_vertex.begin() + 3);
        Mesh open;
        for (std::size_t v = 0; v < m.num_vertices(); ++v) open.add_vertex(m.position(v));
        for (std::size_t c = 0; c < m.corner_vertex.size(); c += 3)
          open.add_face({m.corner_vertex[c], m.corner_vertex[c + 1], m.corner_vertex[c + 2]});
        open.precision = ValuePrecision::Double;
        cases.emplace_back("open", open);
      }
      {  // one apex face reversed: two edges whose faces disagree in orientation
        Mesh m;
        for (std::size_t v = 0; v < closed.num_vertices(); ++v) m.add_vertex(closed.position(v));
        for (std::size_t f = 0; f < closed.num_faces(); ++f) {
          const std::uint32_t* c = &closed.corner_vertex[3 * f];
          if (f == 2) m.add_face({c[0], c[2], c[1]});
          else m.add_face({c[0], c[1], c[2]});
        }
        m.precision = ValuePrecision::Double;
        cases.emplace_back("flipped", m);
      }
      {  // two closed fans sharing the apex (a pinch: no crease, two groups) and a fan whose ring
         // visits one far vertex twice (the apex fan of a double-covered base)
        Mesh m = closed;
        const std::uint32_t shift = std::uint32_t(m.num_vertices()) - 1;
        for (std::size_t v = 1; v < closed.num_vertices(); ++v) {
          const Vec3d p = closed.position(v);
          m.add_vertex({p.x + 0.01, p.y, 2 * h - p.z});  // mirrored above the apex
        }
        for (std::size_t f = 0; f < closed.num_faces(); ++f) {
          auto map = [&](std::uint32_t v) { return v == 0 ? 0u : v + shift; };
          const std::uint32_t* c = &closed.corner_vertex[3 * f];
          m.add_face({map(c[0]), map(c[2]), map(c[1])});
        }
        cases.emplace_back("pinched", m);
      }
      for (auto& [name, m] : cases) {
        std::vector<double> thresholds = {0.0, 5 * kDeg, 30 * kDeg, 90 * kDeg, 150 * kDeg, 179 * kDeg, kPi};
        for (double a : edge_angles(m, Precision::Double))
          for (double t : {a, std::nextafter(a, -1.0), std::nextafter(a, 10.0), 2 * a, std::nextafter(2 * a, 10.0)})
            thresholds.push_back(t);
        const std::string what = name + " fan of " + std::to_string(sides) + ", height " + std::to_string(h);
        for (double t : thresholds) check_same(m, t, Weighting::Angle, Precision::Double, what);
        check_same(m, 60 * kDeg, Weighting::Area, Precision::Float, what);
      }
    }
}

namespace {

// The crease angle at which SmoothCone (corner_normals.cpp) starts to accept a vertex whose d unit
// face normals n_i have spread s = d - |sum n_i| (s < 0.5), margins left out: 2 (1 - cos(alpha)) = s
// with cos(2 alpha) = cos(t) + 5e-5. Computed here from the closed form, not by the library.
double cone_flip_threshold(double s) {
  const double cos_alpha = 1.0 - 0.5 * s, cos_2alpha = 2.0 * cos_alpha * cos_alpha - 1.0;
  return std::acos(std::max(-1.0, cos_2alpha - 5e-5));
}

// An apex fan of `sides` triangles: apex at the origin lifted by h, rim on the unit circle at z = 0,
// rim vertex `lifted` raised by dz (two faces tilt more than the rest).
Mesh apex_fan(int sides, double h, int lifted, double dz) {
  Mesh m;
  m.add_vertex({0.0, 0.0, h});
  for (int k = 0; k < sides; ++k) {
    const double a = 2 * kPi * k / sides;
    m.add_vertex({std::cos(a), std::sin(a), k == lifted ? dz : 0.0});
  }
  for (int k = 0; k < sides; ++k)
    m.add_face({0u, std::uint32_t(1 + k), std::uint32_t(1 + (k + 1) % sides)});
  m.precision = ValuePrecision::Double;
  return m;
}

}  // namespace

// Two triangles hinged on the edge (0, 1) at a dihedral angle phi: both vertices of the hinge have
// two faces at phi, the case where the cone bound is tight.
Mesh hinge(double phi) {
  Mesh m;
  m.add_vertex({0.0, 0.0, 0.0});
  m.add_vertex({1.0, 0.0, 0.0});
  m.add_vertex({0.4, 1.0, 0.0});
  m.add_vertex({0.7, -std::cos(phi), std::sin(phi)});
  m.add_face({0u, 1u, 2u});
  m.add_face({1u, 0u, 3u});
  m.precision = ValuePrecision::Double;
  return m;
}

TEST_CASE("corner_normals: around the smooth-cone test's own limit (the spread of the apex's face normals), "
          "every verdict equals the frozen crease path",
          "[corner_normals][reference]") {
  // The cone test accepts the apex when d - |sum n_i| (plus rounding margins) is below
  // 2 (1 - cos(alpha)); thresholds swept through a band around the angle where that flips, for
  // symmetric cones (every face equally tilted), flat fans with one outlier pair of faces and
  // two-face hinges (where the bound is tight: the shortcut's limit is the crease itself), so that
  // the shortcut is taken on one side of the band and CreaseTest decides on the other.
  std::vector<std::pair<std::string, Mesh>> cases;
  for (int sides : {3, 5, 8, 12, 17, 40})
    for (double h : {0.0, 0.01, 0.05, 0.2})
      for (double dz : {0.0, 0.02, 0.1, 0.4})
        cases.emplace_back("apex fan of " + std::to_string(sides) + ", h " + std::to_string(h) + ", dz " + std::to_string(dz),
                           apex_fan(sides, h, 0, dz));
  for (double phi_deg : {1.0, 5.0, 20.0, 29.0, 30.0, 31.0, 45.0, 60.0, 89.0})
    cases.emplace_back("hinge at " + std::to_string(phi_deg) + " degrees", hinge(phi_deg * kDeg));
  for (const auto& [what, m] : cases) {
    const int sides = int(m.num_faces());  // the apex's (or the hinge edge's vertices') corner count
    const std::vector<double> fn = face_normals(m);
    double sx = 0, sy = 0, sz = 0;
    for (std::size_t f = 0; f < m.num_faces(); ++f) {
      sx += fn[3 * f];
      sy += fn[3 * f + 1];
      sz += fn[3 * f + 2];
    }
    const double spread = double(sides) - std::sqrt(sx * sx + sy * sy + sz * sz);
    if (!(spread < 0.5)) continue;
    const double flip = cone_flip_threshold(spread);
    for (int j = -40; j <= 40; ++j) check_same(m, flip * (1.0 + 2e-4 * j), Weighting::Angle, Precision::Double, what);
    for (double a : edge_angles(m, Precision::Double))
      for (double t : {a, std::nextafter(a, -1.0), std::nextafter(a, 10.0)})
        check_same(m, t, Weighting::Angle, Precision::Double, what);
  }
}

namespace {

// A roof: an n x n grid folded along its middle column into two planes at `fold` radians from the
// horizontal each (a ridge of 2 fold between their normals), split into triangles with random
// diagonals; and, when `spike` is set, one vertex inside the left plane given `spike` extra faces
// by a fan of thin triangles (valence above the one-thread path's slots, its neighbours one group).
Mesh roof(int n, double fold, int spike, std::uint32_t seed) {
  std::mt19937 rng(seed);
  Mesh m;
  const int mid = n / 2;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i - mid);
      m.add_vertex({x, double(j), -std::fabs(x) * std::tan(fold)});
    }
  auto id = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
  const int si = mid / 2, sj = n / 2;  // the spike's quad (left plane), cut into a fan
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (spike && i == si && j == sj) {
        // the quad's corner a fans out to spike + 1 points along edge b-c and c-d (in the plane)
        std::vector<std::uint32_t> ring{b};
        for (int k = 1; k <= spike; ++k) {
          const double t = double(k) / double(spike + 1);
          const Vec3d p = t < 0.5 ? m.position(b) + (m.position(c) - m.position(b)) * (2 * t)
                                  : m.position(c) + (m.position(d) - m.position(c)) * (2 * t - 1);
          ring.push_back(std::uint32_t(m.num_vertices()));
          m.add_vertex(p);
        }
        ring.push_back(d);
        for (std::size_t k = 0; k + 1 < ring.size(); ++k) m.add_face({a, ring[k], ring[k + 1]});
        // close the fan's outer side against c with triangles of the far edges
        for (std::size_t k = 1; k + 1 < ring.size(); ++k) m.add_face({ring[k], c, ring[k + 1]});
        continue;
      }
      if (rng() & 1) {
        m.add_face({a, b, c});
        m.add_face({a, c, d});
      } else {
        m.add_face({a, b, d});
        m.add_face({b, c, d});
      }
    }
  m.precision = ValuePrecision::Double;
  return m;
}

}  // namespace

TEST_CASE("corner_normals, one-thread path: creases beside one-group vertices, a vertex with more corners than a "
          "slot holds among them, smooth and steep cone apexes of 9-13 corners; the frozen copy's bits, the planes' "
          "own normals and the apex's axis", "[corner_normals][reference]") {
  using normals_detail::CreasePath;
  for (int spike : {0, 7, 8, 9, 12})
    for (double fold_deg : {10.0, 20.0, 35.0}) {
      const Mesh m = roof(10, fold_deg * kDeg, spike, 5);
      const std::string what = "roof, fold " + std::to_string(fold_deg) + ", spike " + std::to_string(spike);
      INFO(what);
      for (Weighting w : {Weighting::Angle, Weighting::Uniform})
        for (Precision p : {Precision::Double, Precision::Float})
          for (double crease : {15 * kDeg, 30 * kDeg, 50 * kDeg}) check_same(m, crease, w, p, what);
      // Truth: at 30 degrees a fold of 20 or 35 degrees (ridge 40, 70) splits every ridge vertex into the
      // two planes, and every corner's normal is its plane's normal (all faces of a group are coplanar);
      // a fold of 10 degrees (ridge 20) splits nothing.
      const CornerNormals one = normals_detail::corner_normals_by(MeshView(m), 30 * kDeg, Weighting::Angle,
                                                                  Precision::Double, CreasePath::OneThread);
      const double f = fold_deg * kDeg;
      const Vec3d left{-std::sin(f), 0, std::cos(f)}, right{std::sin(f), 0, std::cos(f)};  // z = -|x| tan(fold), faces up
      std::size_t checked = 0;
      for (std::size_t face = 0; face < m.num_faces(); ++face) {
        double cx = 0;
        for (int k = 0; k < 3; ++k) cx += m.position(m.corner_vertex[3 * face + k]).x;
        const Vec3d plane = cx < 0 ? left : right;
        for (int k = 0; k < 3; ++k) {
          const std::size_t c = 3 * face + k;
          const double* n = &one.normals[3 * std::size_t(one.corner_index[c])];
          const Vec3d got{n[0], n[1], n[2]};
          if (fold_deg > 15.0) {
            CHECK(std::fabs(got.x - plane.x) < 1e-12);
            CHECK(std::fabs(got.z - plane.z) < 1e-12);
            ++checked;
          } else if (std::fabs(m.position(m.corner_vertex[c]).x) > 0.5) {
            CHECK(std::fabs(got.x - plane.x) < 1e-12);  // off the ridge: one plane's faces only
            ++checked;
          }
          CHECK(std::fabs(got.y) < 1e-12);
        }
      }
      CHECK(checked > 300);
    }
  // Cone apexes of 9 to 13 corners (a slot holds kSlotPairs = 11): flat (h small) and steep; the apex's normal is
  // the axis by symmetry. (Open, flipped and pinched apex fans of 3-18 corners: the test case above,
  // whose check_same runs the one-thread path too.)
  for (int sides = 9; sides <= 13; ++sides)
    for (double h : {0.05, 3.0}) {
      const Mesh m = pyramid_fan(sides, h, 0.0);
      const std::string what = "apex of " + std::to_string(sides) + ", h " + std::to_string(h);
      INFO(what);
      for (double crease : {10 * kDeg, 30 * kDeg, 179 * kDeg}) check_same(m, crease, Weighting::Angle, Precision::Double, what);
      const CornerNormals one = normals_detail::corner_normals_by(MeshView(m), 179 * kDeg, Weighting::Angle,
                                                                  Precision::Double, CreasePath::OneThread);
      const double* n = &one.normals[3 * std::size_t(one.corner_index[0])];  // corner 0: the top apex
      CHECK(m.corner_vertex[0] == 0);
      CHECK(std::fabs(n[0]) < 1e-12);
      CHECK(std::fabs(n[1]) < 1e-12);
      CHECK(std::fabs(std::fabs(n[2]) - 1.0) < 1e-12);
    }
}

TEST_CASE("corner_normals, one-thread path: two nearly coplanar closed fans on one vertex (a pinch inside the smooth "
          "cone) stay two groups whichever fan holds the vertex's first corner", "[corner_normals][reference]") {
  using normals_detail::CreasePath;
  // Sheet A: a fan of `a` triangles around the origin in the plane z = 0; sheet B: a fan of `b`
  // triangles around the origin rising to z = 0.02 at radius 1 (its faces tilt ~1 degree), touching
  // A only there. Every face is within the cone of a 30-degree crease; the vertex's corners form
  // two cycles, of a and b, so the general path gives it two groups.
  for (int a = 3; a <= 8; ++a)
    for (int b = 3; a + b <= 11; ++b)
      for (bool a_first : {true, false}) {
        Mesh m;
        m.add_vertex({0, 0, 0});
        auto ring = [&m](int n, double z, double phase) {
          const std::uint32_t first = std::uint32_t(m.num_vertices());
          for (int i = 0; i < n; ++i) m.add_vertex({std::cos(2 * kPi * i / n + phase), std::sin(2 * kPi * i / n + phase), z});
          return first;
        };
        const std::uint32_t ra = ring(a, 0.0, 0.0), rb = ring(b, 0.02, 0.3);
        auto fan = [&m](std::uint32_t first, int n) {
          for (int i = 0; i < n; ++i) m.add_face({0, first + std::uint32_t(i), first + std::uint32_t((i + 1) % n)});
        };
        if (a_first) { fan(ra, a); fan(rb, b); } else { fan(rb, b); fan(ra, a); }
        m.precision = ValuePrecision::Double;
        const std::string what = "pinch of fans " + std::to_string(a) + " and " + std::to_string(b) + (a_first ? ", A first" : ", B first");
        INFO(what);
        check_same(m, 30 * kDeg, Weighting::Angle, Precision::Double, what);
        const CornerNormals one = normals_detail::corner_normals_by(MeshView(m), 30 * kDeg, Weighting::Angle,
                                                                    Precision::Double, CreasePath::OneThread);
        // the origin's corners (corner 3f of every face): one row per sheet, two rows in all
        const std::size_t first_fan = std::size_t(a_first ? a : b);
        for (std::size_t f = 0; f < m.num_faces(); ++f) {
          const std::size_t same = f < first_fan ? 0 : first_fan;
          CHECK(one.corner_index[3 * f] == one.corner_index[3 * same]);
        }
        CHECK(one.corner_index[0] != one.corner_index[3 * first_fan]);
      }
}

// Issue 31 goal 3, sixth round: why an exact crease path cannot skip the parts of the floor that
// bench_crease measures (bench/normals/results/notes.md, "sixth round: the floor"). Each pair of
// meshes below agrees in everything a path that skipped one part would read, yet corner_normals
// (and the frozen copy) give them different outputs; so such a path would be wrong on one of them.
TEST_CASE("corner_normals, the floor's parts: (ii) the same rings with one face folded give another pool; "
          "(iii) the same face data at a vertex in the same corner order, with other far vertices, give another pool",
          "[corner_normals][reference][floor]") {
  // (ii) A hexagonal fan around vertex 0 (one closed ring, every edge manifold), flat, and the same
  // fan (the same corner_vertex: the same (next, prev) pairs at every corner) with the last rim
  // vertex raised so that the last two faces tilt by more than 30 degrees. Only the face normals,
  // compared at the vertex's corners (the last ones included), tell the two apart.
  {
    auto fan = [](double lift) {
      Mesh m;
      m.add_vertex({0, 0, 0});
      for (int i = 0; i < 6; ++i) m.add_vertex({std::cos(kPi * i / 3), std::sin(kPi * i / 3), i == 5 ? lift : 0.0});
      for (std::uint32_t i = 0; i < 6; ++i) m.add_face({0, 1 + i, 1 + (i + 1) % 6});
      m.precision = ValuePrecision::Double;
      return m;
    };
    const Mesh flat = fan(0.0), folded = fan(1.5);
    REQUIRE(flat.corner_vertex == folded.corner_vertex);
    for (const Mesh* m : {&flat, &folded}) check_same(*m, 30 * kDeg, Weighting::Angle, Precision::Double, "hexagonal fan");
    const CornerNormals a = corner_normals(flat, 30 * kDeg, Weighting::Angle);
    const CornerNormals b = corner_normals(folded, 30 * kDeg, Weighting::Angle);
    auto rows_at_centre = [](const CornerNormals& n) {
      std::vector<std::uint32_t> r;
      for (std::size_t f = 0; f < 6; ++f) r.push_back(n.corner_index[3 * f]);
      std::sort(r.begin(), r.end());
      return std::size_t(std::unique(r.begin(), r.end()) - r.begin());
    };
    CHECK(rows_at_centre(a) == 1);
    CHECK(rows_at_centre(b) > 1);  // the fold splits the centre: its last faces are their own group
  }
  // (iii) Vertex 0 with six faces whose positions, corner by corner and in the same order, are the
  // same in both meshes: face k is (origin, p_k, p_{k+1}) with p_j at angle 120 j degrees on the unit
  // circle. In `wound`, the far vertices are six distinct vertices r_0..r_5 (r_{j+3} at r_j's
  // position) and the faces (0, r_k, r_{k+1 mod 6}): one closed ring winding twice around the
  // origin, one group. In `pinched`, the faces are (0, r_0, r_1), (0, r_1, r_2), (0, r_2, r_0) and
  // the same on r_3..r_5: two closed rings, two groups. Any per-corner datum computed from a face's
  // positions (contribution, unit normal, angle, count) is the same bit for bit at every corner of
  // vertex 0 in both, so its sums are too: only the far vertices' identities (ring evidence) tell
  // one group from two.
  {
    auto build = [](bool pinched) {
      Mesh m;
      m.add_vertex({0, 0, 0});
      for (int j = 0; j < 6; ++j) m.add_vertex({std::cos(2 * kPi * (j % 3) / 3), std::sin(2 * kPi * (j % 3) / 3), 0.0});
      for (std::uint32_t k = 0; k < 6; ++k) {
        const std::uint32_t next = pinched ? (k / 3) * 3 + (k + 1) % 3 : (k + 1) % 6;
        m.add_face({0, 1 + k, 1 + next});
      }
      m.precision = ValuePrecision::Double;
      return m;
    };
    const Mesh wound = build(false), pinched = build(true);
    for (std::size_t f = 0; f < 6; ++f)  // the same positions at every corner of every face
      for (int k = 0; k < 3; ++k) {
        const Vec3d pa = wound.position(wound.corner_vertex[3 * f + k]), pb = pinched.position(pinched.corner_vertex[3 * f + k]);
        CHECK(std::memcmp(&pa, &pb, sizeof pa) == 0);
      }
    CHECK(wound.corner_vertex != pinched.corner_vertex);
    for (const Mesh* m : {&wound, &pinched})
      for (Weighting w : kAll) check_same(*m, 30 * kDeg, w, Precision::Double, m == &wound ? "wound twice" : "pinched");
    const CornerNormals a = corner_normals(wound, 30 * kDeg, Weighting::Angle);
    const CornerNormals b = corner_normals(pinched, 30 * kDeg, Weighting::Angle);
    for (std::size_t f = 1; f < 6; ++f) CHECK(a.corner_index[3 * f] == a.corner_index[0]);
    CHECK(b.corner_index[3] == b.corner_index[0]);
    CHECK(b.corner_index[6] == b.corner_index[0]);
    CHECK(b.corner_index[9] != b.corner_index[0]);  // the second ring: its own row
    CHECK(a.normals.size() != b.normals.size());
  }
}

namespace {

// Issue 31 goal 3, seventh round: meshes whose hard vertices (left by the one-thread path to the
// general path on the sub-mesh of their faces) have several groups each, at the first and the last
// vertex id, next to each other and between easy vertices, so that the easy rows between them move
// by every amount (corner_normals.cpp, step (4): the pool's extra rows made in place).
//
// A saddle fan: pole at `centre`, n ring vertices at radius 1 (n divisible by 4), z = t (|x| - |y|)
// relative to the pole: four planar sectors (x, y signs), each sector's faces in one plane whose
// normal is (-sx t, sy t, 1) / sqrt(1 + 2 t^2) (sx, sy the signs of x and y in the sector). At t = 1
// neighbouring sectors meet at acos(1/3) = 70.5 degrees: at a 30-degree crease the pole has four
// groups and the ring vertices on the sector borders two. pole_last: the pole numbered after its
// ring.
void add_saddle_fan(Mesh& m, Vec3d centre, int n, double t, bool pole_last) {
  std::uint32_t pole = 0;
  if (!pole_last) pole = m.add_vertex(centre);
  const std::uint32_t first = std::uint32_t(m.num_vertices());
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n;
    // exact on the axes, where two sectors meet
    const double x = k % (n / 4) == 0 ? std::round(std::cos(a)) : std::cos(a);
    const double y = k % (n / 4) == 0 ? std::round(std::sin(a)) : std::sin(a);
    m.add_vertex(centre + Vec3d{x, y, t * (std::fabs(x) - std::fabs(y))});
  }
  if (pole_last) pole = m.add_vertex(centre);
  for (int k = 0; k < n; ++k) m.add_face({pole, first + std::uint32_t(k), first + std::uint32_t((k + 1) % n)});
}

// The sector normal of a face of add_saddle_fan with ring corners k, k + 1 (n ring vertices).
Vec3d saddle_normal(int k, int n, double t) {
  const double a = 2 * kPi * (k + 0.5) / n;  // the face's middle direction
  const double sx = std::cos(a) > 0 ? 1.0 : -1.0, sy = std::sin(a) > 0 ? 1.0 : -1.0;
  const double l = std::sqrt(1 + 2 * t * t);
  return Vec3d{-sx * t / l, sy * t / l, 1 / l};
}

// Two closed fans of a and b triangles on one vertex (a pinch), sheet B tilted by 1 degree.
void add_pinch(Mesh& m, Vec3d centre, int a, int b) {
  const std::uint32_t c = m.add_vertex(centre);
  for (int s = 0; s < 2; ++s) {
    const int n = s == 0 ? a : b;
    const std::uint32_t first = std::uint32_t(m.num_vertices());
    for (int i = 0; i < n; ++i)
      m.add_vertex(centre + Vec3d{std::cos(2 * kPi * i / n + 0.3 * s), std::sin(2 * kPi * i / n + 0.3 * s), 0.02 * s});
    for (int i = 0; i < n; ++i) m.add_face({c, first + std::uint32_t(i), first + std::uint32_t((i + 1) % n)});
  }
}

void add_mesh(Mesh& m, const Mesh& part, Vec3d offset) {
  const std::uint32_t base = std::uint32_t(m.num_vertices());
  for (std::size_t v = 0; v < part.num_vertices(); ++v) m.add_vertex(part.position(v) + offset);
  for (std::size_t f = 0; f < part.num_faces(); ++f) {
    const std::uint32_t* c = &part.corner_vertex[3 * f];
    m.add_face({base + c[0], base + c[1], base + c[2]});
  }
}

}  // namespace

TEST_CASE("corner_normals, one-thread path: hard vertices of several groups at the first and last vertex ids, side "
          "by side and between easy ones (poles of 40 corners in four creased sectors, pinches of 15 corners, one easy "
          "row between two hard vertices), "
          "more extra rows than the pool reserves; the frozen copy's bits and the sectors' own normals",
          "[corner_normals][reference]") {
  using normals_detail::CreasePath;
  const Mesh ball = icosphere(2).mesh;  // 162 vertices, every one a closed smooth ring: easy
  for (int layout = 0; layout < 3; ++layout) {
    // 0: fans, pinches and double cones between spheres, the first vertex a pole, the last a pole;
    // 1: fans only, side by side (4 + 2 + 2 extra rows per 41 vertices: more than #V / 16 + 16);
    // 2: spheres, then one fan whose pole is the last vertex (no easy row after it).
    Mesh m;
    std::vector<int> fan_first_face;
    const int n = 40;
    auto fan = [&](Vec3d at, bool pole_last) {
      fan_first_face.push_back(int(m.num_faces()));
      add_saddle_fan(m, at, n, 1.0, pole_last);
    };
    // A flat double cone: its apexes are easy (numbered first and last), its six rim vertices hard with
    // two groups (a 174-degree fold): one easy row between hard vertices on either side.
    const Mesh bicone = double_cone(6, 0.05, 1.0, 1.0, -0.05);
    if (layout == 0) {
      fan({0, 0, 0}, false);
      add_mesh(m, bicone, {2.5, 0, 0});
      add_mesh(m, ball, {5, 0, 0});
      fan({10, 0, 0}, false);
      fan({15, 0, 0}, false);
      add_pinch(m, {20, 0, 0}, 7, 8);
      m.add_vertex({25, 0, 0});  // a vertex without corners (no row)
      add_mesh(m, ball, {30, 0, 0});
      add_pinch(m, {35, 0, 0}, 8, 7);
      add_mesh(m, ball, {40, 0, 0});
      add_mesh(m, bicone, {42.5, 0, 0});
      fan({45, 0, 0}, true);
    } else if (layout == 1) {
      for (int i = 0; i < 12; ++i) fan({5.0 * i, 0, 0}, i % 2 == 1);
    } else {
      add_mesh(m, ball, {0, 0, 0});
      add_mesh(m, ball, {5, 0, 0});
      fan({10, 0, 0}, true);
    }
    m.precision = ValuePrecision::Double;
    const std::string what = "layout " + std::to_string(layout);
    INFO(what);
    for (Weighting w : {Weighting::Angle, Weighting::Uniform})
      for (Precision p : {Precision::Double, Precision::Float})
        for (double crease : {30 * kDeg, 80 * kDeg}) check_same(m, crease, w, p, what);
    // Truth: at 30 degrees every corner of a fan's face has its sector's plane normal, and each pole
    // has four rows (one per sector).
    const CornerNormals one = normals_detail::corner_normals_by(MeshView(m), 30 * kDeg, Weighting::Angle, Precision::Double,
                                                                CreasePath::OneThread);
    for (int f0 : fan_first_face) {
      std::vector<std::uint32_t> pole_rows;
      for (int k = 0; k < n; ++k) {
        const Vec3d plane = saddle_normal(k, n, 1.0);
        for (int j = 0; j < 3; ++j) {
          const std::size_t c = 3 * std::size_t(f0 + k) + std::size_t(j);
          const double* got = &one.normals[3 * std::size_t(one.corner_index[c])];
          CHECK(std::fabs(got[0] - plane.x) < 1e-12);
          CHECK(std::fabs(got[1] - plane.y) < 1e-12);
          CHECK(std::fabs(got[2] - plane.z) < 1e-12);
        }
        pole_rows.push_back(one.corner_index[3 * std::size_t(f0 + k)]);
      }
      std::sort(pole_rows.begin(), pole_rows.end());
      CHECK(std::unique(pole_rows.begin(), pole_rows.end()) - pole_rows.begin() == 4);
    }
  }
}
