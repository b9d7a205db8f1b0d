// Robustness of every reader: any prefix of a valid file, and files with bytes flipped, either
// read or fail with shadetool::Error; nothing else (no crash, no other exception, no huge
// allocation). Run under -DSHADETOOL_SANITIZE=ON to catch out-of-bounds reads.
#include <random>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

// Reads bytes; returns true if it read, false if it threw Error. Any other exception fails.
bool reads(const std::string& bytes, Format f) {
  try {
    const Mesh m = read_mesh_from_memory(bytes, f, "fuzz");
    // what was read is consistent: indices in range, offsets increasing
    for (std::uint32_t v : m.corner_vertex) REQUIRE(v < m.num_vertices());
    for (std::size_t i = 0; i + 1 < m.face_start.size(); ++i) REQUIRE(m.face_start[i] + 3 <= m.face_start[i + 1]);
    REQUIRE(m.face_start.back() == m.num_corners());
    return true;
  } catch (const Error&) {
    return false;
  }
}

}  // namespace

TEST_CASE("robustness: truncated and corrupted files never crash", "[robustness]") {
  Mesh m = rich_mesh();
  std::mt19937 rng(42);
  for (Format f : {Format::Obj, Format::Ply, Format::Off, Format::Stl})
    for (bool binary : {true, false}) {
      WriteOptions o;
      o.format = f;
      o.binary = binary;
      const std::string good = write_mesh_to_memory(m, o);
      INFO(format_extension(f) << (binary ? " binary" : " ascii"));
      CHECK(reads(good, f));
      std::size_t failed = 0;
      for (std::size_t n = 1; n < good.size(); ++n) failed += !reads(good.substr(0, n), f);
      CHECK(failed > 0);  // most prefixes are incomplete files
      for (int trial = 0; trial < 300; ++trial) {
        std::string bad = good;
        const int flips = 1 + int(rng() % 4);
        for (int k = 0; k < flips; ++k) bad[rng() % bad.size()] = char(rng() % 256);
        reads(bad, f);
      }
    }
}
