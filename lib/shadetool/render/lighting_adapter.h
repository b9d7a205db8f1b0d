// lighting_adapter.h: EVERY point where the renderer touches lib/lighting, in one file, so that a
// change of lighting's API is absorbed here and nowhere else in lib/render.
//
//   baked_vertex_colors   Gouraud: the colours `bake-lighting --per vertex` computes (the same call,
//                         lighting/bake_lighting.h), #V by 3 linear doubles
//   baked_face_colors     flat: `bake-lighting --per face` (face normal at the face's centroid),
//                         #F by 3 linear doubles
//   shading_vertex_normals Phong: the vertex normals bake_lighting lights each vertex with
//                         (lighting/lit_normals.h, the one home of that choice), #V by 3 object
//                         space, so that Phong at a vertex equals the baked colour there
//   PointShader           Phong: lighting/shade_point.h (the lighting equation at one world-space
//                         point with a world-space normal, or a block of them; every light kind
//                         lighting supports);
//                         with shadows, lighting/light_visibility.h over the mesh in world space
//                         (lighting/world_occluders.h), the visibility multiplying each light's terms
//   shadows (all three)   RenderLightingOptions::shadows: flat and Gouraud take bake_lighting's own
//                         shadowed colours (seeds: face or vertex ids), Phong one visibility row
//                         per sample (seeds: the sample's index in the image)
//   encode_srgb_8bit      lighting/encode_color.h's sRGB curve and 8-bit quantisation
//
// Precision: double, as lib/lighting. PointShader::shade is const and thread-safe (counters are
// the caller's).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/lighting/light_visibility.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/shade_point.h>
#include <shadetool/lighting/shade_points.h>
#include <shadetool/lighting/shading_space.h>
#include <shadetool/lighting/world_occluders.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

struct RenderLightingOptions {
  std::optional<ShadingModel> model;        // overrides the scene's (--model)
  ShadingSpace space = ShadingSpace::Auto;  // where bake_lighting evaluates (--space); same colours
  ShadowOptions shadows;                    // --shadows, --shadow-samples (area and sky lights)
};

std::vector<double> baked_vertex_colors(const Mesh& mesh, const Scene& scene, const RenderLightingOptions& options);
std::vector<double> baked_face_colors(const Mesh& mesh, const Scene& scene, const RenderLightingOptions& options);
std::vector<double> shading_vertex_normals(const Mesh& mesh);

class PointShader {
 public:
  // With options.shadows.enabled, mesh's faces at positions_world (#V by 3) go into a BVH.
  PointShader(const Scene& scene, const RenderLightingOptions& options, const Mesh& mesh,
              const std::vector<double>& positions_world);
  ~PointShader();

  // The linear colour at p_world with normal n_world (any length; zero: ambient terms only).
  Vec3d shade(const Vec3d& p_world, const Vec3d& n_world, ShadeCounters& count) const {
    return shade_point(lighting_, p_world, n_world, &count);
  }

  // Many points at once (lighting/shade_point.h's shade_point_block: four at a time in vector
  // lanes where it can), rgb_out #count by 3.
  void shade_block(const PointBlock& block, double* rgb_out, ShadeCounters& count) const {
    shade_point_block(lighting_, block, rgb_out, &count);
  }

  // Shadows: whether they are on, the visibility rows of points (world space, #P by 3 each; ids
  // the seeds), and the colour with one row (row_size() values) multiplying the lights' terms.
  bool casts_shadows() const { return occluders_ != nullptr; }
  std::size_t row_size() const { return 2 * lighting_.plan.lights.size(); }
  std::vector<double> visibility(const std::vector<double>& points_world, const std::vector<double>& normals_world,
                                 const std::vector<std::uint64_t>& ids) const;
  Vec3d shade(const Vec3d& p_world, const Vec3d& n_world, const double* visibility_row, ShadeCounters& count) const {
    return shade_point_shadowed(lighting_, p_world, n_world, visibility_row, &count);
  }
  std::size_t bvh_bytes() const;

 private:
  PointLighting lighting_;  // world space: lights and eye in world coordinates
  const Scene* scene_ = nullptr;
  std::uint32_t shadow_samples_ = 16;
  std::unique_ptr<const WorldOccluders> occluders_;  // the mesh's faces at world positions (shadows only)
};

// The eye in world space (lighting/scene.h eye_world).
Vec3d scene_eye_world(const Scene& scene);

// Linear value -> 8-bit sRGB code (IEC 61966-2-1, then round(255 * clamp(c, 0, 1)); NaN -> 0).
std::uint8_t encode_srgb_8bit(double linear);

}  // namespace shadetool
#pragma GCC visibility pop
