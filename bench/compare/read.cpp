// read.cpp: bench_compare_read, reading a mesh file: shadetool::read_mesh against
// OpenMesh::IO::read_mesh (OBJ and binary PLY) and against a plain fread of the whole file (the
// memory-speed floor for binary PLY).
//
// The mesh (default sphere_1M_irregular) is written once by bench/generate's writers into --dir
// (OBJ with %.9g, binary little-endian PLY with float positions), then every reader runs on the
// same file, warm in the page cache (a first untimed read), so the rows compare parsing, not disk.
// Each run builds a fresh mesh object; its destruction is outside the timed region. The readers
// are timed round-robin (harness.h run_cases).
// Rows: method = "shadetool read_mesh", "OpenMesh IO::read_mesh", "fread"; weighting = the format.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <tbb/task_arena.h>

#include "harness.h"
#include <shadetool/files/mesh_files.h>
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
  std::vector<Case> cases;
  for (const std::string& path : {obj, ply}) {
    const std::string format = path == obj ? "obj" : "ply";
    for (int t : o.threads) {
      auto ours = std::make_shared<std::unique_ptr<Mesh>>();
      auto arena = std::make_shared<tbb::task_arena>(t);
      Case c;
      c.row = Row{"read", "shadetool read_mesh", format, "file", "", t};
      c.reset = [ours] { ours->reset(); };
      c.run = [ours, arena, path] { arena->execute([&] { *ours = std::make_unique<Mesh>(read_mesh(path)); }); };
      c.note = [ours] { return std::to_string((*ours)->num_vertices()) + " vertices read"; };
      cases.push_back(std::move(c));
    }
    auto om = std::make_shared<std::unique_ptr<TriMeshF>>();
    auto ok = std::make_shared<bool>(true);
    Case c;
    c.row = Row{"read", "OpenMesh IO::read_mesh", format, "file", "", 1};
    c.reset = [om] { om->reset(); };
    c.run = [om, ok, path] {
      *om = std::make_unique<TriMeshF>();
      *ok = OpenMesh::IO::read_mesh(**om, path) && *ok;
    };
    c.note = [om, ok] { return *ok ? std::to_string((*om)->n_vertices()) + " vertices read" : "read_mesh failed"; };
    cases.push_back(std::move(c));
    if (format == "ply") {
      auto bytes = std::make_shared<std::vector<char>>();
      Case f;
      f.row = Row{"read", "fread", format, "file", "", 1};
      f.reset = [bytes] { *bytes = std::vector<char>(); };
      f.run = [bytes, path] {
        std::FILE* file = std::fopen(path.c_str(), "rb");
        if (!file) throw std::runtime_error(path + ": cannot open");
        std::fseek(file, 0, SEEK_END);
        bytes->resize(std::size_t(std::ftell(file)));
        std::fseek(file, 0, SEEK_SET);
        const std::size_t n = std::fread(bytes->data(), 1, bytes->size(), file);
        std::fclose(file);
        if (n != bytes->size()) throw std::runtime_error(path + ": short read");
      };
      f.note = [bytes] { return std::to_string(bytes->size()) + " bytes"; };
      cases.push_back(std::move(f));
    }
  }
  run_cases(b, cases, repeats_for(b, o.repeats));
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
