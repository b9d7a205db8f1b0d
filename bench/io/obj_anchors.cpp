// obj_anchors.cpp: bench_obj_anchors, reading OBJ files: shadetool's reader (1 and 2 threads)
// against fast_obj and rapidobj, the fastest OBJ readers in public use, timed in one program.
//
//   shadetool read_mesh   files/mesh_files.h: exact doubles (correctly rounded), errors name the
//                         line; threads through a tbb::task_arena of 1 or 2
//   fast_obj              thisistherk/fast_obj (third_party/fast_obj, MIT): floats from its own
//                         parse_float (not correctly rounded), no error on malformed numbers
//   rapidobj              guybrush77/rapidobj (third_party/rapidobj, MIT): floats (its own copy of
//                         fast_float, rounded to float), threads patched to 1 or 2
//
// Every contender reads the same file from its path (so file reading is inside every row), warm in
// the page cache (one untimed read of each first). The rows are interleaved run by run
// (every contender once in every repetition, in an order shuffled per repetition), so load
// changes and what the previous row left behind hit every row alike; each
// row's median wall time and median process CPU time (user + system, all threads: on a loaded
// machine the CPU time of a 1-thread row is the steadier measure; a 2-thread row is judged by wall
// time) and the ratios of medians to the first row (below 1: faster) are printed with
// /proc/loadavg before and after.
// Destroying a result is outside the timed region. After each table, the median minor page faults of
// each row's runs (getrusage: 4 KiB faults, or one per 2 MiB huge page); for each 2-thread row the
// median over its runs of wall / (CPU / 2) (1.00: both threads busy for the whole read; above it,
// time one thread ran alone or waited: serial stages, the tail, or a CPU taken by another process);
// and the CPU time other processes used while the table ran (/proc/stat's busy time of all CPUs
// less this process's), the measured form of "was the machine quiet": on this 2-vCPU machine a busy
// loop on the other vCPU doubles the wall time of a 1-thread read (bench/io/results.md, objread6).
// Memory: M_MMAP_THRESHOLD is fixed at 1 MiB, as in io_read.cpp, so that every large block is a
// fresh mapping in every repetition as in a one-shot process (no contender is flattered by glibc
// recycling its last block).
//
// --floors adds rows that bound what any reader of the file can take (not readers; the goal's
// floors, bench/io/results.md): mapping the file's cached pages (io/file_bytes.h, as read_mesh
// does); that plus every number converted, summed: fast_float on v, vt, vn lines, a plain digit
// loop on the others (the numbers' conversion alone: no storage, no checks; faces: corners are
// counted as numbers); that plus the fresh output arrays of the mesh
// (positions, face_start, corner_vertex of the sizes shadetool read), allocated and zero-filled.
//
// Usage: bench_obj_anchors [--reps N] [--only TEXT[,TEXT...]] [--floors] FILE.obj...   (--only: rows
// whose name contains one of the TEXTs, for profiling one reader under perf)
#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <tbb/task_arena.h>

#include <fast_float/fast_float.h>

#include <shadetool/core/bulk_reserve.h>
#include <shadetool/files/mesh_files.h>
#include <shadetool/io/file_bytes.h>

// rapidobj asks std::thread::hardware_concurrency() how many threads to use; the vendored copy asks
// this instead (third_party/README.md), so its 1-thread row is one thread on any machine.
static unsigned g_rapidobj_threads = 1;
inline unsigned rapidobj_bench_threads() { return g_rapidobj_threads; }
#include "third_party/rapidobj/rapidobj.hpp"

extern "C" {
#include "third_party/fast_obj/fast_obj.h"
}

namespace {

std::string loadavg() {
  std::ifstream f("/proc/loadavg");
  std::string a, b, c;
  f >> a >> b >> c;
  return a + " " + b + " " + c;
}

long file_size(const std::string& path) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  return long(f.tellg());
}

struct Contender {
  std::string name;
  std::function<std::size_t()> run;  // returns a count (faces) so the work is not optimised away
  std::function<void()> reset;       // frees the result, untimed
  std::vector<double> ms, cpu_ms, faults;  // faults: minor page faults of the process during the run
  std::size_t count = 0;
};

// User + system CPU time of the whole process (every thread), in ms.
double process_minor_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_minflt);
}

double process_cpu_ms() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return (double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3) + (double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3);
}

