// bench_lighting: time of lighting/shade_points.h on a generated 1M-vertex torus (exact normals),
// (1) with and without each skip (only that one turned off), and (2) in world, camera and object
// space for several kinds of M, against the space `auto` picks. Single thread (the machine has 2
// noisy cores; ratios are what matter), medians of N runs, all configurations in one process.
//
// Usage: bench_lighting [REPEATS]   (default 7)
//        bench_lighting --area [REPEATS] [ratios [WORD]]   issue 16: area, sky and environment
//                                          lights against a point light (with WORD: only the rows
//                                          whose name contains it, e.g. "rect, diffuse"), and
//                                          (without `ratios`) the quadrature paths' and the
//                                          environment's time against error
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

#include <shadetool/lighting/area_light.h>
#include <shadetool/lighting/engine/skip_options.h>
#include <shadetool/lighting/environment_map.h>
#include <shadetool/lighting/look_at.h>
#include <shadetool/lighting/shade_points.h>
#include "support/analytic_meshes.h"

using namespace shadetool;

namespace {

int g_repeats = 7;
bool g_ratios_only = false;  // --area REPEATS ratios: the table against the point light only
std::string g_row_filter;    // --area REPEATS ratios WORD: only the rows whose name contains WORD
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
    o.parallel = false;
    const auto c = shade_points(s, pts.p, pts.n, o, skips, report);
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

Light rect(const Vec3d& c, const Vec3d& u, const Vec3d& v, double intensity) {
  Light L;
  L.type = LightType::Area;
  L.vertices = {c - u - v, c + u - v, c + u + v, c - u + v};
  L.diffuse = L.specular = Vec3d{1, 1, 1} * intensity;
  L.ambient = {0, 0, 0};
  return L;
}

// A procedural sky for the environment rows: gradient, a 2x2-texel sun of radiance 48, a ground.
std::shared_ptr<const EnvironmentMap> sunny_map(int width, int height) {
  std::vector<float> rgb;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Vec3d w = environment_direction(width, height, j, i);
      const Vec3d c = w.y < 0 ? Vec3d{0.25, 0.1875, 0.125} * (1 + 0.5 * w.y) : Vec3d{0.75 - 0.5 * w.y, 0.8125 - 0.25 * w.y, 1.0};
      rgb.insert(rgb.end(), {float(c.x), float(c.y), float(c.z)});
    }
  const int sun_row = height / 5, sun_col = 5 * width / 8;
  for (int j = sun_row; j < sun_row + 2; ++j)
    for (int i = sun_col; i < sun_col + 2; ++i)
      for (int k = 0; k < 3; ++k) rgb[(std::size_t(j) * width + i) * 3 + k] = k == 2 ? 40.f : 48.f;
  return make_environment_map(width, height, rgb);
}

