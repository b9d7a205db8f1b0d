// Tests of issue 21 item 16: normals are scale-invariant at the extremes. A mesh scaled by any
// power of two that keeps its coordinates finite and normal gives bitwise the same vertex, face and
// corner normals as at scale 1, for every weighting and both precisions; an octahedron at 1e77
// and 1e-78 (not powers of two) keeps its analytic normals under every weighting.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <shadetool/geometry/scaled_length.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/engine/normalise_sums.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include "normals_test_util.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

const Weighting kWeightings[] = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
const Precision kPrecisions[] = {Precision::Double, Precision::Float};

std::string name(Weighting w, Precision p) {
  const char* ws[] = {"uniform", "area", "angle", "max"};
  return std::string(ws[int(w)]) + (p == Precision::Float ? "/float" : "/double");
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Nonzero coordinates below 2^-20 in magnitude set to 0, so that every 2^k with k >= -1000 keeps
// them normal (2^-1020 > DBL_MIN = 2^-1022).
Mesh keep_normal_when_scaled(Mesh m) {
  for (double& x : m.positions)
    if (std::fabs(x) < std::ldexp(1.0, -20)) x = 0.0;
  return m;
}

Mesh scaled(const Mesh& m, double s) {
  Mesh r = m;
  for (double& x : r.positions) x *= s;
  return r;
}

Mesh octahedron() {
  Mesh m;
  for (Vec3d p : {Vec3d{1, 0, 0}, Vec3d{-1, 0, 0}, Vec3d{0, 1, 0}, Vec3d{0, -1, 0}, Vec3d{0, 0, 1}, Vec3d{0, 0, -1}})
    m.add_vertex(p);
  // outward: (x, y, z) with signs of the octant, counter-clockwise seen from outside
  m.add_face({0, 2, 4}); m.add_face({2, 1, 4}); m.add_face({1, 3, 4}); m.add_face({3, 0, 4});
  m.add_face({2, 0, 5}); m.add_face({1, 2, 5}); m.add_face({3, 1, 5}); m.add_face({0, 3, 5});
  return m;
}

// A jittered latitude-longitude sphere of quads with triangle fans at the poles and one ring of
// pentagons (a quad with its edge midpoint split in two): triangles, quads and pentagons.
Mesh polygon_sphere() {
  const int nu = 12, nv = 7;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> J(-0.02, 0.02);
  Mesh m;
  m.add_vertex({0, 0, 1});
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = kPi * (j + J(rng)) / nv, ph = 2 * kPi * (i + J(rng)) / nu, r = 1 + J(rng);
      m.add_vertex({r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)});
    }
  const std::uint32_t south = m.add_vertex({0.01, -0.02, -0.97});
  auto ring = [&](int j, int i) { return std::uint32_t(1 + (j - 1) * nu + (i % nu)); };
  for (int i = 0; i < nu; ++i) m.add_face({0, ring(1, i), ring(1, i + 1)});
  for (int j = 1; j + 1 < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      if (j == 3) {  // pentagon: the quad with a point just outside the middle of its top edge
        const Vec3d a = m.position(ring(j, i)), b = m.position(ring(j, i + 1));
        const std::uint32_t mid = m.add_vertex((a + b) * 0.5 * 1.01);
        m.add_face({ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i + 1), mid});
      } else {
        m.add_face({ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i + 1)});
      }
    }
  for (int i = 0; i < nu; ++i) m.add_face({ring(nv - 1, i), south, ring(nv - 1, i + 1)});
  return m;
}

struct TestMesh {
  const char* name;
  Mesh mesh;
};

std::vector<TestMesh> test_meshes() {
  return {{"octahedron", keep_normal_when_scaled(octahedron())},
          {"irregular sphere", keep_normal_when_scaled(irregular(icosphere(2, 0.3)).mesh)},
          {"polygon sphere", keep_normal_when_scaled(polygon_sphere())}};
}

// Every output of the three normals functions for one weighting and precision.
struct AllNormals {
  VertexNormals vertex;
  std::vector<double> face;
  CornerNormals corner;
};

AllNormals all_normals(const Mesh& m, Weighting w, Precision p) {
  return {vertex_normals(m, w, p), face_normals(m, p), corner_normals(m, 30.0 * kPi / 180.0, w, p)};
}

void require_same(const AllNormals& got, const AllNormals& want) {
  CHECK(same_bits(got.vertex.normals, want.vertex.normals));
  CHECK(got.vertex.fallback_vertices == want.vertex.fallback_vertices);
  CHECK(got.vertex.degenerate_faces == want.vertex.degenerate_faces);
  CHECK(same_bits(got.face, want.face));
  CHECK(same_bits(got.corner.normals, want.corner.normals));
  CHECK(got.corner.corner_index == want.corner.corner_index);
  CHECK(got.corner.fallback_corners == want.corner.fallback_corners);
}

}  // namespace

TEST_CASE("normals of a mesh scaled by 2^k, k = -1000..1000 step 50, are bitwise those at scale 1",
          "[normals][scale]") {
  for (const TestMesh& t : test_meshes()) {
    for (Weighting w : kWeightings)
      for (Precision p : kPrecisions) {
        const AllNormals base = all_normals(t.mesh, w, p);
        REQUIRE(base.vertex.fallback_vertices == 0);
        REQUIRE(base.vertex.degenerate_faces == 0);
        for (int k = -1000; k <= 1000; k += 50) {
          INFO(t.name << " " << name(w, p) << " scale 2^" << k);
          require_same(all_normals(scaled(t.mesh, std::ldexp(1.0, k)), w, p), base);
        }
      }
  }
}

