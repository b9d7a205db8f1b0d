// gltf_occlusion.h: ambient occlusion of a glTF document's triangle primitives against its whole
// scene: what `shadetool occlusion` does with a .glb/.gltf, so that a cup on a table darkens the
// table (each primitive alone would see only itself).
//
// Inputs:  document  a GltfDocument (gltf/gltf_document.h) read from a file
//          per_face, options, source  as mesh_occlusion (ambient_occlusion.h)
// Output:  per document primitive, its open fractions (per vertex or face of the primitive as it
//          is in the document: object space), and the scene's BVH statistics.
// Method:  one BVH (visibility_scene.h) of gltf/gltf_scene.h's world mesh: every primitive placed by
//          every node that shows it, in world space. Each primitive's values are those of its
//          FIRST placement (scene order, depth first; glTF vertex data belongs to the mesh, not to
//          the node, so a mesh shown twice can hold one placement's occlusion): the primitive
//          placed by that node (gltf_placed_mesh: the same bits as its part of the BVH, so a vertex
//          is its own BVH vertex), its hemisphere axes the mesh's vertex normals mapped by
//          sign(det A) cof(A), or when it has none the angle-weighted normals of the placed mesh
//          (as mesh_occlusion computes them). `--distance` is then in world units.
//          A primitive no node shows is in the world mesh in its object space and occluded there;
//          a primitive whose every node is singular (scale 0) is occluded alone in its object space
//          (mesh_occlusion). Each case is named in `notes`.
// Rays, hits and skipped are counted per primitive (its first placement's rays).
//
// method (`occlusion --error E`, `--fit least-squares`): with to_error, each primitive's open
// fractions are visibility/occlusion_to_error.h's (mesh_occlusion_to_error against the same BVH,
// the same placement and axes) instead of a fixed count; with fit (per vertex only), each
// primitive's values are then visibility/fit_occlusion.h's least-squares fit on the placed
// primitive (areas in world units, the quadrature points' rays against the whole scene, with the
// fixed count or to the error), started from and compared with those point values.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <shadetool/fit/least_squares_fit.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/fit_occlusion.h>
#include <shadetool/visibility/occlusion_to_error.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct GltfOcclusionMethod {
  std::optional<OcclusionToErrorOptions> to_error;  // none: options.samples rays per point
  std::optional<VertexFitOptions> fit;              // least squares (per vertex; ignored per face)
};

struct GltfSceneOcclusion {
  std::vector<AmbientOcclusion> primitives;  // per document.primitives[i]: the point values
  std::vector<OcclusionToError> to_error;    // per primitive with method.to_error (open_fraction moved
                                             // into primitives[i])
  std::vector<OcclusionFit> fits;            // per primitive with method.fit, per vertex
  std::vector<bool> normals_computed;        // per primitive: per vertex, without vertex normals
  VisibilitySceneStats scene;                // the whole scene's BVH
  std::size_t instances = 0;                 // primitive placements in the BVH
  std::vector<std::string> notes;
};

GltfSceneOcclusion gltf_scene_occlusion(const GltfDocument& document, bool per_face, const AmbientOcclusionOptions& options,
                                        const std::string& source, const GltfOcclusionMethod& method = {});

}  // namespace shadetool
#pragma GCC visibility pop
