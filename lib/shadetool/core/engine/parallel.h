// parallel.h: the one policy for splitting a loop over TBB threads (machinery; not installed).
//
// kSerialBelow: below this many elements (faces, vertices, normals) a loop runs serially on the
// calling thread: starting TBB tasks costs more than it saves there (bench/normals/results,
// bench/transform). Every pass that chooses between one part and several uses this threshold.
//
// parallel_ranges(n, body): body(begin, end) on disjoint ranges covering [0, n).
// count_over_ranges(n, body): the same with body returning a count; returns the sum.
// parallel_blocks(n, body): body(b) for every block b in [0, n), the blocks chosen by the caller.
// Each range or block writes only its own outputs, so results do not depend on the thread count.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

namespace shadetool::engine {

constexpr std::size_t kSerialBelow = std::size_t(1) << 15;
constexpr std::size_t kDefaultGrain = std::size_t(1) << 13;

template <class Body>
void parallel_ranges(std::size_t n, const Body& body, std::size_t grain = kDefaultGrain) {
  if (n < kSerialBelow) {
    if (n > 0) body(std::size_t(0), n);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}

template <class Body>
std::size_t count_over_ranges(std::size_t n, const Body& body, std::size_t grain = kDefaultGrain) {
  if (n < kSerialBelow) return n > 0 ? body(std::size_t(0), n) : 0;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, grain), std::size_t(0),
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t acc) { return acc + body(r.begin(), r.end()); },
      [](std::size_t a, std::size_t b) { return a + b; });
}

// One block runs inline (each block is already a sizeable piece of work).
template <class Body>
void parallel_blocks(std::size_t n, const Body& body) {
  if (n == 1) {
    body(std::size_t(0));
    return;
  }
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t b) { body(b); });
}

}  // namespace shadetool::engine