// Busy time (not idle or iowait) of all CPUs since boot, in ms, from /proc/stat's first line.
double machine_busy_ms() {
  std::ifstream f("/proc/stat");
  std::string cpu;
  double user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  f >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  const long hz = sysconf(_SC_CLK_TCK);
  return hz > 0 ? (user + nice + system + irq + softirq + steal) * 1e3 / double(hz) : 0.0;  // divisor checked
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 9;
  bool floors = false;
  std::string only;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc) reps = std::atoi(argv[++i]);
    else if (a == "--only" && i + 1 < argc) only = argv[++i];
    else if (a == "--floors") floors = true;
    else files.push_back(a);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: bench_obj_anchors [--reps N] [--only TEXT] FILE.obj...\n");
    return 2;
  }
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  for (const std::string& path : files) {
    std::vector<Contender> rows;
    auto ours = std::make_shared<std::unique_ptr<shadetool::Mesh>>();
    auto sizes = std::make_shared<std::array<std::size_t, 3>>();  // the arrays shadetool read (floor rows)
    for (int t : {1, 2}) {
      auto arena = std::make_shared<tbb::task_arena>(t);
      rows.push_back({"shadetool read_mesh, " + std::to_string(t) + " thread" + (t > 1 ? "s" : ""),
                      [ours, arena, path, sizes] {
                        arena->execute([&] { *ours = std::make_unique<shadetool::Mesh>(shadetool::read_mesh(path)); });
                        *sizes = {(*ours)->positions.size(), (*ours)->corner_vertex.size(), (*ours)->face_start.size()};
                        return (*ours)->num_faces();
                      },
                      [ours] { ours->reset(); }});
    }
    auto fo = std::make_shared<fastObjMesh*>(nullptr);
    rows.push_back({"fast_obj",
                    [fo, path] {
                      *fo = fast_obj_read(path.c_str());
                      if (!*fo) throw std::runtime_error(path + ": fast_obj_read failed");
                      return std::size_t((*fo)->face_count);
                    },
                    [fo] {
                      if (*fo) fast_obj_destroy(*fo);
                      *fo = nullptr;
                    }});
    auto ro = std::make_shared<std::unique_ptr<rapidobj::Result>>();
    for (unsigned t : {1u, 2u}) {
      rows.push_back({"rapidobj, " + std::to_string(t) + " thread" + (t > 1 ? "s" : ""),
                      [ro, path, t] {
                        g_rapidobj_threads = t;
                        *ro = std::make_unique<rapidobj::Result>(rapidobj::ParseFile(path));
                        if ((*ro)->error.code) throw std::runtime_error(path + ": rapidobj: " + (*ro)->error.code.message());
                        std::size_t faces = 0;
                        for (const auto& s : (*ro)->shapes) faces += s.mesh.num_face_vertices.size();
                        return faces;
                      },
                      [ro] { ro->reset(); }});
    }
    if (floors) {
      rows.push_back({"floor: map the file", [path] { return shadetool::io::read_file_bytes(path).size(); }, [] {}});
      rows.push_back({"floor: map, convert every number",
                      [path] {
                        const shadetool::io::FileBytes f = shadetool::io::read_file_bytes(path);
                        const char* p = f.view().data();
                        const char* const end = p + f.size();
                        double sum = 0;
                        std::uint64_t isum = 0;
                        std::size_t n = 0;
                        bool v_line = false;  // numbers of v/vt/vn lines: fast_float; of others (f): integers
                        for (bool line_start = true; p < end;) {
                          const char c = *p;
                          if (line_start) v_line = c == 'v';
                          line_start = c == '\n';
                          if ((c >= '0' && c <= '9') || c == '-' || c == '.') {
                            ++n;
                            if (v_line) {
                              double x = 0;
                              const auto r = fast_float::from_chars(p, end, x);
                              sum += x;
                              p = r.ptr > p ? r.ptr : p + 1;
                            } else {
                              std::uint64_t k = 0;
                              for (++p; p < end && *p >= '0' && *p <= '9'; ++p) k = k * 10 + std::uint64_t(*p - '0');
                              isum += k;
                            }
                          } else {
                            ++p;
                          }
                        }
                        return n + (sum == 0.5 ? 1 : 0) + (isum == 1 ? 1 : 0);
                      },
                      [] {}});
      auto arrays = std::make_shared<std::unique_ptr<shadetool::Mesh>>();
      rows.push_back({"floor: map, fresh output arrays",
                      [path, sizes, arrays] {
                        const shadetool::io::FileBytes f = shadetool::io::read_file_bytes(path);
                        *arrays = std::make_unique<shadetool::Mesh>();
                        shadetool::Mesh& m = **arrays;
                        const std::array<std::size_t, 3> n = *sizes;
                        shadetool::reserve_bulk(m.positions, n[0]);
                        shadetool::reserve_bulk(m.corner_vertex, n[1]);
                        shadetool::reserve_bulk(m.face_start, n[2]);
                        m.positions.resize(n[0]);
                        m.corner_vertex.resize(n[1]);
                        m.face_start.resize(n[2]);
                        return m.face_start.size() - 1 + (f.size() == 0 ? 1 : 0);
                      },
                      [arrays] { arrays->reset(); }});
    }
    if (!only.empty())
      rows.erase(std::remove_if(rows.begin(), rows.end(),
                                [&](const Contender& c) {
                                  std::stringstream list(only);
                                  for (std::string part; std::getline(list, part, ',');)
                                    if (c.name.find(part) != std::string::npos) return false;
                                  return true;
                                }),
                 rows.end());
    if (rows.empty()) continue;
    // Warm: one untimed run of each (page cache, lazy library initialisation).
    for (Contender& c : rows) {
      c.count = c.run();
      c.reset();
    }
    const std::string load_before = loadavg();
    const double busy0 = machine_busy_ms(), own0 = process_cpu_ms();
    const auto table0 = std::chrono::steady_clock::now();
    // Each repetition runs the rows in its own order (a shuffle seeded by the repetition's number):
    // what a row leaves behind (memory it freed in 4 KiB pages, worker threads still spinning) is
    // charged to a different next row each time, not always to the same one.
    std::vector<std::size_t> order(rows.size());
    for (int r = 0; r < reps; ++r) {
      std::iota(order.begin(), order.end(), std::size_t(0));
      std::mt19937 shuffle_rng(static_cast<unsigned>(r));
      std::shuffle(order.begin(), order.end(), shuffle_rng);
      for (const std::size_t k : order) {
        Contender& c = rows[k];
        const double faults0 = process_minor_faults();
        const double cpu0 = process_cpu_ms();
        const auto t0 = std::chrono::steady_clock::now();
        c.count = c.run();
        const auto t1 = std::chrono::steady_clock::now();
        c.cpu_ms.push_back(process_cpu_ms() - cpu0);
        c.faults.push_back(process_minor_faults() - faults0);
        c.ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
        c.reset();
      }
    }
    const std::string load_after = loadavg();
    const double table_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - table0).count();
    const double others_ms = std::max(0.0, (machine_busy_ms() - busy0) - (process_cpu_ms() - own0));
    const double mb = file_size(path) / 1e6;
    std::printf("%s: %.1f MB, %d runs per row interleaved, medians; load %s before, %s after\n", path.c_str(), mb, reps,
                load_before.c_str(), load_after.c_str());
    std::printf("| %-30s | %9s | %8s | %8s | %-21s | %10s | %-21s | %10s |\n", "reader", "median ms", "MB/s", "min ms",
                "wall: time / first row", "median CPU ms", "CPU: time / first row", "faces");
    std::printf("|%s|%s|%s|%s|%s|%s|%s|%s|\n", std::string(32, '-').c_str(), std::string(11, '-').c_str(),
                std::string(10, '-').c_str(), std::string(10, '-').c_str(), std::string(23, '-').c_str(),
                std::string(12, '-').c_str(), std::string(23, '-').c_str(), std::string(12, '-').c_str());
    const double base = median(rows[0].ms), base_cpu = median(rows[0].cpu_ms);
    for (const Contender& c : rows) {
      const double m = median(c.ms), cpu = median(c.cpu_ms);
      std::printf("| %-30s | %9.1f | %8.0f | %8.1f | %21.2f | %12.1f | %21.2f | %10zu |\n", c.name.c_str(), m, mb * 1e3 / m,
                  *std::min_element(c.ms.begin(), c.ms.end()), m / base, cpu, cpu / base_cpu, c.count);
    }
    std::printf("minor page faults per run (medians):");
    for (const Contender& c : rows) std::printf(" %s %.0f;", c.name.c_str(), median(c.faults));
    std::printf("\n");
    for (const Contender& c : rows) {
      if (c.name.find("2 threads") == std::string::npos) continue;
      std::vector<double> stretch;
      for (std::size_t i = 0; i < c.ms.size(); ++i)
        if (c.cpu_ms[i] > 0) stretch.push_back(c.ms[i] / (c.cpu_ms[i] / 2));  // divisor checked
      if (!stretch.empty()) std::printf("%s: wall / (CPU / 2), median over runs: %.2f\n", c.name.c_str(), median(stretch));
    }
    std::printf("other processes' CPU while the table ran: %.0f ms in %.0f ms (%.0f%% of one CPU; from /proc/stat)\n", others_ms,
                table_ms, table_ms > 0 ? 100 * others_ms / table_ms : 0.0);  // divisor checked
    std::printf("\n");
  }
  return 0;
}
