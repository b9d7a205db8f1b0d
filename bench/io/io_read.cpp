// io_read.cpp: how fast shadetool reads meshes, against references timed in the same run.
//
//   OBJ:        shadetool::read_mesh  vs  OpenMesh::IO::read_mesh (PolyMesh, default options)
//   binary PLY: shadetool::read_mesh  vs  fread of the whole file into memory (the floor: any
//               reader must at least read the bytes)
// Also: OpenMesh reading the binary PLY, and shadetool writing both files, for context.
//
// The mesh is a torus of NU x NV vertices (2 NU NV triangles), float data, written by
// shadetool's writers to a scratch directory. The files are read once before timing so the
// page cache holds them for every contender alike. Each contender runs REPS times; the median is
// reported (the machine is shared and noisy). Usage: bench_io_read [NU NV REPS DIR].
//
// Memory: a CLI reads one file per process, so every buffer it fills is fresh memory the kernel
// must fault in. glibc would instead recycle freed blocks between repetitions (its mmap threshold
// grows after the first free), which flatters whichever contender allocates one block of the same
// size every time (fread). M_MMAP_THRESHOLD is therefore fixed at 1 MiB: every large block,
// ours and the references', is a fresh mapping in every repetition, as in a one-shot process.
// BENCH_IO_WARM=1 leaves glibc's default (memory recycled between repetitions) for comparison.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <malloc.h>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <shadetool/files/mesh_files.h>
#include "float_torus.h"

using namespace shadetool;

namespace {

using bench::float_torus;
using bench::median_ms;

std::size_t fread_all(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) std::exit(1);
  std::fseek(f, 0, SEEK_END);
  const long size = std::ftell(f);
  std::fseek(f, 0, SEEK_SET);
  std::unique_ptr<char[]> bytes(new char[std::size_t(size)]);  // not zero-filled, like ours
  const std::size_t n = std::fread(bytes.get(), 1, std::size_t(size), f);
  std::fclose(f);
  return n;
}

long file_size(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  std::fseek(f, 0, SEEK_END);
  const long s = std::ftell(f);
  std::fclose(f);
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  const int nu = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int nv = argc > 2 ? std::atoi(argv[2]) : 500;
  const int reps = argc > 3 ? std::atoi(argv[3]) : 7;
  const std::string dir = argc > 4 ? argv[4] : "/tmp";
  const std::string obj = dir + "/bench_io_torus.obj", ply = dir + "/bench_io_torus.ply";

  const bool warm = std::getenv("BENCH_IO_WARM") != nullptr;
  if (!warm) mallopt(M_MMAP_THRESHOLD, 1 << 20);
  const Mesh m = float_torus(nu, nv);
  std::printf("mesh: torus %d x %d: %zu vertices, %zu triangles; %d repetitions, medians; %s memory\n", nu, nv,
              m.num_vertices(), m.num_faces(), reps, warm ? "recycled (warm)" : "fresh (one-shot process)");
  const double write_obj = median_ms(3, [&] { write_mesh(m, obj, WriteOptions{}); });
  const double write_ply = median_ms(3, [&] { write_mesh(m, ply, WriteOptions{}); });
  std::printf("files: %s %.1f MB, %s %.1f MB\n", obj.c_str(), file_size(obj) / 1e6, ply.c_str(), file_size(ply) / 1e6);
  fread_all(obj);
  fread_all(ply);

  std::size_t sink = 0;
  const double ours_obj = median_ms(reps, [&] { sink += read_mesh(obj).num_faces(); });
  const double om_obj = median_ms(reps, [&] {
    OpenMesh::PolyMesh_ArrayKernelT<> om;
    if (!OpenMesh::IO::read_mesh(om, obj)) std::exit(1);
    sink += om.n_faces();
  });
  const double fread_obj = median_ms(reps, [&] { sink += fread_all(obj); });
  const double ours_ply = median_ms(reps, [&] { sink += read_mesh(ply).num_faces(); });
  const double fread_ply = median_ms(reps, [&] { sink += fread_all(ply); });
  const double om_ply = median_ms(reps, [&] {
    OpenMesh::PolyMesh_ArrayKernelT<> om;
    OpenMesh::IO::Options opt = OpenMesh::IO::Options::Binary;
    if (!OpenMesh::IO::read_mesh(om, ply, opt)) std::exit(1);
    sink += om.n_faces();
  });

  std::printf("\n%-34s %10s %10s\n", "", "ms", "MB/s");
  auto row = [&](const char* what, double ms, const std::string& file) {
    std::printf("%-34s %10.1f %10.0f\n", what, ms, file_size(file) / 1e3 / ms);
  };
  row("OBJ  fread (floor)", fread_obj, obj);
  row("OBJ  shadetool read_mesh", ours_obj, obj);
  row("OBJ  OpenMesh IO::read_mesh", om_obj, obj);
  row("PLY  fread (floor)", fread_ply, ply);
  row("PLY  shadetool read_mesh", ours_ply, ply);
  row("PLY  OpenMesh IO::read_mesh", om_ply, ply);
  row("OBJ  shadetool write_mesh", write_obj, obj);
  row("PLY  shadetool write_mesh", write_ply, ply);
  std::printf("\nOBJ: OpenMesh / shadetool = %.2fx (goal >= 5)\n", om_obj / ours_obj);
  std::printf("PLY: shadetool / fread    = %.2fx (goal <= 3)\n", ours_ply / fread_ply);
  std::printf("PLY: OpenMesh / shadetool = %.2fx\n", om_ply / ours_ply);
  if (!std::getenv("BENCH_IO_KEEP")) {
    std::remove(obj.c_str());
    std::remove(ply.c_str());
  }
  return sink == 0;
}