TEST_CASE("normals at the extreme exponents 2^-1020 and 2^1022 are bitwise those at scale 1", "[normals][scale]") {
  // Largest coordinate below 2 (so 2^1022 keeps it finite); smallest nonzero >= 2^-20 (normal at 2^-1000).
  for (const TestMesh& t : test_meshes())
    for (Weighting w : kWeightings)
      for (Precision p : kPrecisions) {
        const AllNormals base = all_normals(t.mesh, w, p);
        for (int k : {-1000, -1001, 1022, 1021, 999}) {
          INFO(t.name << " " << name(w, p) << " scale 2^" << k);
          require_same(all_normals(scaled(t.mesh, std::ldexp(1.0, k)), w, p), base);
        }
      }
}

TEST_CASE("a mesh of 80k faces (threads, sampled scale) scaled by 2^k gives bitwise its normals at scale 1",
          "[normals][scale]") {
  const Mesh m = keep_normal_when_scaled(irregular(icosphere(6, 0.3)).mesh);
  for (Weighting w : kWeightings)
    for (Precision p : kPrecisions) {
      const VertexNormals base = vertex_normals(m, w, p);
      for (int k : {-900, -300, 300, 900}) {
        INFO(name(w, p) << " scale 2^" << k);
        const VertexNormals got = vertex_normals(scaled(m, std::ldexp(1.0, k)), w, p);
        CHECK(same_bits(got.normals, base.normals));
        CHECK(got.fallback_vertices == base.fallback_vertices);
      }
    }
}

TEST_CASE("a mesh with a far isolated vertex (2^40 away) scaled by 2^k gives bitwise its normals at scale 1",
          "[normals][scale]") {
  Mesh m = keep_normal_when_scaled(irregular(icosphere(2, 0.3)).mesh);
  m.add_vertex({std::ldexp(1.0, 40), 0.5, -0.25});  // in no face: its normal is the fallback
  for (Weighting w : kWeightings)
    for (Precision p : kPrecisions) {
      const AllNormals base = all_normals(m, w, p);
      CHECK(base.vertex.fallback_vertices == 1);
      for (int k = -1000; k <= 950; k += 50) {
        INFO(name(w, p) << " scale 2^" << k);
        require_same(all_normals(scaled(m, std::ldexp(1.0, k)), w, p), base);
      }
    }
}

TEST_CASE("an octahedron at 1e77, 1e-78, 1e300 and 1e-300 has its analytic normals under every weighting",
          "[normals][scale]") {
  const Mesh unit = octahedron();
  const double s3 = 1 / std::sqrt(3.0);
  for (double s : {1.0, 1e77, 1e-78, 1e150, 1e-150, 1e300, 1e-300}) {
    const Mesh m = scaled(unit, s);
    for (Weighting w : kWeightings)
      for (Precision p : kPrecisions) {
        INFO(name(w, p) << " scale " << s);
        const double tol = p == Precision::Float ? 1e-3 : 1e-9;  // degrees
        const VertexNormals vn = vertex_normals(m, w, p);
        CHECK(vn.fallback_vertices == 0);
        CHECK(vn.degenerate_faces == 0);
        for (std::size_t v = 0; v < 6; ++v)  // the vertex itself, a unit axis vector
          CHECK(angle_degrees(get3(vn.normals, v), unit.position(std::uint32_t(v))) < tol);
        const std::vector<double> fn = face_normals(m, p);
        for (std::size_t f = 0; f < m.num_faces(); ++f) {
          Vec3d c{};
          for (std::uint32_t k = 0; k < 3; ++k) c += unit.position(unit.corner_vertex[3 * f + k]);
          CHECK(angle_degrees(get3(fn, f), c * s3) < tol);  // (+-1, +-1, +-1) / sqrt 3
        }
        // crease 30 degrees: every edge (dihedral 70.5 degrees) splits, so each corner has its face's normal
        const CornerNormals cn = corner_normals(m, 30.0 * kPi / 180.0, w, p);
        CHECK(cn.fallback_corners == 0);
        for (std::size_t c = 0; c < m.num_corners(); ++c)
          CHECK(angle_degrees(get3(cn.normals, cn.corner_index[c]), get3(fn, c / 3)) < tol);
      }
  }
}

TEST_CASE("vertex sums are normalised by the one safe normalise (scaled_length.h), bitwise, tiny and huge sums included",
          "[normals][scale]") {
  // Pairs of rows through normalise_range's SSE2 path and its scalar fallback, against
  // normalise_checked row by row: in range, both out of range, one of each, zero, Inf.
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> sum;
  for (int k = -1070; k <= 1020; k += 30)
    for (Vec3d v : {Vec3d{1, 2, 2}, Vec3d{-0.3, 1e-5, 0.7}, Vec3d{3, 4, 0}}) {
      const Vec3d s = v * std::ldexp(1.0, k);
      sum.insert(sum.end(), {s.x, s.y, s.z});
    }
  sum.insert(sum.end(), {0, 0, 0, inf, 1, 0, 1, 1, 1});
  const std::size_t rows = sum.size() / 3;
  std::vector<double> out(sum.size(), -7.0);
  std::vector<std::uint32_t> failed;
  normals_detail::normalise_range<double>(sum.data(), out.data(), 0, rows, failed);
  std::vector<std::uint32_t> want_failed;
  for (std::size_t r = 0; r < rows; ++r) {
    double o[3];
    if (!normalise_checked(sum[3 * r], sum[3 * r + 1], sum[3 * r + 2], o)) { want_failed.push_back(std::uint32_t(r)); continue; }
    INFO("row " << r);
    CHECK(std::memcmp(o, &out[3 * r], sizeof o) == 0);
  }
  CHECK(failed == want_failed);
  CHECK(want_failed.size() == 2);
}
