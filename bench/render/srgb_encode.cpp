// srgb_encode.cpp: the linear-float-to-8-bit-sRGB step of a render written as PNG
// (render/output_image.h), on real 1920x1080 renders: the formula per channel
// (render/lighting_adapter.h encode_srgb_8bit: pow for each of 6.2 million channels) against the
// table render_output_image now uses (render/srgb8_encoder.h), rounds interleaved, thread CPU
// time, medians; checks that both give the same bytes.
// Usage: bench_srgb_encode [ROUNDS]   (default 15)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include <shadetool/lighting/look_at.h>
#include <shadetool/render/lighting_adapter.h>
#include <shadetool/render/output_image.h>
#include <shadetool/render/render_mesh.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

double thread_cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
  Scene scene;  // the bench_render scene: two lights, Blinn-Phong, the sphere 3 units away
  scene.model = ShadingModel::BlinnPhong;
  scene.global_ambient = {0.1, 0.1, 0.1};
  scene.material.diffuse = {0.8, 0.5, 0.3};
  scene.material.specular = {0.5, 0.5, 0.5};
  scene.material.shininess = 32;
  Light d;
  d.type = LightType::Directional;
  d.direction = {-1, -1, -2};
  Light p;
  p.type = LightType::Point;
  p.position = {2, 2, 3};
  scene.lights = {d, p};
  look_at({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, scene.camera_from_world);
  scene.has_camera = true;
  RenderOptions o;
  o.width = 1920;
  o.height = 1080;
  o.background = {0.05, 0.05, 0.08};
  std::printf("| frame | formula per channel, CPU ms | table (render_output_image), CPU ms | formula / table (median of rounds) | same bytes |\n|---|---|---|---|---|\n");
  for (RenderShading shading : {RenderShading::Gouraud, RenderShading::Phong}) {
    o.shading = shading;
    const ImageRGB image = render_mesh(testing::uv_sphere(100, 51).mesh, scene, o).image;
    std::vector<double> formula_ms, table_ms, ratio;
    bool same = true;
    for (int r = 0; r < rounds + 1; ++r) {  // round 0 warms up
      double t0 = thread_cpu_ms();
      std::vector<std::uint8_t> by_formula(image.rgb.size());
      for (std::size_t i = 0; i < image.rgb.size(); ++i) by_formula[i] = encode_srgb_8bit(image.rgb[i]);
      const double a = thread_cpu_ms() - t0;
      t0 = thread_cpu_ms();
      const Image by_table = render_output_image(image, false);
      const double b = thread_cpu_ms() - t0;
      same = same && by_table.u8 == by_formula;
      if (r == 0) continue;
      formula_ms.push_back(a);
      table_ms.push_back(b);
      ratio.push_back(a / b);
    }
    std::printf("| 10k-triangle sphere, %s, 1920x1080 | %.1f | %.1f | %.1fx | %s |\n", render_shading_name(shading),
                median(formula_ms), median(table_ms), median(ratio), same ? "yes" : "NO");
  }
  return 0;
}
