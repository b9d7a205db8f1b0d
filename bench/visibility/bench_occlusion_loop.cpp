// bench_occlusion_loop.cpp: shadetool's per-vertex occlusion against bare Embree loops over
// exactly the rays it casts (issue 31, goal 2).
//
//   bench_occlusion_loop MESH.ply [--samples N] [--runs R] [--threads T] [--stride S] [--flags LIST]
//                        [--forms LIST] [--other-forms LIST]
//
// The rays: for every vertex ambient_occlusion_per_vertex traces (unit angle-weighted normal, the
// BVH's float vertex), its N rays made beforehand, outside every timing, by the library's own
// functions (sample_sequence.h, ray_offset.h) in the order ambient_occlusion.cpp makes them:
// origin offset along the normal, tnear 0, tfar +inf, mask all ones. Stored as one float origin
// per vertex and one float direction per ray (12 B a ray), which each bare loop copies into the
// ray layout its Embree call takes: the least a loop over these rays can do.
//
// --stride S: every S-th vertex only (vertex ids 0, S, 2S, ...; the BVH is still the whole mesh's),
// traced by ambient_occlusion_at_points with those ids and the same axes: the same rays as the
// per-vertex call for those vertices (S = 1, the default: ambient_occlusion_per_vertex itself).
//
// Rows, taken round-robin run by run (medians of R runs), each on T threads (tbb::global_control;
// every row splits the vertices with visibility_engine::parallel_point_ranges, ours does too):
//   shadetool      ambient_occlusion_per_vertex(scene, mesh, normals, N): makes its rays as it goes
//   FORM / FLAGS   (--forms on the first FLAGS, --other-forms, default the same, on the others)
//                  a bare loop over the stored rays on an Embree scene built from the same float
//                  buffers with the scene flags FLAGS (robust+compact = shadetool's, none, robust,
//                  compact), in one of the forms:
//     single       rtcOccluded1 per ray
//     stream-v     rtcOccluded1M over one vertex's N rays (RTCRay array)
//     stream-vc    the same with RTC_INTERSECT_CONTEXT_FLAG_COHERENT
//     stream-4k    rtcOccluded1M over up to 4096 rays of consecutive vertices
//     np-4k        rtcOccludedNp (RTCRayNp: one array per field) over up to 4096 rays of
//                  consecutive vertices
//     packet8      rtcOccluded8 (RTCRay8, SoA), 8 rays of one vertex per packet
//     packet16     rtcOccluded16 (RTCRay16)
// Time: process CPU time (all threads; user + system), so Mrays/s per thread = rays / CPU s; wall
// time beside it. Every row must give every vertex the same hit count as shadetool on a scene with
// shadetool's flags (else the program fails: not the same rays); on other flags the vertices whose
// count differs are reported (a non-watertight BVH can let rays through shared edges).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <tbb/global_control.h>

#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/engine/embree_scene.h>
#include <shadetool/visibility/engine/point_ranges.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>
#include <shadetool/visibility/visibility_scene.h>

using namespace shadetool;

namespace {

double cpu_s() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
double wall_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t b = 0;
  while (b <= s.size()) {
    const std::size_t e = std::min(s.find(',', b), s.size());
    if (e > b) out.push_back(s.substr(b, e - b));
    b = e + 1;
  }
  return out;
}

// The rays ambient_occlusion_per_vertex casts (vertex salt 0, options.seed 0).
struct Rays {
  std::uint32_t samples = 0;
  std::vector<std::uint32_t> vertex;  // the traced vertices, ascending
  std::vector<float> origin;          // 3 per traced vertex
  std::vector<float> direction;       // 3 per ray, vertex-major
};

