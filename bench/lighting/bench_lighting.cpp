// bench_lighting: time of lighting/shade_points.h on a generated 1M-vertex torus (exact normals),
// (1) with and without each skip (only that one turned off), and (2) in world, camera and object
// space for several kinds of M, against the space `auto` picks. Single thread (the machine has 2
// noisy cores; ratios are what matter), medians of N runs, all configurations in one process.
//
// Usage: bench_lighting [REPEATS]   (default 7)
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include <shadetool/lighting/look_at.h>
#include <shadetool/lighting/shade_points.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

int g_repeats = 7;
double g_sink = 0;  // keeps results alive

struct Points {
  std::vector<double> p, n;
};

// CPU time of the calling thread: the single-threaded sections run on it, and unlike wall time
// it does not count the time other processes hold the (shared, 2-core) machine.
double thread_cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

// Medians of several configurations timed round-robin (A B C A B C ...), so that a change in the
// machine's load during the run hits every configuration alike.
std::vector<double> interleaved_medians(const std::vector<std::function<void()>>& fs) {
  std::vector<std::vector<double>> t(fs.size());
  for (int r = 0; r < g_repeats; ++r)
    for (std::size_t k = 0; k < fs.size(); ++k) {
      const double t0 = thread_cpu_ms();
      fs[k]();
      t[k].push_back(thread_cpu_ms() - t0);
    }
  std::vector<double> m;
  for (auto& v : t) {
    std::sort(v.begin(), v.end());
    m.push_back(v[v.size() / 2]);
  }
  return m;
}

std::function<void()> shade_job(const Scene& s, const Points& pts, ShadingSpace space, const SkipOptions& skips,
                                ShadeReport* report = nullptr) {
  return [&s, &pts, space, skips, report] {
    ShadeOptions o;
    o.space = space;
    o.skips = skips;
    o.parallel = false;
    const auto c = shade_points(s, pts.p, pts.n, o, report);
    g_sink += c[c.size() / 2];
  };
}

Light directional(const Vec3d& d, const Vec3d& color = {1, 1, 1}) {
  Light L;
  L.type = LightType::Directional;
  L.direction = d;
  L.diffuse = L.specular = color;
  return L;
}
Light point(const Vec3d& p, const Vec3d& color = {1, 1, 1}) {
  Light L;
  L.type = LightType::Point;
  L.position = p;
  L.attenuation = {1, 0.1, 0.01};
  L.diffuse = L.specular = color;
  return L;
}
Light spot(const Vec3d& p, const Vec3d& d, double cutoff) {
  Light L = point(p);
  L.type = LightType::Spot;
  L.direction = d;
  L.cutoff_degrees = cutoff;
  L.exponent = 8;
  return L;
}

Scene base_scene(ShadingModel model) {
  Scene s;
  s.model = model;
  s.has_camera = true;
  look_at({0, 4, 5}, {0, 0, 0}, {0, 1, 0}, s.camera_from_world);
  s.global_ambient = {0.1, 0.1, 0.1};
  s.material.ambient = {1, 1, 1};
  s.material.diffuse = {0.8, 0.5, 0.2};
  s.material.specular = {1, 1, 1};
  s.material.shininess = 32;
  return s;
}

Scene studio() {  // the example scene
  Scene s = base_scene(ShadingModel::BlinnPhong);
  s.lights = {directional({0, -1, -1}), point({2, 2, 2}, {1, 0.9, 0.8}), spot({0, 3, 0}, {0, -1, 0}, 30)};
  return s;
}

void skip_row(const char* skip, const char* scene_text, const Scene& s, const Points& pts, ShadingSpace space,
              SkipOptions off) {
  ShadeReport on_report, off_report;
  const auto t = interleaved_medians({shade_job(s, pts, space, SkipOptions{}, &on_report),
                                      shade_job(s, pts, space, off, &off_report)});
  const double with = t[0], without = t[1];
  std::printf("%-18s %-44s %9.1f %9.1f %7.2fx  %12zu %12zu\n", skip, scene_text, with, without, without / with,
              on_report.counters.vertex_light_evaluations - on_report.counters.back_facing -
                  on_report.counters.outside_cone,
              off_report.counters.vertex_light_evaluations);
}

