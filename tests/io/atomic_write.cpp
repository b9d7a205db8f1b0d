// Tests of io/atomic_write and of write_mesh's promise: no output on error, an existing file is
// untouched on failure and replaced whole on success, no temporary file left behind.
#include <sys/stat.h>

#include <shadetool/io/atomic_write.h>
#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {
std::size_t files_in(const ScratchDir& d) {
  std::size_t n = 0;
  for (auto& e : std::filesystem::directory_iterator(d.path)) n += e.is_regular_file();
  return n;
}
}  // namespace

TEST_CASE("atomic write: replaces the whole file and leaves no temporary", "[atomic_write]") {
  ScratchDir dir;
  write_file(dir / "a.obj", "old contents that are longer than the new ones\n");
  io::write_file_atomically(dir / "a.obj", "new\n");
  CHECK(read_file(dir / "a.obj") == "new\n");
  CHECK(files_in(dir) == 1);
}

TEST_CASE("atomic write: a new file gets the usual permissions, a replaced one keeps its mode", "[atomic_write]") {
  ScratchDir dir;
  const mode_t old = ::umask(022);
  io::write_file_atomically(dir / "n.ply", "x");
  struct stat st {};
  ::stat((dir / "n.ply").c_str(), &st);
  CHECK((st.st_mode & 0777) == 0644);
  ::chmod((dir / "n.ply").c_str(), 0600);
  io::write_file_atomically(dir / "n.ply", "y");
  ::stat((dir / "n.ply").c_str(), &st);
  CHECK((st.st_mode & 0777) == 0600);
  ::umask(old);
}

TEST_CASE("atomic write: errors leave nothing and touch nothing", "[atomic_write][errors]") {
  ScratchDir dir;
  CHECK(error_of([&] { io::write_file_atomically(dir / "missing/a.obj", "x"); }) ==
        dir / "missing/a.obj" + ": cannot write: No such file or directory");
  std::filesystem::create_directory(dir / "d.obj");
  CHECK(error_of([&] { io::write_file_atomically(dir / "d.obj", "x"); }) == dir / "d.obj" + ": cannot write: is a directory");
  CHECK(files_in(dir) == 0);
}

TEST_CASE("write_mesh: a failing write leaves an existing output untouched", "[atomic_write][errors]") {
  ScratchDir dir;
  write_file(dir / "out.xyz", "precious");
  Mesh m = rich_mesh();
  CHECK(error_of([&] { write_mesh(m, dir / "out.xyz", WriteOptions{}); }) ==
        dir / "out.xyz" + ": unknown mesh format 'xyz' (expected .obj, .ply, .off, .stl or .glb/.gltf)");
  CHECK(read_file(dir / "out.xyz") == "precious");
  CHECK(files_in(dir) == 1);
}

TEST_CASE("write_files_atomically: files that belong together are all replaced or none is", "[atomic_write][errors]") {
  ScratchDir dir;
  write_file(dir / "mesh.obj", "old mesh");
  write_file(dir / "report.json", "old report");
  std::filesystem::create_directory(dir / "d.json");
  // The second file cannot be written (a directory): the first is not replaced either.
  CHECK(error_of([&] { io::write_files_atomically({{dir / "mesh.obj", "new mesh"}, {dir / "d.json", "r"}}); }) ==
        dir / "d.json" + ": cannot write: is a directory");
  CHECK(read_file(dir / "mesh.obj") == "old mesh");
  CHECK(error_of([&] { io::write_files_atomically({{dir / "mesh.obj", "new mesh"}, {dir / "no/r.json", "r"}}); }) ==
        dir / "no/r.json" + ": cannot write: No such file or directory");
  CHECK(read_file(dir / "mesh.obj") == "old mesh");
  CHECK(files_in(dir) == 2);  // mesh.obj, report.json: no temporaries left
  io::write_files_atomically({{dir / "mesh.obj", "new mesh"}, {dir / "report.json", "new report"}});
  CHECK(read_file(dir / "mesh.obj") == "new mesh");
  CHECK(read_file(dir / "report.json") == "new report");
  CHECK(files_in(dir) == 2);
}