Rays make_rays(const VisibilityScene& scene, const Mesh& mesh, const std::vector<double>& normals, std::uint32_t samples,
               std::size_t stride) {
  Rays r;
  r.samples = samples;
  const std::vector<float>& local = scene.impl().vertices;
  const std::uint32_t salt_seed = visibility::hash_combine(0, 0);
  for (std::size_t v = 0; v < mesh.num_vertices(); v += stride) {
    const Vec3d raw = get3(normals, v);
    const double l = length(raw);
    if (!is_finite(mesh.position(v)) || !(l > 0) || !std::isfinite(l)) continue;
    const Vec3d n = raw * (1.0 / l);  // divisor checked
    const Vec3f p{local[3 * v], local[3 * v + 1], local[3 * v + 2]};
    Vec3d t, b;
    visibility::orthonormal_basis(n, t, b);
    const Vec3f o = visibility::offset_ray_origin(p, Vec3f(n));
    r.vertex.push_back(std::uint32_t(v));
    r.origin.insert(r.origin.end(), {o.x, o.y, o.z});
    const std::uint32_t seed = visibility::point_seed(v, salt_seed);
    for (std::uint32_t k = 0; k < samples; ++k) {
      const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(k, seed);
      const Vec3d w = visibility::cosine_hemisphere(s.u, s.v);
      const Vec3f d(t * w.x + b * w.y + n * w.z);
      r.direction.insert(r.direction.end(), {d.x, d.y, d.z});
    }
  }
  return r;
}

RTCSceneFlags parse_flags(const std::string& s) {
  if (s == "robust+compact") return RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
  if (s == "robust") return RTC_SCENE_FLAG_ROBUST;
  if (s == "compact") return RTC_SCENE_FLAG_COMPACT;
  if (s == "none") return RTC_SCENE_FLAG_NONE;
  std::fprintf(stderr, "bench_occlusion_loop: unknown flags %s\n", s.c_str());
  std::exit(2);
}

// An Embree scene over the VisibilityScene's own float vertices and the mesh's triangles.
struct BareScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::int64_t bytes[2] = {0, 0};  // Embree's allocations now, and their peak during the build
  BareScene(const VisibilityScene& vs, const Mesh& mesh, RTCSceneFlags flags) {
    device = rtcNewDevice(nullptr);
    rtcSetDeviceMemoryMonitorFunction(
        device,
        [](void* u, ssize_t b, bool) {
          std::int64_t* m = static_cast<std::int64_t*>(u);
          const std::int64_t now = __atomic_add_fetch(&m[0], std::int64_t(b), __ATOMIC_RELAXED);
          std::int64_t peak = __atomic_load_n(&m[1], __ATOMIC_RELAXED);
          while (now > peak && !__atomic_compare_exchange_n(&m[1], &peak, now, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
          }
          return true;
        },
        bytes);
    scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, flags);
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vs.impl().vertices.data(), 0, 12,
                               mesh.num_vertices());
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.corner_vertex.data(), 0, 12,
                               mesh.num_faces());  // the bench meshes are all triangles, none degenerate
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene);
  }
  ~BareScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

enum class Form { Single, StreamVertex, StreamVertexCoherent, Stream4k, StreamNp4k, Packet8, Packet16 };

Form parse_form(const std::string& s) {
  if (s == "single") return Form::Single;
  if (s == "stream-v") return Form::StreamVertex;
  if (s == "stream-vc") return Form::StreamVertexCoherent;
  if (s == "stream-4k") return Form::Stream4k;
  if (s == "np-4k") return Form::StreamNp4k;
  if (s == "packet8") return Form::Packet8;
  if (s == "packet16") return Form::Packet16;
  std::fprintf(stderr, "bench_occlusion_loop: unknown form %s\n", s.c_str());
  std::exit(2);
}

void fill(RTCRay& ray, const float* o, const float* d) {
  ray.org_x = o[0], ray.org_y = o[1], ray.org_z = o[2], ray.tnear = 0.0f;
  ray.dir_x = d[0], ray.dir_y = d[1], ray.dir_z = d[2], ray.time = 0.0f;
  ray.tfar = std::numeric_limits<float>::infinity();
  ray.mask = 0xFFFFFFFFu, ray.id = 0, ray.flags = 0;
}

template <class Packet>
void fill_packet(Packet& p, int* valid, int lane, const float* o, const float* d) {
  valid[lane] = -1;
  p.org_x[lane] = o[0], p.org_y[lane] = o[1], p.org_z[lane] = o[2], p.tnear[lane] = 0.0f;
  p.dir_x[lane] = d[0], p.dir_y[lane] = d[1], p.dir_z[lane] = d[2], p.time[lane] = 0.0f;
  p.tfar[lane] = std::numeric_limits<float>::infinity();
  p.mask[lane] = 0xFFFFFFFFu, p.id[lane] = 0, p.flags[lane] = 0;
}

