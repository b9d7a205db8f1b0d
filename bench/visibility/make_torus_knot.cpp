// make_torus_knot.cpp: a (2,3) torus knot tube, a closed mesh with real concavities (the strands
// shade each other), for the occlusion example (data/torus_knot.ply) and the visibility benchmark.
//
//   make_torus_knot ALONG AROUND OUT.ply   -> 2 * ALONG * AROUND triangles, ALONG * AROUND vertices
//
// Curve c(t) = ((2 + cos 3t) cos 2t, (2 + cos 3t) sin 2t, sin 3t), t in [0, 2 pi); the tube of
// radius 0.35 around it is swept with the frame (T, N, B): T = c'/|c'|, N = the direction from the
// torus's core circle to c(t) made orthogonal to T, B = T x N (periodic, so the tube closes).
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <shadetool/core/mesh.h>
#include <shadetool/files/mesh_files.h>

using shadetool::Vec3d;

namespace {

Vec3d curve(double t) {
  const double r = 2 + std::cos(3 * t);
  return {r * std::cos(2 * t), r * std::sin(2 * t), std::sin(3 * t)};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: make_torus_knot ALONG AROUND OUT.ply\n");
    return 2;
  }
  const int along = std::atoi(argv[1]), around = std::atoi(argv[2]);
  if (along < 8 || around < 3) {
    std::fprintf(stderr, "make_torus_knot: ALONG >= 8 and AROUND >= 3\n");
    return 2;
  }
  const double pi = 3.14159265358979323846, tube = 0.35;
  shadetool::Mesh m;
  for (int i = 0; i < along; ++i) {
    const double t = 2 * pi * i / along, h = 1e-5;
    const Vec3d c = curve(t);
    const Vec3d T = shadetool::normalized_or(curve(t + h) - curve(t - h), Vec3d{1, 0, 0});
    const Vec3d radial{std::cos(3 * t) * std::cos(2 * t), std::cos(3 * t) * std::sin(2 * t), std::sin(3 * t)};
    const Vec3d N = shadetool::normalized_or(radial - T * dot(T, radial), Vec3d{0, 0, 1});
    const Vec3d B = cross(T, N);
    for (int j = 0; j < around; ++j) {
      const double a = 2 * pi * j / around;
      m.add_vertex(c + (N * std::cos(a) + B * std::sin(a)) * tube);
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t((i % along) * around + (j % around)); };
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < around; ++j) {
      // dp/di x dp/dj = T x (-N sin a + B cos a) = -(N cos a + B sin a): inward, so wound j-first.
      m.add_face({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      m.add_face({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
    }
  shadetool::WriteOptions o;
  o.format = shadetool::Format::Ply;
  o.binary = true;
  shadetool::write_mesh(m, argv[3], o);
  std::printf("%zu vertices, %zu triangles\n", m.num_vertices(), m.num_faces());
  return 0;
}
