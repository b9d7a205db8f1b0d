// bench_repair: repair_mesh against reading the same mesh from binary PLY.
//
// Usage: bench_repair [--nu NU] [--nv NV] [--reps R] [--tmp DIR] [--threads N] [--stages 0|1]
//                     [--shuffle 0|1]
// (--stages 0: read and whole repair only, e.g. for a profiler; --shuffle 1: vertices and faces
// in random order, the worst case for memory locality)
// Mesh: torus with NU x NV quads split in two (default 1000 x 500 = 1,000,000 triangles,
// 500,000 vertices), 30% of its faces flipped at random (seed 1), written as binary little-endian
// PLY with float coordinates (what scanners and exporters write). Every time is the median of R
// repetitions (default 9) after one warm-up, in one process:
//   read     read_mesh(file.ply) (the file is in the page cache after the warm-up)
//   repair   repair_mesh on a fresh copy of the mesh as read (the copy is not timed): weld off,
//            normals computed (the PLY has none), so this is the whole `shadetool repair` step
// (these two alternate, a read then a repair in every repetition, so load changes hit both rows)
// plus each stage alone, on the same input. The target from the issue: repair < 3 x read.
// Memory: every large block is fresh in every repetition (M_MMAP_THRESHOLD = 1 MiB), as in a
// one-shot `shadetool repair` process; wall and process CPU time (all threads) are reported.
// Also checked (not timed): the repaired mesh has exactly the torus's original winding.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <malloc.h>
#include <memory>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/core/edge_adjacency.h>
#include <shadetool/info/edge_topology.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/repair/component_boundaries.h>
#include <shadetool/repair/consistent_winding.h>
#include <shadetool/repair/degenerate_faces.h>
#include <shadetool/repair/duplicate_faces.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/repair/fix_normals.h>
#include <shadetool/repair/outward_orientation.h>
#include <shadetool/repair/repair_mesh.h>
#include <shadetool/repair/reverse_faces.h>
#include <shadetool/repair/signed_volume.h>
#include "repair/repair_test_meshes.h"
#include "normals/parallel_control.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// CPU time of the whole process (all threads), in ms.
double cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

struct Timing { double wall = 0, cpu = 0; };

// Median wall time and median process CPU time of `reps` runs of fn (setup not timed).
Timing median_ms(int reps, const std::function<void()>& setup, const std::function<void()>& fn) {
  setup();
  fn();  // warm-up
  std::vector<double> wall, cpu;
  for (int r = 0; r < reps; ++r) {
    setup();
    const double c0 = cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    cpu.push_back(cpu_ms() - c0);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  return {wall[wall.size() / 2], cpu[cpu.size() / 2]};
}

// The same for two steps a and b run alternately, a then b in every repetition (each with its
// untimed setup), so that a change of load hits both rows alike: the ratio b / a is the figure.
std::pair<Timing, Timing> interleaved_median_ms(int reps, const std::function<void()>& setup_a, const std::function<void()>& a,
                                                const std::function<void()>& setup_b, const std::function<void()>& b) {
  setup_a();
  a();  // warm-up
  setup_b();
  b();
  std::vector<double> wall[2], cpu[2];
  for (int r = 0; r < reps; ++r) {
    for (int i = 0; i < 2; ++i) {
      (i == 0 ? setup_a : setup_b)();
      const double c0 = cpu_ms();
      const auto t0 = std::chrono::steady_clock::now();
      (i == 0 ? a : b)();
      wall[i].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
      cpu[i].push_back(cpu_ms() - c0);
    }
  }
  Timing t[2];
  for (int i = 0; i < 2; ++i) {
    std::sort(wall[i].begin(), wall[i].end());
    std::sort(cpu[i].begin(), cpu[i].end());
    t[i] = {wall[i][wall[i].size() / 2], cpu[i][cpu[i].size() / 2]};
  }
  return {t[0], t[1]};
}

}  // namespace