// Packets of W rays of one vertex: hits of vertex i's N rays.
template <int W, class Packet, class Fn>
std::uint32_t packets(const Rays& r, std::size_t i, RTCIntersectContext& ctx, const Fn& occluded) {
  const std::uint32_t n = r.samples;
  std::uint32_t hits = 0;
  for (std::uint32_t b = 0; b < n; b += W) {
    alignas(64) Packet p;
    alignas(64) int valid[W];
    const std::uint32_t k = std::min<std::uint32_t>(W, n - b);
    for (std::uint32_t j = 0; j < k; ++j) fill_packet(p, valid, int(j), &r.origin[3 * i], &r.direction[3 * (i * n + b + j)]);
    for (std::uint32_t j = k; j < W; ++j) valid[j] = 0;
    occluded(valid, ctx, p);
    for (std::uint32_t j = 0; j < k; ++j) hits += p.tfar[j] < 0.0f ? 1u : 0u;
  }
  return hits;
}

// One bare run over all traced vertices: hits per traced vertex into `hits`.
void bare_run(RTCScene scene, const Rays& r, Form form, std::vector<std::uint32_t>& hits) {
  const std::uint32_t n = r.samples;
  visibility_engine::parallel_point_ranges(r.vertex.size(), n, [&](std::size_t b, std::size_t e) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    switch (form) {
      case Form::Single:
        for (std::size_t i = b; i < e; ++i) {
          std::uint32_t h = 0;
          for (std::uint32_t k = 0; k < n; ++k) {
            RTCRay ray;
            fill(ray, &r.origin[3 * i], &r.direction[3 * (i * n + k)]);
            rtcOccluded1(scene, &ctx, &ray);
            h += ray.tfar < 0.0f ? 1u : 0u;
          }
          hits[i] = h;
        }
        break;
      case Form::StreamVertexCoherent:
        ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        [[fallthrough]];
      case Form::StreamVertex: {
        std::vector<RTCRay> rays(n);
        for (std::size_t i = b; i < e; ++i) {
          for (std::uint32_t k = 0; k < n; ++k) fill(rays[k], &r.origin[3 * i], &r.direction[3 * (i * n + k)]);
          rtcOccluded1M(scene, &ctx, rays.data(), n, sizeof(RTCRay));
          std::uint32_t h = 0;
          for (std::uint32_t k = 0; k < n; ++k) h += rays[k].tfar < 0.0f ? 1u : 0u;
          hits[i] = h;
        }
        break;
      }
      case Form::Stream4k: {
        const std::size_t per = std::max<std::size_t>(1, 4096 / n);
        std::vector<RTCRay> rays(per * n);
        for (std::size_t i0 = b; i0 < e; i0 += per) {
          const std::size_t i1 = std::min(e, i0 + per);
          for (std::size_t i = i0; i < i1; ++i)
            for (std::uint32_t k = 0; k < n; ++k)
              fill(rays[(i - i0) * n + k], &r.origin[3 * i], &r.direction[3 * (i * n + k)]);
          rtcOccluded1M(scene, &ctx, rays.data(), unsigned((i1 - i0) * n), sizeof(RTCRay));
          for (std::size_t i = i0; i < i1; ++i) {
            std::uint32_t h = 0;
            for (std::uint32_t k = 0; k < n; ++k) h += rays[(i - i0) * n + k].tfar < 0.0f ? 1u : 0u;
            hits[i] = h;
          }
        }
        break;
      }
      case Form::StreamNp4k: {
        const std::size_t per = std::max<std::size_t>(1, 4096 / n), cap = per * n;
        std::vector<float> f(9 * cap);  // org xyz, tnear, dir xyz, time, tfar
        std::vector<unsigned> u(3 * cap);  // mask, id, flags
        RTCRayNp np;
        float* a[9];
        for (int k = 0; k < 9; ++k) a[k] = f.data() + k * cap;
        np.org_x = a[0], np.org_y = a[1], np.org_z = a[2], np.tnear = a[3];
        np.dir_x = a[4], np.dir_y = a[5], np.dir_z = a[6], np.time = a[7], np.tfar = a[8];
        np.mask = u.data(), np.id = u.data() + cap, np.flags = u.data() + 2 * cap;
        std::fill(u.begin(), u.begin() + cap, 0xFFFFFFFFu);
        for (std::size_t i0 = b; i0 < e; i0 += per) {
          const std::size_t i1 = std::min(e, i0 + per);
          for (std::size_t i = i0; i < i1; ++i)
            for (std::uint32_t k = 0; k < n; ++k) {
              const std::size_t j = (i - i0) * n + k;
              const float* o = &r.origin[3 * i];
              const float* d = &r.direction[3 * (i * n + k)];
              a[0][j] = o[0], a[1][j] = o[1], a[2][j] = o[2], a[3][j] = 0.0f;
              a[4][j] = d[0], a[5][j] = d[1], a[6][j] = d[2], a[7][j] = 0.0f;
              a[8][j] = std::numeric_limits<float>::infinity();
            }
          rtcOccludedNp(scene, &ctx, &np, unsigned((i1 - i0) * n));
          for (std::size_t i = i0; i < i1; ++i) {
            std::uint32_t h = 0;
            for (std::uint32_t k = 0; k < n; ++k) h += a[8][(i - i0) * n + k] < 0.0f ? 1u : 0u;
            hits[i] = h;
          }
        }
        break;
      }
      case Form::Packet8:
        for (std::size_t i = b; i < e; ++i)
          hits[i] = packets<8, RTCRay8>(r, i, ctx, [&](int* valid, RTCIntersectContext& c, RTCRay8& p) {
            rtcOccluded8(valid, scene, &c, &p);
          });
        break;
      case Form::Packet16:
        for (std::size_t i = b; i < e; ++i)
          hits[i] = packets<16, RTCRay16>(r, i, ctx, [&](int* valid, RTCIntersectContext& c, RTCRay16& p) {
            rtcOccluded16(valid, scene, &c, &p);
          });
        break;
    }
  });
}