// Issue 16's environment light: the SH diffuse and the down-sampled specular sums against the
// full-resolution texel sum (errors relative to the largest full-resolution value over the
// points: a per-point relative error is meaningless where the value is ~0), on a 512 x 256 map
// with a sun, at every 64th vertex of the torus (977 points).
void environment_bench(const Points& pts) {
  const auto map = sunny_map(512, 256);
  const Vec3d eye{0, 4, 5};
  std::vector<Vec3d> normals, views;
  for (std::size_t i = 0; i < pts.p.size() / 3; i += 64) {
    const Vec3d p{pts.p[3 * i], pts.p[3 * i + 1], pts.p[3 * i + 2]};
    normals.push_back(normalized_or(Vec3d{pts.n[3 * i], pts.n[3 * i + 1], pts.n[3 * i + 2]}, Vec3d{0, 0, 1}));
    views.push_back(normalized_or(eye - p, Vec3d{0, 0, 0}));
  }
  const std::size_t n = normals.size();
  auto max_abs = [](const Vec3d& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); };
  auto errors = [&](const std::vector<Vec3d>& got, const std::vector<Vec3d>& truth) {
    double peak = 0;
    for (const Vec3d& t : truth) peak = std::max(peak, max_abs(t));
    std::vector<double> e;
    for (std::size_t i = 0; i < n; ++i) e.push_back(peak > 0 ? max_abs(got[i] - truth[i]) / peak : 0.0);
    std::sort(e.begin(), e.end());
    return std::make_pair(e.back(), e[e.size() / 2]);
  };
  std::printf("\nEnvironment 512x256 with a sun: P and S against the full-resolution texel sum, %zu points;\n"
              "errors relative to the largest full-resolution value\n", n);
  std::printf("%-34s %12s %14s %14s\n", "path", "ns/point", "max error", "median error");
  std::vector<Vec3d> full(n), sh(n);
  const auto t = interleaved_medians({[&] {
                                        for (std::size_t i = 0; i < n; ++i) full[i] = environment_irradiance_sum(*map, normals[i]);
                                        g_sink += full[n / 2].x;
                                      },
                                      [&] {
                                        for (std::size_t i = 0; i < n; ++i) sh[i] = environment_irradiance_sh(*map, normals[i]);
                                        g_sink += sh[n / 2].x;
                                      }});
  auto e = errors(sh, full);
  std::printf("%-34s %12.0f %14s %14s\n", "P, every texel (reference)", t[0] * 1e6 / n, "-", "-");
  std::printf("%-34s %12.0f %14.2e %14.2e\n", "P, 9 SH coefficients", t[1] * 1e6 / n, e.first, e.second);
  for (LobeKind kind : {LobeKind::Phong, LobeKind::BlinnPhong})
    for (double shininess : {8.0, 32.0, 128.0}) {
      auto lobe_at = [&](std::size_t i) {
        SpecularLobe lobe;
        lobe.kind = kind;
        lobe.shininess = shininess;
        lobe.reflected = normalized_or(normals[i] * (2 * dot(normals[i], views[i])) - views[i], Vec3d{0, 0, 0});
        lobe.view = views[i];
        lobe.normal = normals[i];
        return lobe;
      };
      std::vector<Vec3d> truth(n);
      for (std::size_t i = 0; i < n; ++i) truth[i] = environment_specular_sum(*map, normals[i], lobe_at(i), 0);
      const int chosen = environment_specular_level(*map, shininess);
      for (int level = 1; level < int(map->levels.size()); ++level) {
        std::vector<Vec3d> got(n);
        const auto tl = interleaved_medians({[&] {
          for (std::size_t i = 0; i < n; ++i) got[i] = environment_specular_sum(*map, normals[i], lobe_at(i), level);
          g_sink += got[n / 2].x;
        }});
        const auto el = errors(got, truth);
        char name[64];
        std::snprintf(name, sizeof name, "S %s %g, %dx%d%s", kind == LobeKind::Phong ? "phong" : "blinn", shininess,
                      map->levels[level].width, map->levels[level].height, level == chosen ? " (chosen)" : "");
        std::printf("%-34s %12.0f %14.2e %14.2e\n", name, tl[0] * 1e6 / n, el.first, el.second);
      }
    }
}

