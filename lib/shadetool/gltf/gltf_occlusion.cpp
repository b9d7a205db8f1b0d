// gltf_occlusion.cpp: see gltf_occlusion.h.
#include <shadetool/gltf/gltf_occlusion.h>

#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/visibility/visibility_scene.h>

namespace shadetool {

namespace {

// Primitive i's values as `method` asks, the rays against `scene` (null: the mesh's own BVH, a
// primitive occluded alone). Its fixed-count values are the calls that were here before the
// methods: the same bits.
void occlude_primitive(const VisibilityScene* scene, const Mesh& mesh, bool per_face, const AmbientOcclusionOptions& options,
                       const GltfOcclusionMethod& method, const std::string& where, std::size_t i, GltfSceneOcclusion& out) {
  bool computed = false;
  if (method.to_error) {
    OcclusionToError r = scene ? mesh_occlusion_to_error(*scene, mesh, per_face, *method.to_error, where, computed)
                               : mesh_occlusion_to_error(mesh, per_face, *method.to_error, where, computed);
    AmbientOcclusion& ao = out.primitives[i];
    ao.open_fraction = std::move(r.open_fraction);
    ao.rays = r.total_rays;
    ao.hits = r.hits;
    ao.skipped = r.skipped;
    out.to_error[i] = std::move(r);
  } else if (scene) {
    out.primitives[i] = mesh_occlusion(*scene, mesh, per_face, options, where, computed);
  } else {
    const MeshOcclusion job = mesh_occlusion(mesh, per_face, options, where);
    out.primitives[i] = job.ao;
    computed = job.normals_computed;
  }
  out.normals_computed[i] = computed;
  if (!method.fit || per_face) return;
  const OcclusionToErrorOptions* adaptive = method.to_error ? &*method.to_error : nullptr;
  out.fits[i] = scene ? fit_occlusion(*scene, mesh, out.primitives[i].open_fraction, options, adaptive, *method.fit, where)
                      : fit_occlusion(mesh, out.primitives[i].open_fraction, options, adaptive, *method.fit, where);
}

}  // namespace

GltfSceneOcclusion gltf_scene_occlusion(const GltfDocument& document, bool per_face, const AmbientOcclusionOptions& options,
                                        const std::string& source, const GltfOcclusionMethod& method) {
  GltfSceneOcclusion out;
  const std::vector<GltfPrimitivePlacements> placements = gltf_primitive_placements(document);
  std::vector<std::string> world_notes;  // the world mesh's own notes (texture coordinates, colours) do not concern occlusion
  const Mesh world = gltf_world_mesh(document, world_notes);
  const VisibilityScene scene(world);
  out.scene = scene.stats();
  out.primitives.resize(document.primitives.size());
  out.normals_computed.assign(document.primitives.size(), false);
  if (method.to_error) out.to_error.resize(document.primitives.size());
  if (method.fit && !per_face) out.fits.resize(document.primitives.size());
  std::size_t repeated = 0;
  std::vector<std::string> alone, unplaced;
  for (std::size_t i = 0; i < document.primitives.size(); ++i) {
    const GltfPrimitive& p = document.primitives[i];
    const GltfPrimitivePlacements& where = placements[i];
    if (where.in_scene && where.nodes.empty()) {  // every node singular: not in the BVH
      alone.push_back(p.json_path);
      occlude_primitive(nullptr, p.mesh, per_face, options, method, source + ": " + p.json_path, i, out);
      continue;
    }
    if (!where.in_scene) unplaced.push_back(p.json_path);
    out.instances += where.in_scene ? where.nodes.size() : 1;
    repeated += where.nodes.size() > 1 ? where.nodes.size() - 1 : 0;
    const Mesh placed = gltf_placed_mesh(document, p, where.in_scene ? &where.nodes[0] : nullptr);
    occlude_primitive(&scene, placed, per_face, options, method, source + ": " + p.json_path, i, out);
  }
  out.notes.push_back("occluded by the whole scene in world space: one BVH of " + std::to_string(out.instances) +
                      " primitive placements" +
                      (repeated ? "; a mesh shown by several nodes holds its first node's occlusion (" +
                                      std::to_string(repeated) + " other placements occlude only)"
                                : std::string()));
  auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (std::size_t k = 0; k < v.size() && k < 4; ++k) s += (k ? ", " : "") + v[k];
    if (v.size() > 4) s += " and " + std::to_string(v.size() - 4) + " more";
    return s;
  };
  if (!unplaced.empty()) out.notes.push_back("no node of the scene shows " + list(unplaced) + ": occluded in its object space");
  if (!alone.empty()) out.notes.push_back(list(alone) + ": every node showing it is singular (scale 0): occluded alone");
  return out;
}

}  // namespace shadetool
