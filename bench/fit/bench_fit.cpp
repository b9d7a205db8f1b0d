// bench_fit: `bake-lighting --fit point` against `--fit least-squares` at 1, 3 and 6 quadrature
// points per triangle (lighting/fit_vertex_lighting.h), on tori of about 10k, 100k (and 1M)
// triangles under data/scenes/studio.json and window.json.
//   time   the whole per-vertex bake: bake_lighting (the point colours), plus for least squares the
//          quadrature, f at its points, assembly and CG; median of REPEATS runs
//   error  relative L2 distance of the interpolated colours (8-bit bounds: clamped to [0, 1], as
//          written) to the per-point colour render --shading phong computes (clamped likewise),
//          measured with the 12-point degree-6 rule: finer than any fit's own rule, so no fit is
//          scored by its own objective
// Usage: bench_fit table SRC_DIR [REPEATS] [MAX_TRIANGLES]
//        bench_fit picture SRC_DIR OUT.png   (point Gouraud | least-squares Gouraud | Phong, coarse)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <shadetool/fit/least_squares_fit.h>
#include <shadetool/io/image_png.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/fit_vertex_lighting.h>
#include <shadetool/lighting/read_scene.h>
#include <shadetool/render/render_mesh.h>

#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<double> clamped(std::vector<double> v) {
  for (double& x : v) x = std::min(std::max(x, 0.0), 1.0);
  return v;
}

struct Row {
  double ms;
  double error;
};

Row run(const Mesh& mesh, const Scene& scene, int samples, int repeats, const FitQuadrature& ref,
        const std::vector<double>& f_ref) {
  std::vector<double> times;
  std::vector<double> rgb;
  for (int k = 0; k < repeats; ++k) {
    const double t0 = now_ms();
    BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
    if (samples > 0) {
      VertexFitOptions fit;
      fit.method = VertexFit::LeastSquares;
      fit.samples = samples;
      fit.solve.upper = 1;
      rgb = fit_vertex_lighting(mesh, scene, point, {}, {}, fit).rgb;
    } else {
      rgb = clamped(point.rgb);
    }
    times.push_back(now_ms() - t0);
  }
  return {median(times), relative_l2_error(ref, f_ref, rgb, 3)};
}

int table(const std::string& src, int repeats, std::size_t max_triangles) {
  std::printf("| mesh | scene | method | time (ms) | x point | relative L2 error | vs point |\n|---|---|---|---|---|---|---|\n");
  const int sizes[][2] = {{100, 50}, {316, 158}, {1000, 500}};
  for (const auto& s : sizes) {
    if (std::size_t(2 * s[0] * s[1]) > max_triangles) continue;
    const Mesh mesh = testing::torus(s[0], s[1], 1.0, 0.4).mesh;
    for (const char* name : {"studio", "window"}) {
      const Scene scene = read_scene(src + "/data/scenes/" + name + ".json");
      const BakeResult normals = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
      const std::vector<double> world = world_positions(mesh, scene);
      const FitQuadrature ref = fit_quadrature(fit_elements(mesh), world, 12);
      const std::vector<double> f = clamped(lighting_at_quadrature(mesh, scene, ref, world, normals.vertex_normals, {}, {}));
      const Row point = run(mesh, scene, 0, repeats, ref, f);
      for (int samples : {0, 1, 3, 6}) {
        const Row r = samples == 0 ? point : run(mesh, scene, samples, repeats, ref, f);
        std::printf("| torus %zuk tri | %s | %s | %.1f | %.2f | %.5f | %+.0f%% |\n", mesh.num_faces() / 1000, name,
                    samples == 0 ? "point" : ("least squares, " + std::to_string(samples) + " pt").c_str(), r.ms,
                    r.ms / point.ms, r.error, 100 * (r.error / point.error - 1));
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

int picture(const std::string& src, const std::string& out) {
  const Mesh mesh = testing::icosphere(1).mesh;  // 80 triangles: highlights fall between vertices
  Scene scene = read_scene(src + "/data/scenes/studio.json");
  scene.lens.fov_y_degrees = 26;  // the sphere fills the frame
  const BakeResult point = bake_lighting(mesh, scene, ShadingFrequency::PerVertex);
  VertexFitOptions fit;
  fit.method = VertexFit::LeastSquares;
  fit.samples = 6;
  fit.solve.upper = 1;
  const VertexLightingFit lsq = fit_vertex_lighting(mesh, scene, point, {}, {}, fit);
  std::printf("icosphere(1), studio: relative L2 error (its own 6-point rule) least squares %.4f, point %.4f\n",
              lsq.error_fit, lsq.error_point);
  RenderOptions o;
  o.width = o.height = 400;
  o.samples = 4;
  std::vector<ImageRGB> images;
  o.shading = RenderShading::Gouraud;
  images.push_back(render_mesh(mesh, scene, o).image);
  o.vertex_rgb = &lsq.rgb;
  images.push_back(render_mesh(mesh, scene, o).image);
  o.vertex_rgb = nullptr;
  o.shading = RenderShading::Phong;
  images.push_back(render_mesh(mesh, scene, o).image);
  const int W = 3 * o.width + 2 * 8, H = o.height;
  std::vector<std::uint8_t> srgb(std::size_t(3) * W * H, 255);
  for (int k = 0; k < 3; ++k)
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < o.width; ++x)
        for (int c = 0; c < 3; ++c)
          srgb[3 * (std::size_t(y) * W + std::size_t(k * (o.width + 8) + x)) + c] = encode_srgb_8bit(images[k].pixel(x, y)[c]);
  std::ofstream(out, std::ios::binary) << io::encode_png_srgb8(W, H, srgb, out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_fit table SRC_DIR [REPEATS] [MAX_TRIANGLES] | picture SRC_DIR OUT.png\n");
    return 2;
  }
  const std::string mode = argv[1], src = argv[2];
  if (mode == "picture" && argc > 3) return picture(src, argv[3]);
  return table(src, argc > 3 ? std::atoi(argv[3]) : 5, argc > 4 ? std::size_t(std::atoll(argv[4])) : 200000);
}
