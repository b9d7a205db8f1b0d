// render_mesh.cpp: see render_mesh.h. Steps 1-3 (world and clip space, splitting into triangles, clipping,
// snapping, culling) are here; the tile loop is engine/tile_raster.cpp.
#include <shadetool/render/render_mesh.h>

#include <shadetool/lighting/encode_color.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <shadetool/core/error.h>
#include <shadetool/render/clip_polygon.h>
#include <shadetool/render/engine/screen_triangle.h>
#include <shadetool/render/fill_rule.h>
#include <shadetool/core/vocabulary.h>
#include <shadetool/geometry/polygon_triangles.h>
#include <shadetool/geometry/winding_number.h>
#include <shadetool/io/split_corner_normals.h>

namespace shadetool {

using render_engine::kSubUnits;
using render_engine::ScreenTriangle;

namespace {
const NamedValue<RenderShading> kRenderShadings[] = {
    {RenderShading::Flat, "flat"},
    {RenderShading::Gouraud, "gouraud"},
    {RenderShading::Phong, "phong"},
};
}  // namespace

RenderShading parse_render_shading(std::string_view text, const std::string& what) {
  return parse_named(kRenderShadings, text, what);
}
const char* render_shading_name(RenderShading shading) { return name_of(kRenderShadings, shading); }
std::vector<std::string> render_shading_names() { return names_of(kRenderShadings); }

namespace {

enum class TriangleFate { Drawn, Culled, Outside, Degenerate };

struct SetupContext {
  int sample_width, sample_height;  // W N, H N
  double guard;                     // guard band g (clip_polygon.h)
  bool mirror;                      // det(V M) < 0
  bool two_sided;
  bool quad = false;                // the face being set up has 4 corners
};

struct SetupOutput {
  std::vector<ScreenTriangle> triangles;
  std::vector<double> clip_b;
  std::size_t near_clipped = 0;
};

// Nearest integer, halves away from zero (|x| < 2^30 here: the guard band): a truncating cast
// instead of llround's library call, the same for every triangle sharing the vertex.
inline std::int64_t round_to_integer(double x) {
  return x >= 0 ? std::int64_t(x + 0.5) : -std::int64_t(-x + 0.5);
}

// A vertex in clip space, which planes it is outside of (bit k: clip_distance(plane k) < 0), and,
// when inside all of them, its snapped screen position: computed once per mesh vertex, so that
// triangles sharing it read the very same numbers (and the common unclipped triangle does no
// per-corner work).
struct ScreenVertex {
  std::int32_t X, Y;   // fixed point (fill_rule.h), y down
  double inv_w, z;     // 1 / w and z / w
};
struct VertexSetup {
  ClipPoint c;
  std::uint8_t outcode = 0;
  ScreenVertex screen{0, 0, 0, 0};
};

// Project and snap: sample-grid coordinates in 1/256 units, y down. w > 0.
ScreenVertex project(double x, double y, double z, double w, const SetupContext& ctx) {
  ScreenVertex s;
  s.inv_w = 1.0 / w;  // w > 0: callers check
  const double xs = (x * s.inv_w * 0.5 + 0.5) * ctx.sample_width;
  const double ys = (0.5 - y * s.inv_w * 0.5) * ctx.sample_height;
  s.X = std::int32_t(round_to_integer(xs * kSubUnits));
  s.Y = std::int32_t(round_to_integer(ys * kSubUnits));
  s.z = z * s.inv_w;
  return s;
}

VertexSetup setup_vertex(const ClipPoint& c, const SetupContext& ctx) {
  VertexSetup v;
  v.c = c;
  const ClipVertex cv{c.x, c.y, c.z, c.w, {0, 0, 0}};
  for (int plane = 0; plane < 6; ++plane)
    if (clip_distance(cv, plane, ctx.guard) < 0) v.outcode |= std::uint8_t(1u << plane);
  if (v.outcode == 0 && c.w > 0) v.screen = project(c.x, c.y, c.z, c.w, ctx);
  // w <= 0 (at or behind the eye) is outside the near plane: z + w = 2 far (w - near) / (far - near)
  // < 0; kept so under rounding, so that such a point is never projected.
  if (!(c.w > 0)) v.outcode |= 1;
  return v;
}

// One original triangle (mesh vertices v[3], their setups) to screen triangles.
TriangleFate setup_triangle(const SetupContext& ctx, std::uint32_t face, const std::uint32_t v[3],
                            const VertexSetup* const vs[3], SetupOutput& out) {
  if (vs[0]->outcode & vs[1]->outcode & vs[2]->outcode) return TriangleFate::Outside;  // all beyond one plane
  ClipVertex poly[kMaxClipVertices], scratch[kMaxClipVertices];
  std::int32_t X[kMaxClipVertices], Y[kMaxClipVertices];
  double inv_w[kMaxClipVertices], z[kMaxClipVertices];
  int n = 3;
  const bool clipped = (vs[0]->outcode | vs[1]->outcode | vs[2]->outcode) != 0;
  if (!clipped) {
    for (int i = 0; i < 3; ++i) {
      X[i] = vs[i]->screen.X;
      Y[i] = vs[i]->screen.Y;
      inv_w[i] = vs[i]->screen.inv_w;
      z[i] = vs[i]->screen.z;
    }
  } else {
    for (int i = 0; i < 3; ++i) {
      const ClipPoint& c = vs[i]->c;
      poly[i] = {c.x, c.y, c.z, c.w, {0, 0, 0}};
      poly[i].b[i] = 1;
    }
    for (int plane = 0; plane < 6; ++plane) {
      int outside = 0;
      for (int i = 0; i < n; ++i) outside += clip_distance(poly[i], plane, ctx.guard) < 0;
      if (outside == 0) continue;
      if (outside == n) return TriangleFate::Outside;
      if (plane == 0) ++out.near_clipped;
      n = clip_against(poly, n, plane, ctx.guard, scratch);
      std::copy(scratch, scratch + n, poly);
      if (n < 3) return TriangleFate::Outside;
    }
    for (int i = 0; i < n; ++i) {
      if (!(poly[i].w > 0)) return TriangleFate::Outside;  // only behind-the-eye points have w <= 0
      const ScreenVertex sv = project(poly[i].x, poly[i].y, poly[i].z, poly[i].w, ctx);
      X[i] = sv.X;
      Y[i] = sv.Y;
      inv_w[i] = sv.inv_w;
      z[i] = sv.z;
    }
  }
  std::int64_t area = 0;  // twice the polygon's signed area, y down
  for (int i = 1; i + 1 < n; ++i) area += orient(X[0], Y[0], X[i], Y[i], X[i + 1], Y[i + 1]);
  if (area == 0) return TriangleFate::Degenerate;
  // OpenGL's front face: counter-clockwise with y up, i.e. negative area with y down; a mirror in
  // V M turns the outside's winding over.
  const bool front = (area < 0) != ctx.mirror;
  if (!front && !ctx.two_sided) return TriangleFate::Culled;

  bool any = false;
  for (int i = 1; i + 1 < n; ++i) {
    int k[3] = {0, i, i + 1};
    const std::int64_t a = orient(X[k[0]], Y[k[0]], X[k[1]], Y[k[1]], X[k[2]], Y[k[2]]);
    if (a == 0 || (a > 0) != (area > 0)) continue;  // a sliver flipped or flattened by snapping
    if (a < 0) std::swap(k[1], k[2]);
    ScreenTriangle t;
    t.face = face;
    t.quad = ctx.quad;
    for (int j = 0; j < 3; ++j) {
      t.X[j] = X[k[j]];
      t.Y[j] = Y[k[j]];
      t.inv_w[j] = inv_w[k[j]];
      t.z[j] = z[k[j]];
      t.vertex[j] = v[j];
    }
    if (!clipped) {
      t.clip_index = -1;
      for (int j = 0; j < 3; ++j) t.perm[j] = std::uint8_t(k[j]);
    } else {
      t.clip_index = std::int32_t(out.clip_b.size() / 9);
      for (int j = 0; j < 3; ++j)
        for (int m = 0; m < 3; ++m) out.clip_b.push_back(poly[k[j]].b[m]);
    }
    // Sample bounds: samples at 256 s + 128 inside [min, max].
    const std::int64_t xmin = std::min({t.X[0], t.X[1], t.X[2]}), xmax = std::max({t.X[0], t.X[1], t.X[2]});
    const std::int64_t ymin = std::min({t.Y[0], t.Y[1], t.Y[2]}), ymax = std::max({t.Y[0], t.Y[1], t.Y[2]});
    auto first_sample = [](std::int64_t lo) {  // ceil((lo - 128) / 256)
      const std::int64_t a2 = lo - kSubUnits / 2;
      return a2 >= 0 ? (a2 + kSubUnits - 1) / kSubUnits : -((-a2) / kSubUnits);
    };
    auto last_sample = [](std::int64_t hi) {  // floor((hi - 128) / 256)
      const std::int64_t a2 = hi - kSubUnits / 2;
      return a2 >= 0 ? a2 / kSubUnits : -((-a2 + kSubUnits - 1) / kSubUnits);
    };
    t.sx0 = std::int32_t(std::max<std::int64_t>(0, first_sample(xmin)));
    t.sx1 = std::int32_t(std::min<std::int64_t>(ctx.sample_width - 1, last_sample(xmax)));
    t.sy0 = std::int32_t(std::max<std::int64_t>(0, first_sample(ymin)));
    t.sy1 = std::int32_t(std::min<std::int64_t>(ctx.sample_height - 1, last_sample(ymax)));
    out.triangles.push_back(t);
    any = true;
  }
  return any ? TriangleFate::Drawn : TriangleFate::Degenerate;
}

// The camera's eye inside a closed mesh sees only the inside: refuse (|w| > 1/2, winding number).
// Only an eye inside the mesh's bounding box can be inside the mesh: the winding-number tree (costly
// on large meshes: bench/render/results.md) is built only then.
void check_eye_outside(const Mesh& mesh, const Scene& scene, const RenderCamera& cam, const Bounds3d& bounds,
                       const std::string& name) {
  if (cam.orthographic || mesh.num_faces() == 0 || bounds.empty) return;
  const Vec3d e = cam.eye_world;
  if (e.x < bounds.lo.x || e.y < bounds.lo.y || e.z < bounds.lo.z || e.x > bounds.hi.x || e.y > bounds.hi.y ||
      e.z > bounds.hi.z)
    return;
  Affine3d object_from_world;
  if (!invert_affine(scene.world_from_object, object_from_world)) return;  // checked on read
  const Vec3d eye_object = transform_point(object_from_world, cam.eye_world);
  std::vector<std::uint32_t> faces(mesh.num_faces());
  for (std::size_t f = 0; f < faces.size(); ++f) faces[f] = std::uint32_t(f);
  const WindingNumberTree tree = winding_number_tree(mesh, faces, {});
  const double w = winding_number(tree, eye_object);
  if (std::fabs(w) > 0.5) {
    fail(name, 0, "the camera's eye (" + std::to_string(e.x) + ", " + std::to_string(e.y) + ", " + std::to_string(e.z) +
                      ") is inside the mesh (winding number " + std::to_string(w) + "): move the eye outside");
  }
}

RenderResult render_in_arena(const Mesh& mesh, const Scene& scene, const RenderOptions& options, const std::string& name) {
  RenderResult result;
  const std::size_t V = mesh.num_vertices(), F = mesh.num_faces();

  // 1. World and clip space.
  render_engine::SurfaceInputs surface;
  surface.shading = options.shading;
  surface.mesh = &mesh;
  surface.background = options.background;
  surface.positions_world.resize(3 * V);
  Bounds3d bounds;
  for (std::size_t v = 0; v < V; ++v) {
    const Vec3d p = transform_point(scene.world_from_object, mesh.position(v));
    set3(surface.positions_world, v, p);
    bounds.add(p);
  }
  const RenderCamera cam = make_render_camera(scene, bounds, options.width, options.height);
  result.camera = cam;
  if (options.check_eye_inside && scene.has_camera) check_eye_outside(mesh, scene, cam, bounds, name);

  std::unique_ptr<PointShader> shader;
  switch (options.shading) {
    case RenderShading::Flat:
      surface.face_rgb = baked_face_colors(mesh, scene, options.lighting);
      break;
    case RenderShading::Gouraud:
      if (options.vertex_rgb && options.vertex_rgb->size() != 3 * V)
        throw Error("render: " + std::to_string(options.vertex_rgb->size() / 3) + " vertex colours for " + std::to_string(V) + " vertices");
      surface.vertex_rgb = options.vertex_rgb ? *options.vertex_rgb : baked_vertex_colors(mesh, scene, options.lighting);
      if (options.clamp_vertex_colors)  // OpenGL 2.1: the vertex colour is clamped before it is interpolated
        for (double& c : surface.vertex_rgb) c = clamp_displayable(c);
      break;
    case RenderShading::Phong: {
      const std::vector<double> normals_object = shading_vertex_normals(mesh);
      const Mat3d to_world = signed_cofactor(scene.world_from_object.A);
      surface.normals_world.resize(3 * V);
      for (std::size_t v = 0; v < V; ++v) set3(surface.normals_world, v, transform_normal(to_world, Normal3d(get3(normals_object, v))));
      shader = std::make_unique<PointShader>(scene, options.lighting, mesh, surface.positions_world);
      surface.shader = shader.get();
      break;
    }
  }

  // 2-3. Split into triangles, clip, snap, cull: fixed chunks of faces in parallel, joined in face order.
  SetupContext ctx;
  ctx.sample_width = options.width * options.samples;
  ctx.sample_height = options.height * options.samples;
  ctx.guard = double(1 << 20) / double(std::max(ctx.sample_width, ctx.sample_height));  // >= 4 (sizes checked)
  ctx.mirror = determinant(cam.camera_from_world.A * scene.world_from_object.A) < 0;
  ctx.two_sided = scene.two_sided;
  std::vector<VertexSetup> vertex_setup(V);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, V, 4096), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t v = r.begin(); v < r.end(); ++v)
      vertex_setup[v] = setup_vertex(cam.to_clip(transform_point(cam.camera_from_world, get3(surface.positions_world, v))), ctx);
  });
  constexpr std::size_t kChunk = 4096;
  const std::size_t chunks = (F + kChunk - 1) / kChunk;
  std::vector<SetupOutput> parts(chunks);
  std::vector<RenderStats> part_stats(chunks);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t k) {
    SetupOutput& out = parts[k];
    RenderStats& st = part_stats[k];
    SetupContext face_ctx = ctx;
    out.triangles.reserve(kChunk);
    std::vector<std::uint32_t> split;  // one face's triangles (polygon_triangles), reused
    for (std::size_t f = k * kChunk; f < std::min(F, (k + 1) * kChunk); ++f) {
      const std::size_t size = mesh.face_size(f);
      if (size < 3) {
        ++st.faces_degenerate;
        continue;
      }
      const std::uint32_t* corners = mesh.corner_vertex.data() + mesh.face_start[f];
      // A convex quad keeps its bilinear shading; a concave one (geometry/polygon_triangles.h
      // quad_is_concave: its bilinear map folds) is two triangles shaded linearly.
      face_ctx.quad = size == 4 && !quad_is_concave(mesh.positions.data(), corners);
      bool drawn = false, culled = false, outside = false;
      // Triangles as corner positions within the face: a convex quad by its 0-2 diagonal (its
      // shading is the bilinear map of all four corners, step 4); a concave quad and 5+ corners by
      // geometry/polygon_triangles.h (inside the outline, as the glTF and STL writers split it: a
      // concave quad through its reflex corner; a convex polygon: the fan).
      split.clear();
      if (face_ctx.quad) split.insert(split.end(), {0u, 1u, 2u, 0u, 2u, 3u});
      else polygon_triangles(mesh.positions.data(), corners, std::uint32_t(size), split);
      for (std::size_t t = 0; t + 2 < split.size(); t += 3) {
        const std::uint32_t v[3] = {corners[split[t]], corners[split[t + 1]], corners[split[t + 2]]};
        const VertexSetup* const c[3] = {&vertex_setup[v[0]], &vertex_setup[v[1]], &vertex_setup[v[2]]};
        ++st.triangles;
        switch (setup_triangle(face_ctx, std::uint32_t(f), v, c, out)) {
          case TriangleFate::Drawn: drawn = true; break;
          case TriangleFate::Culled: culled = true; break;
          case TriangleFate::Outside: outside = true; break;
          case TriangleFate::Degenerate: break;
        }
      }
      if (drawn) continue;
      if (culled) ++st.faces_culled;
      else if (outside) ++st.faces_outside_view;
      else ++st.faces_degenerate;
    }
    st.triangles_near_clipped = out.near_clipped;
  });

  render_engine::RasterInput raster;
  raster.width = options.width;
  raster.height = options.height;
  raster.samples = options.samples;
  raster.surface = &surface;
  raster.count_coverage = options.count_coverage;
  raster.progress = options.progress;
  RenderStats& stats = result.stats;
  stats.faces = F;
  raster.parts.resize(chunks);
  for (std::size_t k = 0; k < chunks; ++k) {
    const std::int32_t offset = std::int32_t(raster.clip_b.size() / 9);
    if (offset != 0)
      for (ScreenTriangle& t : parts[k].triangles)
        if (t.clip_index >= 0) t.clip_index += offset;
    raster.parts[k] = std::move(parts[k].triangles);
    raster.clip_b.insert(raster.clip_b.end(), parts[k].clip_b.begin(), parts[k].clip_b.end());
    stats.triangles += part_stats[k].triangles;
    stats.faces_culled += part_stats[k].faces_culled;
    stats.faces_outside_view += part_stats[k].faces_outside_view;
    stats.faces_degenerate += part_stats[k].faces_degenerate;
    stats.triangles_near_clipped += part_stats[k].triangles_near_clipped;
    parts[k] = SetupOutput{};
  }

  // 4-5. Tiles.
  render_engine::RasterOutput raster_out = render_engine::rasterize_tiles(raster);
  result.image = std::move(raster_out.image);
  result.coverage = std::move(raster_out.coverage);
  stats.samples_covered = raster_out.samples_covered;
  stats.quad_fallbacks = raster_out.quad_fallbacks;
  return result;
}

}  // namespace

