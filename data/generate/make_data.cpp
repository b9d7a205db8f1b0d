// make_data.cpp: writes the sample meshes in data/ (run data/generate/make_data.sh).
//
// Every mesh is made by code here from closed-form geometry, so the files can be regenerated and
// their truth is known:
//   cube.obj                  unit cube [-1,1]^3, 8 vertices, 12 triangles, wound outward
//   torus.obj                 torus R = 1, r = 0.4, 48 x 24 vertices, 2304 triangles, double
//                             (tests/support/analytic_meshes.h: exact normal at each vertex)
//   icosphere.ply             icosahedron subdivided 3 times on the unit sphere, 642 vertices,
//                             binary PLY, double, uchar vertex colours = round(255 (n + 1) / 2)
//   quad_sphere.obj           cube subdivided 8 x 8 per side, projected onto the unit sphere:
//                             386 vertices, 384 quads
//   dodecahedron.off          regular dodecahedron on the sphere of radius sqrt(3): 20 vertices,
//                             12 pentagons, one integer RGB colour per face
//   inconsistent_winding.obj  icosphere (1 subdivision, 80 faces) with faces 0, 7, 14, ... (12 of
//                             them) reversed: 36 edges are wound the same way by both faces
//   non_manifold.obj          a fin (3 triangles on one edge), a bow-tie (2 triangles meeting at
//                             one vertex), a duplicated triangle and an isolated vertex
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/mesh_io.h"
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

void save(const Mesh& mesh, const std::string& path, const std::string& comment, bool binary = true) {
  WriteOptions o;
  o.format = format_from_extension(path);
  o.binary = binary;
  std::string bytes = write_mesh_to_memory(mesh, o);
  if (o.format == Format::Obj) {
    std::string header;
    std::size_t b = 0;
    while (b < comment.size()) {
      std::size_t e = comment.find('\n', b);
      if (e == std::string::npos) e = comment.size();
      header += "# " + comment.substr(b, e - b) + "\n";
      b = e + 1;
    }
    bytes = header + bytes;
  }
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) {
    std::perror(path.c_str());
    std::exit(1);
  }
  std::fclose(f);
  std::printf("%s: %zu vertices, %zu faces, %zu bytes\n", path.c_str(), mesh.num_vertices(), mesh.num_faces(), bytes.size());
}

Mesh cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) m.add_vertex({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  // vertex i has x = bit 0, y = bit 1, z = bit 2; each side as two triangles, counter-clockwise
  // seen from outside.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (auto& q : quads) {
    m.add_face({q[0], q[1], q[2]});
    m.add_face({q[0], q[2], q[3]});
  }
  m.precision = ValuePrecision::Float;
  return m;
}