struct Row {
  std::string name;
  std::vector<double> cpu, wall;
  std::size_t differing = 0;  // vertices whose hit count differs from shadetool's
  std::uint64_t hits = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: bench_occlusion_loop MESH.ply [--samples N] [--runs R] [--threads T] [--flags LIST] [--forms LIST]\n");
    return 2;
  }
  std::uint32_t samples = 64;
  int runs = 7, threads = 1;
  std::size_t stride = 1;
  std::string other_forms;
  std::string flag_list = "robust+compact,none", form_list = "single,stream-v,stream-4k,packet8,packet16";
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--samples") samples = std::uint32_t(std::atoi(argv[i + 1]));
    else if (a == "--runs") runs = std::atoi(argv[i + 1]);
    else if (a == "--threads") threads = std::atoi(argv[i + 1]);
    else if (a == "--flags") flag_list = argv[i + 1];
    else if (a == "--forms") form_list = argv[i + 1];
    else if (a == "--other-forms") other_forms = argv[i + 1];
    else if (a == "--stride") stride = std::max<std::size_t>(1, std::size_t(std::atol(argv[i + 1])));
    else {
      std::fprintf(stderr, "bench_occlusion_loop: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  const Mesh mesh = read_mesh(argv[1]);
  const std::vector<double> normals = vertex_normals(mesh).normals;
  const VisibilityScene scene(mesh);
  const Rays rays = make_rays(scene, mesh, normals, samples, stride);
  // --stride: the points, their axes and ids for ambient_occlusion_at_points (every S-th vertex).
  std::vector<double> points, axes;
  std::vector<std::uint64_t> ids;
  for (std::size_t v = 0; stride > 1 && v < mesh.num_vertices(); v += stride) {
    for (int k = 0; k < 3; ++k) points.push_back(mesh.positions[3 * v + k]), axes.push_back(normals[3 * v + k]);
    ids.push_back(v);
  }
  const double total_rays = double(rays.vertex.size()) * samples;
  std::printf("mesh %s: %zu vertices, %zu triangles; %zu traced vertices (stride %zu) x N = %u = %.0f rays; %d thread(s), %d runs\n",
              argv[1], mesh.num_vertices(), mesh.num_faces(), rays.vertex.size(), stride, samples, total_rays, threads, runs);
  std::printf("shadetool's BVH: %.1f MB (robust+compact)\n", double(scene.stats().bvh_bytes) / 1e6);

  const std::vector<std::string> flag_names = split(flag_list), form_names = split(form_list),
                                 other_names = other_forms.empty() ? form_names : split(other_forms);
  const auto forms_of = [&](std::size_t s) -> const std::vector<std::string>& { return s == 0 ? form_names : other_names; };
  std::vector<std::unique_ptr<BareScene>> scenes;
  for (const std::string& f : flag_names) {
    scenes.push_back(std::make_unique<BareScene>(scene, mesh, parse_flags(f)));
    std::printf("bare BVH %s: %.1f MB after the build, %.1f MB at its peak (Embree's memory monitor)\n", f.c_str(),
                double(scenes.back()->bytes[0]) / 1e6, double(scenes.back()->bytes[1]) / 1e6);
  }

  AmbientOcclusionOptions options;
  options.samples = samples;
  std::vector<Row> rows;
  rows.push_back({stride == 1 ? "shadetool ambient_occlusion_per_vertex" : "shadetool ambient_occlusion_at_points", {}, {}, 0, 0});
  for (std::size_t s = 0; s < flag_names.size(); ++s)
    for (const std::string& fo : forms_of(s)) rows.push_back({fo + " / " + flag_names[s], {}, {}, 0, 0});

  std::vector<std::uint32_t> ours(rays.vertex.size()), hits(rays.vertex.size());
  for (int run = 0; run < runs; ++run) {
    std::size_t row = 0;
    {
      const double c0 = cpu_s(), w0 = wall_s();
      const AmbientOcclusion ao = stride == 1 ? ambient_occlusion_per_vertex(scene, mesh, normals, options)
                                              : ambient_occlusion_at_points(scene, points, axes, ids, options);
      rows[row].cpu.push_back(cpu_s() - c0);
      rows[row].wall.push_back(wall_s() - w0);
      rows[row].hits = ao.hits;
      if (stride > 1 && ao.skipped != 0) {
        std::fprintf(stderr, "bench_occlusion_loop: --stride: %zu points skipped: not the traced vertices\n", ao.skipped);
        return 1;
      }
      for (std::size_t i = 0; i < rays.vertex.size(); ++i)  // open = (N - hits)/N exactly: invert
        ours[i] = samples - std::uint32_t(std::lround(double(ao.open_fraction[stride == 1 ? rays.vertex[i] : i]) * samples));
      ++row;
    }
    for (std::size_t s = 0; s < flag_names.size(); ++s)
      for (const std::string& fo : forms_of(s)) {
        std::fill(hits.begin(), hits.end(), 0u);
        const double c0 = cpu_s(), w0 = wall_s();
        bare_run(scenes[s]->scene, rays, parse_form(fo), hits);
        Row& r = rows[row++];
        r.cpu.push_back(cpu_s() - c0);
        r.wall.push_back(wall_s() - w0);
        r.differing = 0;
        r.hits = 0;
        for (std::size_t i = 0; i < hits.size(); ++i) r.differing += hits[i] != ours[i], r.hits += hits[i];
        if (flag_names[s] == "robust+compact" && r.differing != 0) {
          std::fprintf(stderr, "bench_occlusion_loop: %s: %zu vertices' hits differ from shadetool's: not the same rays\n",
                       r.name.c_str(), r.differing);
          return 1;
        }
      }
    std::fprintf(stderr, "run %d done\n", run + 1);
  }

  char load[128] = "?";
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (!std::fgets(load, sizeof load, f)) load[0] = 0;
    std::fclose(f);
    load[std::strcspn(load, "\n")] = 0;
  }
  std::printf("load average after: %s\n\n", load);
  const double ours_cpu = median(rows[0].cpu);
  double fastest_same = 1e300, fastest_any = 1e300;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double c = median(rows[i].cpu);
    fastest_any = std::min(fastest_any, c);
    if (rows[i].name.find("/ robust+compact") != std::string::npos) fastest_same = std::min(fastest_same, c);
  }
  std::printf("| row | CPU s (median) | wall s | Mrays/s per thread | shadetool / row | hits | vertices differing |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const double c = median(r.cpu);
    std::printf("| %s | %.3f | %.3f | %.2f | %.3f | %llu | %zu |\n", r.name.c_str(), c, median(r.wall),
                total_rays / c / 1e6, ours_cpu / c, (unsigned long long)r.hits, r.differing);
  }
  std::printf("\nshadetool against the fastest bare row with its flags: %.3f; against the fastest bare row of any flags: %.3f\n",
              ours_cpu / fastest_same, ours_cpu / fastest_any);
  return 0;
}
