// fit_vertex_lighting.cpp: see fit_vertex_lighting.h.
#include <shadetool/lighting/fit_vertex_lighting.h>

#include <algorithm>
#include <limits>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/error.h>
#include <shadetool/lighting/shade_point.h>

namespace shadetool {

std::vector<double> world_positions(const Mesh& mesh, const Scene& scene) {
  std::vector<double> out(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) set3(out, v, transform_point(scene.world_from_object, mesh.position(v)));
  return out;
}

std::vector<double> lighting_at_quadrature(const Mesh& mesh, const Scene& scene, const FitQuadrature& q,
                                           const std::vector<double>& positions_world,
                                           const std::vector<double>& vertex_normals_object,
                                           const ShadeOptions& options, const ShadowOptions& shadows,
                                           ShadowStats* shadow_stats) {
  return site_values_at_points(
      q, lighting_at_sites(mesh, scene, q, positions_world, vertex_normals_object, options, shadows, shadow_stats), 3);
}

std::vector<double> lighting_at_sites(const Mesh& mesh, const Scene& scene, const FitQuadrature& q,
                                      const std::vector<double>& positions_world,
                                      const std::vector<double>& vertex_normals_object, const ShadeOptions& options,
                                      const ShadowOptions& shadows, ShadowStats* shadow_stats, double lower,
                                      double upper) {
  const auto clamp = [lower, upper](double* v, std::size_t n) {  // std::min(std::max(v, lower), upper)
    for (std::size_t i = 0; i < n; ++i) v[i] = std::min(std::max(v[i], lower), upper);
  };
  // The normals into the world (not copied when the placement is the identity: the same bits).
  const bool placed = !is_identity(scene.world_from_object);
  const Mat3d cof = signed_cofactor(scene.world_from_object.A);
  std::vector<double> normals_placed(placed ? vertex_normals_object.size() : 0);
  for (std::size_t v = 0; v < normals_placed.size() / 3; ++v)
    set3(normals_placed, v, Vec3d(transform_normal(cof, Normal3d(get3(vertex_normals_object, v)))));
  const std::vector<double>& normals_world = placed ? normals_placed : vertex_normals_object;
  // f at each site (shared edge midpoints once)
  const PointLighting lit = prepare_point_lighting(scene, options.model);
  const std::size_t S = q.sites();
  std::vector<double> f;  // 36 MB at 1M triangles and 3 points: on huge pages (core/bulk_reserve.h)
  reserve_bulk(f, 3 * S);
  f.resize(3 * S);
  if (!shadows.enabled) {  // p and n interpolated where they are shaded, a block at a time: no arrays of them
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, S, 2048), [&](const tbb::blocked_range<std::size_t>& r) {
      ShadeCounters counters;  // the point bake reports the counts; these are not summed
      constexpr std::size_t kBlock = 64;
      double soa[6][kBlock];  // px, py, pz, nx, ny, nz
      for (std::size_t begin = r.begin(); begin < r.end(); begin += kBlock) {
        const std::size_t count = std::min(kBlock, r.end() - begin);
        if (!q.midpoint_corners.empty()) {  // every site an edge's midpoint: 0.5 d_lo + 0.5 d_hi
          const double* P = positions_world.data();
          const double* Nv = normals_world.data();
          for (std::size_t i = 0; i < count; ++i) {
            std::uint32_t lo, hi;
            site_edge_vertices(q, begin + i, lo, hi);
            const std::size_t a = 3 * std::size_t(lo), b = 3 * std::size_t(hi);
            for (int k = 0; k < 3; ++k) {
              soa[k][i] = 0.5 * P[a + k] + 0.5 * P[b + k];
              soa[3 + k][i] = 0.5 * Nv[a + k] + 0.5 * Nv[b + k];  // renormalised by shade_point_block
            }
          }
        } else {
          for (std::size_t i = 0; i < count; ++i) {
            double p[3], n[3];  // n renormalised by shade_point_block
            interpolate_vertex_data_at_site(q, begin + i, positions_world.data(), 3, p);
            interpolate_vertex_data_at_site(q, begin + i, normals_world.data(), 3, n);
            for (int k = 0; k < 3; ++k) {
              soa[k][i] = p[k];
              soa[3 + k][i] = n[k];
            }
          }
        }
        PointBlock block;  // shade_point's bits, four points at a time where the CPU allows
        block.count = count;
        block.px = soa[0], block.py = soa[1], block.pz = soa[2];
        block.nx = soa[3], block.ny = soa[4], block.nz = soa[5];
        shade_point_block(lit, block, &f[3 * begin], &counters);
        clamp(&f[3 * begin], 3 * count);
      }
    });
    return f;
  }
  const std::vector<double> p = interpolate_vertex_data_at_sites(q, positions_world, 3);
  const std::vector<double> n = interpolate_vertex_data_at_sites(q, normals_world, 3);  // renormalised by shade_point
  Mesh world;  // the mesh's own occluders, unless the caller built the scene's
  std::unique_ptr<VisibilityScene> own;
  if (!shadows.occluders) {
    world.positions = positions_world;
    world.face_start = mesh.face_start;
    world.corner_vertex = mesh.corner_vertex;
    own = std::make_unique<VisibilityScene>(world);
  }
  const VisibilityScene& bvh = shadows.occluders ? *shadows.occluders : *own;
  const std::vector<double> visibility = light_visibility(bvh, scene, lit.plan, p, n, {}, shadows.samples, shadow_stats);
  const std::size_t row = 2 * lit.plan.lights.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, S, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    ShadeCounters counters;
    for (std::size_t s = r.begin(); s < r.end(); ++s) {
      set3(f, s, shade_point_shadowed(lit, get3(p, s), get3(n, s), visibility.data() + s * row, &counters));
      clamp(&f[3 * s], 3);
    }
  });
  return f;
}