Mesh quad_sphere(int n) {
  Mesh m;
  std::map<std::tuple<int, int, int>, std::uint32_t> ids;  // lattice point on the cube -> vertex
  auto vertex = [&](int x, int y, int z) {
    auto key = std::make_tuple(x, y, z);
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    const Vec3d p{2.0 * x / n - 1, 2.0 * y / n - 1, 2.0 * z / n - 1};
    return ids[key] = m.add_vertex(p * (1.0 / length(p)));
  };
  // For each side: axis a fixed at 0 or n; (u, v) span the other two so that u x v points out.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u_axis = (axis + 1) % 3, v_axis = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto at = [&](int a, int b) {
            int c[3];
            c[axis] = side * n;
            c[u_axis] = a;
            c[v_axis] = b;
            return vertex(c[0], c[1], c[2]);
          };
          if (side == 1) m.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
          else m.add_face({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
  m.precision = ValuePrecision::Double;
  return m;
}

Mesh dodecahedron() {
  Mesh m;
  const double phi = (1 + std::sqrt(5.0)) / 2, iphi = 1 / phi;
  std::vector<Vec3d> P;
  for (int i = 0; i < 8; ++i) P.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  for (int s = 0; s < 4; ++s) {
    const double a = s & 1 ? iphi : -iphi, b = s & 2 ? phi : -phi;
    P.push_back({0, a, b});
    P.push_back({a, b, 0});
    P.push_back({b, 0, a});
  }
  for (auto& p : P) m.add_vertex(p);
  // Face centres point at the icosahedron's vertices (0, ±phi, ±1) and cyclic shifts; the face
  // is the 5 vertices nearest that direction, ordered counter-clockwise around it.
  std::vector<Vec3d> centres;
  for (int s = 0; s < 4; ++s) {
    const double a = s & 1 ? phi : -phi, b = s & 2 ? 1.0 : -1.0;
    centres.push_back({0, a, b});
    centres.push_back({a, b, 0});
    centres.push_back({b, 0, a});
  }
  const std::uint8_t palette[12][3] = {{230, 25, 75},  {60, 180, 75},  {255, 225, 25}, {0, 130, 200},
                                       {245, 130, 48}, {145, 30, 180}, {70, 240, 240}, {240, 50, 230},
                                       {210, 245, 60}, {250, 190, 212}, {0, 128, 128}, {170, 110, 40}};
  for (std::size_t f = 0; f < centres.size(); ++f) {
    const Vec3d d = centres[f] * (1.0 / length(centres[f]));
    std::vector<std::pair<double, std::uint32_t>> near;
    for (std::uint32_t v = 0; v < P.size(); ++v) near.push_back({-dot(d, P[v]), v});
    std::sort(near.begin(), near.end());
    const Vec3d e1 = P[near[0].second] - d * dot(d, P[near[0].second]);
    const Vec3d e2 = cross(d, e1);
    std::vector<std::pair<double, std::uint32_t>> ring;
    for (int k = 0; k < 5; ++k) {
      const Vec3d p = P[near[std::size_t(k)].second];
      ring.push_back({std::atan2(dot(p, e2), dot(p, e1)), near[std::size_t(k)].second});
    }
    std::sort(ring.begin(), ring.end());
    std::vector<std::uint32_t> face;
    for (auto& r : ring) face.push_back(r.second);
    m.add_face(face);
    for (int k = 0; k < 3; ++k) m.face_colors.push_back(palette[f][k] / 255.0f);
  }
  m.color_channels = 3;
  m.colors_are_float = false;
  m.precision = ValuePrecision::Double;
  return m;
}

Mesh non_manifold() {
  Mesh m;
  // fin: edge 0-1 shared by three triangles
  m.add_vertex({0, 0, 0});
  m.add_vertex({1, 0, 0});
  m.add_vertex({0.5, 1, 0});
  m.add_vertex({0.5, -1, 0});
  m.add_vertex({0.5, 0, 1});
  m.add_face({0, 1, 2});
  m.add_face({1, 0, 3});
  m.add_face({0, 1, 4});
  // bow-tie: two triangles meeting only at vertex 5
  m.add_vertex({3, 0, 0});
  m.add_vertex({4, 1, 0});
  m.add_vertex({4, -1, 0});
  m.add_vertex({2, 1, 0});
  m.add_vertex({2, -1, 0});
  m.add_face({5, 7, 6});
  m.add_face({5, 8, 9});
  // duplicated triangle
  m.add_vertex({0, 3, 0});
  m.add_vertex({1, 3, 0});
  m.add_vertex({0, 4, 0});
  m.add_face({10, 11, 12});
  m.add_face({10, 11, 12});
  // isolated vertex
  m.add_vertex({5, 5, 5});
  m.precision = ValuePrecision::Float;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "data";
  save(cube(), dir + "/cube.obj", "unit cube [-1,1]^3: 8 vertices, 12 triangles wound outward (data/generate/make_data.cpp)");
  save(testing::torus(48, 24).mesh, dir + "/torus.obj",
       "torus R = 1, r = 0.4 around z: 48 x 24 vertices, 2304 triangles (data/generate/make_data.cpp)");
  {
    Mesh ico = testing::icosphere(3).mesh;
    for (std::size_t v = 0; v < ico.num_vertices(); ++v)
      for (int k = 0; k < 3; ++k)
        ico.vertex_colors.push_back(float(std::lround(255.0 * (ico.positions[3 * v + std::size_t(k)] + 1) / 2)) / 255.0f);
    ico.color_channels = 3;
    ico.colors_are_float = false;
    save(ico, dir + "/icosphere.ply", "");
  }
  save(quad_sphere(8), dir + "/quad_sphere.obj",
       "cube subdivided 8 x 8 per side and projected onto the unit sphere: 384 quads (data/generate/make_data.cpp)");
  save(dodecahedron(), dir + "/dodecahedron.off", "");
  {
    Mesh ico = testing::icosphere(1).mesh;
    for (std::size_t f = 0; f < ico.num_faces(); f += 7)
      std::reverse(ico.corner_vertex.begin() + ico.face_start[f], ico.corner_vertex.begin() + ico.face_start[f + 1]);
    save(ico, dir + "/inconsistent_winding.obj",
         "icosphere (80 triangles) with faces 0, 7, 14, ... reversed: inconsistent winding (data/generate/make_data.cpp)");
  }
  save(non_manifold(), dir + "/non_manifold.obj",
       "a fin (edge 1-2 shared by 3 triangles), a bow-tie at vertex 6, a duplicated triangle and an\n"
       "isolated vertex (data/generate/make_data.cpp)");
  return 0;
}
