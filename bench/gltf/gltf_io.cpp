// gltf_io.cpp: how fast shadetool reads and writes a .glb, against fread + fwrite of the same
// bytes timed in the same run (the floor: any reader and writer must at least move the bytes).
//
//   ours:   read_file_bytes + read_gltf (tinygltf parse, buffers loaded, every triangle primitive
//           decoded into a Mesh) + write_gltf (unchanged document) + fwrite of the result
//   floor:  fread of the whole file into memory + fwrite of it to another file
//
// The mesh is a torus of NU x NV vertices (2 NU NV triangles; 708 x 707 = 1.0M), float
// positions and uint32 indices, written as a GLB by shadetool's table writer. Files are read once
// before timing (page cache warm for both). REPS repetitions each; medians reported.
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
#include <vector>

#include <shadetool/io/file_bytes.h>
#include <shadetool/gltf/gltf_document.h>
#include <shadetool/files/mesh_files.h>
#include "../io/float_torus.h"

using namespace shadetool;

namespace {

using bench::float_torus;
using bench::median_ms;

void write_all(const std::string& path, const char* data, std::size_t n) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || std::fwrite(data, 1, n, f) != n) std::perror(path.c_str());
  if (f) std::fclose(f);
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

  std::size_t bytes = 0;
  const double floor_ms = median_ms(reps, [&] {
    FILE* f = std::fopen(in.c_str(), "rb");
    std::fseek(f, 0, SEEK_END);
    const long n = std::ftell(f);
    std::fseek(f, 0, SEEK_SET);
    std::vector<char> buf(static_cast<std::size_t>(n));
    if (std::fread(buf.data(), 1, buf.size(), f) != buf.size()) std::perror("fread");
    std::fclose(f);
    write_all(out_copy, buf.data(), buf.size());
    bytes = buf.size();
  });
  double read_ms = 0, write_ms = 0;
  const double ours_ms = median_ms(reps, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    const io::FileBytes b = io::read_file_bytes(in);
    const GltfDocument d = read_gltf(b.view(), in);
    const auto t1 = std::chrono::steady_clock::now();
    GltfWriteResult r;
    const std::string out = write_gltf(d, true, out_ours, r);
    write_all(out_ours, out.data(), out.size());
    read_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    write_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t1).count();
  });
  std::printf("| glb read+write, %zu triangles, %.1f MB, %s memory | %.1f ms (last rep: read %.1f, write %.1f) | fread+fwrite %.1f ms | %.2fx |\n",
              m.num_faces(), bytes / 1e6, warm && std::string(warm) == "1" ? "recycled" : "fresh", ours_ms, read_ms, write_ms,
              floor_ms, ours_ms / floor_ms);
  return 0;
}
