// lit_normals.cpp: see lit_normals.h.
#include <shadetool/lighting/lit_normals.h>

#include <shadetool/normals/vertex_normals.h>

namespace shadetool {

namespace {

// True when every corner of each vertex references the same normal value; fills `normals`.
bool corner_normals_per_vertex(const Mesh& mesh, std::vector<double>& normals) {
  const std::size_t V = mesh.num_vertices();
  std::vector<double> out(3 * V, 0.0);
  std::vector<char> seen(V, 0);
  for (std::size_t c = 0; c < mesh.num_corners(); ++c) {
    const std::size_t v = mesh.corner_vertex[c];
    const std::size_t k = mesh.corner_normal_index[c];
    if (v >= V || 3 * k + 2 >= mesh.corner_normals.size()) return false;
    const Vec3d n = get3(mesh.corner_normals, k);
    if (!seen[v]) {
      set3(out, v, n);
      seen[v] = 1;
    } else if (get3(out, v) != n) {
      return false;  // a crease: this vertex has several normals
    }
  }
  normals = std::move(out);
  return true;
}

}  // namespace

LitVertexNormals lit_vertex_normals(const Mesh& mesh) {
  LitVertexNormals lit;
  if (mesh.has_vertex_normals() && mesh.vertex_normals.size() == mesh.positions.size()) {
    lit.source = "input vertex normals";
    lit.normals = mesh.vertex_normals;
  } else if (mesh.has_corner_normals() && corner_normals_per_vertex(mesh, lit.normals)) {
    lit.source = "input corner normals (one per vertex)";
  } else {
    VertexNormals computed = vertex_normals(mesh, Weighting::Angle, Precision::Double);
    lit.source = mesh.has_corner_normals()
                     ? "computed (angle-weighted): the input's corner normals differ at some vertices"
                     : "computed (angle-weighted)";
    lit.fallback_vertices = computed.fallback_vertices;
    lit.normals = std::move(computed.normals);
  }
  return lit;
}

}  // namespace shadetool
