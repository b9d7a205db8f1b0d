// repeated_index.cpp: see repeated_index.h.
#include <shadetool/core/repeated_index.h>

#include <algorithm>

namespace shadetool {

bool has_repeated_index(const std::uint32_t* v, std::uint32_t n, std::vector<std::uint32_t>& scratch) {
  if (n <= 16) {
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j)
        if (v[i] == v[j]) return true;
    return false;
  }
  scratch.assign(v, v + n);
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

}  // namespace shadetool
