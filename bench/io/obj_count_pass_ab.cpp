// obj_count_pass_ab.cpp: bench/io/obj_count_pass_ab.sh's driver (not in the build): count_obj_statements of a
// past commit (namespace shadetool_old) against the work tree's (shadetool_new) over a whole file,
// interleaved run by run (the order alternating), process CPU medians; exits 1 if the counts differ.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <ctime>
// The two builds' declarations (the layout of ObjCounts and ObjCountMasks as in obj_statement_counts.h).
namespace shadetool_old::io { struct ObjCounts { std::size_t v, vt, vn, faces, corners, lines; bool cr, nul; }; enum class ObjCountMasks { Best, Sse2, Plain };  // the old build's first three values
ObjCounts count_obj_statements(const char*, const char*, ObjCountMasks); }
namespace shadetool_new::io { struct ObjCounts { std::size_t v, vt, vn, faces, corners, lines; bool cr, nul; }; enum class ObjCountMasks { Best, Sse2, Plain, Avx2, Avx512 };
ObjCounts count_obj_statements(const char*, const char*, ObjCountMasks); }
static double cpu_ms() { timespec t; clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t); return t.tv_sec * 1e3 + t.tv_nsec / 1e6; }
int main(int argc, char** argv) {
  std::ifstream f(argv[1], std::ios::binary); std::stringstream ss; ss << f.rdbuf(); const std::string s = ss.str();
  const int reps = argc > 2 ? std::atoi(argv[2]) : 11;
  const char* p = s.data(); const char* e = p + s.size();
  // Rows: the old build's mode against the new build's; the old Best is AVX2 on an AVX2 machine.
  const int old_mode[] = {0, 0, 1, 2}, new_mode[] = {0, 3, 1, 2};
  const char* names[] = {"old Best, new Best", "old Best, new Avx2", "Sse2", "Plain"};
  for (int m = 0; m < 4; ++m) {
    std::vector<double> to, tn;
    for (int r = 0; r < reps; ++r) {
      shadetool_old::io::ObjCounts a; shadetool_new::io::ObjCounts b; double d_old, d_new;
      auto run_old = [&] { double t0 = cpu_ms(); a = shadetool_old::io::count_obj_statements(p, e, shadetool_old::io::ObjCountMasks(old_mode[m])); d_old = cpu_ms() - t0; };
      auto run_new = [&] { double t0 = cpu_ms(); b = shadetool_new::io::count_obj_statements(p, e, shadetool_new::io::ObjCountMasks(new_mode[m])); d_new = cpu_ms() - t0; };
      if (r % 2) { run_old(); run_new(); } else { run_new(); run_old(); }
      if (a.v != b.v || a.faces != b.faces || a.corners != b.corners || a.lines != b.lines || a.vt != b.vt || a.vn != b.vn) { std::puts("DIFFER"); return 1; }
      to.push_back(d_old); tn.push_back(d_new);
    }
    std::sort(to.begin(), to.end()); std::sort(tn.begin(), tn.end());
    std::printf("%-20s old %.2f ms  new %.2f ms  new/old %.3f  (medians of %d, CPU)\n", names[m], to[reps / 2], tn[reps / 2], tn[reps / 2] / to[reps / 2], reps);
  }
}
