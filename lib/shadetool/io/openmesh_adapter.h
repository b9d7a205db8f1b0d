// openmesh_adapter.h: shadetool::Mesh <-> OpenMesh (PolyMesh or TriMesh of any traits), for
// library users who hold an OpenMesh mesh. Header-only: include it where OpenMesh is available
// (link OpenMeshCore); the shadetool library itself does not depend on OpenMesh.
//
//   to_openmesh<OM>(mesh, &skipped)  Inputs: mesh (V, F, optional attributes)
//                                    Outputs: an OM with V vertices in order and the faces
//                                    OpenMesh accepts, in order; attributes copied into
//                                    OpenMesh's standard properties (requested as needed):
//                                      vertex normals  -> vertex_normals
//                                      face normals    -> face_normals
//                                      corner normals  -> halfedge_normals (the halfedge of the
//                                                         face that points to the corner's vertex)
//                                      texcoords (2D)  -> halfedge_texcoords2D, likewise
//                                      vertex / face colours -> vertex_colors / face_colors
//                                                         (integer channels: round(255 c))
//                                    `skipped` (optional) = faces add_face refused. OpenMesh
//                                    cannot hold every mesh shadetool keeps: non-manifold edges,
//                                    some non-manifold vertices, faces with a repeated vertex
//                                    and, in a TriMesh, polygons (OpenMesh triangulates them:
//                                    the face count grows) are lost or changed there. That is
//                                    why shadetool does not route input through OpenMesh.
//   from_openmesh(om)                Inputs: an OpenMesh mesh
//                                    Outputs: Mesh with the non-deleted vertices and faces in
//                                    index order, each face's corners in OpenMesh's fv order,
//                                    and the standard properties above that are present.
// Precision: OpenMesh's point type decides (float for DefaultTraits); the result has
// precision Float when the point scalar is float, else Double.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

// OpenMesh's property containers trip GCC 12's -Wmaybe-uninitialized inside OpenMesh's own code
// (PropertyT::push_back); silenced for OpenMesh's headers only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Mesh/PolyConnectivity.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

namespace openmesh_detail {

template <class Color>
Color color_from_float(const float* c, int channels) {
  using S = std::decay_t<decltype(std::declval<Color>()[0])>;
  Color out;
  for (int k = 0; k < int(Color::size_); ++k) {
    const float v = k < channels ? c[k] : 1.0f;
    if constexpr (std::is_integral_v<S>) {
      const float clamped = v < 0 ? 0.0f : (v > 1 ? 1.0f : v);
      out[k] = S(std::lround(clamped * 255.0f));
    } else {
      out[k] = S(v);
    }
  }
  return out;
}

template <class Color>
void color_to_float(const Color& c, float* out, int channels) {
  using S = std::decay_t<decltype(std::declval<Color>()[0])>;
  for (int k = 0; k < channels; ++k) {
    const float v = k < int(Color::size_) ? float(c[k]) : (std::is_integral_v<S> ? 255.0f : 1.0f);
    out[k] = std::is_integral_v<S> ? v / 255.0f : v;
  }
}

}  // namespace openmesh_detail