Mat3d rotation(const Vec3d& axis_in, double angle) {
  const Vec3d k = normalized_or(axis_in, Vec3d{0, 0, 1});
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  Mat3d R;
  R.m = {{{t * k.x * k.x + c, t * k.x * k.y - s * k.z, t * k.x * k.z + s * k.y},
          {t * k.x * k.y + s * k.z, t * k.y * k.y + c, t * k.y * k.z - s * k.x},
          {t * k.x * k.z - s * k.y, t * k.y * k.z + s * k.x, t * k.z * k.z + c}}};
  return R;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) g_repeats = std::max(1, std::atoi(argv[1]));
  testing::AnalyticMesh torus = testing::torus(1000, 1000, 1.0, 0.4);  // 1,000,000 vertices
  Points pts;
  pts.p = torus.mesh.positions;
  for (const Vec3d& n : torus.exact_normals) pts.n.insert(pts.n.end(), {n.x, n.y, n.z});
  std::printf("bench_lighting: %zu points (torus 1000 x 1000), 1 thread, median of %d interleaved runs, thread CPU ms\n\n",
              pts.p.size() / 3, g_repeats);

  {  // sections (1) and (2) on one thread
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  // ---- (1) each skip on vs off (only that skip off)
  std::printf("%-18s %-44s %9s %9s %8s  %12s %12s\n", "skip", "scene", "with", "without", "saved", "lit pairs",
              "pairs w/o");
  {
    Scene s = base_scene(ShadingModel::BlinnPhong);
    s.lights = {directional({0, -1, -1}), point({2, 2, 2}, {0, 0, 0}), point({-2, 2, 2}, {0, 0, 0}),
                point({0, -2, 2}, {0, 0, 0})};
    SkipOptions off;
    off.dark_lights = false;
    skip_row("dark_lights", "blinn-phong, 1 directional + 3 black points", s, pts, ShadingSpace::World, off);
  }
  {
    Scene s = base_scene(ShadingModel::BlinnPhong);
    s.material.specular = {0, 0, 0};
    s.lights = {directional({0, -1, -1}), point({2, 2, 2}), point({-2, 2, 2})};
    SkipOptions off;
    off.specular = false;
    skip_row("specular", "blinn-phong, ks = 0, 1 directional + 2 points", s, pts, ShadingSpace::World, off);
  }
  {
    Scene s = base_scene(ShadingModel::Lambert);
    s.lights = {directional({0, -1, -1}), point({2, 2, 2})};
    SkipOptions off;
    off.view_vector = false;
    skip_row("view_vector", "lambert, 1 directional + 1 point", s, pts, ShadingSpace::World, off);
  }
  {
    SkipOptions off;
    off.early_tests = false;
    skip_row("early_tests", "studio (directional, point, spot 30 deg)", studio(), pts, ShadingSpace::World, off);
  }
  {
    Scene s = studio();  // M = identity, forced world space
    SkipOptions off;
    off.identity_transform = false;
    skip_row("identity_transform", "studio, M = identity, --space world", s, pts, ShadingSpace::World, off);
  }
  {
    Scene s = base_scene(ShadingModel::Lambert);
    s.lights = {directional({0, -1, -1}), directional({1, 0.5, -1}, {0.3, 0.3, 0.5})};
    s.world_from_object.A.m = {{{1, 0.4, 0}, {0, 2, 0.3}, {0, 0, 0.5}}};
    SkipOptions off;
    off.unused_positions = false;
    skip_row("unused_positions", "lambert, 2 directional, sheared M, world", s, pts, ShadingSpace::World, off);
  }
  {
    skip_row("all", "studio, every skip off", studio(), pts, ShadingSpace::Auto, SkipOptions::none());
  }

  // ---- (2) spaces: world, camera, object, and what auto picks
  std::printf("\n%-22s %-36s %8s %8s %8s   %-7s %s\n", "M", "scene", "world", "camera", "object", "auto",
              "auto/fastest");
  struct MCase {
    const char* name;
    Affine3d M;
  };
  std::vector<MCase> ms;
  ms.push_back({"identity", Affine3d{}});
  ms.push_back({"rotation+translation", Affine3d{rotation({1, 2, 3}, 0.8), {0.5, -0.2, 0.3}}});
  ms.push_back({"similarity (x2)", Affine3d{rotation({1, 2, 3}, 0.8) * Mat3d::diagonal(2, 2, 2), {0.5, -0.2, 0.3}}});
  Mat3d shear;
  shear.m = {{{1.5, 0.4, 0}, {0, 0.7, 0.3}, {0, 0, 1.2}}};
  ms.push_back({"shear+non-uniform", Affine3d{rotation({1, 2, 3}, 0.8) * shear, {0.5, -0.2, 0.3}}});

  struct SCase {
    const char* name;
    Scene scene;
  };
  std::vector<SCase> scenes;
  {
    Scene s = base_scene(ShadingModel::Lambert);
    s.lights = {directional({0, -1, -1})};
    scenes.push_back({"lambert, 1 directional", s});
  }
  {
    Scene s = base_scene(ShadingModel::Lambert);
    s.lights = {point({2, 2, 2})};
    scenes.push_back({"lambert, 1 point", s});
  }
  scenes.push_back({"studio (blinn-phong, 3 lights)", studio()});
  {
    Scene s = studio();
    s.lights.push_back(point({-2, 2, 2}));
    s.lights.push_back(point({0, -2, 3}));
    scenes.push_back({"blinn-phong, 1 dir + 3 points + 1 spot", s});
  }

  int auto_fastest = 0, auto_total = 0;
  double worst = 1;
  for (const MCase& m : ms) {
    for (SCase& sc : scenes) {
      Scene s = sc.scene;
      s.world_from_object = m.M;
      const auto t = interleaved_medians({shade_job(s, pts, ShadingSpace::World, {}),
                                          shade_job(s, pts, ShadingSpace::Camera, {}),
                                          shade_job(s, pts, ShadingSpace::Object, {})});
      const double w = t[0], c = t[1], o = t[2];
      ShadeReport r;
      ShadeOptions probe;
      probe.parallel = false;
      shade_points(s, std::vector<double>(pts.p.begin(), pts.p.begin() + 3), std::vector<double>(pts.n.begin(), pts.n.begin() + 3),
                   probe, &r);
      const double picked = r.space == ShadingSpace::World ? w : r.space == ShadingSpace::Camera ? c : o;
      const double fastest = std::min({w, c, o});
      const double ratio = picked / fastest;
      ++auto_total;
      if (ratio <= 1.05) ++auto_fastest;
      worst = std::max(worst, ratio);
      std::printf("%-22s %-36s %8.1f %8.1f %8.1f   %-7s %.2f\n", m.name, sc.name, w, c, o, shading_space_name(r.space),
                  ratio);
    }
  }
  std::printf("\nauto within 5%% of the fastest space in %d of %d cases; worst auto/fastest %.2f\n", auto_fastest,
              auto_total, worst);

  }  // one thread

  // ---- (3) the default (parallel) path once, for scale
  {  // wall time here (CPU time of one thread cannot show a parallel speed-up); load-sensitive
    auto wall_median = [&](const std::function<void()>& f) {
      std::vector<double> t;
      for (int r = 0; r < g_repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      }
      std::sort(t.begin(), t.end());
      return t[t.size() / 2];
    };
    ShadeOptions o;
    const Scene s = studio();
    const double par = wall_median([&] { g_sink += shade_points(s, pts.p, pts.n, o)[0]; });
    o.parallel = false;
    const double ser = wall_median([&] { g_sink += shade_points(s, pts.p, pts.n, o)[0]; });
    std::printf("studio, auto space, wall time: 1 thread %.1f ms, all threads %.1f ms (%.2fx)\n", ser, par, ser / par);
  }
  std::printf("(checksum %g)\n", g_sink);
  return 0;
}
