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
#include <shadetool/normals/replace_invalid_normals.h>
#include <shadetool/core/error.h>
#include <shadetool/core/validate.h>
#include "driver.h"
#include "fit_options.h"
#include "usage_error.h"
#include <shadetool/gltf/gltf_baked.h>
#include <shadetool/gltf/gltf_lights.h>
#include <shadetool/gltf/gltf_scene.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/io/split_corner_normals.h>
#include <shadetool/lighting/encode_color.h>
#include <shadetool/lighting/fit_vertex_lighting.h>
#include <shadetool/lighting/default_scene.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/lighting/world_occluders.h>

namespace shadetool_cli {
namespace {

struct BakeLightingOptions {
  std::string scene;
  std::string model;  // "" = the scene's
  std::string space = shadetool::shading_space_name(shadetool::ShadingSpace::Auto);
  std::string per = shadetool::shading_frequency_name(shadetool::ShadingFrequency::PerVertex);
  bool hdr = false;
  bool srgb = false;    // the default now: a no-op with a note
  bool linear = false;  // 8-bit outputs: linear bytes (lighting/encode_color.h's rule)
  bool unlit = false;
  bool shadows = false;
  std::uint32_t samples = 16;
  std::string camera = shadetool::camera_choice_name(shadetool::CameraChoice::Scene);
  FitCliOptions fit;  // --fit, --fit-regularization, --fit-samples (fit_options.h)
};

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& x : items) s += (s.empty() ? "" : ",") + x;
  return s.empty() ? "none" : s;
}

// The options every file of one call is baked with, parsed once.
struct BakeSettings {
  shadetool::ShadeOptions shade;
  shadetool::ShadingFrequency frequency = shadetool::ShadingFrequency::PerVertex;
  bool hdr = false;
  bool linear = false;
  shadetool::ShadowOptions shadows;
  bool samples_given = false;
};

// No --scene: a glTF primitive is lit by its own file's KHR_lights_punctual lights, camera and
// placement (gltf/gltf_lights.h); a file without lights (every other format, a glTF without any)
// by the default scene (lighting/default_scene.h: a sky and a key light over the viewer's
// shoulder) seen by the camera that frames the mesh, a glTF primitive placed by its nodes.
shadetool::Scene own_or_default_scene(const shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
  shadetool::Affine3d placement;
  if (r.gltf) {
    std::vector<std::string> scene_notes;
    shadetool::Scene scene = shadetool::gltf_scene(*r.gltf_document, *r.gltf, scene_notes);
    for (auto& n : scene_notes) r.notes.push_back(n);
    if (!scene.lights.empty()) return scene;
    placement = scene.world_from_object;
  }
  shadetool::Scene scene = shadetool::default_scene();
  scene.world_from_object = placement;
  shadetool::frame_camera(mesh, scene, input);
  r.notes.push_back(std::string("no --scene") + (r.gltf ? " and no KHR_lights_punctual light in the file" : "") +
                    ": the default scene (a sky and a key light over the viewer's shoulder, grey Phong), seen by "
                    "a camera that frames the mesh");
  return scene;
}

// What the mesh must carry to be lit: finite positions, faces per face, normals or faces per vertex.
// Normals pass through to the output: one without a direction is replaced by the computed one, with
// a counted note (normals/replace_invalid_normals.h).
void check_bakeable(shadetool::Mesh& mesh, const std::string& input, shadetool::ShadingFrequency frequency, FileResult& r) {
  shadetool::require_finite_positions(mesh, input);
  if (const std::string note = shadetool::invalid_normals_note(shadetool::replace_invalid_normals(mesh)); !note.empty())
    r.notes.push_back(note);
  shadetool::require_bakeable(mesh, frequency, input);
}

// A glTF file lit by its own lights: shadows from its whole scene (every primitive placed by its
// nodes, gltf/gltf_scene.h), one BVH per document (lighting/world_occluders.h) built at its first
// primitive; with --scene the scene file places the mesh and only the primitive itself casts
// shadows (null: bake_lighting builds that one).
const shadetool::VisibilityScene* document_occluders(FileResult& r) {
  if (!r.gltf_document_state) return nullptr;
  const shadetool::WorldOccluders& occluders =
      r.gltf_document_state->get_or_make<shadetool::WorldOccluders>([&](shadetool::WorldOccluders& made) {
        std::vector<std::string> unused;  // the world mesh's notes concern writing it, not its shadows
        const shadetool::Mesh world = shadetool::gltf_world_mesh(*r.gltf_document, unused);
        std::unique_ptr<shadetool::WorldOccluders> built = shadetool::world_occluders(world.positions, world);
        made.world = std::move(built->world);  // a moved vector keeps its buffer: the BVH's view stays valid
        made.bvh = std::move(built->bvh);
      });
  r.notes.push_back("shadows cast by the whole scene (every primitive placed by its nodes), one BVH");
  return occluders.bvh.get();
}

