// bench_visibility.cpp: ambient occlusion time against error on a concave mesh, and the limit set
// by Embree itself.
//
//   bench_visibility MESH.ply [--points K] [--runs R] [--full-n N] [--csv FILE] [--export FILE] [--whole-only]
//
// 1. Error against time: K vertices spread over the mesh (every V/K-th), open fraction for
//    N = 4 .. 1024 through ambient_occlusion_at_points (ids = vertex ids, so the same rays as the
//    per-vertex call), RMS difference from a 4096-sample reference with another seed (its own RMS
//    error is that of the N = 4096 row, about N^-3/4 below the N = 1024 row).
// 2. Anchor: a bare loop of rtcOccluded1 over the same rays (origins and directions computed
//    beforehand, outside the timing), on an Embree scene built with the same flags from the same
//    float buffers: the cost of the traversal alone. Both run on all threads with the same
//    tbb::parallel_for grain. The hit counts must agree (same rays), else the program fails.
// 3. The whole mesh per vertex at N = full-n, two ways round-robin: the steps written out (the
//    angle-weighted normals of the whole mesh, a BVH, ambient_occlusion_per_vertex) against
//    mesh_occlusion, the CLI's job (the same BVH and rays, but the normals made 4096 vertices at a
//    time just before their rays and the hits kept as counts: its memory, results.md). The open
//    fractions must be the same bits, else the program fails; the ratio is what the blocks cost.
//    Also the BVH's bytes against the mesh's arrays. --whole-only runs this part alone.
// Times are medians over R runs, the cases taken round-robin.
// 4. --export FILE: what the other programs' anchors need to meet the same mesh and points
//    (anchor_open3d.py, anchor_blender.py): little-endian, in this order: uint64 V, T, K; float32
//    V x 3 vertices in the BVH's frame (visibility_scene.h: centred, power-of-two scaled, the very
//    floats Embree holds); uint32 T x 3 triangles; uint64 K vertex ids of the points; float64 K x 3
//    their unit normals (angle-weighted vertex normals); float32 K reference open fractions
//    (4096 samples, unlimited distance).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <fstream>

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/visibility/ambient_occlusion.h>
#include <shadetool/visibility/ray_offset.h>
#include <shadetool/visibility/sample_sequence.h>
#include <shadetool/visibility/visibility_scene.h>

#include "../bench_timing.h"

using namespace shadetool;

namespace {

// The bare Embree scene: same float vertices and triangles as VisibilityScene builds.
struct BareScene {
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = nullptr;
  std::vector<float> vertices;
  std::vector<std::uint32_t> triangles;
  BareScene(const Mesh& m, const VisibilityScene& vs) {
    vertices.assign(3 * m.num_vertices() + 1, 0.0f);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      const Vec3f l = vs.to_local(m.position(v));
      std::memcpy(&vertices[3 * v], &l, 12);
    }
    triangles = m.corner_vertex;  // the bench mesh is all triangles, none degenerate
    scene = rtcNewScene(device);
    rtcSetSceneFlags(scene, RTCSceneFlags(RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT));
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices.data(), 0, 12, m.num_vertices());
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, triangles.data(), 0, 12, m.num_faces());
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

// The rays ambient_occlusion_at_points casts for point i (same salt and seed rule as
// lib/shadetool/visibility/ambient_occlusion.cpp: vertex salt 0, options.seed 0).
void make_rays(const Vec3f& p_local, const Vec3d& n, std::uint64_t id, std::uint32_t samples, std::vector<RTCRay>& rays) {
  const std::uint32_t seed = visibility::point_seed(id, visibility::hash_combine(0, 0));
  Vec3d t, b;
  visibility::orthonormal_basis(n, t, b);
  const Vec3f o = visibility::offset_ray_origin(p_local, Vec3f(n));
  for (std::uint32_t k = 0; k < samples; ++k) {
    const visibility::UnitSquarePoint s = visibility::scrambled_sobol_2d(k, seed);
    const Vec3d w = visibility::cosine_hemisphere(s.u, s.v);
    const Vec3f d(t * w.x + b * w.y + n * w.z);
    RTCRay r;
    r.org_x = o.x, r.org_y = o.y, r.org_z = o.z, r.tnear = 0;
    r.dir_x = d.x, r.dir_y = d.y, r.dir_z = d.z, r.time = 0;
    r.tfar = std::numeric_limits<float>::infinity();
    r.mask = 0xFFFFFFFFu, r.id = 0, r.flags = 0;
    rays.push_back(r);
  }
}

