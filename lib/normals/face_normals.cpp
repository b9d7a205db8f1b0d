// face_normals.cpp: one unit normal per face (see face_normals.h).
//
// Triangles: cross product of the two shortest edges; polygons: Newell's method (face_geometry.h).
// Precision: both compute in double (edges, cross product, length, division); Float then rounds
// the unit normal once to float (relative error <= 2^-24 per component, so within ~1e-5 deg of
// Double whatever the triangle's shape or the mesh's scale: 1e-30 and 1e30 included) and widens it
// back to double. Float therefore costs what Double costs here; it exists so that a float run is
// float throughout. A degenerate face (fewer than 3 corners, zero area,
// repeated index, non-finite position) gets (0, 0, 0).
#include <shadetool/normals/face_normals.h>

#include <shadetool/normals/face_geometry.h>
#include <shadetool/core/engine/parallel.h>

namespace shadetool {
namespace {

using namespace normals_detail;

template <class T>
void face_normals_range(const Mesh& mesh, std::size_t f_begin, std::size_t f_end, double* out) {
  const double* P = mesh.positions.data();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const bool triangles = mesh.all_triangles();
  for (std::size_t f = f_begin; f < f_end; ++f) {
    Vec3d N;
    if (triangles || mesh.face_size(f) == 3) {
      const std::size_t c = triangles ? 3 * f : mesh.face_start[f];
      const Vec3d p0 = load_position(P, cv[c]), p1 = load_position(P, cv[c + 1]), p2 = load_position(P, cv[c + 2]);
      const Vec3d e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
      N = triangle_area_vector(P, cv[c], cv[c + 1], cv[c + 2], dot(e0, e0), dot(e1, e1), dot(e2, e2));
    } else {
      N = newell_area_vector(mesh, f);
    }
    const double l = checked_length(N);
    double* o = out + 3 * f;
    if (l > 0.0) {  // divisor checked: non-zero and finite
      o[0] = double(T(N.x / l)); o[1] = double(T(N.y / l)); o[2] = double(T(N.z / l));
    } else {        // degenerate face: zero normal, never NaN
      o[0] = o[1] = o[2] = 0.0;
    }
  }
}

}  // namespace

std::vector<double> face_normals(const Mesh& mesh, Precision precision) {
  const std::size_t F = mesh.num_faces();
  std::vector<double> out(3 * F);
  engine::parallel_ranges(F, [&](std::size_t b, std::size_t e) {
    if (precision == Precision::Float) face_normals_range<float>(mesh, b, e, out.data());
    else face_normals_range<double>(mesh, b, e, out.data());
  });
  return out;
}

}  // namespace shadetool
