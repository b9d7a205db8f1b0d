// screen_triangle.h (engine): the rasteriser's triangle after clipping, projection and snapping,
// and what the tile loop needs to shade a sample. Internal to lib/render.
#pragma once

#include <cstdint>
#include <vector>

#include <shadetool/core/mesh.h>
#include <shadetool/render/lighting_adapter.h>
#include <shadetool/render/render_mesh.h>

namespace shadetool::render_engine {

constexpr int kSubUnits = 256;      // fixed-point units per sample spacing (fill_rule.h)
constexpr int kMaxTilePixels = 64;  // tile side in pixels: at most this (tile_raster.cpp tile_pixels)

struct ScreenTriangle {
  std::int32_t X[3], Y[3];      // fixed point, orient(v0, v1, v2) > 0
  double inv_w[3];              // 1 / w of each screen vertex (> 0)
  double z[3];                  // z / w (NDC depth)
  std::uint32_t face;
  std::uint32_t vertex[3];      // mesh vertices of the ORIGINAL triangle (of the face split, step 2)
  std::int32_t clip_index;      // -1: screen vertex i is original corner perm[i]; else into clip_b
  std::uint8_t perm[3];
  bool quad;                    // its face is a convex quad: bilinear interpolation of the 4 corners
  std::int32_t sx0, sx1, sy0, sy1;  // sample bounds, inclusive (may be empty: sx0 > sx1)
};

// Everything the per-sample shading reads (shared, read-only, by every tile).
struct SurfaceInputs {
  RenderShading shading = RenderShading::Phong;
  const Mesh* mesh = nullptr;
  std::vector<double> positions_world;  // #V by 3
  std::vector<double> normals_world;    // #V by 3 (phong)
  std::vector<double> vertex_rgb;       // #V by 3 (gouraud)
  std::vector<double> face_rgb;         // #F by 3 (flat)
  const PointShader* shader = nullptr;  // phong
  Vec3d background{0, 0, 0};
};

struct RasterInput {
  int width = 0, height = 0, samples = 1;
  // The triangles, in face order, as the setup's chunks made them (not joined into one array: at
  // 1M triangles that copy alone was 100 MB of traffic). Tiles refer to them by address.
  std::vector<std::vector<ScreenTriangle>> parts;
  std::vector<double> clip_b;  // 9 per clipped triangle: B_i (3 doubles) per screen vertex
  const SurfaceInputs* surface = nullptr;
  bool count_coverage = false;
  ProgressSink* progress = nullptr;  // the stage "render" in tiles (core/progress.h)
};

struct RasterOutput {
  ImageRGB image;
  std::vector<std::uint32_t> coverage;
  std::size_t samples_covered = 0;
  std::size_t quad_fallbacks = 0;
};

RasterOutput rasterize_tiles(const RasterInput& input);

}  // namespace shadetool::render_engine
