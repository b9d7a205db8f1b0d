// tile_raster.cpp (engine): binning, the tile loop on TBB threads, per-sample visibility and
// shading, and the box filter. The formulas it calls live in lib/shadetool/render/*.h by name:
// fill_rule.h (coverage), perspective_barycentrics.h, inverse_bilinear.h, lighting_adapter.h.
#include <shadetool/render/engine/screen_triangle.h>
#include <shadetool/render/engine/depth_row_lanes.h>
#include <shadetool/render/engine/gouraud_run_lanes.h>
#include <shadetool/render/engine/phong_point_lanes.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <shadetool/render/fill_rule.h>
#include <shadetool/render/inverse_bilinear.h>
#include <shadetool/render/perspective_barycentrics.h>

namespace shadetool::render_engine {

namespace {

// Copies n floats of one tile row into the image (bit for bit). Non-temporal stores where the
// destination is 16-byte aligned: the renderer writes each pixel of the image (25 MB at 1920x1080)
// once and never reads it back, so the stores need not first read every cache line they fill
// (bench/render/results.md); raster_tile ends with a store fence so the pixels are visible to
// whoever reads the image after the tile loop.
void write_image_row(float* dst, const float* src, std::size_t n) {
#if defined(__SSE2__)
  std::size_t i = 0;
  for (; i < n && (reinterpret_cast<std::uintptr_t>(dst + i) & 15) != 0; ++i) dst[i] = src[i];
  for (; i + 4 <= n; i += 4) _mm_stream_ps(dst + i, _mm_loadu_ps(src + i));
  for (; i < n; ++i) dst[i] = src[i];
#else
  std::memcpy(dst, src, n * sizeof(float));
#endif
}

void store_fence() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}


// The original triangle's barycentrics at a sample with screen barycentrics lambda.
void original_barycentrics(const RasterInput& in, const ScreenTriangle& t, const double lambda[3], double ob[3]) {
  double b[3];
  perspective_barycentrics(lambda, t.inv_w, b);
  if (t.clip_index < 0) {
    ob[0] = ob[1] = ob[2] = 0;
    for (int i = 0; i < 3; ++i) ob[t.perm[i]] = b[i];
    return;
  }
  const double* B = in.clip_b.data() + 9 * std::size_t(t.clip_index);
  for (int k = 0; k < 3; ++k) ob[k] = b[0] * B[k] + b[1] * B[3 + k] + b[2] * B[6 + k];
}

// Weights of mesh vertices for the sample: 3 (triangle) or 4 (quad, bilinear) entries.
struct VertexWeights {
  std::uint32_t vertex[4];
  double weight[4];
  int count = 0;
};

VertexWeights vertex_weights(const SurfaceInputs& s, const ScreenTriangle& t, const double ob[3], std::size_t& fallbacks) {
  VertexWeights w;
  const Mesh& mesh = *s.mesh;
  if (t.quad) {
    const std::uint32_t* q = mesh.corner_vertex.data() + mesh.face_start[t.face];
    Vec3d corners[4];
    for (int k = 0; k < 4; ++k) corners[k] = get3(s.positions_world, q[k]);
    Vec3d p{0, 0, 0};
    for (int k = 0; k < 3; ++k) p += get3(s.positions_world, t.vertex[k]) * ob[k];
    QuadUV uv;
    if (inverse_bilinear_3d(p, corners, uv)) {
      const double u = uv.u, v = uv.v;
      const double weight[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
      for (int k = 0; k < 4; ++k) {
        w.vertex[k] = q[k];
        w.weight[k] = weight[k];
      }
      w.count = 4;
      return w;
    }
    ++fallbacks;
  }
  for (int k = 0; k < 3; ++k) {
    w.vertex[k] = t.vertex[k];
    w.weight[k] = ob[k];
  }
  w.count = 3;
  return w;
}

// The mesh-vertex weights at a sample with screen barycentrics lambda. Fast path, for the common
// unclipped triangle: the perspective-correct barycentrics ARE the weights of its corners (in
// screen order, t.perm); otherwise through the original triangle (clipped) and the quad's map.
VertexWeights sample_weights(const RasterInput& in, const ScreenTriangle& t, const double lambda[3],
                             std::size_t& fallbacks) {
  if (!t.quad && t.clip_index < 0) {
    VertexWeights w;
    perspective_barycentrics(lambda, t.inv_w, w.weight);
    for (int i = 0; i < 3; ++i) w.vertex[i] = t.vertex[t.perm[i]];
    w.count = 3;
    return w;
  }
  double ob[3];
  original_barycentrics(in, t, lambda, ob);
  return vertex_weights(*in.surface, t, ob, fallbacks);
}

// Phong's world point and unit normal at a sample. Position and normal from the same weights: on a
// quad the point of the bilinear patch, so the quad's look does not depend on the diagonal it was
// fanned along.
void phong_point(const RasterInput& in, const ScreenTriangle& t, const double lambda[3], std::size_t& fallbacks,
                 Vec3d& p, Vec3d& n) {
  const SurfaceInputs& s = *in.surface;
  const VertexWeights w = sample_weights(in, t, lambda, fallbacks);
  p = {0, 0, 0}, n = {0, 0, 0};
  for (int k = 0; k < w.count; ++k) {
    p += get3(s.positions_world, w.vertex[k]) * w.weight[k];
    n += get3(s.normals_world, w.vertex[k]) * w.weight[k];
  }
  n = unit_or_zero_normal(n);  // phong_point_lanes.h
}

// Gouraud's colour at a sample: the corners' colours blended by the sample's weights, summed in
// weight order (the one home of this sum: shade_sample and the tile loop's run cache call it).
inline Vec3d blend_vertex_colors(const Vec3d* rgb, const double* weight, int count) {
  Vec3d c{0, 0, 0};
  for (int k = 0; k < count; ++k) c += rgb[k] * weight[k];
  return c;
}

// A Gouraud triangle's corner colours in screen order, looked up once for a run of samples that
// the same triangle owns. direct: unclipped and not a quad, so that the perspective-correct
// barycentrics are the corners' weights (sample_weights' fast path); otherwise shade_sample.
struct GouraudCorners {
  const ScreenTriangle* triangle = nullptr;
  bool direct = false;
  Vec3d rgb[3];

  void load(const SurfaceInputs& s, const ScreenTriangle* t) {
    triangle = t;
    direct = !t->quad && t->clip_index < 0;
    if (direct)
      for (int i = 0; i < 3; ++i) rgb[i] = get3(s.vertex_rgb, t->vertex[t->perm[i]]);
  }
};

// One sample per pixel, Gouraud, a run of n pixels that one direct triangle owns (GouraudCorners).
// The scalar loop is the definition: per pixel the operations of the general loop in the same
// order (lambda, perspective_barycentrics, blend_vertex_colors, the box filter's sum and scale).
// With AVX2 four pixels (gouraud_run_lanes.h), then with SSE2 two, go through the very same IEEE
// operations side by side (no fused multiply-add, same order, the same selects), so the floats are
// bitwise the scalar loop's.
void gouraud_run(const Vec3d corner_rgb[3], const double inv_w[3], const double* lambda1, const double* lambda2,
                 int n, double inv_samples, float* out) {
  int i = gouraud_run_lanes(corner_rgb, inv_w, lambda1, lambda2, n, inv_samples, out);  // four at a time (AVX2)
#if defined(__SSE2__)
  const __m128d one = _mm_set1_pd(1.0), zero = _mm_setzero_pd(), scale = _mm_set1_pd(inv_samples);
  const __m128d iw0 = _mm_set1_pd(inv_w[0]), iw1 = _mm_set1_pd(inv_w[1]), iw2 = _mm_set1_pd(inv_w[2]);
  auto select = [](__m128d mask, __m128d a, __m128d b) { return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b)); };
  __m128d rgb[3][3];  // rgb[k][c]: corner k's channel c in both lanes
  for (int k = 0; k < 3; ++k)
    for (int c = 0; c < 3; ++c) rgb[k][c] = _mm_set1_pd(corner_rgb[k][c]);
  for (; i + 2 <= n; i += 2) {
    const __m128d l1 = _mm_loadu_pd(lambda1 + i), l2 = _mm_loadu_pd(lambda2 + i);
    const __m128d l0 = _mm_sub_pd(_mm_sub_pd(one, l1), l2);
    // perspective_barycentrics
    const __m128d m0 = _mm_mul_pd(l0, iw0), m1 = _mm_mul_pd(l1, iw1), m2 = _mm_mul_pd(l2, iw2);
    const __m128d sum = _mm_add_pd(_mm_add_pd(m0, m1), m2);
    const __m128d positive = _mm_cmpgt_pd(sum, zero);
    const __m128d inv = _mm_div_pd(one, sum);
    const __m128d w0 = select(positive, _mm_mul_pd(m0, inv), l0);
    const __m128d w1 = select(positive, _mm_mul_pd(m1, inv), l1);
    const __m128d w2 = select(positive, _mm_mul_pd(m2, inv), l2);
    // blend_vertex_colors, then the box filter's 0 + c and scale, per channel
    float channel[3][4];
    for (int c = 0; c < 3; ++c) {
      __m128d acc = _mm_add_pd(zero, _mm_mul_pd(rgb[0][c], w0));
      acc = _mm_add_pd(acc, _mm_mul_pd(rgb[1][c], w1));
      acc = _mm_add_pd(acc, _mm_mul_pd(rgb[2][c], w2));
      _mm_storeu_ps(channel[c], _mm_cvtpd_ps(_mm_mul_pd(_mm_add_pd(zero, acc), scale)));
    }
    for (int k = 0; k < 2; ++k)
      for (int c = 0; c < 3; ++c) out[3 * (i + k) + c] = channel[c][k];
  }
#endif
  for (; i < n; ++i) {
    const double lambda[3] = {1.0 - lambda1[i] - lambda2[i], lambda1[i], lambda2[i]};
    double weight[3];
    perspective_barycentrics(lambda, inv_w, weight);
    Vec3d sum{0, 0, 0};
    sum += blend_vertex_colors(corner_rgb, weight, 3);
    out[3 * i] = float(sum.x * inv_samples);
    out[3 * i + 1] = float(sum.y * inv_samples);
    out[3 * i + 2] = float(sum.z * inv_samples);
  }
}

