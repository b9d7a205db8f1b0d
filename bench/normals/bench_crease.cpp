// bench_crease: crease normals (corner_normals, angle weighting, crease 30 degrees) against
// angle-weighted vertex normals on the same mesh, one thread (issue 31 goal 3: at most 2x).
//
// Usage: bench_crease [--reps R] [--faces N] [--file MESH]... [--no-reference] [--no-floor] [--no-paths] [--round4]
// Meshes: the irregular UV sphere of bench_normals (about N triangles, default 1M; no edge above
// 30 degrees, so every group is a whole vertex fan), a faceted icosahedron (its 20 flat faces
// subdivided 4^7 times each: 1.3M triangles, real 41.8-degree creases along the 30 edges and
// exactly flat fans elsewhere), and any --file (e.g. CAD models of the corpus).
// Rows per mesh: vertex_normals(mesh, Angle) (fresh call), corner_normals(mesh, 30 deg, Angle),
// each of its two paths forced (normals/engine/crease_paths.h: the general path; the one-thread
// path without its probe, triangle meshes only; --no-paths drops them; their output is checked
// against corner_normals' bit for bit),
// and the frozen copy of the crease path before issue 31 (tests/support/corner_normals_reference.h;
// --no-reference drops it); then (--no-floor drops them) three rows whose sum is the floor of a
// crease path built like the general path: face_normals (the crease test needs them), the vertex
// -> corner adjacency alone (count + fill of 4-byte corner ids, the cheapest vertex-major
// gathering of the fans), and corner_group_normals given corner_normals' own groups (the weighted
// sums and normalisation alone, the same kernel as vertex_normals); and on triangle meshes the
// sixth round's rows (crease_new_shape.h, hard vertices counted, not computed): the floor of any
// exact path with today's output, (i) vertex_normals + writing corner_index, (ii) (i) + every
// corner's unit face normal summed into its vertex's cone evidence (SmoothCone) in the same pass,
// no ring test, (iii) (ii) + 12 (next, prev) pairs of 16-bit offsets per vertex and the ring test
// (layout C; the same with the ring test taken as passed: its cost; and with other forms of the
// ring test: the walk in a register, one walk of dependent searches, 8 vertices at once in SSE2
// lanes, 16 in AVX2 lanes where the CPU has AVX2); and the library's one-thread path up to its hard vertices in its own 128-byte slots
// (layout L), each layout with fresh scratch per call (as the library allocates), with the
// caller's scratch reused (no page faults after the first call), pass 1 alone, and (AVX2) its ring
// test on 8 vertices at once. --round4 adds
// the fourth round's rows of the same file (variants A and B). Lines after the rows say how many
// vertices each of (ii), C and L left hard, check their easy vertices' normals against
// corner_normals bit for bit, check the vectorised ring tests' verdicts against the scalar ones at
// every vertex, and count the vertices with a neighbour outside 16-bit offsets.
// Repetitions interleaved round-robin
// (rep 1 of every row, then rep 2, ...) after one warm-up, inside one TBB arena of 1 thread; medians of wall and process CPU time.
// The new and old crease outputs are compared bit for bit once per mesh (a mismatch is reported
// and the exit code is 1).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/normals/corner_normals.h>
#include <shadetool/normals/engine/crease_paths.h>
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include "load_average.h"
#include "support/analytic_meshes.h"
#include "support/corner_normals_reference.h"
#include "crease_new_shape.h"

using namespace shadetool;
using namespace shadetool::testing;

