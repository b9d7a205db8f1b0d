// Numerical stress tests of lib/repair: orientation decided right far from the origin (1e6,
// 1e8), at scales 1e-30 and 1e30, and with slivers of aspect 1e8 in the mesh. The truth is the
// analytic mesh's own outward winding: repair of the wholly inverted mesh, or of the mesh with a
// random 30% of faces flipped, must give back exactly the original faces (same corners, same
// order, same first corner), every time.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include <shadetool/core/mesh.h>
#include <shadetool/repair/repair_mesh.h>
#include "stress/stress_util.h"
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

// Reverses face f keeping its first corner (what repair's reverse_faces does): a b c d -> a d c b.
void flip(Mesh& m, std::size_t f) {
  std::reverse(m.corner_vertex.begin() + m.face_start[f] + 1, m.corner_vertex.begin() + m.face_start[f + 1]);
}

Mesh positioned(const Mesh& base, double scale, double offset) {
  Mesh m = base;
  m.precision = ValuePrecision::Double;
  for (std::size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = m.positions[i] * scale + offset * (i % 3 == 2 ? -1 : 1);
  return m;
}

}  // namespace

TEST_CASE("stress repair: inverted and 30%-flipped closed meshes come back exactly, far away and at any scale",
          "[stress][repair]") {
  // Signed volume relative to the component's centroid (repair's step 2): at offset 1e8 a unit
  // torus's volume (2 pi^2 R r^2 = 3.2) is still computed from coordinates of size ~1; without the
  // centroid it would be the difference of terms ~1e24, all rounding. At scale 1e-30 the volume is
  // ~1e-90 and at 1e30 ~1e90: far inside double, so the sign is right if nothing squares lengths
  // needlessly. Expected: exactly the original faces in every case.
  const testing::AnalyticMesh torus = testing::torus(48, 24, 1.0, 0.4, 0.2, 3);
  const testing::AnalyticMesh sphere = testing::icosphere(3, 0.2, 4);
  for (const auto* am : {&torus, &sphere}) {
    for (double scale : {1.0, 1e-30, 1e30}) {
      for (double offset : {0.0, 1e6, 1e8}) {
        if (scale != 1.0 && offset != 0.0) continue;  // offsets are relative to unit size
        const Mesh original = positioned(am->mesh, scale, offset);
        INFO((am == &torus ? "torus" : "sphere") << " scale " << scale << " offset " << offset);
        Mesh inverted = original;
        for (std::size_t f = 0; f < inverted.num_faces(); ++f) flip(inverted, f);
        Mesh flipped = original;
        std::mt19937 rng(11);
        for (std::size_t f = 0; f < flipped.num_faces(); ++f)
          if (rng() % 10 < 3) flip(flipped, f);
        for (Mesh* m : {&inverted, &flipped}) {
          repair_mesh(*m);
          CHECK(m->face_start == original.face_start);
          CHECK(m->corner_vertex == original.corner_vertex);
          CHECK(m->positions == original.positions);
          CHECK(stress::all_finite(m->vertex_normals));
          // and repairing again changes nothing
          const RepairReport again = repair_mesh(*m);
          CHECK(again.changes() == 0);
        }
      }
    }
  }
}

TEST_CASE("stress repair: slivers of aspect 1e8 and zero-area faces do not mislead the orientation", "[stress][repair]") {
  // A closed tetrahedron-like solid whose every face is split by a cap of aspect ~1e8 (an extra
  // vertex 2^-27 off an edge's midpoint), plus a zero-area face, all inverted: repair must orient
  // all of them outward again (the caps' own normals are noise; the winding propagates through
  // their edges), keep every face (no --remove-degenerate), and give finite normals.
  Mesh m;
  m.precision = ValuePrecision::Double;
  const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0}), d = m.add_vertex({0, 0, 1});
  // Face (a, c, b) split at the midpoint of a-b by a point just outside it (in z, off the face).
  const double h = std::ldexp(1.0, -27);
  const auto ab = m.add_vertex({0.5, -h, 0});
  m.add_face({a, c, b, ab});  // a quad with a sliver corner: still the outward bottom face
  m.add_face({a, ab, b, d});  // the front face through the sliver corner
  m.add_face({a, d, c});
  m.add_face({b, c, d});
  m.add_face({a, a, d});  // zero area (repeated index)
  const Mesh original = m;
  Mesh inverted = original;
  for (std::size_t f = 0; f < inverted.num_faces(); ++f) flip(inverted, f);
  const RepairReport rep = repair_mesh(inverted);
  CHECK(inverted.num_faces() == original.num_faces());
  for (std::size_t f = 0; f + 1 < original.num_faces(); ++f) {  // the degenerate face is left alone
    INFO("face " << f);
    CHECK(std::vector<std::uint32_t>(inverted.corner_vertex.begin() + inverted.face_start[f],
                                     inverted.corner_vertex.begin() + inverted.face_start[f + 1]) ==
          std::vector<std::uint32_t>(original.corner_vertex.begin() + original.face_start[f],
                                     original.corner_vertex.begin() + original.face_start[f + 1]));
  }
  CHECK(stress::all_finite(inverted.vertex_normals));
  (void)rep;
}