Vec3d shade_sample(const RasterInput& in, const ScreenTriangle& t, const double lambda[3], ShadeCounters& counters,
                   std::size_t& fallbacks) {
  const SurfaceInputs& s = *in.surface;
  switch (s.shading) {
    case RenderShading::Flat:
      return get3(s.face_rgb, t.face);
    case RenderShading::Gouraud: {
      const VertexWeights w = sample_weights(in, t, lambda, fallbacks);
      Vec3d rgb[4];
      for (int k = 0; k < w.count; ++k) rgb[k] = get3(s.vertex_rgb, w.vertex[k]);
      return blend_vertex_colors(rgb, w.weight, w.count);
    }
    case RenderShading::Phong: {
      Vec3d p, n;
      phong_point(in, t, lambda, fallbacks, p, n);
      return s.shader->shade(p, n, counters);
    }
  }
  return {0, 0, 0};
}

// One sample per pixel, Phong, no shadows: pixels [px0, px1) of one tile row (owner, lambda1 and
// lambda2 indexed by pixel x), into out (3 floats a pixel, from px0). The visible samples' points
// and normals (phong_point's: a run of pixels that one unclipped triangle owns by
// phong_points_run, four at a time in vector lanes, others one by one) are shaded as one block
// (PointShader::shade_block: four at a time in vector lanes), then written as the general loop
// writes them (0 + colour, scaled). Returns the number of covered pixels.
std::size_t phong_row(const RasterInput& in, const ScreenTriangle* const* owner, const double* lambda1,
                      const double* lambda2, int px0, int px1, double inv_samples, ShadeCounters& counters,
                      std::size_t& fallbacks, float* out) {
  double px[kMaxTilePixels], py[kMaxTilePixels], pz[kMaxTilePixels];
  double nx[kMaxTilePixels], ny[kMaxTilePixels], nz[kMaxTilePixels];
  double rgb[3 * kMaxTilePixels];
  int pixel[kMaxTilePixels];
  std::size_t k = 0;
  const Vec3d background = in.surface->background;
  for (int x = px0; x < px1; ++x) {
    const ScreenTriangle* t = owner[x];
    if (t == nullptr) {
      Vec3d sum{0, 0, 0};
      sum += background;
      float* o = out + 3 * (x - px0);
      o[0] = float(sum.x * inv_samples), o[1] = float(sum.y * inv_samples), o[2] = float(sum.z * inv_samples);
      continue;
    }
    if (!t->quad && t->clip_index < 0) {  // sample_weights' fast path: the run this triangle owns
      int end = x + 1;
      while (end < px1 && owner[end] == t) ++end;
      const SurfaceInputs& s = *in.surface;
      Vec3d corner_p[3], corner_n[3];
      for (int i = 0; i < 3; ++i) {
        corner_p[i] = get3(s.positions_world, t->vertex[t->perm[i]]);
        corner_n[i] = get3(s.normals_world, t->vertex[t->perm[i]]);
      }
      phong_points_run(corner_p, corner_n, t->inv_w, lambda1 + x, lambda2 + x, std::size_t(end - x),
                       {px + k, py + k, pz + k, nx + k, ny + k, nz + k});
      for (; x < end; ++x) pixel[k++] = x - px0;
      --x;  // the loop's ++x
      continue;
    }
    const double lambda[3] = {1.0 - lambda1[x] - lambda2[x], lambda1[x], lambda2[x]};
    Vec3d p, n;
    phong_point(in, *t, lambda, fallbacks, p, n);
    px[k] = p.x, py[k] = p.y, pz[k] = p.z, nx[k] = n.x, ny[k] = n.y, nz[k] = n.z;
    pixel[k++] = x - px0;
  }
  PointBlock block;
  block.count = k;
  block.px = px, block.py = py, block.pz = pz, block.nx = nx, block.ny = ny, block.nz = nz;
  in.surface->shader->shade_block(block, rgb, counters);
  for (std::size_t j = 0; j < k; ++j) {
    Vec3d sum{0, 0, 0};
    sum += Vec3d{rgb[3 * j], rgb[3 * j + 1], rgb[3 * j + 2]};
    float* o = out + 3 * pixel[j];
    o[0] = float(sum.x * inv_samples), o[1] = float(sum.y * inv_samples), o[2] = float(sum.z * inv_samples);
  }
  return k;
}

