// generate.cpp: shadetool_bench_generate, writes the benchmark's analytic meshes to disk.
//
//   shadetool_bench_generate --out DIR [--surface S]... [--size Z]... [--regular] [--irregular]
//                            [--format ply|obj]... [--double] [--degenerate]
//
// S: sphere icosphere torus ellipsoid (default all); Z: 10k 1M 4M (default all); default both
// regular and irregular; default both formats. Writes DIR/NAME.ply (binary), DIR/NAME.obj and
// DIR/NAME.normals.f64 (exact normals, #V by 3 little-endian doubles); NAME as bench_meshes.h.
// --double writes double positions (float by default, as most real files are). --degenerate adds
// sphere_10k_degenerate. Prints one line per mesh: name, vertices, triangles, seconds.
// --self-check (alone): checks that random_edge_flips_sorted makes exactly the flips of
// tests/support's random_edge_flips on the four 10k irregular surfaces; exit 1 if not.
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "bench_meshes.h"
#include "write_bench_files.h"

using namespace shadetool::bench;

namespace {

int self_check() {
  using namespace shadetool::testing;
  int failures = 0;
  const char* names[] = {"sphere", "torus", "icosphere", "ellipsoid"};
  for (int k = 0; k < 4; ++k) {
    const AnalyticMesh base = k == 0 ? uv_sphere(100, 50, 0.3, 2) : k == 1 ? torus(100, 50, 1, 0.4, 0.3, 4)
                            : k == 2 ? icosphere(5, 0.3, 6) : uv_ellipsoid(100, 50, 1.5, 1, 0.5, 0.3, 3);
    AnalyticMesh by_map = base, by_sort = base;
    random_edge_flips(by_map, 0.3, 7);
    random_edge_flips_sorted(by_sort, 0.3, 7);
    std::size_t changed = 0;
    for (std::size_t c = 0; c < base.mesh.num_corners(); ++c) changed += by_map.mesh.corner_vertex[c] != base.mesh.corner_vertex[c];
    const bool same = by_map.mesh.corner_vertex == by_sort.mesh.corner_vertex;
    std::printf("self-check %-9s %s (%zu corners changed by the flips)\n", names[k], same ? "same flips" : "DIFFERENT FLIPS", changed);
    failures += !same || changed == 0;
  }
  return failures ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 2 && std::string(argv[1]) == "--self-check") return self_check();
    std::string out;
    std::vector<Surface> surfaces;
    std::vector<SizeClass> sizes;
    bool regular = false, irregular = false, ply = false, obj = false, dbl = false, degenerate = false;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--out") out = value();
      else if (a == "--surface") surfaces.push_back(parse_surface(value()));
      else if (a == "--size") sizes.push_back(parse_size(value()));
      else if (a == "--regular") regular = true;
      else if (a == "--irregular") irregular = true;
      else if (a == "--format") {
        const std::string f = value();
        if (f == "ply") ply = true;
        else if (f == "obj") obj = true;
        else throw std::runtime_error("unknown format '" + f + "' (ply, obj)");
      } else if (a == "--double") dbl = true;
      else if (a == "--degenerate") degenerate = true;
      else if (a == "-h" || a == "--help") {
        std::puts("usage: shadetool_bench_generate --out DIR [--surface sphere|icosphere|torus|ellipsoid]... "
                  "[--size 10k|1M|4M]... [--regular] [--irregular] [--format ply|obj]... [--double] [--degenerate]");
        return 0;
      } else throw std::runtime_error("unknown argument '" + a + "'");
    }
    if (out.empty()) throw std::runtime_error("--out DIR is required");
    if (surfaces.empty()) surfaces = {Surface::Sphere, Surface::Icosphere, Surface::Torus, Surface::Ellipsoid};
    if (sizes.empty()) sizes = {SizeClass::S10k, SizeClass::S1M, SizeClass::S4M};
    if (!regular && !irregular) regular = irregular = true;
    if (!ply && !obj) ply = obj = true;

    auto emit = [&](const BenchMesh& b, double gen_s) {
      const auto t0 = std::chrono::steady_clock::now();
      const std::string base = out + "/" + b.name;
      if (ply) write_binary_ply(b.am.mesh, base + ".ply", dbl);
      if (obj) write_obj(b.am.mesh, base + ".obj", dbl);
      write_normals_f64(b.am.exact_normals, base + ".normals.f64");
      const double write_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%-28s %9zu vertices %9zu triangles  generate %.2f s  write %.2f s\n", b.name.c_str(),
                  b.am.mesh.num_vertices(), b.am.mesh.num_faces(), gen_s, write_s);
      std::fflush(stdout);
    };
    for (SizeClass z : sizes)
      for (Surface s : surfaces)
        for (bool irr : {false, true}) {
          if ((irr && !irregular) || (!irr && !regular)) continue;
          const auto t0 = std::chrono::steady_clock::now();
          const BenchMesh b = make_bench_mesh(s, z, irr);
          emit(b, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        }
    if (degenerate) emit(make_degenerate_mesh(), 0.0);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadetool_bench_generate: %s\n", e.what());
    return 1;
  }
}