int main(int argc, char** argv) {
  int nu = 1000, nv = 500, reps = 9, threads = 0, stages = 1, shuffle = 0;
  std::string tmp = std::filesystem::temp_directory_path().string();
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--nu") nu = std::atoi(argv[i + 1]);
    else if (a == "--nv") nv = std::atoi(argv[i + 1]);
    else if (a == "--reps") reps = std::atoi(argv[i + 1]);
    else if (a == "--tmp") tmp = argv[i + 1];
    else if (a == "--threads") threads = std::atoi(argv[i + 1]);
    else if (a == "--stages") stages = std::atoi(argv[i + 1]);
    else if (a == "--shuffle") shuffle = std::atoi(argv[i + 1]);
    else { std::fprintf(stderr, "usage: bench_repair [--nu NU] [--nv NV] [--reps R] [--tmp DIR] [--threads N] [--stages 0|1] [--shuffle 0|1]\n"); return 2; }
  }

  // A CLI repairs one file per process: every large buffer, the reader's and ours, is fresh
  // memory the kernel must fault in. glibc would recycle freed blocks between repetitions (its
  // mmap threshold grows after the first free), so fix it at 1 MiB, as bench/io does: every large
  // block is a fresh mapping in every repetition.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  // --threads N caps TBB's threads (reading included); default: all cores.
  std::unique_ptr<tbb::global_control> cap;
  if (threads > 0) cap = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  std::printf("threads: %zu\n", tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));

  Mesh truth = testing::torus(nu, nv).mesh;
  truth.precision = ValuePrecision::Float;
  if (shuffle) {
    // Vertices and faces in random order: no locality for any pass to lean on.
    std::mt19937 rng(7);
    const std::size_t V = truth.num_vertices(), F = truth.num_faces();
    std::vector<std::uint32_t> new_id(V), face_order(F);
    for (std::size_t v = 0; v < V; ++v) new_id[v] = std::uint32_t(v);
    for (std::size_t f = 0; f < F; ++f) face_order[f] = std::uint32_t(f);
    std::shuffle(new_id.begin(), new_id.end(), rng);
    std::shuffle(face_order.begin(), face_order.end(), rng);
    Mesh shuffled;
    shuffled.precision = truth.precision;
    shuffled.positions.resize(truth.positions.size());
    for (std::size_t v = 0; v < V; ++v)
      for (int i = 0; i < 3; ++i) shuffled.positions[3 * new_id[v] + i] = truth.positions[3 * v + i];
    for (std::uint32_t f : face_order)
      shuffled.add_face({new_id[truth.corner_vertex[3 * f]], new_id[truth.corner_vertex[3 * f + 1]], new_id[truth.corner_vertex[3 * f + 2]]});
    truth = std::move(shuffled);
  }
  Mesh damaged = truth;
  flip_random_faces(damaged, 0.3, 1);
  const std::string path = (std::filesystem::path(tmp) / "bench_repair_torus.ply").string();
  WriteOptions ply;
  ply.format = Format::Ply;  // binary (the default)
  write_mesh(damaged, path, ply);
  const auto bytes = std::filesystem::file_size(path);
  std::printf("mesh: torus %d x %d%s: %zu triangles, %zu vertices, 30%% of faces flipped; binary PLY %.1f MB\n", nu, nv,
              shuffle ? " (vertices and faces shuffled)" : "",
              damaged.num_faces(), damaged.num_vertices(), double(bytes) / 1e6);

  Mesh as_read, work;
  as_read = read_mesh(path);
  // The mesh to repair: a copy of the mesh as read (not timed), its large arrays fresh and in huge
  // pages as read_mesh leaves them (a plain vector copy would put them in 4 KiB pages, which the
  // CLI never sees, and cost every pass TLB misses).
  auto copy_as_read = [&] {
    work = Mesh();
    work = as_read;
    auto rehome = [](auto& v) {
      std::remove_reference_t<decltype(v)> fresh;
      reserve_bulk(fresh, v.size());
      fresh.assign(v.begin(), v.end());
      v.swap(fresh);
    };
    rehome(work.positions);
    rehome(work.corner_vertex);
    rehome(work.face_start);
  };
  // Read and whole repair alternate repetition by repetition (the read into a mesh of its own, so
  // that the copy to repair is always of the same mesh).
  Mesh read_back;
  Timing read, repair;
  std::tie(read, repair) = interleaved_median_ms(reps, [&] { read_back = Mesh(); }, [&] { read_back = read_mesh(path); },
                                                 copy_as_read, [&] { repair_mesh(work); });

  // Check: the repaired mesh has the original winding, face for face (float positions round the
  // same way in both, and the winding does not depend on positions here).
  Mesh check = as_read;
  const RepairReport report = repair_mesh(check);
  const bool restored = check.corner_vertex == truth.corner_vertex;

  std::printf("\n| step | wall ms (median) | x read | CPU ms (median) | x read |\n|---|---:|---:|---:|---:|\n");
  auto row = [&](const char* name, Timing t) {
    std::printf("| %s | %.1f | %.2f | %.1f | %.2f |\n", name, t.wall, t.wall / read.wall, t.cpu, t.cpu / read.cpu);
  };
  auto summary = [&]() {
    std::printf("\nrepair / read, wall = %.2f (target < 3): %s;  CPU = %.2f\n", repair.wall / read.wall,
                repair.wall / read.wall < 3 ? "met" : "NOT met", repair.cpu / read.cpu);
    std::printf("faces flipped %zu of %zu; original winding restored exactly: %s\n", report.faces_flipped,
                check.num_faces(), restored ? "yes" : "NO");
    std::filesystem::remove(path);
    return restored ? 0 : 1;
  };
  // Control: a trivially parallel loop on 1 and 2 threads in this process (bench/normals'
  // parallel_control.h). Near 1x, the second core was busy and a 2-thread repair says little.
  volatile double control_sink = 0;
  const Timing control1 = median_ms(reps, [] {}, [&] {
    tbb::task_arena(1).execute([&] { control_sink = control_sink + parallel_sqrt_control(); });
  });
  const Timing control2 = median_ms(reps, [] {}, [&] { control_sink = control_sink + parallel_sqrt_control(); });
  std::printf("control (a trivially parallel sqrt loop): 1 thread %.2f ms, %zu threads %.2f ms: speed-up %.2fx\n",
              control1.wall, tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
              control2.wall, control1.wall / control2.wall);
  row("read binary PLY (reference)", read);
  row("**repair_mesh, whole**", repair);
  if (!stages) return summary();

  // Stages alone, on the mesh as read.
  EdgeAdjacencyOptions left_out;
  left_out.skip_unwound_faces = true;
  EdgeAdjacency adj;
  ConsistentWinding winding;
  ComponentBoundaries bounds;
  const Timing t_adjacency = median_ms(reps, [] {}, [&] { adj = edge_adjacency(as_read, left_out); });
  const Timing t_winding = median_ms(reps, [] {}, [&] { winding = consistent_winding(as_read, adj, left_out); });
  const Timing t_bounds = median_ms(reps, [] {}, [&] { bounds = component_boundaries(as_read, adj, winding); });
  ComponentVolumes volumes;
  const Timing t_volume = median_ms(reps, [] {}, [&] {
    DegenerateFaces degenerate;
    volumes = component_signed_volumes(as_read, winding, &degenerate);
  });
  const Timing t_outward = median_ms(reps, [] {}, [&] { outward_orientation(as_read, winding, bounds, volumes); });
  std::vector<std::uint8_t> flags(as_read.num_faces());
  for (std::size_t f = 0; f < flags.size(); ++f) flags[f] = winding.face_reverse[f];
  const Timing t_reverse = median_ms(reps, copy_as_read, [&] { reverse_faces(work, flags); });
  const Timing t_normals = median_ms(reps, copy_as_read, [&] { fix_normals(work); });
  const Timing t_vertex_normals = median_ms(reps, [] {}, [&] { vertex_normals(as_read); });

  const Timing t_info_topology = median_ms(reps, [] {}, [&] { info::edge_topology(as_read); });
  const Timing t_duplicates = median_ms(reps, [] {}, [&] { duplicate_faces(as_read, adj, winding); });

  // Floors: the least any orientation pass can cost here, on the same mesh and memory regime.
  const std::size_t C = as_read.num_corners(), F = as_read.num_faces();
  volatile std::uint64_t sink = 0;
  const Timing f_stream = median_ms(reps, [] {}, [&] {
    std::uint64_t sum = 0;
    for (std::size_t c = 0; c < C; ++c) sum += as_read.corner_vertex[c];
    sink = sink + sum;
  });
  const Timing f_gather = median_ms(reps, [] {}, [&] {
    double sum = 0;
    for (std::size_t c = 0; c < C; ++c) sum += as_read.positions[3 * std::size_t(as_read.corner_vertex[c])];
    sink = sink + std::uint64_t(sum);
  });
  const Timing f_fill = median_ms(reps, [] {}, [&] {
    std::vector<std::uint32_t> fresh(C);
    for (std::size_t c = 0; c < C; ++c) fresh[c] = std::uint32_t(c);
    sink = sink + fresh[C / 2];
  });
  const Timing f_fill_huge = median_ms(reps, [] {}, [&] {
    std::vector<std::uint32_t> fresh;
    reserve_bulk(fresh, C);  // huge pages, as the repair's large arrays
    fresh.resize(C);
    for (std::size_t c = 0; c < C; ++c) fresh[c] = std::uint32_t(c);
    sink = sink + fresh[C / 2];
  });
  const std::size_t V = as_read.num_vertices();
  const Timing f_counting_sort = median_ms(reps, [] {}, [&] {
    // The half-edges bucketed by lower vertex: counts, prefix sum, scatter of 8-byte keys; no
    // matching, no output. The least a flat-array edge adjacency can do.
    std::vector<std::uint32_t> pos;
    reserve_bulk(pos, V + 1);
    pos.assign(V + 1, 0);
    const std::uint32_t* cv = as_read.corner_vertex.data();
    for (std::size_t c = 0; c < C; c += 3) {
      const std::uint32_t a = cv[c], b = cv[c + 1], d = cv[c + 2];
      ++pos[std::min(a, b) + 1];
      ++pos[std::min(b, d) + 1];
      ++pos[std::min(d, a) + 1];
    }
    for (std::size_t v = 0; v < V; ++v) pos[v + 1] += pos[v];
    std::vector<std::uint64_t> slot;
    reserve_bulk(slot, C);
    slot.resize(C);
    for (std::size_t c = 0; c < C; c += 3) {
      const std::uint32_t a = cv[c], b = cv[c + 1], d = cv[c + 2];
      slot[pos[std::min(a, b)]++] = (std::uint64_t(std::max(a, b)) << 32) | c;
      slot[pos[std::min(b, d)]++] = (std::uint64_t(std::max(b, d)) << 32) | (c + 1);
      slot[pos[std::min(d, a)]++] = (std::uint64_t(std::max(d, a)) << 32) | (c + 2);
    }
    sink = sink + slot[C / 2];
  });
  const Timing f_faces = median_ms(reps, [] {}, [&] {
    std::vector<std::uint8_t> fresh(F, 1);
    sink = sink + fresh[F / 2];
  });

  row("  edge_adjacency", t_adjacency);
  row("  consistent_winding (union-find)", t_winding);
  row("  duplicate_faces (given the winding)", t_duplicates);
  row("  component_boundaries", t_bounds);
  row("  signed volumes + degenerate faces (one pass)", t_volume);
  row("  outward_orientation (given the volumes)", t_outward);
  row("  reverse_faces", t_reverse);
  row("  fix_normals (computes angle-weighted normals)", t_normals);
  row("    of which vertex_normals (lib/normals)", t_vertex_normals);
  row("info::edge_topology (`shadetool info`; the same pairing)", t_info_topology);
  row("floor: stream the 3M corner indices (12 MB)", f_stream);
  row("floor: gather one coordinate per corner (3M position reads)", f_gather);
  row("floor: fill a fresh 3M x uint32 array (one corner-sized output), 4 KiB pages", f_fill);
  row("floor: the same in huge pages (core/bulk_reserve.h)", f_fill_huge);
  row("floor: counting sort of the 3M half-edges by lower vertex (no matching)", f_counting_sort);
  row("floor: fill a fresh 1M x uint8 array (one face-sized flag array)", f_faces);
  return summary();
}