template <class OM>
OM to_openmesh(const Mesh& mesh, std::size_t* skipped_faces = nullptr) {
  using Point = typename OM::Point;
  using Normal = typename OM::Normal;
  using Scalar = typename Point::value_type;
  OM om;
  std::vector<typename OM::VertexHandle> vh(mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
    vh[v] = om.add_vertex(Point(Scalar(mesh.positions[3 * v]), Scalar(mesh.positions[3 * v + 1]),
                                Scalar(mesh.positions[3 * v + 2])));
  if (mesh.has_vertex_normals()) {
    om.request_vertex_normals();
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
      const Vec3d n = get3(mesh.vertex_normals, v);
      om.set_normal(vh[v], Normal(Scalar(n.x), Scalar(n.y), Scalar(n.z)));
    }
  }
  const int ch = mesh.color_channels;
  if (mesh.has_vertex_colors()) {
    om.request_vertex_colors();
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
      om.set_color(vh[v], openmesh_detail::color_from_float<typename OM::Color>(&mesh.vertex_colors[std::size_t(ch) * v], ch));
  }
  if (mesh.has_face_normals()) om.request_face_normals();
  if (mesh.has_face_colors()) om.request_face_colors();
  if (mesh.has_corner_normals()) om.request_halfedge_normals();
  const bool tex2 = mesh.has_texcoords() && mesh.texcoord_dims >= 2;
  if (tex2) om.request_halfedge_texcoords2D();

  std::size_t skipped = 0;
  std::vector<typename OM::VertexHandle> face;
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    face.clear();
    for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) face.push_back(vh[mesh.corner_vertex[c]]);
    const std::size_t before = om.n_faces();
    const auto fh = om.add_face(face);
    if (!fh.is_valid()) {
      ++skipped;
      continue;
    }
    // A TriMesh splits a polygon into a fan: the attributes go to every face it added.
    for (std::size_t g = before; g < om.n_faces(); ++g) {
      const typename OM::FaceHandle h{int(g)};
      if (mesh.has_face_normals()) {
        const Vec3d n = get3(mesh.face_normals, f);
        om.set_normal(h, Normal(Scalar(n.x), Scalar(n.y), Scalar(n.z)));
      }
      if (mesh.has_face_colors())
        om.set_color(h, openmesh_detail::color_from_float<typename OM::Color>(&mesh.face_colors[std::size_t(ch) * f], ch));
      if (mesh.has_corner_normals() || tex2) {
        for (auto heh : om.fh_range(h)) {
          // the corner of face f at the halfedge's target vertex
          const int target = om.to_vertex_handle(heh).idx();
          for (std::uint32_t c = mesh.face_start[f]; c < mesh.face_start[f + 1]; ++c) {
            if (int(mesh.corner_vertex[c]) != target) continue;
            if (mesh.has_corner_normals()) {
              const Vec3d n = get3(mesh.corner_normals, mesh.corner_normal_index[c]);
              om.set_normal(heh, Normal(Scalar(n.x), Scalar(n.y), Scalar(n.z)));
            }
            if (tex2) {
              const std::size_t t = std::size_t(mesh.corner_texcoord_index[c]) * std::size_t(mesh.texcoord_dims);
              om.set_texcoord2D(heh, typename OM::TexCoord2D(typename OM::TexCoord2D::value_type(mesh.texcoords[t]),
                                                             typename OM::TexCoord2D::value_type(mesh.texcoords[t + 1])));
            }
            break;
          }
        }
      }
    }
  }
  if (skipped_faces) *skipped_faces = skipped;
  return om;
}

template <class OM>
Mesh from_openmesh(const OM& om) {
  Mesh mesh;
  using Scalar = typename OM::Point::value_type;
  mesh.precision = std::is_same_v<Scalar, float> ? ValuePrecision::Float : ValuePrecision::Double;
  std::vector<std::uint32_t> index(om.n_vertices(), UINT32_MAX);  // OpenMesh index -> ours (deleted skipped)
  for (auto v : om.vertices()) {
    const auto p = om.point(v);
    index[std::size_t(v.idx())] = mesh.add_vertex({double(p[0]), double(p[1]), double(p[2])});
    if (om.has_vertex_normals()) {
      const auto n = om.normal(v);
      mesh.vertex_normals.insert(mesh.vertex_normals.end(), {double(n[0]), double(n[1]), double(n[2])});
    }
  }
  if (om.has_vertex_colors() || om.has_face_colors()) {
    mesh.color_channels = int(OM::Color::size_) >= 4 ? 4 : 3;
    mesh.colors_are_float = !std::is_integral_v<std::decay_t<decltype(std::declval<typename OM::Color>()[0])>>;
  }
  if (om.has_vertex_colors())
    for (auto v : om.vertices()) {
      float c[4];
      openmesh_detail::color_to_float(om.color(v), c, mesh.color_channels);
      mesh.vertex_colors.insert(mesh.vertex_colors.end(), c, c + mesh.color_channels);
    }
  for (auto f : om.faces()) {
    for (auto heh : om.fh_range(f)) {
      mesh.corner_vertex.push_back(index[std::size_t(om.to_vertex_handle(heh).idx())]);
      if (om.has_halfedge_normals()) {
        const auto n = om.normal(heh);
        mesh.corner_normal_index.push_back(std::uint32_t(mesh.corner_normals.size() / 3));
        mesh.corner_normals.insert(mesh.corner_normals.end(), {double(n[0]), double(n[1]), double(n[2])});
      }
      if (om.has_halfedge_texcoords2D()) {
        const auto t = om.texcoord2D(heh);
        mesh.corner_texcoord_index.push_back(std::uint32_t(mesh.texcoords.size() / 2));
        mesh.texcoords.insert(mesh.texcoords.end(), {double(t[0]), double(t[1])});
      }
    }
    mesh.face_start.push_back(std::uint32_t(mesh.corner_vertex.size()));
    if (om.has_face_normals()) {
      const auto n = om.normal(f);
      mesh.face_normals.insert(mesh.face_normals.end(), {double(n[0]), double(n[1]), double(n[2])});
    }
    if (om.has_face_colors()) {
      float c[4];
      openmesh_detail::color_to_float(om.color(f), c, mesh.color_channels);
      mesh.face_colors.insert(mesh.face_colors.end(), c, c + mesh.color_channels);
    }
  }
  mesh.texcoord_dims = 2;
  return mesh;
}

}  // namespace shadetool
#pragma GCC visibility pop