void check_render_options(const RenderOptions& o, const std::string& name) {
  if (o.width < 1 || o.height < 1 || o.width > kMaxImageSide || o.height > kMaxImageSide)
    fail(name, 0, "image size " + std::to_string(o.width) + "x" + std::to_string(o.height) + ": each side must be 1.." +
                      std::to_string(kMaxImageSide) + " pixels");
  if (o.samples < 1 || o.samples > kMaxSamples)
    fail(name, 0, "samples must be 1.." + std::to_string(kMaxSamples) + " (N x N per pixel), got " +
                      std::to_string(o.samples));
  if (o.threads < 0 || o.threads > kMaxThreads)
    fail(name, 0, "threads must be 0.." + std::to_string(kMaxThreads) + " (0: all cores), got " + std::to_string(o.threads));
  check_shadow_options(o.lighting.shadows, located(name, 0, "shadow samples"));
  for (int i = 0; i < 3; ++i)
    if (!(o.background[i] >= 0) || !std::isfinite(o.background[i]))
      fail(name, 0, "background channels must be finite and >= 0, got " + std::to_string(o.background[i]));
  switch (o.shading) {
    case RenderShading::Flat:
    case RenderShading::Gouraud:
      break;
    case RenderShading::Phong:
      if (o.lighting.space != ShadingSpace::Auto)
        fail(name, 0, std::string("space '") + shading_space_name(o.lighting.space) +
                          "' applies to flat and gouraud shading (bake-lighting's evaluation); phong evaluates per "
                          "sample in world space");
      break;
  }
}

RenderResult render_mesh(const Mesh& input, const Scene& scene, const RenderOptions& options, const std::string& name) {
  check_render_options(options, name);
  // Corner normals that differ at a vertex (creases, OBJ vn): each corner shaded with its own, as
  // the same normals read from a PLY file (split the same way by its writer) are.
  Mesh split;
  std::size_t added = 0;
  const Mesh& mesh = io::with_creases_split(input, split, added);
  if (options.threads <= 0) return render_in_arena(mesh, scene, options, name);
  tbb::task_arena arena(options.threads);  // every parallel step (setup and tiles) on these threads
  RenderResult result;
  arena.execute([&] { result = render_in_arena(mesh, scene, options, name); });
  return result;
}

}  // namespace shadetool
