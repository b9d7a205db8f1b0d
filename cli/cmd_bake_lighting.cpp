// cmd_bake_lighting.cpp: `shadetool bake-lighting IN -o OUT --scene SCENE.json [...]`.
// Parses options, reads the scene once, and per mesh calls lighting/bake_lighting.h; the equation,
// spaces, skips and encodings all live in lib/lighting (see man/shadetool-bake-lighting.1).
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "command_registry.h"
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include "fit_options.h"
#include "usage_error.h"
#include <shadetool/gltf/gltf_lights.h>
#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include <shadetool/lighting/fit_vertex_lighting.h>
#include <shadetool/lighting/read_scene.h>

namespace shadetool_cli {
namespace {

// A glTF document's whole scene in world space and its BVH (the BVH reads the mesh's arrays).
struct SceneOccluders {
  shadetool::Mesh world;
  std::unique_ptr<shadetool::VisibilityScene> bvh;
};

struct BakeLightingOptions {
  std::string scene;
  std::string model;  // "" = the scene's
  std::string space = "auto";
  std::string per = "vertex";
  bool hdr = false;
  bool srgb = false;
  bool shadows = false;
  std::uint32_t samples = 16;
};

shadetool::ShadingModel parse_model(const std::string& s) {
  if (s == "lambert") return shadetool::ShadingModel::Lambert;
  if (s == "phong") return shadetool::ShadingModel::Phong;
  return shadetool::ShadingModel::BlinnPhong;
}

shadetool::ShadingSpace parse_space(const std::string& s) {
  if (s == "world") return shadetool::ShadingSpace::World;
  if (s == "camera") return shadetool::ShadingSpace::Camera;
  if (s == "object") return shadetool::ShadingSpace::Object;
  return shadetool::ShadingSpace::Auto;
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& x : items) s += (s.empty() ? "" : ",") + x;
  return s.empty() ? "none" : s;
}

RegisterCommand reg(50, [](CLI::App& app) -> std::function<int()> {
  static IoOptions io;
  static BakeLightingOptions opt;
  static FitCliOptions fit;
  auto* sub = app.add_subcommand(
      "bake-lighting",
      "Bake lit colours into a mesh: OpenGL 2.1 fixed-function lighting (lambert, phong, blinn-phong; ambient, "
      "directional, point and spot lights; area and sky lights, exact where a closed form exists) per vertex or per "
      "face");
  add_io_options(*sub, io, /*writes_mesh=*/true);
  sub->add_option("--scene", opt.scene,
                  "Scene file (JSON): material, lights, camera, world_from_object (required, except for glTF input: "
                  "then its KHR_lights_punctual lights, first camera and node placement are used)")
      ->type_name("SCENE.json");
  sub->add_option("--model", opt.model, "Shading model, overriding the scene's (default: the scene's, else blinn-phong)")
      ->check(CLI::IsMember({"lambert", "phong", "blinn-phong"}));
  sub->add_option("--space", opt.space,
                  "Space the equation is evaluated in; all give the same colours (default auto: the cheapest)")
      ->check(CLI::IsMember({"world", "camera", "object", "auto"}));
  sub->add_option("--per", opt.per, "vertex: one colour per vertex (Gouraud); face: one per face (flat) (default vertex)")
      ->check(CLI::IsMember({"vertex", "face"}));
  sub->add_flag("--hdr", opt.hdr, "Write float colours, unclamped (default: 8-bit, round(255 * clamp(c, 0, 1)))");
  sub->add_flag("--srgb", opt.srgb, "Encode colours with the sRGB curve (default: linear)");
  auto* shadows_flag = sub->add_flag("--shadows", opt.shadows,
                "Shadows: multiply each light's diffuse and specular terms by its visibility from the point (one ray "
                "for directional, point and spot lights; --samples rays for area and sky lights)");
  auto* samples = sub->add_option("--samples", opt.samples,
                                  "With --shadows: rays per point per area or sky light (default 16; a sky casts them "
                                  "for the sky and again for the ground)")
                      ->check(CLI::Range(1u, 1u << 20))
                      ->needs(shadows_flag);
  add_fit_options(*sub, fit, "lit colour");

  return [samples] {
    // The scene is read once, before any mesh: a bad scene fails the command (exit 1), no output.
    const bool own_scene = opt.scene.empty();  // glTF input: the file's lights (gltf/gltf_lights.h)
    const shadetool::Scene file_scene = own_scene ? shadetool::Scene() : shadetool::read_scene(opt.scene);
    shadetool::ShadeOptions shade;
    if (!opt.model.empty()) shade.model = parse_model(opt.model);
    shade.space = parse_space(opt.space);
    const auto frequency = opt.per == "face" ? shadetool::ShadingFrequency::PerFace : shadetool::ShadingFrequency::PerVertex;
    shadetool::ColorEncoding encoding;
    encoding.hdr = opt.hdr;
    encoding.srgb = opt.srgb;
    shadetool::ShadowOptions shadows;
    shadows.enabled = opt.shadows;
    shadows.samples = opt.samples;
    const bool samples_given = samples->count() > 0;

    return run_mesh_command("bake-lighting", io, [=](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
      if (own_scene && !r.gltf)
        throw UsageError(input + ": --scene is required (only glTF files carry their own lights)");
      std::vector<std::string> scene_notes;
      const shadetool::Scene scene = own_scene ? shadetool::gltf_scene(*r.gltf_document, *r.gltf, scene_notes) : file_scene;
      if (own_scene && scene.lights.empty())
        throw shadetool::Error(shadetool::located(input, 0, "no --scene given and the file has no KHR_lights_punctual light"));
      for (auto& n : scene_notes) r.notes.push_back(n);
      shadetool::require_finite_positions(mesh, input);
      // The mesh's normals go to the output unchanged: none may be NaN/Inf (nor light with them).
      shadetool::require_finite_normals(mesh, input, "run `shadetool repair` or `shadetool normals --recompute` first");
      if (frequency == shadetool::ShadingFrequency::PerFace) {
        shadetool::require_faces(mesh, input);
      } else if (mesh.num_faces() == 0 && !mesh.has_vertex_normals() && mesh.num_vertices() > 0) {
        throw shadetool::Error(shadetool::located(input, 0, "no vertex normals and no faces to compute them from"));
      }
      // A glTF file lit by its own lights: shadows from its whole scene (every primitive placed by its
      // nodes, gltf/gltf_scene.h), one BVH per document built at its first primitive; with --scene the
      // scene file places the mesh and only the primitive itself casts shadows.
      shadetool::ShadowOptions cast = shadows;
      if (shadows.enabled && own_scene && r.gltf_document_state) {
        std::shared_ptr<void>& state = *r.gltf_document_state;
        if (!state) {
          auto occluders = std::make_shared<SceneOccluders>();
          std::vector<std::string> unused;  // the world mesh's notes concern writing it, not its shadows
          occluders->world = shadetool::gltf_world_mesh(*r.gltf_document, unused);
          occluders->bvh = std::make_unique<shadetool::VisibilityScene>(occluders->world);
          state = occluders;
        }
        cast.occluders = static_cast<const SceneOccluders*>(state.get())->bvh.get();
        r.notes.push_back("shadows cast by the whole scene (every primitive placed by its nodes), one BVH");
      }
      shadetool::BakeResult baked = shadetool::bake_lighting(mesh, scene, frequency, shade, cast);
      // --fit least-squares (lighting/fit_vertex_lighting.h): the point colours replaced by the fit.
      if (fit_method(fit) == shadetool::VertexFit::LeastSquares && frequency == shadetool::ShadingFrequency::PerVertex) {
        shadetool::VertexFitOptions vfit;
        vfit.method = shadetool::VertexFit::LeastSquares;
        vfit.samples = fit.samples;
        vfit.solve.regularization = fit.regularization;
        if (!encoding.hdr) vfit.solve.upper = 1;  // 8-bit: [0, 1]
        shadetool::VertexLightingFit lsq = shadetool::fit_vertex_lighting(mesh, scene, baked, shade, cast, vfit);
        baked.rgb = std::move(lsq.rgb);
        report_fit(r, lsq.solve, lsq.error_fit, lsq.error_point, lsq.quadrature_points, fit);
        if (shadows.enabled) r.stats["fit_shadow_rays"] = lsq.shadows.shadow_rays;
      } else if (fit_method(fit) == shadetool::VertexFit::LeastSquares) {
        r.notes.push_back("--fit least-squares ignored with --per face (one colour per face is its mean, not a fit)");
      }
      const shadetool::ShadeReport& rep = baked.report;

      if (frequency == shadetool::ShadingFrequency::PerVertex && baked.normals_source.rfind("computed", 0) == 0)
        r.notes.push_back("vertex normals " + baked.normals_source);
      if (baked.normal_fallback_vertices > 0)
        r.notes.push_back(std::to_string(baked.normal_fallback_vertices) +
                          " vertices have no valid face: their normal is the normals module's fallback");
      if (rep.counters.zero_normals > 0)
        r.notes.push_back(std::to_string(rep.counters.zero_normals) +
                          (frequency == shadetool::ShadingFrequency::PerFace ? " faces" : " vertices") +
                          " have a zero or non-finite normal: lit by the emission and ambient terms only");
      if (rep.counters.at_light > 0)
        r.notes.push_back(std::to_string(rep.counters.at_light) +
                          " vertex-light pairs have the point at the light's position: that light adds nothing there");
      if (shadows.enabled && samples_given && baked.shadows.sampled_lights == 0)
        r.notes.push_back("--samples ignored: the scene has no area, sky or environment light (directional, point and spot "
                          "lights cast one shadow ray each)");
      if (rep.plan.view && !scene.has_camera)
        r.notes.push_back("the scene has no camera: the eye is at the world origin (OpenGL's default)");

      // No NaN or Inf colour is ever written (8-bit encoding would turn NaN into a silent black):
      // lights, intensities or positions near the limits of double can produce them; refuse.
      std::vector<float> colors = shadetool::encode_colors(baked.rgb, encoding);
      std::size_t nonfinite = 0;
      for (std::size_t i = 0; i < baked.rgb.size(); ++i)
        nonfinite += !(std::isfinite(baked.rgb[i]) && std::isfinite(colors[i]));
      if (nonfinite > 0)
        throw shadetool::Error(shadetool::located(
            input, 0, std::to_string(nonfinite) + " colour values came out NaN or infinite (light positions, " +
                          "intensities or the world map near the limits of double?); nothing written"));
      shadetool::store_baked_colors(mesh, std::move(colors), frequency, encoding.hdr);

      r.stats["model"] = shadetool::shading_model_name(rep.model);
      r.stats["space"] = shadetool::shading_space_name(rep.space);
      r.stats["skipped"] = join(rep.skipped);
      r.setting("lights", rep.plan.lights.size());
      r.stats["dark_lights_dropped"] = rep.plan.dark_lights_dropped;
      r.stats["vertex_light_evaluations"] = rep.counters.vertex_light_evaluations;
      r.stats["back_facing_skips"] = rep.counters.back_facing;
      r.stats["outside_cone_skips"] = rep.counters.outside_cone;
      if (rep.plan.area_lights > 0) {  // only then, so that other scenes' reports stay as they were
        r.stats["below_horizon_skips"] = rep.counters.below_horizon;
        r.stats["inside_light"] = rep.counters.inside_light;
      }
      if (shadows.enabled) {
        r.stats["shadow_rays"] = baked.shadows.shadow_rays;
        r.stats["occluded_light_terms"] = rep.counters.shadowed;
        r.setting("shadow_samples", baked.shadows.sampled_lights > 0 ? shadows.samples : 1u);
        if (cast.occluders) r.setting("bvh_bytes", baked.shadows.bvh_bytes);  // one BVH for the document
        else r.stats["bvh_bytes"] = baked.shadows.bvh_bytes;
      }
    }, true);
  };
});

}  // namespace
}  // namespace shadetool_cli
