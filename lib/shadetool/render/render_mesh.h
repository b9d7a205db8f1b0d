// render_mesh.h: a mesh rendered to a linear RGB image: flat, Gouraud or Phong shading, with the
// lighting of lib/lighting (the same equation and code as `bake-lighting`).
//
// Inputs:  mesh     positions #V by 3 (object space), faces of any size; normals if it has them
//                   (corner normals that differ at a vertex: the vertex is split per normal first,
//                   io/split_corner_normals.h with_creases_split, so each corner is shaded with its
//                   own normal and an OBJ with `vn` renders as the same normals from a PLY)
//          scene    lighting/scene.h: lights, material, world_from_object M, camera (render/camera.h
//                   for the projection fields), two_sided
//          options  shading, size W x H, N x N samples per pixel, background, model/space, threads
// Output:  RenderResult: image (H x W x 3 floats, linear, unclamped, row 0 at the top), camera,
//          counts (RenderStats), and optionally the coverage count of every sample.
//
// Pipeline (one step per file):
//   1. positions to world (M) and to clip space (camera.h); normals to world by sign(det) cof(M).
//   2. faces split into triangles: 5+ corners by geometry/polygon_triangles.h (ear clipping inside the
//      outline, as the glTF and STL writers write them; a convex polygon: the fan from corner 0),
//      convex quads along their 0-2 diagonal, keeping their four corners for shading; a concave
//      quad (polygon_triangles.h quad_is_concave: one corner turning right, its bilinear map folds)
//      by polygon_triangles, through its reflex corner as the writers and Blender split it, each
//      triangle shaded linearly as a triangle.
//   3. per triangle: clipped against near/far/guard band (clip_polygon.h), projected, snapped to
//      1/256 of a sample (fill_rule.h), back faces culled unless scene.two_sided (orientation
//      as seen by the camera, times sign(det(V M)): a mirror keeps its outside outside).
//   4. square tiles (32 or 64 pixels, tile_raster.cpp) on TBB threads: per sample the nearest
//      triangle (depth test on z/w, ties to the lower triangle index) and its screen barycentrics;
//      then per visible sample the perspective-correct barycentrics of the original triangle,
//        b_i = (lambda_i / w_i) / sum_j (lambda_j / w_j)
//      (screen barycentrics lambda are affine in screen space, attributes are affine in 1/w-space),
//      and the shading:
//        flat     the face's colour from bake_lighting per face (face normal at the centroid)
//        gouraud  the baked vertex colours (bake_lighting per vertex), each clamped to [0, 1]
//                 first (lighting/encode_color.h clamp_displayable, as OpenGL 2.1 clamps a vertex's
//                 colour before interpolating it) unless options.clamp_vertex_colors is false
//                 (float output: --hdr), then interpolated
//        phong    world position and world normal interpolated, the normal renormalised, the
//                 lighting equation evaluated at the sample (render/lighting_adapter.h)
//      convex quads: the sample's world point through the inverse bilinear map (inverse_bilinear.h) and
//      the four corners' values (colours; for phong positions and normals) blended bilinearly,
//      so no diagonal seam shows and the image does not depend on the diagonal fanned along;
//   5. box filter: each pixel is the mean of its N x N samples (strata centres, background where
//      no triangle is).
// Shadows (options.lighting.shadows, render/lighting_adapter.h): flat and Gouraud take
// bake-lighting's shadowed colours; Phong casts, per visible sample, lighting/light_visibility.h's
// rays from its world point into a BVH of the mesh in world space (one per directional, point or
// spot light; shadows.samples per area or sky light), seeded by the sample's index in the image;
// each tile asks for its samples' visibility in one batch. Each light's diffuse and specular terms
// are multiplied by its visibility; with nothing in the way the image is bitwise the unshadowed one.
//
// Determinism: every tile reads the triangles in index order and writes only its own pixels, so
// the image is bitwise the same for any number of threads.
// Precision: geometry and shading in double (the lighting's), fixed-point coverage (exact), the
// image stored as float.
// Errors (shadetool::Error, one line naming `name`): check_render_options below, a perspective
// camera whose eye is inside the mesh (|generalised winding number| above 1/2, repair/
// winding_number.h; tested only when the eye is inside the mesh's bounding box).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <shadetool/core/progress.h>
#include <shadetool/core/mesh.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/render/camera.h>
#include <shadetool/render/image.h>
#include <shadetool/render/lighting_adapter.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class RenderShading { Flat, Gouraud, Phong };
// Its vocabulary (core/vocabulary.h): "flat", "gouraud", "phong".
RenderShading parse_render_shading(std::string_view text, const std::string& what);
const char* render_shading_name(RenderShading shading);
std::vector<std::string> render_shading_names();

constexpr int kMaxImageSide = 16384;
constexpr int kMaxSamples = 16;
constexpr int kMaxThreads = 1024;

struct RenderOptions {
  RenderShading shading = RenderShading::Phong;
  int width = 800, height = 600;
  int samples = 1;                    // N: N x N samples per pixel, 1..16
  Vec3d background{0, 0, 0};          // linear RGB
  RenderLightingOptions lighting;     // --model, --space (flat and Gouraud only), shadows
  int threads = 0;                    // 0: TBB's default
  bool count_coverage = false;        // fill RenderResult::coverage (tests)
  bool check_eye_inside = true;       // refuse a camera inside the mesh
  // Gouraud: these linear colours (#V by 3) instead of bake-lighting's point colours (null), e.g.
  // lighting/fit_vertex_lighting.h's least-squares ones. The caller owns them for the call.
  const std::vector<double>* vertex_rgb = nullptr;
  // Gouraud: clamp each vertex colour to [0, 1] before interpolating (OpenGL 2.1; the 8-bit
  // image). false: unclamped (a float image, --hdr). Flat and Phong clamp per pixel when encoded.
  bool clamp_vertex_colors = true;
  // Where the stage "render" reports, in tiles of the image (core/progress.h); null: nobody
  // listens. Never changes a pixel.
  ProgressSink* progress = nullptr;
};

struct RenderStats {
  std::size_t faces = 0;
  std::size_t triangles = 0;              // after fanning
  std::size_t faces_culled = 0;           // every triangle back-facing (not two_sided)
  std::size_t faces_outside_view = 0;     // every triangle outside the view volume
  std::size_t faces_degenerate = 0;       // < 3 corners, or zero area on screen (seen edge-on)
  std::size_t triangles_near_clipped = 0; // triangles crossing the near plane, clipped
  std::size_t samples_covered = 0;        // samples with a visible triangle
  std::size_t quad_fallbacks = 0;         // quad samples whose inverse bilinear map failed (fan used)
};

struct RenderResult {
  ImageRGB image;
  RenderCamera camera;
  RenderStats stats;
  std::vector<std::uint32_t> coverage;  // count_coverage: (H N) x (W N) counts, row-major
};

RenderResult render_mesh(const Mesh& mesh, const Scene& scene, const RenderOptions& options,
                         const std::string& name = "<mesh>");

// The limits of RenderOptions, checked once here (render_mesh calls it first; the CLI and Python
// call it before reading anything and relay the message): Error "NAME: what" when a side is
// outside 1..kMaxImageSide, samples outside 1..kMaxSamples, threads outside 0..kMaxThreads,
// shadow samples outside light_visibility.h's range, a background channel negative or not
// finite, or a shading space is asked of Phong (it
// evaluates the equation per sample in world space: options.lighting.space must be Auto).
void check_render_options(const RenderOptions& options, const std::string& name);

}  // namespace shadetool
#pragma GCC visibility pop
