// gltf_io.cpp: how fast shadetool reads and writes a .glb, against fread + fwrite of the same
// bytes timed in the same run (the floor: any reader and writer must at least move the bytes).
//
//   ours:   read_file_bytes + read_gltf (tinygltf parse, buffers loaded or the BIN chunk read in
//           place, every triangle primitive decoded into a Mesh) + write_gltf (unchanged document) + fwrite of the result
//   floor:  fread of the whole file into memory + fwrite of it to another file
//
// The mesh is a torus of NU x NV vertices (2 NU NV triangles; 708 x 707 = 1.0M), float
// positions and uint32 indices, written as a GLB by shadetool's table writer. Files are read once
// before timing (page cache warm for both). REPS repetitions each, the contenders alternating rep
// by rep; medians of process CPU time (the ratio) and of wall time reported.
// Usage: bench_gltf_io [NU NV REPS DIR] -> prints a table row and writes DIR/torus_1m.glb (kept
// for the CLI comparison in run.sh).
//
// Memory, as in bench/io: a CLI reads one file per process, so every buffer is fresh memory the
// kernel must fault in; glibc would instead recycle freed blocks between repetitions, which
// flatters whichever contender allocates one block of the same size every time (fread).
// M_MMAP_THRESHOLD is fixed at 1 MiB so every large block, ours and the reference's, is a fresh
// mapping in every repetition. BENCH_GLTF_WARM=1 leaves glibc's default (memory recycled).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <malloc.h>
#include <string>
#include <ctime>
#include <vector>

#include <shadetool/io/file_bytes.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/files/mesh_files.h>
#include "../io/float_torus.h"

using namespace shadetool;

namespace {

using bench::float_torus;

void write_all(const std::string& path, const char* data, std::size_t n) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(data, 1, n, f) != n) std::perror(path.c_str());
  if (f) std::fclose(f);
}

double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

void time_once(const std::function<void()>& f, std::vector<double>& cpu, std::vector<double>& wall) {
  const double c0 = cpu_ms();
  const auto t0 = std::chrono::steady_clock::now();
  f();
  wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  cpu.push_back(cpu_ms() - c0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::string load_average() {
  std::string s;
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    char buf[64] = {};
    if (std::fgets(buf, sizeof buf, f)) s = buf;
    std::fclose(f);
  }
  while (!s.empty() && s.back() == '\n') s.pop_back();
  return s.substr(0, s.find(' ', s.find(' ', s.find(' ') + 1) + 1));
}

}  // namespace

int main(int argc, char** argv) {
  const char* warm = std::getenv("BENCH_GLTF_WARM");
  if (!(warm && std::string(warm) == "1")) mallopt(M_MMAP_THRESHOLD, 1 << 20);
  const int nu = argc > 1 ? std::atoi(argv[1]) : 708, nv = argc > 2 ? std::atoi(argv[2]) : 707;
  const int reps = argc > 3 ? std::atoi(argv[3]) : 7;
  const std::string dir = argc > 4 ? argv[4] : "/tmp";
  const std::string in = dir + "/torus_1m.glb", out_ours = dir + "/torus_1m_ours.glb", out_copy = dir + "/torus_1m_copy.glb";
  const Mesh m = float_torus(nu, nv);
  WriteOptions wo;
  wo.format = Format::Gltf;
  write_mesh(m, in, wo);
  { const io::FileBytes warm = io::read_file_bytes(in); }

  // The two contenders alternate rep by rep (floor, ours, floor, ours, ...), so that a burst of
  // load from other processes falls on both; each rep is timed as process CPU time (user + system:
  // the page faults and the kernel's copies into the page cache are the process's own work) and
  // as wall time. Medians of each.
  std::size_t bytes = 0;
  auto fread_fwrite = [&] {
    FILE* f = std::fopen(in.c_str(), "rb");
    std::fseek(f, 0, SEEK_END);
    const long n = std::ftell(f);
    std::fseek(f, 0, SEEK_SET);
    std::vector<char> buf(static_cast<std::size_t>(n));
    if (std::fread(buf.data(), 1, buf.size(), f) != buf.size()) std::perror("fread");
    std::fclose(f);
    write_all(out_copy, buf.data(), buf.size());
    bytes = buf.size();
  };
  double read_ms = 0, write_ms = 0;
  auto ours = [&] {
    const auto t0 = std::chrono::steady_clock::now();
    const GltfDocument d = read_gltf(io::read_file_bytes(in), in);  // as the CLI reads a file
    const auto t1 = std::chrono::steady_clock::now();
    GltfWriteResult r;
    const std::string out = write_gltf(d, true, out_ours, r);
    write_all(out_ours, out.data(), out.size());
    read_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    write_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
  };
  std::vector<double> floor_cpu, floor_wall, ours_cpu, ours_wall;
  for (int r = 0; r < reps; ++r) {
    time_once(fread_fwrite, floor_cpu, floor_wall);
    time_once(ours, ours_cpu, ours_wall);
  }
  const double oc = median(ours_cpu), ow = median(ours_wall), fc = median(floor_cpu), fw = median(floor_wall);
  std::printf("| glb read+write, %zu triangles, %.1f MB, %s memory, process CPU time (wall) | %.1f ms (wall %.1f; last rep: read %.1f, write %.1f) | fread+fwrite %.1f ms (wall %.1f) | %.2fx |\n",
              m.num_faces(), bytes / 1e6, warm && std::string(warm) == "1" ? "recycled" : "fresh", oc, ow, read_ms, write_ms,
              fc, fw, oc / fc);
  std::fprintf(stderr, "(%s memory: %d reps each, interleaved; wall-time ratio %.2fx; load average %s)\n",
               warm && std::string(warm) == "1" ? "recycled" : "fresh", reps, ow / fw, load_average().c_str());
  return 0;
}
