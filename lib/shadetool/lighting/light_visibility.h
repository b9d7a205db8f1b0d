// light_visibility.h: how much of each light a point sees, for bake-lighting --shadows (issue 18).
// The rays are lib/visibility's (shadow_visibility.h, an Embree BVH of the mesh); this file says
// which rays each kind of light casts and how the result enters the equation.
//
//   directional          one ray toward the light, unbounded: 0 or 1 (hard shadow)
//   point, spot          one segment to the light's position: 0 or 1
//   area polygon         N points uniform on the polygon's area (fan of triangles chosen by area),
//                        weight w = max(n.w, 0) cos_light / d^2 (the integrand of P, whose pdf is
//                        constant): the weighted visible fraction sum w V / sum w
//   area sphere          N directions uniform in the cone the sphere subtends, each cast to the
//                        sphere's near surface, weight w = max(n.w, 0) (P's integrand / constant pdf)
//   sky                  N directions cosine-weighted about n, at infinity: the sky's fraction from
//                        those above the horizon of up (w = 1), the ground's from those below
//                        (w = 1), each with its own seed (so 2N rays)
// The equation multiplies the closed-form diffuse and specular terms by the fraction
// (lighting_equation.h's add_light_term); with nothing in the way every fraction is exactly 1 and
// the colours are bitwise the unshadowed ones. Ambient terms are never shadowed.
//
// Inputs:  scene       the mesh's VisibilityScene, built from WORLD-space positions
//          lighting    the scene (world-space lights), plan its kept lights (plan_lighting)
//          points, normals  #P by 3, world space (normals any length; zero: see shadow_visibility.h)
//          ids         #P seeds (vertex or face ids; empty: the index)
//          samples     N >= 1 for area and sky lights
// Output:  #P rows of 2 * plan.lights.size(): per light its fraction, then the sky's ground's
//          (1 for other kinds), the layout ShadeOptions::visibility reads.
// Progress: the stage "shadows" in rays per point (1 per point for a hard light, N for an area
//          or environment light, 2N for a sky), told to `progress` (core/progress.h) when given.
// Threads: any count; same bits (each point's rays depend only on its id and the light's index).
// Errors:  throws Error for samples = 0 or mismatched sizes (shadow_visibility.h's checks).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <shadetool/core/progress.h>
#include <shadetool/lighting/lighting_plan.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/visibility/visibility_scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct ShadowOptions {
  bool enabled = false;
  std::uint32_t samples = 16;  // per point per area or sky light (twice for a sky: sky and ground)
  // What casts the shadows: null, the mesh itself placed by world_from_object; else a world-space
  // scene built by the caller (a glTF document's whole scene, gltf/gltf_scene.h's world mesh, in
  // which this mesh is placed by world_from_object too), shared by every mesh of that scene.
  const VisibilityScene* occluders = nullptr;
  // Where the stage "shadows" reports (light_visibility; core/progress.h). Null: nobody listens.
  ProgressSink* progress = nullptr;
};

// The limit of ShadowOptions::samples, and its check at every entry point that casts shadows
// (bake_lighting, render_mesh): Error "WHAT must be 1..1048576, got N" (WHAT: "--samples",
// "bake_lighting: samples", ...) when
// shadows.enabled and samples is outside 1..kMaxShadowSamples. The CLI and Python relay it.
constexpr std::uint32_t kMaxShadowSamples = 1u << 20;
void check_shadow_options(const ShadowOptions& shadows, const std::string& what);

struct ShadowStats {
  std::size_t hard_lights = 0;      // directional, point and spot lights: one ray each
  std::size_t sampled_lights = 0;   // area and sky lights: `samples` rays each
  std::size_t shadow_rays = 0;      // rays cast (a sampled ray is cast only where its weight > 0)
  std::size_t occluded_terms = 0;   // (point, light) pairs whose visibility is below 1
  std::size_t bvh_bytes = 0;        // the VisibilityScene's BVH and buffers
  double build_ms = 0;
};

std::vector<double> light_visibility(const VisibilityScene& scene, const Scene& lighting, const LightingPlan& plan,
                                     const std::vector<double>& points, const std::vector<double>& normals,
                                     const std::vector<std::uint64_t>& ids, std::uint32_t samples,
                                     ShadowStats* stats = nullptr, ProgressSink* progress = nullptr);

}  // namespace shadetool
#pragma GCC visibility pop
