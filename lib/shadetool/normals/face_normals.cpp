// face_normals.cpp: one unit normal per face (see face_normals.h).
//
// Triangles: cross product of the two shortest edges; polygons: Newell's method
// (geometry/face_area_vector.h). All-triangle meshes go through the vectorised block pass of the
// normals kernels (engine/triangle_blocks.h; same bits, several times faster than the scalar loop,
// bench/normals/results/notes.md), its rejects through the scalar loop.
// Precision: both compute in double (edges, cross product, length, division); Float then rounds
// the unit normal once to float (relative error <= 2^-24 per component, so within ~1e-5 deg of
// Double whatever the triangle's shape or the mesh's scale: 1e-30 and 1e30 included) and widens it
// back to double. Float therefore costs what Double costs here; it exists so that a float run is
// float throughout. A face without area (geometry/degenerate_face.h, face_area_kind:
// fewer than 3 corners, non-finite position, zero area to 64 eps) gets (0, 0, 0).
// Scale: a mesh whose largest sampled coordinate lies outside [2^-32, 2^32) is computed on a copy scaled
// exactly by a power of two (engine/mesh_scale.h): the cross products of a mesh at 1e160 or 1e-160
// neither overflow nor underflow, and a 2^k-scaled mesh gives bitwise the same normals.
#include <shadetool/normals/face_normals.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/engine/parallel.h>
#include <shadetool/geometry/degenerate_face.h>
#include <shadetool/geometry/face_area_vector.h>
#include <shadetool/geometry/scaled_length.h>
#include <shadetool/normals/engine/mesh_scale.h>
#include <shadetool/normals/engine/triangle_blocks.h>

namespace shadetool {
namespace {

template <class T>
void face_normals_range(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, double* out) {
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  const bool triangles = mesh.all_triangles();
  for (std::size_t f = f_begin; f < f_end; ++f) {
    Vec3d N;
    bool degenerate;
    if (triangles || mesh.face_size(f) == 3) {
      const std::size_t c = triangles ? 3 * f : mesh.face_begin(f);
      const TriangleAreaVector t = triangle_area_vector(P, cv[c], cv[c + 1], cv[c + 2]);
      N = t.N;
      degenerate = triangle_is_degenerate(t, P, cv[c], cv[c + 1], cv[c + 2]);
    } else {
      const std::uint32_t begin = mesh.face_begin(f), n = mesh.face_size(f);
      N = newell_area_vector(P, cv + begin, n);
      degenerate = face_area_kind(P, cv + begin, n) != DegenerateKind::None;
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

// All-triangle meshes: blocks of kTriangleBlock faces through the vectorised pass
// (normals/engine/triangle_blocks.h, triangle_block_unit_normals: the same N, the same length and
// divisions, so the same bits as face_normals_range); a face it leaves NaN (degenerate, or
// outside its range) goes through face_normals_range, which asks the degenerate-face rule.
template <class T>
void face_normals_triangle_blocks(const MeshView& mesh, std::size_t f_begin, std::size_t f_end, double* out) {
  using normals_detail::kTriangleBlock;
  const double* P = mesh.positions;
  const std::uint32_t* cv = mesh.corner_vertex;
  alignas(64) double xyz[9][kTriangleBlock];
  alignas(64) double unit[3][kTriangleBlock];
  for (std::size_t b = f_begin; b < f_end; b += kTriangleBlock) {
    const std::size_t count = std::min(kTriangleBlock, f_end - b);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t c = 3 * (b + i);
      for (int k = 0; k < 3; ++k) {
        const double* p = P + 3 * std::size_t(cv[c + k]);
        xyz[3 * k][i] = p[0]; xyz[3 * k + 1][i] = p[1]; xyz[3 * k + 2][i] = p[2];
      }
    }
    normals_detail::triangle_block_unit_normals(count, &xyz[0][0], &unit[0][0]);
    for (std::size_t i = 0; i < count; ++i) {
      double* o = out + 3 * (b + i);
      if (std::isnan(unit[0][i])) {
        face_normals_range<T>(mesh, b + i, b + i + 1, out);
        continue;
      }
      o[0] = double(T(unit[0][i])); o[1] = double(T(unit[1][i])); o[2] = double(T(unit[2][i]));
    }
  }
}

}  // namespace

void face_normals(const MeshView& mesh, Precision precision, double* out) {
  std::vector<double> storage;  // exactly scaled positions for a mesh outside the kernels' range (engine/mesh_scale.h)
  const MeshView in_range = normals_detail::in_kernel_range(mesh, storage);
  engine::parallel_ranges(mesh.num_faces(), [&](std::size_t b, std::size_t e) {
    const bool triangles = in_range.all_triangles();
    if (precision == Precision::Float) {
      if (triangles) face_normals_triangle_blocks<float>(in_range, b, e, out);
      else face_normals_range<float>(in_range, b, e, out);
    } else {
      if (triangles) face_normals_triangle_blocks<double>(in_range, b, e, out);
      else face_normals_range<double>(in_range, b, e, out);
    }
  });
}

std::vector<double> face_normals(const MeshView& mesh, Precision precision) {
  std::vector<double> out;
  reserve_bulk(out, 3 * mesh.num_faces());  // huge pages for the fresh array (core/bulk_reserve.h)
  out.resize(3 * mesh.num_faces());
  face_normals(mesh, precision, out.data());
  return out;
}

std::vector<double> face_normals(const Mesh& mesh, Precision precision) {
  return face_normals(MeshView(mesh), precision);
}

}  // namespace shadetool