void add_bake_notes(const shadetool::BakeResult& baked, const shadetool::Scene& scene, const BakeSettings& set,
                    FileResult& r) {
  const shadetool::ShadeReport& rep = baked.report;
  const bool per_face = set.frequency == shadetool::ShadingFrequency::PerFace;
  if (!per_face && baked.normals_source.rfind("computed", 0) == 0)
    r.notes.push_back("vertex normals " + baked.normals_source);
  if (baked.normal_fallback_vertices > 0)
    r.notes.push_back(std::to_string(baked.normal_fallback_vertices) +
                      " vertices have no valid face: their normal is the normals module's fallback");
  if (rep.counters.zero_normals > 0)
    r.notes.push_back(std::to_string(rep.counters.zero_normals) + (per_face ? " faces" : " vertices") +
                      " have a zero or non-finite normal: lit by the emission and ambient terms only");
  if (rep.counters.at_light > 0)
    r.notes.push_back(std::to_string(rep.counters.at_light) +
                      " vertex-light pairs have the point at the light's position: that light adds nothing there");
  if (set.shadows.enabled && set.samples_given && baked.shadows.sampled_lights == 0)
    r.notes.push_back("--samples ignored: the scene has no area, sky or environment light (directional, point and spot "
                      "lights cast one shadow ray each)");
  if (rep.plan.view && !scene.has_camera)
    r.notes.push_back("the scene has no camera: the eye is at the world origin (OpenGL's default)");
}

// The colours as stored. No NaN or Inf colour is ever written (8-bit encoding would turn NaN into
// a silent black): lights, intensities or positions near the limits of double can produce them;
// refuse.
std::vector<float> encoded_colors(const shadetool::BakeResult& baked, const shadetool::ColorEncoding& encoding,
                                  const std::string& input) {
  std::vector<float> colors = shadetool::encode_colors(baked.rgb, encoding);
  std::size_t nonfinite = 0;
  for (std::size_t i = 0; i < baked.rgb.size(); ++i)
    nonfinite += !(std::isfinite(baked.rgb[i]) && std::isfinite(colors[i]));
  if (nonfinite > 0)
    throw shadetool::Error(shadetool::located(
        input, 0, std::to_string(nonfinite) + " colour values came out NaN or infinite (light positions, " +
                      "intensities or the world map near the limits of double?); nothing written"));
  return colors;
}

void add_bake_stats(const shadetool::BakeResult& baked, const BakeSettings& set, bool document_bvh, FileResult& r) {
  const shadetool::ShadeReport& rep = baked.report;
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
  if (set.shadows.enabled) {
    r.stats["shadow_rays"] = baked.shadows.shadow_rays;
    r.stats["occluded_light_terms"] = rep.counters.shadowed;
    r.setting("shadow_samples", baked.shadows.sampled_lights > 0 ? set.shadows.samples : 1u);
    if (document_bvh) r.setting("bvh_bytes", baked.shadows.bvh_bytes);  // one BVH for the document
    else r.stats["bvh_bytes"] = baked.shadows.bvh_bytes;
  }
}

