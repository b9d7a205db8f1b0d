// lighting.cpp: bake_lighting, occlusion and render on NumPy arrays: the library's
// lighting/bake_lighting.h, visibility/ambient_occlusion.h and render/render_mesh.h, with the
// input checks of their subcommands (cli/cmd_bake_lighting.cpp, cmd_occlusion.cpp, cmd_render.cpp)
// and the GIL released.
#include <cmath>
#include <filesystem>
#include <limits>

#include <shadetool/core/validate.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/encode_color.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/normals/invalid_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/render/lighting_adapter.h>
#include <shadetool/render/output_image.h>
#include <shadetool/render/render_mesh.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/visibility_scene.h>

#include "arrays.h"
#include "bindings.h"

namespace shadetool_python {
namespace {

namespace fs = std::filesystem;
using shadetool::Mesh;

// The mesh to light: shared when no N is given (a shadetool.Mesh's own normals count), else a
// mesh of its own with N as its vertex normals.
std::shared_ptr<const Mesh> lit_mesh(py::handle V, py::handle F, py::handle N, const std::string& fn) {
  if (N.is_none()) return mesh_input(V, F, fn).mesh;
  if (as_mesh(V)) throw py::value_error(fn + ": N must be None when the first argument is a shadetool.Mesh (set Mesh.vertex_normals)");
  FaceLayout layout;
  auto mesh = std::make_shared<Mesh>(owned_mesh(V, F, fn, layout));
  mesh->vertex_normals = read_double_rows(N, mesh->num_vertices(), 3, fn + ": N");
  return mesh;
}

// A scene dict (the JSON schema of man/shadetool-bake-lighting.1) or a path to a JSON file.
shadetool::Scene scene_of(py::handle scene, const std::string& fn) {
  if (scene.is_none()) throw py::value_error(fn + ": scene is required (a dict in the scene JSON schema, or a path)");
  if (py::isinstance<py::dict>(scene)) {
    const std::string text = py::module_::import("json").attr("dumps")(scene).cast<std::string>();
    return shadetool::parse_scene(text, "scene");
  }
  const std::string path = py::module_::import("os").attr("fspath")(scene).cast<std::string>();
  if (!fs::exists(path)) throw_file_not_found(path, "no such file");
  return shadetool::read_scene(path);
}

// The options' vocabularies are the library's (core/vocabulary.h): its Error names FN: ARG.
std::optional<shadetool::ShadingModel> parse_model(py::handle model, const std::string& fn) {
  if (model.is_none()) return std::nullopt;
  return shadetool::parse_shading_model(model.cast<std::string>(), fn + ": model");
}

bool parse_per(const std::string& s, const std::string& fn) {
  return shadetool::parse_shading_frequency(s, fn + ": per") == shadetool::ShadingFrequency::PerFace;
}

// Colours as a uint8 array: lighting/encode_color.h's rule for an 8-bit output (not glTF), the
// bytes the CLI writes to PLY (sRGB-encoded unless `linear`).
template <typename T>
py::array_t<std::uint8_t> colour_bytes(const std::vector<T>& values, bool linear, std::vector<py::ssize_t> shape) {
  const std::vector<float> encoded = shadetool::encode_colors(std::vector<double>(values.begin(), values.end()),
                                                              shadetool::output_color_encoding(true, false, linear));
  std::vector<std::uint8_t> bytes(encoded.size());
  for (std::size_t i = 0; i < encoded.size(); ++i) bytes[i] = std::uint8_t(std::lround(255.0 * encoded[i]));  // k/255 -> k
  return to_numpy(std::move(bytes), std::move(shape));
}

}  // namespace

void init_lighting(py::module_& m) {
  m.def(
      "bake_lighting",
      [](py::object V, py::object F, py::object N, py::object scene_arg, const std::string& per, py::object model,
         const std::string& space, bool shadows, std::uint32_t samples, bool uint8, bool linear) -> py::object {
        const std::shared_ptr<const Mesh> mesh = lit_mesh(V, F, N, "bake_lighting");
        const shadetool::Scene scene = scene_of(scene_arg, "bake_lighting");
        const bool per_face = parse_per(per, "bake_lighting");
        shadetool::ShadeOptions shade;
        shade.model = parse_model(model, "bake_lighting");
        shade.space = shadetool::parse_shading_space(space, "bake_lighting: space");
        shadetool::ShadowOptions shadow;
        shadow.enabled = shadows;
        shadow.samples = samples;
        shadetool::check_shadow_options(shadow, "bake_lighting: samples");  // the library's limit
        const auto frequency = per_face ? shadetool::ShadingFrequency::PerFace : shadetool::ShadingFrequency::PerVertex;
        shadetool::BakeResult baked;
        {
          py::gil_scoped_release nogil;
          shadetool::require_finite_positions(*mesh, "bake_lighting: V");
          shadetool::require_finite_normals(*mesh, "bake_lighting: N", "recompute them (vertex_normals) or repair first");
          shadetool::require_bakeable(*mesh, frequency, per_face ? "bake_lighting: F" : "bake_lighting");
          baked = shadetool::bake_lighting(*mesh, scene, frequency, shade, shadow);
        }
        std::size_t nonfinite = 0;
        for (double c : baked.rgb) nonfinite += !std::isfinite(c);
        if (nonfinite > 0)
          throw py::value_error("bake_lighting: " + std::to_string(nonfinite) +
                                " colour values came out NaN or infinite (light positions, intensities or the world map "
                                "near the limits of double?)");
        const py::ssize_t rows = py::ssize_t(baked.rgb.size() / 3);
        if (uint8) return colour_bytes(baked.rgb, linear, {rows, 3});
        return to_numpy(std::move(baked.rgb), {rows, 3});
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("N") = py::none(), py::arg("scene") = py::none(),
      py::arg("per") = "vertex", py::arg("model") = py::none(), py::arg("space") = "auto", py::arg("shadows") = false,
      py::arg("samples") = 16, py::arg("uint8") = false, py::arg("linear") = false,
      R"doc(bake_lighting(V, F, N, scene, per="vertex", model=None, space="auto", shadows=False, samples=16, uint8=False, linear=False) -> (rows, 3) float64 or uint8

Lit colours per vertex (Gouraud) or per face (flat): OpenGL 2.1 fixed-function lighting with the
library's lighting/bake_lighting.h, the colours `shadetool bake-lighting --hdr` stores (before
its float rounding): linear RGB, unclamped, float64, (n, 3) per vertex or (m, 3) per face.
  V, F    (n, 3) float positions, (m, k) integer faces or (indices, offsets); or a shadetool.Mesh
          (F None) whose own normals are used
  N       (n, 3) float vertex normals, or None: the mesh's, else angle-weighted vertex normals
  scene   a dict in the scene JSON schema (man shadetool-bake-lighting: model, material, lights,
          camera, world_from_object, ...) or a path to a JSON file (FileNotFoundError if missing)
  per     "vertex" or "face"; model overrides the scene's ("lambert", "phong", "blinn-phong");
  space   "auto", "world", "camera" or "object" (same colours; render: flat and gouraud only,
          phong refuses any but "auto"); shadows: per-light visibility
          by ray casting (samples rays per area or sky light)
  uint8   True: the 8-bit colours `shadetool bake-lighting` writes to PLY, sRGB-encoded (man
          shadetool, COLOUR), or linear round(255 * clamp(c, 0, 1)) with linear=True
ValueError: bad arrays, a bad scene (the library's `scene: $.path: what` message), non-finite
positions or normals.
)doc");

  m.def(
      "occlusion",
      [](py::object V, py::object F, py::object N, std::uint32_t samples, double distance, const std::string& per,
         std::uint32_t seed, bool uint8, bool linear) -> py::object {
        const std::shared_ptr<const Mesh> mesh = lit_mesh(V, F, N, "occlusion");
        const bool per_face = parse_per(per, "occlusion");
        shadetool::AmbientOcclusionOptions options;
        options.samples = samples;
        options.max_distance = distance;
        options.seed = seed;
        shadetool::check_occlusion_options(options, "occlusion");  // the library's limits
        shadetool::AmbientOcclusion ao;
        {
          py::gil_scoped_release nogil;
          shadetool::require_faces(*mesh, "occlusion: F");
          shadetool::require_finite_positions(*mesh, "occlusion: V");
          shadetool::require_finite_normals(*mesh, "occlusion: N", "recompute them (vertex_normals) or repair first");
          ao = shadetool::mesh_occlusion(*mesh, per_face, options, "occlusion: N").ao;
        }
        const py::ssize_t rows = py::ssize_t(ao.open_fraction.size());
        if (uint8) return colour_bytes(ao.open_fraction, linear, {rows});
        return to_numpy(std::move(ao.open_fraction), {rows});
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("N") = py::none(), py::arg("samples") = 64,
      py::arg("distance") = std::numeric_limits<double>::infinity(), py::arg("per") = "vertex", py::arg("seed") = 0,
      py::arg("uint8") = false, py::arg("linear") = false,
      R"doc(occlusion(V, F, N=None, samples=64, distance=inf, per="vertex", seed=0, uint8=False, linear=False) -> (rows,) float32 or uint8

How open the sky is from each vertex (or face): the cosine-weighted fraction of the hemisphere
about its normal from which a ray leaves without meeting the mesh within `distance`, in [0, 1]
(1 - ambient occlusion), estimated with `samples` rays (Embree; the library's
visibility/ambient_occlusion.h, the values `shadetool occlusion` stores). Bitwise the same for any
thread count and run; the error falls as samples^-3/4.
  V, F   (n, 3) float positions, (m, k) integer faces or (indices, offsets); or a shadetool.Mesh
  N      (n, 3) float vertex normals (the hemispheres' axes) or None: angle-weighted normals
  per    "vertex" -> (n,), "face" -> (m,) (face normal at the face's centroid)
Points without a usable normal get 1 (no ray cast).
  uint8  True: the grey bytes `shadetool occlusion` writes to PLY, sRGB-encoded (man shadetool,
         COLOUR), or linear round(255 * open) with linear=True
)doc");

  m.def(
      "render",
      [](py::object V, py::object F, py::object N, py::object scene_arg, int width, int height,
         const std::string& shading, int samples, py::object background, py::object model, const std::string& space,
         bool hdr, int threads) -> py::object {
        const std::shared_ptr<const Mesh> mesh = lit_mesh(V, F, N, "render");
        const shadetool::Scene scene = scene_of(scene_arg, "render");
        shadetool::RenderOptions ro;
        ro.shading = shadetool::parse_render_shading(shading, "render: shading");
        const std::vector<double> bg = read_double_rows(
            py::module_::import("numpy").attr("asarray")(background, "float64").attr("reshape")(1, 3), 1, 3,
            "render: background");
        ro.width = width;
        ro.height = height;
        ro.samples = samples;
        ro.background = {bg[0], bg[1], bg[2]};
        ro.lighting.model = parse_model(model, "render");
        ro.lighting.space = shadetool::parse_shading_space(space, "render: space");
        ro.threads = threads;
        ro.clamp_vertex_colors = !hdr;  // gouraud: OpenGL 2.1's clamped vertex colours, unless float output
        shadetool::check_render_options(ro, "render");  // the library's limits (render_mesh.h)
        shadetool::RenderResult result;
        {
          py::gil_scoped_release nogil;
          shadetool::require_finite_positions(*mesh, "render: V");
          shadetool::require_finite_normals(*mesh, "render: N", "recompute them (vertex_normals) or repair first");
          result = shadetool::render_mesh(*mesh, scene, ro, "render: V");
        }
        std::size_t nonfinite = 0;
        for (float c : result.image.rgb) nonfinite += !std::isfinite(c);
        if (nonfinite > 0)
          throw py::value_error("render: " + std::to_string(nonfinite) + " colour values came out NaN or infinite");
        const py::ssize_t h = result.image.height, w = result.image.width;
        if (hdr) return to_numpy(std::move(result.image.rgb), {h, w, 3});
        return to_numpy(shadetool::render_output_image(result.image, false).u8, {h, w, 3});
      },
      py::arg("V"), py::arg("F") = py::none(), py::arg("N") = py::none(), py::arg("scene") = py::none(),
      py::arg("width") = 800, py::arg("height") = 600, py::arg("shading") = "phong", py::arg("samples") = 1,
      py::arg("background") = py::make_tuple(0.0, 0.0, 0.0), py::arg("model") = py::none(), py::arg("space") = "auto",
      py::arg("hdr") = false, py::arg("threads") = 0,
      R"doc(render(V, F, N, scene, width=800, height=600, shading="phong", samples=1, background=(0, 0, 0), model=None, space="auto", hdr=False, threads=0) -> (height, width, 3) array

Renders the mesh with bake_lighting's lighting (the library's render/render_mesh.h, what
`shadetool render` writes): row 0 at the top.
  hdr=False: uint8 sRGB-encoded pixels (the PNG's bytes); hdr=True: float32 linear, unclamped
  (gouraud: vertex colours clamped to [0, 1] before interpolating, as OpenGL 2.1, unless hdr=True)
  (the PFM's values, top row first)
  shading  "flat" (face normals), "gouraud" (baked vertex colours) or "phong" (per sample)
  samples  N: N x N samples per pixel, box-filtered (1..16); background linear RGB (3 floats >= 0)
  V, F, N, scene, model, space as in bake_lighting; scene's camera (fov_y, near, far,
  orthographic), or one that frames the mesh
Bitwise the same image for any number of threads.
)doc");
}

}  // namespace shadetool_python
