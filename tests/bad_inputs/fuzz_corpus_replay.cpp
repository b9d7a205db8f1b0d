// Replays fuzz/corpus/ (the seeds and every input a fuzzer ever crashed on, kept there as
// crash-*) and this folder's hostile files through the same checks the libFuzzer targets make
// (fuzz/fuzz_mesh_reader.h), in the ordinary build and under the sanitizers (.ci/sanitizers.sh):
// each file either reads into a mesh that keeps every Mesh invariant and survives a round trip
// through our writers, or is refused with shadetool::Error; nothing else.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#define SHADETOOL_FUZZ_REPLAY 1
#include "../fuzz/fuzz_mesh_reader.h"

namespace fs = std::filesystem;

namespace {

std::string bytes_of(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

shadetool::Format format_of(const std::string& target) {
  if (target == "fuzz_read_obj") return shadetool::Format::Obj;
  if (target == "fuzz_read_ply") return shadetool::Format::Ply;
  if (target == "fuzz_read_off") return shadetool::Format::Off;
  return shadetool::Format::Stl;
}

}  // namespace

TEST_CASE("fuzz corpus replay: every seed and past crash input reads cleanly or is refused", "[bad_inputs][fuzz]") {
  const fs::path root = fs::path(SHADETOOL_SOURCE_DIR) / "fuzz" / "corpus";
  std::size_t files = 0;
  for (const char* target : {"fuzz_read_obj", "fuzz_read_ply", "fuzz_read_off", "fuzz_read_stl"}) {
    for (const auto& e : fs::directory_iterator(root / target)) {
      const std::string bytes = bytes_of(e.path());
      INFO(e.path().string());
      CHECK_NOTHROW(shadetool_fuzz::fuzz_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(),
                                             format_of(target), "replay"));
      ++files;
    }
  }
  CHECK(files >= 19);
}

TEST_CASE("fuzz corpus replay: the hostile-input corpus passes the fuzz targets' checks", "[bad_inputs][fuzz]") {
  const fs::path dir = fs::path(SHADETOOL_SOURCE_DIR) / "tests" / "bad_inputs" / "files";
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    shadetool::Format f;
    if (ext == ".obj") f = shadetool::Format::Obj;
    else if (ext == ".ply") f = shadetool::Format::Ply;
    else if (ext == ".off") f = shadetool::Format::Off;
    else if (ext == ".stl") f = shadetool::Format::Stl;
    else continue;
    const std::string bytes = bytes_of(e.path());
    INFO(e.path().string());
    CHECK_NOTHROW(shadetool_fuzz::fuzz_one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), f, "replay"));
  }
}