RegisterCommand reg("bake-lighting", HelpSection::Shade, [](CLI::App& app) -> std::function<int()> {
  auto options = std::make_shared<CommandOptions<BakeLightingOptions>>();  // bound to the flags, read by the run function
  IoOptions& io = options->io;
  BakeLightingOptions& opt = options->opt;
  auto* sub = app.add_subcommand(
      "bake-lighting",
      "Bake lit colours into a mesh: OpenGL 2.1 fixed-function lighting (lambert, phong, blinn-phong; ambient, "
      "directional, point and spot lights; area and sky lights, exact where a closed form exists) per vertex or per "
      "face");
  add_io_options(*sub, io, OutputKind::Mesh);
  sub->add_option("--scene", opt.scene,
                  "Scene file (JSON): material, lights, camera, world_from_object; default: a glTF input's own "
                  "KHR_lights_punctual lights, first camera and node placement, else the default scene (a sky and a key "
                  "light over the viewer's shoulder, a camera framing the mesh)")
      ->type_name("SCENE.json");
  sub->add_option("--camera", opt.camera,
                  "scene: the scene's camera (default; it sets the view for specular highlights); frame: a camera that "
                  "frames the mesh instead")
      ->check(CLI::IsMember(shadetool::camera_choice_names()));
  sub->add_option("--model", opt.model, "Shading model, overriding the scene's (default: the scene's, else blinn-phong)")
      ->check(CLI::IsMember(shadetool::shading_model_names()));
  sub->add_option("--space", opt.space,
                  "Space the equation is evaluated in; all give the same colours (default auto: the cheapest)")
      ->check(CLI::IsMember(shadetool::shading_space_names()));
  sub->add_option("--per", opt.per, "vertex: one colour per vertex (Gouraud); face: one per face (flat) (default vertex)")
      ->check(CLI::IsMember(shadetool::shading_frequency_names()));
  sub->add_flag("--hdr", opt.hdr, "Write float colours, unclamped (default: 8-bit, round(255 * clamp(c, 0, 1)))");
  sub->add_flag("--linear", opt.linear,
                "Write linear 8-bit colours, the OpenGL 2.1 look (default: sRGB-encoded bytes, as viewers read them; "
                "float and glTF colours are always linear; see man shadetool, COLOUR)");
  sub->add_flag("--srgb", opt.srgb, "sRGB-encoded 8-bit colours: the default now (kept as a no-op)");
  sub->add_flag("--unlit", opt.unlit,
                "glTF input to glTF output: give the baked primitives' materials KHR_materials_unlit (a non-glTF input "
                "written as glTF always gets an unlit material)");
  auto* shadows_flag = sub->add_flag("--shadows", opt.shadows,
                "Shadows: multiply each light's diffuse and specular terms by its visibility from the point (one ray "
                "for directional, point and spot lights; --samples rays for area and sky lights)");
  auto* samples = sub->add_option("--samples", opt.samples,
                                  "With --shadows: rays per point per area or sky light (default 16; a sky casts them "
                                  "for the sky and again for the ground)")
                      ->needs(shadows_flag);
  add_fit_options(*sub, opt.fit, "lit colour");

  return [options, samples] {
    IoOptions& io = options->io;
    const BakeLightingOptions& opt = options->opt;
    const FitCliOptions fit = opt.fit;
    // The scene is read once, before any mesh: a bad scene fails the command (exit 1), no output.
    const bool own_scene = opt.scene.empty();  // glTF input: the file's lights (gltf/gltf_lights.h)
    BakeSettings set;
    if (!opt.model.empty()) set.shade.model = shadetool::parse_shading_model(opt.model, "--model");
    set.shade.space = shadetool::parse_shading_space(opt.space, "--space");
    set.frequency = shadetool::parse_shading_frequency(opt.per, "--per");
    set.hdr = opt.hdr;
    set.linear = opt.linear;
    if (opt.linear && opt.srgb) throw UsageError("--linear and --srgb contradict each other");
    set.shadows.enabled = opt.shadows;
    set.shadows.samples = opt.samples;
    set.samples_given = samples->count() > 0;
    try {  // the library's limit (lighting/light_visibility.h), relayed as a usage error
      shadetool::check_shadow_options(set.shadows, "--samples");
    } catch (const shadetool::Error& e) {
      throw UsageError(e.what());
    }
    const shadetool::Scene file_scene = own_scene ? shadetool::Scene() : shadetool::read_scene(opt.scene);
    const bool frame = shadetool::parse_camera_choice(opt.camera, "--camera") == shadetool::CameraChoice::Frame;
    // The result is colours: an output format without them is refused before any work.
    const bool per_face = set.frequency == shadetool::ShadingFrequency::PerFace;
    io.result_attributes = {per_face ? &shadetool::FormatAttributes::face_colors : &shadetool::FormatAttributes::vertex_colors};
    io.result_name = per_face ? "face colours" : "vertex colours";

    return run_command("bake-lighting", io, [=](shadetool::Mesh& mesh, const std::string& input, FileResult& r) {
      // lighting/encode_color.h's rule: 8-bit sRGB unless --linear; float and glTF COLOR_0 linear.
      const shadetool::ColorEncoding file_encoding = shadetool::output_color_encoding(!set.hdr, r.output_gltf, set.linear);
      if (opt.srgb) r.notes.push_back("--srgb is the default now (8-bit colours are sRGB-encoded; float and glTF colours linear)");
      if (opt.linear && !file_encoding.hdr && r.output_gltf) r.notes.push_back("--linear: glTF's COLOR_0 is linear anyway");
      if (opt.linear && file_encoding.hdr) r.notes.push_back("--linear: float colours are linear anyway");
      if (opt.unlit && !r.output_gltf) r.notes.push_back("--unlit ignored: only a glTF output has materials");
      shadetool::Scene scene = own_scene ? own_or_default_scene(mesh, input, r) : file_scene;
      if (frame) shadetool::frame_camera(mesh, scene, input);
      check_bakeable(mesh, input, set.frequency, r);
      shadetool::ShadowOptions cast = set.shadows;
      if (set.shadows.enabled && own_scene) cast.occluders = document_occluders(r);
      cast.progress = r.progress;
      if (set.frequency == shadetool::ShadingFrequency::PerVertex && shadetool::io::corner_normals_disagree(mesh)) {
        // Corner normals that differ at a vertex (creases, OBJ vn): one vertex per (vertex, normal)
        // pair, each lit with its own normal, as the same normals read from a PLY file are.
        std::size_t added = 0;
        mesh = shadetool::io::split_corner_normals(mesh, added);
        r.notes.push_back(std::to_string(added) + " vertices added so that each corner is lit with its own normal (corner "
                          "normals differ there); the output's vertex normals are those corner normals");
      }
      // --fit least-squares (lighting/fit_vertex_lighting.h): the point colours replaced by the fit;
      // they are computed only when --stats or --json reports them (the point error, the counts).
      const bool fitted = fit_method(fit) == shadetool::VertexFit::LeastSquares &&
                          set.frequency == shadetool::ShadingFrequency::PerVertex;
      shadetool::VertexFitOptions vfit = vertex_fit_options(fit, io);
      const shadetool::VertexColors point_colors =
          fitted && !vfit.measure_error ? shadetool::VertexColors::None : shadetool::VertexColors::All;
      shadetool::BakeResult baked = shadetool::bake_lighting(mesh, scene, set.frequency, set.shade, cast, point_colors);
      if (fitted) {
        if (!set.hdr) {  // 8-bit: [0, 1], and the solve to a quarter of a step
          vfit.solve.upper = 1;
          vfit.solve.accuracy = shadetool::kEightBitFitAccuracy;
        }
        shadetool::VertexLightingFit lsq = shadetool::fit_vertex_lighting(mesh, scene, baked, set.shade, cast, vfit);
        baked.rgb = std::move(lsq.rgb);
        if (point_colors == shadetool::VertexColors::None) {  // no point shading: the fit's counts stand in
          baked.report.counters += lsq.fallback_counters;     // the fallback vertices it lit
          baked.shadows.hard_lights = lsq.shadows.hard_lights;  // the lights its shadow rays were cast for
          baked.shadows.sampled_lights = lsq.shadows.sampled_lights;
        }
        report_fit(r, lsq.solve, lsq.error_fit, lsq.error_point, lsq.quadrature_points, fit);
        if (set.shadows.enabled) r.stats["fit_shadow_rays"] = lsq.shadows.shadow_rays;
      } else if (fit_method(fit) == shadetool::VertexFit::LeastSquares) {
        r.notes.push_back("--fit least-squares ignored with --per face (one colour per face is its mean, not a fit)");
      }
      add_bake_notes(baked, scene, set, r);
      for (auto& n : shadetool::store_baked_colors(mesh, encoded_colors(baked, file_encoding, input), set.frequency,
                                                   set.hdr))
        r.notes.push_back(n);
      if (r.output_gltf && !r.gltf) {  // a baked glTF from another format: the normals used, an unlit material
        const std::string added =
            shadetool::add_baked_normals(mesh, set.frequency == shadetool::ShadingFrequency::PerFace);
        if (!added.empty()) r.notes.push_back(added);
        r.unlit = true;
      }
      if (r.output_gltf && r.gltf && opt.unlit) r.unlit = true;
      add_bake_stats(baked, set, cast.occluders != nullptr, r);
    }, OutputKind::Mesh);
  };
});

}  // namespace
}  // namespace shadetool_cli