// Issue 16: per-vertex cost of area and sky lights against a point light on the same mesh, and
// the quadrature paths as time against error (the error against Arvo's closed form).
void area_bench(const Points& pts) {
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const double n_points = double(pts.p.size() / 3);
  auto scene_with = [](ShadingModel model, const Light& L) {
    Scene s = base_scene(model);
    s.material.shininess = 32;
    s.lights = {L};
    return s;
  };
  Light pt = point({0, 3, 0});
  Light window = rect({0, 3, 0}, {1, 0, 0}, {0, 0, 0.5}, 4);
  window.vertices = {{-1, 3, -0.5}, {1, 3, -0.5}, {1, 3, 0.5}, {-1, 3, 0.5}};  // emits downward (-y)
  Light poly = window;
  poly.vertices = {{-0.5, 3, -0.5}, {0.3, 3, -0.8}, {0.8, 3, 0}, {0.3, 3, 0.8}, {-0.5, 3, 0.5}};  // emits -y
  Light sphere = window;
  sphere.shape = AreaShape::Sphere;
  sphere.center = {0, 3, 0};
  sphere.radius = 0.5;
  Light sky;
  sky.type = LightType::Sky;
  sky.diffuse = sky.specular = {0.5, 0.7, 1};
  sky.ground = {0.3, 0.25, 0.2};
  sky.ambient = {0, 0, 0};
  Light env;
  env.type = LightType::Environment;
  env.environment = sunny_map(64, 32);
  env.diffuse = env.specular = {0.3, 0.3, 0.3};
  env.ambient = {0, 0, 0};
  struct Row {
    const char* name;
    ShadingModel model;
    Light light;
  };
  const Row rows[] = {
      {"rect, diffuse (Lambert's formula)", ShadingModel::Lambert, window},
      {"polygon (5), diffuse", ShadingModel::Lambert, poly},
      {"sphere, diffuse (Snyder)", ShadingModel::Lambert, sphere},
      {"sky, diffuse", ShadingModel::Lambert, sky},
      {"rect, phong 32 (Arvo closed form)", ShadingModel::Phong, window},
      {"sky, phong 32 (Arvo, 8 triangles)", ShadingModel::Phong, sky},
      {"rect, blinn-phong 32 (quadrature q=16)", ShadingModel::BlinnPhong, window},
      {"sphere, phong 32 (quadrature q=16)", ShadingModel::Phong, sphere},
      {"environment 64x32, diffuse (SH)", ShadingModel::Lambert, env},
      {"environment 64x32, phong 32 (sum)", ShadingModel::Phong, env},
      {"environment 64x32, blinn-phong 32 (sum)", ShadingModel::BlinnPhong, env},
  };
  std::printf("\nArea and sky lights (issue 16): %.0f points, 1 thread, median of %d interleaved runs, thread CPU ms\n",
              n_points, g_repeats);
  std::printf("%-40s %10s %12s %10s %8s\n", "light", "ms", "point light", "ns/vertex", "ratio");
  for (const Row& r : rows) {
    if (std::string(r.name).find(g_row_filter) == std::string::npos) continue;
    const Scene a = scene_with(r.model, r.light), b = scene_with(r.model, pt);
    const auto t = interleaved_medians({shade_job(a, pts, ShadingSpace::Auto, {}), shade_job(b, pts, ShadingSpace::Auto, {})});
    std::printf("%-40s %10.1f %12.1f %10.0f %7.2fx\n", r.name, t[0], t[1], t[0] * 1e6 / n_points, t[0] / t[1]);
  }

  if (g_ratios_only) return;
  // Quadrature order q against error: Phong with shininess 32 + 1e-9 takes the quadrature path;
  // its truth is Arvo's closed form for 32 (the two integrands differ by < 1e-8 relative).
  std::printf("\nQuadrature (rect light, phong 32 + 1e-9 vs Arvo's closed form for 32; sphere: vs q = 64)\n");
  std::printf("%-8s %4s %12s %16s %16s\n", "light", "q", "ns/vertex", "max rel error", "median rel error");
  const std::size_t n = pts.p.size() / 3;
  const Vec3d eye{0, 4, 5};
  std::vector<double> truth_rect(n), truth_sphere(n);
  auto lobe_at = [&](std::size_t i, double shininess, int q) {
    const Vec3d p{pts.p[3 * i], pts.p[3 * i + 1], pts.p[3 * i + 2]};
    const Vec3d nn = normalized_or(Vec3d{pts.n[3 * i], pts.n[3 * i + 1], pts.n[3 * i + 2]}, Vec3d{0, 0, 1});
    const Vec3d V = normalized_or(eye - p, Vec3d{0, 0, 0});
    SpecularLobe lobe;
    lobe.kind = LobeKind::Phong;
    lobe.shininess = shininess;
    lobe.reflected = nn * (2 * dot(nn, V)) - V;
    lobe.quadrature_order = q;
    return std::make_pair(lobe, std::make_pair(p, nn));
  };
  const Vec3d emit{0, -1, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const auto l = lobe_at(i, 32, 16);
    truth_rect[i] = polygon_light_terms(window.vertices.data(), 4, emit, false, l.second.first, l.second.second, l.first).S;
    auto l64 = lobe_at(i, 32, 64);
    truth_sphere[i] = sphere_light_terms(sphere.center, sphere.radius, l.second.first, l.second.second, l64.first).S;
  }
  for (int shape = 0; shape < 2; ++shape)
    for (int q : {2, 4, 8, 16, 32}) {
      std::vector<double> got(n);
      const auto t = interleaved_medians({[&] {
        for (std::size_t i = 0; i < n; ++i) {
          const auto l = lobe_at(i, shape == 0 ? 32 + 1e-9 : 32, q);
          got[i] = shape == 0 ? polygon_light_terms(window.vertices.data(), 4, emit, false, l.second.first,
                                                    l.second.second, l.first).S
                              : sphere_light_terms(sphere.center, sphere.radius, l.second.first, l.second.second,
                                                   l.first).S;
        }
        g_sink += got[n / 2];
      }});
      const std::vector<double>& truth = shape == 0 ? truth_rect : truth_sphere;
      double scale = 0;
      for (double x : truth) scale = std::max(scale, x);
      std::vector<double> err;
      for (std::size_t i = 0; i < n; ++i)
        if (truth[i] > 1e-6 * scale) err.push_back(std::fabs(got[i] - truth[i]) / truth[i]);
      std::sort(err.begin(), err.end());
      std::printf("%-8s %4d %12.0f %16.2e %16.2e\n", shape == 0 ? "rect" : "sphere", q, t[0] * 1e6 / n_points,
                  err.empty() ? 0.0 : err.back(), err.empty() ? 0.0 : err[err.size() / 2]);
    }
  environment_bench(pts);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // line by line: a long run shows its tables as they come
  if (argc > 1 && std::string(argv[1]) == "--area") {  // issue 16's table only, on a 250 x 250 torus
    if (argc > 2) g_repeats = std::max(1, std::atoi(argv[2]));
    g_ratios_only = argc > 3 && std::string(argv[3]) == "ratios";
    if (g_ratios_only && argc > 4) g_row_filter = argv[4];
    testing::AnalyticMesh torus = testing::torus(250, 250, 1.0, 0.4);
    Points pts;
    pts.p = torus.mesh.positions;
    for (const Vec3d& n : torus.exact_normals) pts.n.insert(pts.n.end(), {n.x, n.y, n.z});
    area_bench(pts);
    std::printf("(checksum %g)\n", g_sink);
    return 0;
  }
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