VertexLightingFit fit_vertex_lighting(const Mesh& mesh, const Scene& scene, const BakeResult& point,
                                      const ShadeOptions& options, const ShadowOptions& shadows,
                                      const VertexFitOptions& fit) {
  VertexLightingFit out;
  switch (fit.method) {
    case VertexFit::Point:
      if (point.rgb.size() != mesh.positions.size())
        throw Error("fit_vertex_lighting: the point fit needs the point colours (bake_lighting with VertexColors::All)");
      out.rgb = point.rgb;
      return out;
    case VertexFit::LeastSquares: break;
  }
  // World positions (the mesh's own when the placement is the identity: the same bits, no copy).
  const bool placed = !is_identity(scene.world_from_object);
  const std::vector<double> positions_placed = placed ? world_positions(mesh, scene) : std::vector<double>();
  const std::vector<double>& positions_world = placed ? positions_placed : mesh.positions;
  const FitElements elements = fit_elements(mesh);
  FitScratch spent;  // the site search's memory, for the solve's b and x (least_squares_fit.h, FitScratch)
  spent.wanted = fit_scratch_bytes(elements.nodes, 3);
  const FitQuadrature q = fit_quadrature(elements, positions_world, fit.samples, &spent);
  out.quadrature_points = q.size();
  // At the sites: least_squares_fit and relative_l2_error read it per site. The target is the
  // colour as it will be shown: clamped to the bounds (8-bit: [0, 1], as a renderer's per-pixel
  // Phong is stored), so that light above 1 is not fitted with a slope that the clamp then cuts;
  // clamped as it is shaded (no second pass over f: 36 MB at 1M triangles and 3 points).
  std::vector<double> f = lighting_at_sites(mesh, scene, q, positions_world, point.vertex_normals, options, shadows,
                                            &out.shadows, fit.solve.lower, fit.solve.upper);
  // The point colours are read only at the fallback nodes (least_squares_fit.h); a bake without
  // them (VertexColors::None) has them shaded there alone, as bake_lighting would.
  const auto shade_fallback = [&](const std::vector<std::uint32_t>& fallback) {
    return bake_vertex_colors(mesh, scene, point, fallback, options, shadows, out.fallback_counters);
  };
  LeastSquaresFitOptions solve = fit.solve;
  solve.scratch = &spent;
  if (point.rgb.empty() && !fit.measure_error)  // f has no further use: its memory holds CG's vectors
    out.solve = least_squares_fit(elements, positions_world, q, std::move(f), shade_fallback, 3, solve);
  else if (point.rgb.empty())
    out.solve = least_squares_fit(elements, positions_world, q, f, shade_fallback, 3, solve);
  else
    out.solve = least_squares_fit(elements, positions_world, q, f, point.rgb, 3, solve);
  out.rgb = std::move(out.solve.values);
  out.solve.values.clear();
  if (!fit.measure_error) {
    out.error_fit = out.error_point = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  out.error_fit = relative_l2_error(q, f, out.rgb, 3);
  if (point.rgb.empty()) {  // no point colours to measure
    out.error_point = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  std::vector<double> point_clamped = point.rgb;  // as written: the same bounds as the fit's
  for (double& v : point_clamped) v = std::min(std::max(v, fit.solve.lower), fit.solve.upper);
  out.error_point = relative_l2_error(q, f, point_clamped, 3);
  return out;
}

}  // namespace shadetool
