// Tests of core/repeated_index: faces written out by hand, with and without a repeated index.
#include <catch2/catch.hpp>

#include <numeric>
#include <vector>

#include <shadetool/core/repeated_index.h>

using namespace shadetool;

namespace {
bool repeats(const std::vector<std::uint32_t>& face) {
  std::vector<std::uint32_t> scratch;
  return has_repeated_index(face.data(), std::uint32_t(face.size()), scratch);
}
}  // namespace

TEST_CASE("a repeated index is found next to itself, apart, and in faces of more than 16 corners", "[core][repeated_index]") {
  CHECK(!repeats({}));
  CHECK(!repeats({7}));
  CHECK(!repeats({0, 1, 2}));
  CHECK(repeats({0, 0, 1}));
  CHECK(repeats({1, 0, 1}));     // first and last: neighbours around the face
  CHECK(repeats({4, 5, 4, 6}));  // apart: (a, b, a, c)
  CHECK(!repeats({4, 5, 6, 7}));
  std::vector<std::uint32_t> big(40);
  std::iota(big.begin(), big.end(), 100u);  // 100 .. 139, all distinct (the sorting path)
  CHECK(!repeats(big));
  big[39] = 100;                            // the last corner repeats the first
  CHECK(repeats(big));
  big[39] = 139;
  big[17] = 120;                            // two corners deep inside
  CHECK(repeats(big));
}