namespace {

// The icosahedron with each face cut into 4^levels coplanar triangles (midpoints not projected).
Mesh faceted_icosahedron(int levels) {
  Mesh ico = icosphere(0).mesh;
  std::vector<Vec3d> P;
  for (std::size_t v = 0; v < ico.num_vertices(); ++v) P.push_back(ico.position(v));
  std::vector<std::uint32_t> F(ico.corner_vertex.begin(), ico.corner_vertex.end());
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto k = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(k);
      if (it != mid.end()) return it->second;
      P.push_back((P[a] + P[b]) * 0.5);
      return mid[k] = std::uint32_t(P.size() - 1);
    };
    std::vector<std::uint32_t> G;
    G.reserve(4 * F.size());
    for (std::size_t f = 0; f < F.size(); f += 3) {
      const std::uint32_t a = F[f], b = F[f + 1], c = F[f + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      G.insert(G.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    F.swap(G);
  }
  Mesh m;
  for (const Vec3d& p : P) m.add_vertex(p);
  for (std::size_t f = 0; f < F.size(); f += 3) m.add_face({F[f], F[f + 1], F[f + 2]});
  m.precision = ValuePrecision::Double;
  return m;
}

bool same_bits(const CornerNormals& a, const CornerNormals& b) {
  return a.corner_index == b.corner_index && a.normals.size() == b.normals.size() &&
         std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(double)) == 0 &&
         a.fallback_corners == b.fallback_corners && a.degenerate_faces == b.degenerate_faces;
}

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t faces = 1000000;
  int reps = 15;
  bool reference = true, floor = true, paths = true, round4 = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--faces") && i + 1 < argc) faces = std::stoul(argv[++i]);
    else if (!std::strcmp(argv[i], "--file") && i + 1 < argc) files.push_back(argv[++i]);
    else if (!std::strcmp(argv[i], "--no-reference")) reference = false;
    else if (!std::strcmp(argv[i], "--no-floor")) floor = false;
    else if (!std::strcmp(argv[i], "--no-paths")) paths = false;
    else if (!std::strcmp(argv[i], "--round4")) round4 = true;
    else {
      std::fprintf(stderr, "usage: bench_crease [--reps R] [--faces N] [--file MESH]... [--no-reference] [--no-floor] [--no-paths] [--round4]\n");
      return 2;
    }
  }
  std::vector<std::pair<std::string, Mesh>> meshes;
  {
    const int nv = std::max(4, int(std::lround(std::sqrt(double(faces) / 4.0))));
    meshes.emplace_back("irregular UV sphere", irregular(uv_sphere(2 * nv, nv, 0.15, 11), 13).mesh);
    int levels = 1;
    while (20.0 * std::pow(4.0, levels + 1) <= 1.5 * double(faces)) ++levels;
    meshes.emplace_back("faceted icosahedron", faceted_icosahedron(levels));
  }
  for (const std::string& path : files) {
    const std::size_t slash = path.find_last_of('/');
    meshes.emplace_back(slash == std::string::npos ? path : path.substr(slash + 1), read_mesh(path));
  }
  const double crease = 30.0 * kPi / 180.0;
  const std::string load_start = load_average();
  int status = 0;
  tbb::task_arena arena(1);

  std::printf("bench_crease: 1 thread, median of %d interleaved runs (after 1 warm-up); crease 30 degrees, angle weighting, double\n",
              reps);
  std::printf("load average at start: %s\n\n", load_start.c_str());
  std::printf("| mesh | triangles | row | median ms | median CPU ms | CPU / vertex_normals |\n|---|---:|---|---:|---:|---:|\n");
  for (auto& [name, mesh] : meshes) {
    VertexNormals vn;
    CornerNormals cn, old;
    struct Row { const char* name; std::function<void()> run; std::vector<double> wall, cpu; };
    std::vector<Row> rows;
    rows.push_back({"vertex_normals angle", [&] { vn = vertex_normals(mesh, Weighting::Angle); }, {}, {}});
    rows.push_back({"corner_normals angle, crease 30", [&] { cn = corner_normals(mesh, crease, Weighting::Angle); }, {}, {}});
    CornerNormals general, one_thread;
    if (paths) {
      rows.push_back({"corner_normals, general path", [&] {
                        general = normals_detail::corner_normals_by(mesh, crease, Weighting::Angle, Precision::Double,
                                                                    normals_detail::CreasePath::General);
                      }, {}, {}});
      if (mesh.all_triangles())
        rows.push_back({"corner_normals, one-thread path (no probe)", [&] {
                          one_thread = normals_detail::corner_normals_by(mesh, crease, Weighting::Angle, Precision::Double,
                                                                         normals_detail::CreasePath::OneThread);
                        }, {}, {}});
    }
    if (reference)
      rows.push_back({"crease path before issue 31 (frozen copy)", [&] {
                        old = reference_crease::corner_normals_reference(MeshView(mesh), crease, Weighting::Angle);
                      }, {}, {}});
    std::vector<double> fn;
    std::vector<std::uint32_t> offset;
    BulkVector<std::uint32_t> corners;
    GroupNormals gn;
    if (floor) {
      const CornerNormals own = corner_normals(mesh, crease, Weighting::Angle);
      const std::vector<std::uint32_t> groups = own.corner_index;
      const std::size_t num_groups = own.normals.size() / 3;
      rows.push_back({"floor: face_normals", [&] { fn = face_normals(mesh); }, {}, {}});
      rows.push_back({"floor: vertex -> corner adjacency (count, fill)", [&, V = mesh.num_vertices(), C = mesh.num_corners()] {
                        const std::uint32_t* cv = mesh.corner_vertex.data();
                        offset.assign(V + 1, 0);
                        for (std::size_t c = 0; c < C; ++c) ++offset[cv[c] + 1];
                        for (std::size_t v = 0; v < V; ++v) offset[v + 1] += offset[v];
                        BulkVector<std::uint32_t> next(C), fill(offset.begin(), offset.end() - 1);
                        for (std::size_t c = 0; c < C; ++c) next[fill[cv[c]]++] = std::uint32_t(c);
                        corners.swap(next);
                      }, {}, {}});
      rows.push_back({"floor: corner_group_normals, the same groups", [&, groups, num_groups] {
                        gn = corner_group_normals(mesh, groups, num_groups, Weighting::Angle);
                      }, {}, {}});
    }
    BulkVector<crease_new_shape::Slot> slots;
    BulkVector<crease_new_shape::SlotB> slots_b;
    crease_new_shape::Result shape_b;
    std::vector<double> slot_sums;
    crease_new_shape::Result shape;
    crease_new_shape::Round6Scratch scratch6;
    crease_new_shape::Result floor_i, floor_ii, layout_l, layout_c, layout_c_packed, layout_c_walk, layout_c_x8, layout_c_x16, layout_l_x8;
    if (floor && mesh.all_triangles()) {
      rows.push_back({"floor (i): vertex_normals + corner_index", [&, C = mesh.num_corners()] {
                        floor_i.normals = vertex_normals(mesh, Weighting::Angle).normals;
                        BulkVector<std::uint32_t> ci(C);
                        const std::uint32_t* cv = mesh.corner_vertex.data();
                        for (std::size_t c = 0; c < C; ++c) ci[c] = cv[c];
                        floor_i.corner_index.assign(ci.begin(), ci.end());
                      }, {}, {}});
      rows.push_back({"floor (ii): (i) + cone evidence per corner, no ring test", [&] {
                        floor_ii = crease_new_shape::run_floor_cone(mesh, crease);
                      }, {}, {}});
      rows.push_back({"floor (iii) = layout C: (ii) + 12 pairs of 16-bit offsets, ring test (hard left out)", [&] {
                        layout_c = crease_new_shape::run_layout_c(mesh, crease, 2, true, scratch6);
                      }, {}, {}});
      rows.push_back({"layout C, scratch reused", [&] {
                        crease_new_shape::run_layout_c(mesh, crease, 2, false, scratch6);
                      }, {}, {}});
      rows.push_back({"layout C, ring test: fixed 8-corner search, walk in a register", [&] {
                        layout_c_packed = crease_new_shape::run_layout_c(mesh, crease, 2, true, scratch6, 1);
                      }, {}, {}});
      rows.push_back({"layout C, ring test as one walk of d searches", [&] {
                        layout_c_walk = crease_new_shape::run_layout_c(mesh, crease, 2, true, scratch6, 2);
                      }, {}, {}});
      rows.push_back({"layout C, ring test of 8 vertices at once (SSE2 lanes)", [&] {
                        layout_c_x8 = crease_new_shape::run_layout_c(mesh, crease, 2, true, scratch6, 3);
                      }, {}, {}});
      if (__builtin_cpu_supports("avx2"))
        rows.push_back({"layout C, ring test of 16 vertices at once (AVX2 lanes)", [&] {
                          layout_c_x16 = crease_new_shape::run_layout_c(mesh, crease, 2, true, scratch6, 4);
                        }, {}, {}});
      rows.push_back({"layout C, ring test taken as passed (its cost)", [&] {
                        crease_new_shape::run_layout_c(mesh, crease, 3, true, scratch6);
                      }, {}, {}});
      rows.push_back({"layout C, pass 1 only", [&] {
                        crease_new_shape::run_layout_c(mesh, crease, 1, true, scratch6);
                      }, {}, {}});
      rows.push_back({"layout L (library's 128 B slot), hard left out", [&] {
                        layout_l = crease_new_shape::run_layout_l(mesh, crease, 2, true, scratch6);
                      }, {}, {}});
      if (__builtin_cpu_supports("avx2"))
        rows.push_back({"layout L, ring test of 8 vertices at once (AVX2 lanes)", [&] {
                          layout_l_x8 = crease_new_shape::run_layout_l(mesh, crease, 2, true, scratch6, 4);
                        }, {}, {}});
      rows.push_back({"layout L, scratch reused", [&] {
                        crease_new_shape::run_layout_l(mesh, crease, 2, false, scratch6);
                      }, {}, {}});
      rows.push_back({"layout L, pass 1 only", [&] {
                        crease_new_shape::run_layout_l(mesh, crease, 1, true, scratch6);
                      }, {}, {}});
    }
    if (floor && round4 && mesh.all_triangles()) {
      rows.push_back({"new shape: pass 1, sums only", [&] {
                        crease_new_shape::run<0>(mesh, crease, 1, slots, slot_sums);
                      }, {}, {}});
      rows.push_back({"new shape: pass 1, sums and cone test", [&] {
                        crease_new_shape::run<1>(mesh, crease, 1, slots, slot_sums);
                      }, {}, {}});
      rows.push_back({"new shape: pass 1 (sums, cone, 6 pair slots)", [&] {
                        shape = crease_new_shape::run(mesh, crease, 1, slots, slot_sums);
                      }, {}, {}});
      rows.push_back({"new shape: passes 1-3 (hard vertices left out)", [&] {
                        shape = crease_new_shape::run(mesh, crease, 3, slots, slot_sums);
                      }, {}, {}});
      rows.push_back({"new shape B: pass 1 (S, U, 9 pairs in 128 B)", [&] {
                        crease_new_shape::run_b<1>(mesh, crease, slots_b);
                      }, {}, {}});
      rows.push_back({"new shape B: passes 1-3 (hard vertices left out)", [&] {
                        shape_b = crease_new_shape::run_b<3>(mesh, crease, slots_b);
                      }, {}, {}});
      rows.push_back({"new shape B: passes 1-3 with the ring test skipped", [&] {
                        crease_new_shape::run_b<4>(mesh, crease, slots_b);
                      }, {}, {}});
    }
    arena.execute([&] {
      for (int rep = -1; rep < reps; ++rep)
        for (Row& r : rows) {
          const double c0 = cpu_now();
          const auto t0 = std::chrono::steady_clock::now();
          r.run();
          const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          if (rep >= 0) {
            r.wall.push_back(ms);
            r.cpu.push_back(cpu_now() - c0);
          }
        }
    });
    auto median = [](std::vector<double> x) {
      std::sort(x.begin(), x.end());
      return x[x.size() / 2];
    };
    const double base = median(rows[0].cpu);
    for (Row& r : rows)
      std::printf("| %s | %zu | %s | %.2f | %.2f | %.2fx |\n", name.c_str(), mesh.num_faces(), r.name, median(r.wall), median(r.cpu),
                  median(r.cpu) / base);
    const std::pair<const char*, const crease_new_shape::Result*> shapes[] = {
        {"new shape A", &shape}, {"new shape B", &shape_b}, {"floor (ii)", &floor_ii}, {"layout C", &layout_c},
        {"layout C, register walk", &layout_c_packed}, {"layout C, one walk", &layout_c_walk},
        {"layout C, 8 at once", &layout_c_x8}, {"layout C, 16 at once", &layout_c_x16}, {"layout L", &layout_l},
        {"layout L, 8 at once", &layout_l_x8}};
    for (const auto& [label, sh] : shapes) {
      if (!sh->used) continue;
      const crease_new_shape::Result& shape = *sh;
      std::size_t differ = 0, easy = 0;
      for (std::size_t c = 0; c < mesh.num_corners(); ++c) {
        const std::uint32_t r = shape.corner_index[c];
        if (r == ~0u) continue;
        ++easy;
        differ += std::memcmp(&shape.normals[3 * std::size_t(r)], &cn.normals[3 * std::size_t(cn.corner_index[c])], 24) != 0;
      }
      std::printf("| %s | | %s: %zu of %zu vertices hard (%.1f%%); %zu easy corners, %zu differ from corner_normals | | | |\n",
                  name.c_str(), label, shape.hard, shape.used, 100.0 * double(shape.hard) / double(shape.used), easy, differ);
      if (differ) status = 1;
    }
    if (floor && mesh.all_triangles()) {  // the 8-lane ring test against the scalar one, every vertex (the reused scratch's slots)
      const auto& slots = scratch6.compact;
      std::size_t differ = 0, rings = 0;
      for (std::size_t b = 0; b + 8 <= mesh.num_vertices(); b += 8) {
        const std::uint32_t m = crease_new_shape::compact_rings8(&slots[b]);
        for (std::size_t k = 0; k < 8; ++k) {
          const crease_new_shape::CompactSlot& sl = slots[b + k];
          const bool scalar = sl.d >= 1 && sl.d <= crease_new_shape::kCompactPairs && crease_new_shape::one_compact_ring(sl);
          const bool lanes = sl.d >= 1 && ((m >> k) & 1u);
          differ += scalar != lanes;
          rings += scalar;
        }
      }
      std::size_t differ16 = 0;
      if (__builtin_cpu_supports("avx2"))
        for (std::size_t b = 0; b + 16 <= mesh.num_vertices(); b += 16) {
          const std::uint32_t m = crease_new_shape::compact_rings16(&slots[b]);
          for (std::size_t k = 0; k < 16; ++k) {
            const crease_new_shape::CompactSlot& sl = slots[b + k];
            const bool scalar = sl.d >= 1 && sl.d <= crease_new_shape::kCompactPairs && crease_new_shape::one_compact_ring(sl);
            differ16 += scalar != (sl.d >= 1 && ((m >> k) & 1u));
          }
        }
      std::printf("| %s | | layout C: the 8-lane ring test differs from the scalar one at %zu vertices, the 16-lane at %zu (%zu rings) | | | |\n",
                  name.c_str(), differ, differ16, rings);
      differ += differ16;
      std::size_t differ_l = 0, rings_l = 0;  // the library's slots (the reused scratch's) against slot_rings8
      if (__builtin_cpu_supports("avx2"))
        for (std::uint32_t b = 0; b + 8 <= mesh.num_vertices(); b += 8) {
          const std::uint32_t m = crease_new_shape::slot_rings8(b, &scratch6.slots[b]);
          for (std::uint32_t k = 0; k < 8; ++k) {
            const auto& sl = scratch6.slots[b + k];
            const bool scalar = sl.d >= 1 && sl.d <= normals_detail::kSlotPairs && normals_detail::one_smooth_ring(b + k, sl);
            differ_l += scalar != (sl.d >= 1 && ((m >> k) & 1u));
            rings_l += scalar;
          }
        }
      std::printf("| %s | | layout L: the 8-lane ring test differs from one_smooth_ring at %zu vertices (%zu rings) | | | |\n",
                  name.c_str(), differ_l, rings_l);
      differ += differ_l;
      if (differ) status = 1;
    }
    if (floor && mesh.all_triangles()) {  // why layout C leaves vertices hard: 16-bit offsets
      std::vector<std::uint8_t> wide(mesh.num_vertices(), 0);
      const std::uint32_t* cv = mesh.corner_vertex.data();
      for (std::size_t c = 0; c < mesh.num_corners(); ++c) {
        const std::uint32_t v = cv[c], w = cv[c % 3 == 2 ? c - 2 : c + 1];
        const bool far = (w - v + 32768u) >= 65536u;
        wide[v] |= far;
        wide[w] |= far;
      }
      std::size_t n = 0;
      for (std::uint8_t x : wide) n += x;
      std::printf("| %s | | layout C: %zu of %zu vertices have a neighbour more than 32767 ids away (%.1f%%) | | | |\n", name.c_str(), n,
                  mesh.num_vertices(), 100.0 * double(n) / double(mesh.num_vertices()));
    }
    if (paths && (!same_bits(cn, general) || (mesh.all_triangles() && !same_bits(cn, one_thread)))) {
      std::printf("| %s | | MISMATCH: corner_normals' two paths differ | | | |\n", name.c_str());
      status = 1;
    }
    if (reference && !same_bits(cn, old)) {
      std::printf("| %s | | MISMATCH: corner_normals differs from the frozen copy | | | |\n", name.c_str());
      status = 1;
    }
  }
  std::printf("\nload average at end: %s\n", load_average().c_str());
  return status;
}
