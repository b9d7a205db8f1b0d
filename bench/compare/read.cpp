// read.cpp: bench_compare_read, reading a mesh file: shadetool::read_mesh against
// OpenMesh::IO::read_mesh (OBJ and binary PLY) and against a plain fread of the whole file (the
// memory-speed floor for binary PLY).
//
// The mesh (default sphere_1M_irregular) is written once by bench/generate's writers into --dir
// (OBJ with %.9g, binary little-endian PLY with float positions), then every reader runs on the
// same file, warm in the page cache (a first untimed read), so the rows compare parsing, not disk.
// Each run builds a fresh mesh object; its destruction is outside the timed region.
// Rows: method = "shadetool read_mesh", "OpenMesh IO::read_mesh", "fread"; weighting = the format.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <tbb/task_arena.h>

#include "harness.h"
#include "io/mesh_io.h"
#include "write_bench_files.h"

using namespace shadetool;
using namespace shadetool::bench;

namespace {

using TriMeshF = OpenMesh::TriMesh_ArrayKernelT<>;

void run(const BenchMesh& b, const Options& o, const std::string& dir) {
  const std::string base = dir + "/" + b.name + "_read";
  const std::string obj = base + ".obj", ply = base + ".ply";
  write_obj(b.am.mesh, obj, false);
  write_binary_ply(b.am.mesh, ply, false);
  const int reps = repeats_for(b, o.repeats);
  for (const std::string& path : {obj, ply}) {
    const std::string format = path == obj ? "obj" : "ply";
    std::unique_ptr<Mesh> ours;
    for (int t : o.threads) {
      tbb::task_arena arena(t);
      const Timing time = time_median(reps, [&] { ours.reset(); },
                                      [&] { arena.execute([&] { ours = std::make_unique<Mesh>(read_mesh(path)); }); });
      std::string note = std::to_string(ours->num_vertices()) + " vertices read";
      print_row(b, Row{"read", "shadetool read_mesh", format, "file", note, t}, time, ErrorStats{});
    }
    std::unique_ptr<TriMeshF> om;
    bool ok = true;
    const Timing time = time_median(reps, [&] { om.reset(); }, [&] {
      om = std::make_unique<TriMeshF>();
      ok = OpenMesh::IO::read_mesh(*om, path) && ok;
    });
    print_row(b, Row{"read", "OpenMesh IO::read_mesh", format, "file",
                     ok ? std::to_string(om->n_vertices()) + " vertices read" : "read_mesh failed", 1}, time, ErrorStats{});
    if (format == "ply") {
      std::vector<char> bytes;
      const Timing tf = time_median(reps, [&] { bytes = std::vector<char>(); }, [&] {
        std::FILE* f = std::fopen(path.c_str(), "rb");
        if (!f) throw std::runtime_error(path + ": cannot open");
        std::fseek(f, 0, SEEK_END);
        bytes.resize(std::size_t(std::ftell(f)));
        std::fseek(f, 0, SEEK_SET);
        const std::size_t n = std::fread(bytes.data(), 1, bytes.size(), f);
        std::fclose(f);
        if (n != bytes.size()) throw std::runtime_error(path + ": short read");
      });
      print_row(b, Row{"read", "fread", format, "file", std::to_string(bytes.size()) + " bytes", 1}, tf, ErrorStats{});
    }
  }
  std::remove(obj.c_str());
  std::remove(ply.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string dir = ".";
    std::vector<char*> rest{argv[0]};
    for (int i = 1; i < argc; ++i) {
      if (std::string(argv[i]) == "--dir" && i + 1 < argc) dir = argv[++i];
      else rest.push_back(argv[i]);
    }
    Options o = parse_options(int(rest.size()), rest.data());
    o.repeats = std::min(o.repeats, 5);
    if (o.header) std::puts(csv_header());
    for (const std::string& name : o.meshes) {
      if (name == "degenerate") continue;
      run(load_bench_mesh(name), o, dir);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_compare_read: %s\n", e.what());
    return 1;
  }
}
