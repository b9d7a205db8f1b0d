// bench_progress: the cost of a progress listener (core/progress.h) in the kernels that report
// per block: mesh_occlusion (per vertex, computed normals) and render_mesh (Phong), each run with
// progress = null and with a ProgressMeter, alternating run by run (round-robin) so that load
// drifts hit both rows alike. Prints process CPU time and wall time per run and the medians, and
// fails unless both rows give the same bits (listening never changes a result).
//
// Usage: bench_progress [runs=9] [torus cells u=400] [samples=64] [render side=1600]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <vector>

#include <shadetool/core/progress.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/look_at.h>
#include <shadetool/render/render_mesh.h>
#include <shadetool/visibility/ambient_occlusion.h>

using namespace shadetool;

namespace {

double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}
double wall_seconds() { return steady_seconds(); }

// A torus of nu x nv quads split into triangles (R = 1, r = 0.4).
Mesh torus(int nu, int nv) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;  // divisors: nu, nv >= 3
      m.add_vertex({(1 + 0.4 * std::cos(v)) * std::cos(u), (1 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v)});
    }
  auto id = [&](int i, int j) { return std::uint32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Row {
  std::vector<double> cpu, wall;
};

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 9;
  const int nu = argc > 2 ? std::atoi(argv[2]) : 400;
  const std::uint32_t samples = argc > 3 ? std::uint32_t(std::atoi(argv[3])) : 64;
  const int side = argc > 4 ? std::atoi(argv[4]) : 1600;
  const Mesh mesh = torus(nu, nu / 2);
  std::printf("torus %zu vertices, %zu triangles; occlusion %u samples; render %dx%d phong; %d runs each\n",
              mesh.num_vertices(), mesh.num_faces(), samples, side, side, runs);

  AmbientOcclusionOptions ao;
  ao.samples = samples;
  Scene scene;
  Light key;
  key.direction = {-1, -2, -3};
  scene.lights = {key};
  look_at({0, -3, 2}, {0, 0, 0}, {0, 0, 1}, scene.camera_from_world);
  scene.has_camera = true;
  RenderOptions ro;
  ro.width = ro.height = side;

  Row occ[2], ren[2];
  std::vector<float> occ_bits[2];
  std::vector<float> ren_bits[2];
  for (int r = 0; r < runs; ++r)
    for (int listen = 0; listen < 2; ++listen) {  // round-robin: none, meter, none, meter, ...
      ProgressMeter meter;
      AmbientOcclusionOptions a = ao;
      a.progress = listen ? &meter : nullptr;
      double c0 = cpu_seconds(), w0 = wall_seconds();
      MeshOcclusion o = mesh_occlusion(mesh, false, a, "torus");
      occ[listen].cpu.push_back(cpu_seconds() - c0);
      occ[listen].wall.push_back(wall_seconds() - w0);
      occ_bits[listen] = std::move(o.ao.open_fraction);

      RenderOptions b = ro;
      b.progress = listen ? &meter : nullptr;
      c0 = cpu_seconds(), w0 = wall_seconds();
      RenderResult img = render_mesh(mesh, scene, b, "torus");
      ren[listen].cpu.push_back(cpu_seconds() - c0);
      ren[listen].wall.push_back(wall_seconds() - w0);
      ren_bits[listen].assign(img.image.rgb.begin(), img.image.rgb.end());
      std::printf("run %d %-8s occlusion cpu %.3f s wall %.3f s | render cpu %.3f s wall %.3f s\n", r,
                  listen ? "meter" : "none", occ[listen].cpu.back(), occ[listen].wall.back(), ren[listen].cpu.back(),
                  ren[listen].wall.back());
    }
  const bool same = occ_bits[0] == occ_bits[1] && ren_bits[0] == ren_bits[1];
  std::printf("\n| kernel | no sink: CPU s (wall s) | ProgressMeter: CPU s (wall s) | ratio CPU (wall) |\n|---|---|---|---|\n");
  for (int k = 0; k < 2; ++k) {
    const Row* rows = k == 0 ? occ : ren;
    const double c0 = median(rows[0].cpu), c1 = median(rows[1].cpu), w0 = median(rows[0].wall), w1 = median(rows[1].wall);
    std::printf("| %s | %.3f (%.3f) | %.3f (%.3f) | %.3f (%.3f) |\n", k == 0 ? "occlusion" : "render", c0, w0, c1, w1,
                c1 / c0, w1 / w0);  // divisors: a kernel's time > 0
  }
  std::printf("\nresults bit-identical with and without the sink: %s\n", same ? "yes" : "NO");
  return same ? 0 : 1;
}
