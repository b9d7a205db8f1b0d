// ours_rows.h: shadetool's own kernels as cases of a comparison table (harness.h), so that every
// anchor program times our kernels on the same mesh, in the same process run and round-robin with
// the anchor (ratios from one run).
//
// Threads: each case runs inside a tbb::task_arena of `threads` slots, so that the kernels see that
// concurrency (tbb::this_task_arena::max_concurrency(); tbb::global_control would cap the workers
// but leave a kernel believing it has all cores, and running its parallel code path on one).
#pragma once

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include "harness.h"
#include <shadetool/normals/face_normals.h>
#include <shadetool/normals/vertex_normals.h>
#include <shadetool/normals/weighting.h>  // weighting_name: the option vocabulary's names

namespace shadetool::bench {

inline std::string fmt_g(const char* format, double x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

// One case per (weighting, precision, threads): shadetool::vertex_normals. Notes: vertices that
// took the fallback; for float, the largest angle to the double result (vertices not at risk); for
// more threads, whether the result differs from the 1-thread one (it must not).
// prepared = false: method "shadetool vertex_normals", the plain call; its result is freed before
// every run (untimed), so allocating the output is inside the timing (as for Open3D, whose arrays
// are cleared and shrunk before every run). prepared = true: method "shadetool vertex_normals
// (prepared)": a VertexNormalsPlan built before the timing in the case's arena, and the output of
// the previous run reused (as OpenMesh runs on its prebuilt topology and writes into normal
// properties allocated before the timing; its reset only zeroes them, untimed).
inline std::vector<Case> ours_vertex_cases(const std::string& program, const BenchMesh& b,
                                           const std::vector<Weighting>& weightings,
                                           const std::vector<Precision>& precisions, const std::vector<int>& threads,
                                           bool prepared = false) {
  std::vector<Case> cases;
  for (Weighting w : weightings) {
    std::shared_ptr<VertexNormals> double_result;
    for (Precision p : precisions) {
      std::shared_ptr<VertexNormals> first_result;
      for (int t : threads) {
        auto result = std::make_shared<VertexNormals>();
        auto arena = std::make_shared<tbb::task_arena>(t);
        if (p == Precision::Double && !double_result) double_result = result;
        const bool first = !first_result;
        if (first) first_result = result;
        Case c;
        c.row = Row{program, prepared ? "shadetool vertex_normals (prepared)" : "shadetool vertex_normals", weighting_name(w),
                    p == Precision::Double ? "double" : "float", "", t};
        if (prepared) {
          auto plan = std::make_shared<VertexNormalsPlan>();
          arena->execute([&] { *plan = VertexNormalsPlan(b.am.mesh); });
          c.run = [result, arena, plan, &b, w, p] { arena->execute([&] { vertex_normals(b.am.mesh, *plan, w, p, *result); }); };
        } else {
          c.reset = [result] { *result = VertexNormals{}; };
          c.run = [result, arena, &b, w, p] { arena->execute([&] { *result = vertex_normals(b.am.mesh, w, p); }); };
        }
        c.error = [result, &b] { return angular_error(b, result->normals); };
        const std::shared_ptr<VertexNormals> dbl = p == Precision::Float ? double_result : nullptr;
        const std::shared_ptr<VertexNormals> one = first ? nullptr : first_result;
        c.note = [result, dbl, one, &b] {
          std::string note;
          auto add = [&](const std::string& x) { note += (note.empty() ? "" : "; ") + x; };
          if (result->fallback_vertices) add(std::to_string(result->fallback_vertices) + " fallback vertices");
          if (one && one->normals != result->normals) add("differs from the 1-thread result");
          if (dbl && dbl->normals.size() == result->normals.size()) {
            double worst = 0;
            for (std::size_t v = 0; 3 * v < result->normals.size(); ++v)
              if (!b.at_risk[v]) worst = std::max(worst, testing::angle_degrees(get3(result->normals, v), get3(dbl->normals, v)));
            add(fmt_g("max angle to double result %.3g deg", worst));
          }
          return note;
        };
        cases.push_back(std::move(c));
      }
    }
  }
  return cases;
}

// shadetool::face_normals (timing only: the truth is per vertex).
inline std::vector<Case> ours_face_cases(const std::string& program, const BenchMesh& b, const std::vector<int>& threads) {
  std::vector<Case> cases;
  for (int t : threads) {
    auto fn = std::make_shared<std::vector<double>>();
    auto arena = std::make_shared<tbb::task_arena>(t);
    Case c;
    c.row = Row{program, "shadetool face_normals", "face", "double", "", t};
    c.reset = [fn] { fn->clear(); fn->shrink_to_fit(); };
    c.run = [fn, arena, &b] { arena->execute([&] { *fn = face_normals(b.am.mesh, Precision::Double); }); };
    cases.push_back(std::move(c));
  }
  return cases;
}

inline void append(std::vector<Case>& to, std::vector<Case> from) {
  for (Case& c : from) to.push_back(std::move(c));
}

}  // namespace shadetool::bench