// Part 3: the whole mesh per vertex, the steps written out against mesh_occlusion, round-robin.
int whole_mesh(const Mesh& mesh, std::uint32_t samples, int runs) {
  if (mesh.has_vertex_normals()) std::printf("(the mesh's own normals: mesh_occlusion computes none)\n");
  AmbientOcclusionOptions full;
  full.samples = samples;
  std::vector<double> steps_ms, job_ms;
  AmbientOcclusion steps;
  MeshOcclusion job;
  for (int r = 0; r < runs; ++r) {
    double t0 = now_ms();
    {
      const std::vector<double> normals = mesh.has_vertex_normals() ? mesh.vertex_normals : vertex_normals(mesh).normals;
      const VisibilityScene scene(mesh);
      steps = ambient_occlusion_per_vertex(scene, mesh, normals, full);
    }
    steps_ms.push_back(now_ms() - t0);
    t0 = now_ms();
    job = mesh_occlusion(mesh, false, full, "bench");
    job_ms.push_back(now_ms() - t0);
  }
  if (job.ao.open_fraction != steps.open_fraction || job.ao.hits != steps.hits) {
    std::fprintf(stderr, "bench_visibility: mesh_occlusion and the written-out steps differ\n");
    return 1;
  }
  double mean = 0;
  for (float v : steps.open_fraction) mean += v;
  const double a = median(steps_ms), b = median(job_ms);
  std::printf("\nwhole mesh per vertex, N = %u (normals, BVH, rays; medians of %d runs): written-out steps %.0f ms "
              "(%.2f Mrays/s), mesh_occlusion %.0f ms: ratio %.3f; the same bits; mean open fraction %.4f\n",
              samples, runs, a, double(steps.rays) / (a * 1000), b, b / a, mean / double(steps.open_fraction.size()));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_visibility MESH.ply [--points K] [--runs R] [--full-n N] [--csv FILE] [--export FILE] [--whole-only]\n");
    return 2;
  }
  std::size_t points = 4000;
  int runs = 5;
  std::uint32_t full_n = 64;
  std::string csv, export_path;
  bool whole_only = false;
  for (int i = 2; i < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--whole-only") {
      whole_only = true;
      --i;  // a flag without a value
      continue;
    }
    if (i + 1 >= argc) break;
    if (a == "--points") points = std::size_t(std::atol(argv[i + 1]));
    else if (a == "--runs") runs = std::atoi(argv[i + 1]);
    else if (a == "--full-n") full_n = std::uint32_t(std::atoi(argv[i + 1]));
    else if (a == "--csv") csv = argv[i + 1];
    else if (a == "--export") export_path = argv[i + 1];
  }
  const Mesh mesh = read_mesh(argv[1]);
  const double arrays = double(mesh.positions.size() * 8 + mesh.corner_vertex.size() * 4 + mesh.face_start.size() * 4);
  const std::vector<double> normals = vertex_normals(mesh).normals;
  double t0 = now_ms();
  const VisibilityScene scene(mesh);
  const double build_ms = now_ms() - t0;
  const VisibilitySceneStats& st = scene.stats();
  std::printf("mesh %s: %zu vertices, %zu triangles; mesh arrays %.1f MB\n", argv[1], mesh.num_vertices(), mesh.num_faces(), arrays / 1e6);
  std::printf("BVH: %.1f MB (Embree) + %.1f MB (float buffers) = %.2fx the mesh arrays; build %.0f ms\n\n",
              st.bvh_bytes / 1e6, st.buffer_bytes / 1e6, (st.bvh_bytes + st.buffer_bytes) / arrays, build_ms);
  if (whole_only) return whole_mesh(mesh, full_n, runs);

  // The K points: every (V/K)-th vertex.
  const std::size_t stride = std::max<std::size_t>(1, mesh.num_vertices() / points);
  std::vector<double> P, N;
  std::vector<std::uint64_t> ids;
  for (std::size_t v = 0; v < mesh.num_vertices() && ids.size() < points; v += stride) {
    for (int k = 0; k < 3; ++k) P.push_back(mesh.positions[3 * v + k]), N.push_back(normals[3 * v + k]);
    ids.push_back(v);
  }
  const std::size_t K = ids.size();
  AmbientOcclusionOptions ref_options;
  ref_options.samples = 4096;
  ref_options.seed = 1;
  t0 = now_ms();
  const AmbientOcclusion reference = ambient_occlusion_at_points(scene, P, N, ids, ref_options);
  std::printf("reference: %zu points x 4096 samples (seed 1) in %.0f ms\n\n", K, now_ms() - t0);

  BareScene bare(mesh, scene);
  if (!export_path.empty()) {
    std::ofstream f(export_path, std::ios::binary);
    const std::uint64_t counts[3] = {mesh.num_vertices(), bare.triangles.size() / 3, K};
    f.write(reinterpret_cast<const char*>(counts), sizeof counts);
    f.write(reinterpret_cast<const char*>(bare.vertices.data()), std::streamsize(12 * mesh.num_vertices()));
    f.write(reinterpret_cast<const char*>(bare.triangles.data()), std::streamsize(4 * bare.triangles.size()));
    f.write(reinterpret_cast<const char*>(ids.data()), std::streamsize(8 * K));
    std::vector<double> unit(3 * K);
    for (std::size_t i = 0; i < K; ++i) set3(unit, i, normalized_or(get3(N, i), Vec3d{0, 0, 1}));
    f.write(reinterpret_cast<const char*>(unit.data()), std::streamsize(8 * unit.size()));
    f.write(reinterpret_cast<const char*>(reference.open_fraction.data()), std::streamsize(4 * K));
    if (!f) {
      std::fprintf(stderr, "bench_visibility: cannot write %s\n", export_path.c_str());
      return 1;
    }
  }
  FILE* out = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
  if (out) std::fprintf(out, "samples,rms_error,shadetool_ms,embree_ms,ratio,us_per_vertex,mrays_per_s\n");
  std::printf("| N | RMS error | shadetool ms | bare rtcOccluded1 ms | ratio | us / vertex | Mrays/s |\n|---|---|---|---|---|---|---|\n");
  for (std::uint32_t n = 4; n <= 1024; n *= 2) {
    AmbientOcclusionOptions o;
    o.samples = n;
    std::vector<RTCRay> rays;
    rays.reserve(K * n);
    for (std::size_t i = 0; i < K; ++i)
      make_rays(scene.to_local(get3(P, i)), normalized_or(get3(N, i), Vec3d{0, 0, 1}), ids[i], n, rays);
    std::vector<double> ours, theirs;
    AmbientOcclusion ao;
    std::uint64_t bare_hits = 0;
    for (int r = 0; r < runs; ++r) {
      t0 = now_ms();
      ao = ambient_occlusion_at_points(scene, P, N, ids, o);
      ours.push_back(now_ms() - t0);
      std::vector<RTCRay> work = rays;  // rtcOccluded1 writes tfar: a fresh copy per run, untimed
      std::vector<std::uint8_t> hit(work.size(), 0);
      t0 = now_ms();
      const std::size_t grain = std::max<std::size_t>(1, 2048 / n);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, K, grain), [&](const tbb::blocked_range<std::size_t>& br) {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        for (std::size_t i = br.begin(); i < br.end(); ++i)
          for (std::uint32_t k = 0; k < n; ++k) {
            rtcOccluded1(bare.scene, &ctx, &work[i * n + k]);
            hit[i * n + k] = work[i * n + k].tfar < 0;
          }
      });
      theirs.push_back(now_ms() - t0);
      bare_hits = 0;
      for (auto h : hit) bare_hits += h;
    }
    if (bare_hits != ao.hits) {
      std::fprintf(stderr, "bench_visibility: N %u: bare Embree %llu hits, shadetool %llu: not the same rays\n", n,
                   (unsigned long long)bare_hits, (unsigned long long)ao.hits);
      return 1;
    }
    double se = 0;
    for (std::size_t i = 0; i < K; ++i) se += std::pow(double(ao.open_fraction[i]) - reference.open_fraction[i], 2);
    const double rms = std::sqrt(se / double(K)), ms = median(ours), ems = median(theirs);
    const double us_vertex = 1000 * ms / double(K), mrays = double(K) * n / (ms * 1000);
    std::printf("| %u | %.5f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", n, rms, ms, ems, ms / ems, us_vertex, mrays);
    if (out) std::fprintf(out, "%u,%.6g,%.4f,%.4f,%.4f,%.4f,%.4f\n", n, rms, ms, ems, ms / ems, us_vertex, mrays);
  }
  if (out) std::fclose(out);
  return whole_mesh(mesh, full_n, runs);
}
