// Tests of issue 21 item 12: meshes split at their texture seams are oriented as the closed
// surfaces they are (seam_join.h), and closed sheets too thin for a volume sign follow their
// authored normals (authored_normals_vote.h). The truth is geometric: on a sphere centred at the
// origin every face's area vector points away from the origin.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/repair/repair_mesh.h>
#include <shadetool/repair/seam_join.h>
#include <shadetool/core/edge_adjacency.h>

using namespace shadetool;

namespace {

// A latitude-longitude sphere of radius 1 (quads, triangles at the poles) split as an exporter
// splits it at UV seams: every band of `band` columns is an island with vertices of its own
// (positions bitwise equal along the cuts). Faces wound outward; islands listed in `flip` are
// reversed as a whole (an island authored inside out), and faces f % 7 == 3 of the rest reversed
// singly (sloppy winding).
Mesh seam_split_sphere(int columns, int rows, int band, const std::vector<int>& flip) {
  Mesh m;
  auto position = [&](int i, int j) {  // column i (mod columns), row j in 0..rows
    const double phi = kTwoPi * (i % columns) / columns, theta = kPi * j / rows;
    if (j == 0 || j == rows) return Vec3d{0, 0, j == 0 ? 1.0 : -1.0};  // one pole position per pole, as exporters write
    return Vec3d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  };
  for (int b = 0; b * band < columns; ++b) {
    const int i0 = b * band, i1 = std::min(columns, i0 + band);
    const std::uint32_t base = std::uint32_t(m.num_vertices());
    for (int i = i0; i <= i1; ++i)
      for (int j = 0; j <= rows; ++j) m.add_vertex(position(i, j));
    auto id = [&](int i, int j) { return base + std::uint32_t((i - i0) * (rows + 1) + j); };
    const bool flipped = std::find(flip.begin(), flip.end(), b) != flip.end();
    for (int i = i0; i < i1; ++i)
      for (int j = 0; j < rows; ++j) {
        // Outward: (i, j) -> (i, j+1) -> (i+1, j+1) -> (i+1, j) seen from outside.
        std::vector<std::uint32_t> f = j == 0          ? std::vector<std::uint32_t>{id(i, 0), id(i, 1), id(i + 1, 1)}
                                       : j == rows - 1 ? std::vector<std::uint32_t>{id(i, j), id(i, j + 1), id(i + 1, j)}
                                                       : std::vector<std::uint32_t>{id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)};
        const bool sloppy = !flipped && m.num_faces() % 7 == 3;
        if (flipped != sloppy) std::reverse(f.begin(), f.end());
        m.add_face(f);
      }
  }
  return m;
}

