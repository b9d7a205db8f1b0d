// face_normals.cpp: one unit normal per face (see face_normals.h).
//
// Triangles: cross product of the two shortest edges; polygons: Newell's method
// (geometry/face_area_vector.h).
// Precision: both compute in double (edges, cross product, length, division); Float then rounds
// the unit normal once to float (relative error <= 2^-24 per component, so within ~1e-5 deg of
// Double whatever the triangle's shape or the mesh's scale: 1e-30 and 1e30 included) and widens it
// back to double. Float therefore costs what Double costs here; it exists so that a float run is
// float throughout. A face without area (geometry/degenerate_face.h, face_area_kind:
// fewer than 3 corners, non-finite position, zero area to 64 eps) gets (0, 0, 0).
#include <shadetool/normals/face_normals.h>

#include <vector>

#include <shadetool/core/engine/parallel.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/scaled_length.h>

namespace shadetool {
namespace {

template <class T>
void face_normals_range(const Mesh& mesh, std::size_t f_begin, std::size_t f_end, double* out) {
  const double* P = mesh.positions.data();
  const std::uint32_t* cv = mesh.corner_vertex.data();
  const bool triangles = mesh.all_triangles();
  for (std::size_t f = f_begin; f < f_end; ++f) {
    Vec3d N;
    bool degenerate;
    if (triangles || mesh.face_size(f) == 3) {
      const std::size_t c = triangles ? 3 * f : mesh.face_start[f];
      const TriangleAreaVector t = triangle_area_vector(P, cv[c], cv[c + 1], cv[c + 2]);
      N = t.N;
      degenerate = triangle_is_degenerate(t, P, cv[c], cv[c + 1], cv[c + 2]);
    } else {
      N = newell_area_vector(mesh, f);
      degenerate = face_area_kind(mesh, f) != DegenerateKind::None;
    }
    const double l = degenerate ? 0.0 : checked_length(N);
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