struct TileResult {
  std::size_t covered = 0, fallbacks = 0;
};

// Per-thread scratch for one tile (reused from tile to tile).
struct TileBuffers {
  std::vector<double> depth, lambda1, lambda2;
  std::vector<const ScreenTriangle*> owner;
};

// Tile side in pixels (the pixels are the same for any side: every sample's value depends only on
// the triangles in index order). 64 where the per-sample work is light (flat and Gouraud at one
// sample per pixel: fewer tiles, so fewer per-tile clears and bin entries); 32 otherwise: Phong
// reads three vertices' positions and normals per sample, and at 1M triangles a 64-pixel tile's
// working set made it 1.4x slower; N x N samples multiply a tile's buffers (bench/render/results.md).
int tile_pixels(RenderShading shading, int samples) {
  switch (shading) {
    case RenderShading::Flat:
    case RenderShading::Gouraud:
      return samples == 1 ? kMaxTilePixels : 32;
    case RenderShading::Phong:
      return 32;
  }
  return 32;
}

TileResult raster_tile(const RasterInput& in, const std::vector<const ScreenTriangle*>& bin, int tile_side, int tile_x,
                       int tile_y, TileBuffers& buffers, RasterOutput& out) {
  const int N = in.samples;
  const int px0 = tile_x * tile_side, py0 = tile_y * tile_side;
  const int px1 = std::min(in.width, px0 + tile_side), py1 = std::min(in.height, py0 + tile_side);
  const Vec3d background = in.surface->background;
  const std::size_t row_floats = 3 * std::size_t(px1 - px0);
  float tile_row[3 * kMaxTilePixels];  // one pixel row of the tile, written to the image by write_image_row
  if (bin.empty()) {  // nothing here: the background, no per-sample work
    for (int pxl = px0; pxl < px1; ++pxl) {
      float* o = tile_row + 3 * (pxl - px0);
      o[0] = float(background.x), o[1] = float(background.y), o[2] = float(background.z);
    }
    for (int py = py0; py < py1; ++py) write_image_row(out.image.pixel(px0, py), tile_row, row_floats);
    store_fence();
    return {};
  }
  const int sx0 = px0 * N, sy0 = py0 * N, sx1 = px1 * N - 1, sy1 = py1 * N - 1;  // inclusive
  const int tw = sx1 - sx0 + 1, th = sy1 - sy0 + 1;
  const std::size_t count = std::size_t(tw) * std::size_t(th);
  // depth[s] is meaningful only where owner[s] is set (else +infinity, the depth test's start):
  // only the owners are cleared per tile.
  buffers.depth.resize(count);
  buffers.owner.assign(count, nullptr);
  buffers.lambda1.resize(count);
  buffers.lambda2.resize(count);
  double* depth = buffers.depth.data();
  const ScreenTriangle** owner = buffers.owner.data();
  double* lambda1 = buffers.lambda1.data();
  double* lambda2 = buffers.lambda2.data();
  const std::size_t full_width = std::size_t(in.width) * std::size_t(N);
  const bool count_coverage = in.count_coverage;
  constexpr double kNoDepth = std::numeric_limits<double>::infinity();

  for (const ScreenTriangle* tp : bin) {
    const ScreenTriangle& t = *tp;
    const int bx0 = std::max(t.sx0, sx0), bx1 = std::min(t.sx1, sx1);
    const int by0 = std::max(t.sy0, sy0), by1 = std::min(t.sy1, sy1);
    if (bx0 > bx1 || by0 > by1) continue;
    const std::int64_t X0 = t.X[0], Y0 = t.Y[0], X1 = t.X[1], Y1 = t.Y[1], X2 = t.X[2], Y2 = t.Y[2];
    const std::int64_t area = orient(X0, Y0, X1, Y1, X2, Y2);  // > 0 (setup)
    const double inv_area = 1.0 / double(area);
    const std::int64_t bias0 = top_left_bias(X1, Y1, X2, Y2);
    const std::int64_t bias1 = top_left_bias(X2, Y2, X0, Y0);
    const std::int64_t bias2 = top_left_bias(X0, Y0, X1, Y1);
    // Per-sample steps of the edge functions (orient(a, b, p): d/dpx = -(by - ay), d/dpy = bx - ax).
    const std::int64_t step_x0 = -(Y2 - Y1) * kSubUnits, step_y0 = (X2 - X1) * kSubUnits;
    const std::int64_t step_x1 = -(Y0 - Y2) * kSubUnits, step_y1 = (X0 - X2) * kSubUnits;
    const std::int64_t step_x2 = -(Y1 - Y0) * kSubUnits, step_y2 = (X1 - X0) * kSubUnits;
    const std::int64_t px = std::int64_t(bx0) * kSubUnits + kSubUnits / 2;
    const std::int64_t py = std::int64_t(by0) * kSubUnits + kSubUnits / 2;
    std::int64_t row0 = orient(X1, Y1, X2, Y2, px, py) + bias0 - 1;  // inside: E + bias - 1 >= 0
    std::int64_t row1 = orient(X2, Y2, X0, Y0, px, py) + bias1 - 1;
    std::int64_t row2 = orient(X0, Y0, X1, Y1, px, py) + bias2 - 1;
    const double z0 = t.z[0], z1 = t.z[1], z2 = t.z[2];  // locals: the stores below cannot change them
    // Four samples at a time where exact (depth_row_lanes.h: the same bits as the loop below).
    const bool lanes = !count_coverage && depth_row_lanes_exact(t);
    DepthRow lane_row{{0, 0, 0},
                      {double(step_x0), double(step_x1), double(step_x2)},
                      {bias0, bias1, bias2},
                      inv_area,
                      {z0, z1, z2}};
    for (int sy = by0; sy <= by1; ++sy) {
      std::int64_t e0 = row0, e1 = row1, e2 = row2;
      std::size_t s = std::size_t(sy - sy0) * std::size_t(tw) + std::size_t(bx0 - sx0);
      if (lanes) {
        lane_row.edge[0] = double(e0 + 1 - bias0);
        lane_row.edge[1] = double(e1 + 1 - bias1);
        lane_row.edge[2] = double(e2 + 1 - bias2);
        depth_row_lanes(lane_row, bx1 - bx0 + 1, tp, depth + s, owner + s, lambda1 + s, lambda2 + s);
        row0 += step_y0;
        row1 += step_y1;
        row2 += step_y2;
        continue;
      }
      int sx = bx0;
      // The covered samples of a row are one interval (the triangle is convex): skip to it, walk
      // it, and stop at its end.
      for (; sx <= bx1 && (e0 | e1 | e2) < 0; ++sx, ++s, e0 += step_x0, e1 += step_x1, e2 += step_x2) {
      }
      for (; sx <= bx1 && (e0 | e1 | e2) >= 0; ++sx, ++s, e0 += step_x0, e1 += step_x1, e2 += step_x2) {
        if (count_coverage) ++out.coverage[std::size_t(sy) * full_width + std::size_t(sx)];
        const double l0 = double(e0 + 1 - bias0) * inv_area;
        const double l1 = double(e1 + 1 - bias1) * inv_area;
        const double l2 = double(e2 + 1 - bias2) * inv_area;
        const double z = l0 * z0 + l1 * z1 + l2 * z2;
        if (z < (owner[s] != nullptr ? depth[s] : kNoDepth)) {
          depth[s] = z;
          owner[s] = tp;
          lambda1[s] = l1;
          lambda2[s] = l2;
        }
      }
      row0 += step_y0;
      row1 += step_y1;
      row2 += step_y2;
    }
  }

  // Shade the visible samples and box-filter them into pixels. Phong with shadows first gathers the
  // tile's visible points and asks for their visibility in one batch (seeds: the sample's index in
  // the whole image, so the bits do not depend on tiles or threads), then shades them in the same
  // order.
  TileResult r;
  ShadeCounters counters;
  const bool shadowed = in.surface->shading == RenderShading::Phong && in.surface->shader->casts_shadows();
  std::vector<double> points, normals, visibility;
  std::vector<std::uint64_t> ids;
  if (shadowed) {
    for (int py = py0; py < py1; ++py)
      for (int pxl = px0; pxl < px1; ++pxl)
        for (int j = 0; j < N; ++j)
          for (int i = 0; i < N; ++i) {
            const std::size_t s = std::size_t((py - py0) * N + j) * std::size_t(tw) + std::size_t((pxl - px0) * N + i);
            if (owner[s] == nullptr) continue;
            const double lambda[3] = {1.0 - lambda1[s] - lambda2[s], lambda1[s], lambda2[s]};
            Vec3d p, n;
            phong_point(in, *owner[s], lambda, r.fallbacks, p, n);
            points.insert(points.end(), {p.x, p.y, p.z});
            normals.insert(normals.end(), {n.x, n.y, n.z});
            ids.push_back(std::uint64_t(py * N + j) * full_width + std::uint64_t(pxl * N + i));
          }
    visibility = in.surface->shader->visibility(points, normals, ids);
  }
  const std::size_t row = shadowed ? in.surface->shader->row_size() : 0;
  std::size_t next = 0;  // shadowed: the next gathered point
  const double inv_samples = 1.0 / double(N * N);  // N >= 1
  if (N == 1 && !shadowed) {  // the common case: the loop below with its sample index arithmetic folded
    const bool gouraud = in.surface->shading == RenderShading::Gouraud;
    GouraudCorners corners;
    for (int py = py0; py < py1; ++py) {
      const std::size_t s_row = std::size_t(py - py0) * std::size_t(tw) - std::size_t(px0);
      if (in.surface->shading == RenderShading::Phong) {
        r.covered += phong_row(in, owner + s_row, lambda1 + s_row, lambda2 + s_row, px0, px1, inv_samples, counters,
                               r.fallbacks, tile_row);
        write_image_row(out.image.pixel(px0, py), tile_row, row_floats);
        continue;
      }
      for (int pxl = px0; pxl < px1;) {
        const std::size_t s = s_row + std::size_t(pxl);
        const ScreenTriangle* t = owner[s];
        float* out_px = tile_row + 3 * (pxl - px0);
        if (gouraud && t != nullptr) {
          if (t != corners.triangle) corners.load(*in.surface, t);
          if (corners.direct) {  // the run of pixels this triangle owns, in one loop
            int end = pxl + 1;
            while (end < px1 && owner[s_row + std::size_t(end)] == t) ++end;
            gouraud_run(corners.rgb, t->inv_w, lambda1 + s, lambda2 + s, end - pxl, inv_samples, out_px);
            r.covered += std::size_t(end - pxl);
            pxl = end;
            continue;
          }
        }
        Vec3d sum{0, 0, 0};
        if (t == nullptr) {
          sum += background;
        } else {
          ++r.covered;
          const double lambda[3] = {1.0 - lambda1[s] - lambda2[s], lambda1[s], lambda2[s]};
          sum += shade_sample(in, *t, lambda, counters, r.fallbacks);
        }
        out_px[0] = float(sum.x * inv_samples);
        out_px[1] = float(sum.y * inv_samples);
        out_px[2] = float(sum.z * inv_samples);
        ++pxl;
      }
      write_image_row(out.image.pixel(px0, py), tile_row, row_floats);
    }
    store_fence();
    return r;
  }
  for (int py = py0; py < py1; ++py) {
    for (int pxl = px0; pxl < px1; ++pxl) {
      Vec3d sum{0, 0, 0};
      for (int j = 0; j < N; ++j) {
        for (int i = 0; i < N; ++i) {
          const std::size_t s = std::size_t((py - py0) * N + j) * std::size_t(tw) + std::size_t((pxl - px0) * N + i);
          if (owner[s] == nullptr) {
            sum += background;
            continue;
          }
          ++r.covered;
          if (shadowed) {
            sum += in.surface->shader->shade(get3(points, next), get3(normals, next), visibility.data() + row * next,
                                             counters);
            ++next;
            continue;
          }
          const double lambda[3] = {1.0 - lambda1[s] - lambda2[s], lambda1[s], lambda2[s]};
          sum += shade_sample(in, *owner[s], lambda, counters, r.fallbacks);
        }
      }
      float* out_px = tile_row + 3 * (pxl - px0);
      out_px[0] = float(sum.x * inv_samples);
      out_px[1] = float(sum.y * inv_samples);
      out_px[2] = float(sum.z * inv_samples);
    }
    write_image_row(out.image.pixel(px0, py), tile_row, row_floats);
  }
  store_fence();
  return r;
}

}  // namespace

