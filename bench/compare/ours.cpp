// ours.cpp: bench_compare_ours, shadetool's vertex normals in every weighting, both precisions,
// 1 and 2 threads (tbb::task_arena), on the meshes named with --mesh; with `--refinement`,
// one row per weighting and precision at 1 thread on every surface, regular and irregular, at
// 10k, 1M and 4M (the error order under refinement).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "ours_rows.h"

using namespace shadetool;
using namespace shadetool::bench;

int main(int argc, char** argv) {
  try {
    bool refinement = false;
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]) == "--refinement") refinement = true;
      else rest.push_back(argv[i]);
    }
    Options o = parse_options(int(rest.size()), rest.data());
    if (refinement) {
      o.meshes.clear();
      for (const char* z : {"10k", "1M", "4M"})
        for (const char* s : {"sphere", "icosphere", "torus", "ellipsoid"})
          for (const char* k : {"regular", "irregular"}) o.meshes.push_back(std::string(s) + "_" + z + "_" + k);
    }
    if (o.header) std::puts(csv_header());
    const std::vector<Weighting> all = {Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max};
    for (const std::string& name : o.meshes) {
      const BenchMesh b = load_bench_mesh(name);
      std::vector<Case> cases;
      if (refinement) {
        cases = ours_vertex_cases("ours_refinement", b, all, {Precision::Double, Precision::Float}, {1});
      } else {
        cases = ours_vertex_cases("ours", b, all, {Precision::Double, Precision::Float}, o.threads);
        append(cases, ours_vertex_cases("ours", b, all, {Precision::Double, Precision::Float}, o.threads, /*prepared=*/true));
        append(cases, ours_face_cases("ours", b, o.threads));
      }
      run_cases(b, cases, repeats_for(b, o.repeats));
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_ours: %s\n", e.what());
    return 1;
  }
}
