// gltf_occlusion.cpp: see gltf_occlusion.h.
#include <shadetool/gltf/gltf_occlusion.h>

#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/visibility/visibility_scene.h>

namespace shadetool {

GltfSceneOcclusion gltf_scene_occlusion(const GltfDocument& document, bool per_face, const AmbientOcclusionOptions& options,
                                        const std::string& source) {
  GltfSceneOcclusion out;
  const std::vector<GltfPrimitivePlacements> placements = gltf_primitive_placements(document);
  std::vector<std::string> world_notes;  // the world mesh's own notes (texture coordinates, colours) do not concern occlusion
  const Mesh world = gltf_world_mesh(document, world_notes);
  const VisibilityScene scene(world);
  out.scene = scene.stats();
  out.primitives.resize(document.primitives.size());
  out.normals_computed.assign(document.primitives.size(), false);
  std::size_t repeated = 0;
  std::vector<std::string> alone, unplaced;
  for (std::size_t i = 0; i < document.primitives.size(); ++i) {
    const GltfPrimitive& p = document.primitives[i];
    const GltfPrimitivePlacements& where = placements[i];
    if (where.in_scene && where.nodes.empty()) {  // every node singular: not in the BVH
      alone.push_back(p.json_path);
      const MeshOcclusion job = mesh_occlusion(p.mesh, per_face, options, source + ": " + p.json_path);
      out.primitives[i] = job.ao;
      out.normals_computed[i] = job.normals_computed;
      continue;
    }
    if (!where.in_scene) unplaced.push_back(p.json_path);
    out.instances += where.in_scene ? where.nodes.size() : 1;
    repeated += where.nodes.size() > 1 ? where.nodes.size() - 1 : 0;
    const Mesh placed = gltf_placed_mesh(document, p, where.in_scene ? &where.nodes[0] : nullptr);
    bool computed = false;
    out.primitives[i] = mesh_occlusion(scene, placed, per_face, options, source + ": " + p.json_path, computed);
    out.normals_computed[i] = computed;
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
