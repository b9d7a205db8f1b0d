// gltf_transform.cpp: tangents and morph deltas under an affine map (see gltf_transform.h).
#include <shadetool/gltf/gltf_transform.h>

#include <algorithm>

#include <cmath>

#include <shadetool/transform/classify_affine.h>
#include <shadetool/transform/transform_normals.h>

namespace shadetool {

namespace {

void map_vectors(std::vector<double>& v, const Affine3d& M) {
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) set3(v, i / 3, transform_vector(M, get3(v, i / 3)));
}

}  // namespace

GltfTransformReport transform_gltf_extras(GltfPrimitive& p, const Affine3d& M, bool drop_normals) {
  GltfTransformReport rep;
  const AffineClass cls = classify_affine(M);
  const bool singular = cls.path == TransformPath::Singular;
  const bool mirror = determinant(M.A) < 0;

  // NORMAL dropped: TANGENT goes with it (a reader ignores tangents without normals, glTF 2.0
  // 3.7.2.1, and the validator warns MESH_PRIMITIVE_TANGENT_WITHOUT_NORMAL); the writer removes its
  // morph deltas with it.
  const bool had_tangent = std::find(p.attributes.begin(), p.attributes.end(), "TANGENT") != p.attributes.end();
  if (drop_normals && had_tangent && !p.mesh.vertex_normals.empty()) {
    p.drop_tangents = true;
    p.corner_tangents.clear();
    rep.tangents_dropped = true;
  }

  const bool linear_identity = cls.path == TransformPath::Identity || cls.path == TransformPath::Translation;
  for (std::size_t i = 0; i + 3 < p.tangents.size() && !linear_identity && !p.drop_tangents; i += 4) {
    double* t = &p.tangents[i];
    const Vec3d mapped = transform_vector(M, {t[0], t[1], t[2]});
    const double len = length(mapped);
    if (singular || !(std::isfinite(len) && len > 0)) {  // divisor checked: zero/NaN left as read
      ++rep.tangents_left;
      continue;
    }
    t[0] = mapped.x / len, t[1] = mapped.y / len, t[2] = mapped.z / len;
    if (mirror) t[3] = -t[3];
    ++rep.tangents;
  }

  const NormalMap nmap = singular ? NormalMap{} : normal_map(M, cls);
  for (GltfMorphTarget& target : p.targets) {
    map_vectors(target.position_deltas, M);
    map_vectors(target.tangent_deltas, M);
    rep.target_deltas += (target.position_deltas.size() + target.tangent_deltas.size()) / 3;
    if (drop_normals) {
      target.normal_deltas.clear();
      continue;
    }
    if (target.normal_deltas.empty() || singular || nmap.untouched) continue;
    if (p.mesh.vertex_normals.size() != target.normal_deltas.size()) {
      // No base normals to displace: the deltas map as normals themselves.
      transform_normals(target.normal_deltas, nmap);
      continue;
    }
    std::vector<double> displaced(target.normal_deltas.size()), base = p.mesh.vertex_normals;
    for (std::size_t k = 0; k < displaced.size(); ++k) displaced[k] = base[k] + target.normal_deltas[k];
    transform_normals(displaced, nmap);
    transform_normals(base, nmap);
    for (std::size_t k = 0; k < displaced.size(); ++k) target.normal_deltas[k] = displaced[k] - base[k];
    rep.target_deltas += displaced.size() / 3;
  }
  return rep;
}

bool mapped_tangents_stay_mikktspace(TransformPath path) {
  switch (path) {
    case TransformPath::Identity:
    case TransformPath::Translation:
    case TransformPath::Rotation:
    case TransformPath::UniformScale:
      return true;
    case TransformPath::General:
    case TransformPath::Singular:
      return false;
  }
  return false;
}

}  // namespace shadetool