RasterOutput rasterize_tiles(const RasterInput& in) {
  RasterOutput out;
  out.image.width = in.width;
  out.image.height = in.height;
  out.image.rgb.resize(std::size_t(in.width) * std::size_t(in.height) * 3);  // every pixel written by its tile
  const int N = in.samples;
  if (in.count_coverage) out.coverage.assign(std::size_t(in.width) * N * std::size_t(in.height) * N, 0);

  // Bins: each tile lists the triangles whose sample bounds meet it, in triangle order.
  const int tile_side = tile_pixels(in.surface->shading, N);
  const int tiles_x = (in.width + tile_side - 1) / tile_side;
  const int tiles_y = (in.height + tile_side - 1) / tile_side;
  const int tile_samples = tile_side * N;
  std::vector<std::vector<const ScreenTriangle*>> bins(std::size_t(tiles_x) * std::size_t(tiles_y));
  for (const auto& part : in.parts)
    for (const ScreenTriangle& t : part) {
      if (t.sx0 > t.sx1 || t.sy0 > t.sy1) continue;
      for (int ty = t.sy0 / tile_samples; ty <= t.sy1 / tile_samples; ++ty)
        for (int tx = t.sx0 / tile_samples; tx <= t.sx1 / tile_samples; ++tx)
          bins[std::size_t(ty) * std::size_t(tiles_x) + std::size_t(tx)].push_back(&t);
    }

  std::vector<TileResult> results(bins.size());
  tbb::enumerable_thread_specific<TileBuffers> scratch;
  report_begin(in.progress, "render", bins.size());
  // In the caller's arena (render_mesh sets the thread count); which thread runs a tile does not
  // change its pixels.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bins.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
    TileBuffers& buffers = scratch.local();
    for (std::size_t k = r.begin(); k < r.end(); ++k)
      results[k] = raster_tile(in, bins[k], tile_side, int(k % std::size_t(tiles_x)), int(k / std::size_t(tiles_x)),
                               buffers, out);
    report_advance(in.progress, r.end() - r.begin());
  });
  for (const TileResult& r : results) {
    out.samples_covered += r.covered;
    out.quad_fallbacks += r.fallbacks;
  }
  return out;
}

}  // namespace shadetool::render_engine
