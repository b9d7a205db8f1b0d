// Replays fuzz/corpus/fuzz_scene/ (seeds and every input the scene fuzzer ever stopped on, e.g.
// issue 21's `"intensity": 0.51e308`) through the libFuzzer target itself, in the ordinary build
// and under the sanitizers (.ci/sanitizers.sh): each scene is refused with shadetool::Error or
// keeps every invariant fuzz_scene.cpp checks, and lights its test mesh with finite colours. A
// broken invariant aborts the target, which fails this test.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <catch2/catch.hpp>

#include "../../fuzz/fuzz_scene.cpp"

namespace fs = std::filesystem;

TEST_CASE("fuzz_scene corpus replays cleanly through the fuzz target", "[fuzz][scene]") {
  const fs::path dir = fs::path(SHADETOOL_SOURCE_DIR) / "fuzz" / "corpus" / "fuzz_scene";
  REQUIRE(fs::is_directory(dir));
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    INFO(entry.path().filename().string());
    CHECK(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()) == 0);
    ++files;
  }
  CHECK(files >= 5);
}