// Faces whose area vector points toward the sphere's centre.
std::size_t inward_faces(const Mesh& m) {
  std::size_t n = 0;
  for (std::size_t f = 0; f < m.num_faces(); ++f) {
    Vec3d N{0, 0, 0}, c{0, 0, 0};
    const std::uint32_t b = m.face_start[f], e = m.face_start[f + 1];
    for (std::uint32_t k = b; k < e; ++k) {
      N += cross(m.position(m.corner_vertex[k]), m.position(m.corner_vertex[k + 1 < e ? k + 1 : b]));
      c += m.position(m.corner_vertex[k]);
    }
    if (dot(N, c) < 0) ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("seam_join joins exactly the boundary vertices at another's position", "[repair][seams]") {
  const Mesh m = seam_split_sphere(24, 12, 4, {});
  const EdgeAdjacency before = edge_adjacency(m);
  REQUIRE(before.boundary_edges > 0);  // islands, and a pole vertex per column
  const SeamJoin join = seam_join(m, before);
  CHECK(join.joined > 0);
  REQUIRE(join.corner_vertex.size() == m.num_corners());
  for (std::size_t c = 0; c < m.num_corners(); ++c)
    CHECK(m.position(join.corner_vertex[c]) == m.position(m.corner_vertex[c]));  // same place, maybe a lower index
  // Joined, the sphere is closed and manifold: every edge has exactly two faces.
  Mesh joined = m;
  joined.corner_vertex = join.corner_vertex;
  const EdgeAdjacency after = edge_adjacency(joined);
  CHECK(after.boundary_edges == 0);
  CHECK(after.non_manifold_edges == 0);
  // Each vertex replaced was a boundary vertex at the position of a lower-numbered one.
  std::size_t replaced = 0;
  for (std::uint32_t v = 0; v < m.num_vertices(); ++v) {
    bool moved = false;
    for (std::size_t c = 0; c < m.num_corners(); ++c)
      if (m.corner_vertex[c] == v && join.corner_vertex[c] != v) {
        CHECK(join.corner_vertex[c] < v);
        moved = true;
      }
    replaced += moved;
  }
  // Unreferenced vertices (the last column's poles of each island) are joined too but appear in
  // no corner; so the corners show at most `joined` replacements.
  CHECK(replaced > 0);
  CHECK(replaced <= join.joined);
}

TEST_CASE("A sphere split at its seams, islands inverted, comes out wholly outward", "[repair][seams]") {
  Mesh m = seam_split_sphere(24, 12, 4, {1, 4});
  const std::size_t vertices = m.num_vertices();
  REQUIRE(inward_faces(m) > 0);
  const RepairReport r = repair_mesh(m);
  CHECK(inward_faces(m) == 0);
  CHECK(r.seam_vertices_joined > 0);
  CHECK(r.components == 1);
  CHECK(r.closed_components == 1);
  CHECK(r.oriented_by_volume == 1);
  CHECK(m.num_vertices() == vertices);  // joined for the decision only: no vertex merged
  Mesh again = m;
  CHECK(repair_mesh(again).changes() == 0);
}

TEST_CASE("An island-split sphere with every island inverted and a sloppy winding", "[repair][seams]") {
  // One island per column: 24 open strips, half of them authored inside out.
  Mesh m = seam_split_sphere(24, 12, 1, {0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22});
  const RepairReport r = repair_mesh(m);
  CHECK(r.closed_components == 1);
  CHECK(inward_faces(m) == 0);
}

namespace {

// A closed pillow of zero or tiny thickness t: an n x n grid on top (z = t * bump) and one below
// (z = 0), sharing their rim vertices. Wound so that the top faces +z and the bottom -z when
// `outward`, the other way round otherwise. Corner normals as authored: +z on top, -z below.
Mesh pillow(int n, double t, bool outward) {
  Mesh m;
  auto rim = [&](int i, int j) { return i == 0 || j == 0 || i == n || j == n; };
  std::vector<std::uint32_t> top((n + 1) * (n + 1)), bottom((n + 1) * (n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = double(i) / n, y = double(j) / n;
      const double bump = rim(i, j) ? 0.0 : t * std::sin(kPi * x) * std::sin(kPi * y);
      top[i * (n + 1) + j] = m.add_vertex({x, y, bump});
      bottom[i * (n + 1) + j] = rim(i, j) ? top[i * (n + 1) + j] : m.add_vertex({x, y, 0.0});
    }
  m.corner_normals = {0, 0, 1, 0, 0, -1};
  for (int side = 0; side < 2; ++side)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const auto& g = side == 0 ? top : bottom;
        std::vector<std::uint32_t> f = {g[i * (n + 1) + j], g[(i + 1) * (n + 1) + j], g[(i + 1) * (n + 1) + j + 1],
                                        g[i * (n + 1) + j + 1]};  // +z by the right-hand rule
        if ((side == 1) == outward) std::reverse(f.begin(), f.end());
        m.add_face(f);
        for (int k = 0; k < 4; ++k) m.corner_normal_index.push_back(std::uint32_t(side));
      }
  return m;
}

// +1 if the top faces +z (as authored), -1 if -z.
int top_facing(const Mesh& m) {
  const std::uint32_t b = m.face_start[0];
  const Vec3d N = cross(m.position(m.corner_vertex[b + 1]) - m.position(m.corner_vertex[b]),
                        m.position(m.corner_vertex[b + 2]) - m.position(m.corner_vertex[b]));
  return N.z > 0 ? 1 : -1;
}

}  // namespace

TEST_CASE("A closed sheet of zero volume follows its authored normals", "[repair][normals-evidence]") {
  for (bool outward : {true, false}) {
    Mesh m = pillow(6, 0.0, outward);
    REQUIRE(top_facing(m) == (outward ? 1 : -1));
    const RepairReport r = repair_mesh(m);
    CHECK(r.closed_components == 1);
    // Wound as its normals say: kept as authored; wound against them: the normals decide.
    CHECK(r.oriented_by_agreement == (outward ? 1u : 0u));
    CHECK(r.oriented_by_normals == (outward ? 0u : 1u));
    CHECK(top_facing(m) == 1);
  }
}

TEST_CASE("A closed shell too thin for its volume's sign follows its authored normals", "[repair][normals-evidence]") {
  // Thickness 1e-5 of a unit sheet: |V| / (A L) ~ 1e-6, far below the 1e-3 rule. The wound-inward
  // version has a (tiny) negative volume; its normals say +z on top: they win.
  Mesh m = pillow(6, 1e-5, false);
  const RepairReport r = repair_mesh(m);
  CHECK(r.oriented_by_normals == 1);
  CHECK(top_facing(m) == 1);
  // A thick pillow (t = 0.5) wound outward with normals authored inward: the normals contradict
  // the winding, so they are no statement; the volume decides (and keeps it).
  Mesh thick = pillow(6, 0.5, true);
  for (auto& x : thick.corner_normals) x = -x;
  const RepairReport rt = repair_mesh(thick);
  CHECK(rt.oriented_by_volume == 1);
  CHECK(rt.oriented_by_normals == 0);
  CHECK(top_facing(thick) == 1);
  // Wound inward with normals inward too: winding and normals agree, kept as authored (issue 27).
  Mesh in = pillow(6, 0.5, false);
  for (auto& x : in.corner_normals) x = -x;
  const RepairReport ri = repair_mesh(in);
  CHECK(ri.oriented_by_agreement == 1);
  CHECK(ri.faces_flipped == 0);
  CHECK(top_facing(in) == -1);
}
