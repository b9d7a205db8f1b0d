// parallel_ranges.h: how the transform kernels split a loop over threads (internal to
// lib/transform; the same policy as lib/normals/parallel.h, kept separate so that neither module
// reaches into the other's internals).
//
// count_over_ranges(n, body): calls body(begin, end) -> std::size_t on disjoint ranges covering
// [0, n) and returns the sum of the results. Below kSerialBelow elements it runs serially on the
// calling thread (starting TBB tasks costs more than it saves there). Each range writes only its
// own elements, so the results do not depend on the number of threads.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace shadetool::transform_detail {

constexpr std::size_t kSerialBelow = 1 << 15;

template <class Body>
std::size_t count_over_ranges(std::size_t n, const Body& body, std::size_t grain = 1 << 13) {
  if (n < kSerialBelow) return n > 0 ? body(std::size_t(0), n) : 0;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, grain), std::size_t(0),
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t acc) { return acc + body(r.begin(), r.end()); },
      [](std::size_t a, std::size_t b) { return a + b; });
}

}  // namespace shadetool::transform_detail
