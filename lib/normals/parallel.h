// parallel.h: how the normals kernels split work over threads (internal to lib/normals).
//
// parallel_ranges(n, body): calls body(begin, end) on disjoint ranges covering [0, n). Small
// problems (n < kSerialBelow) run serially on the calling thread: below that size, starting TBB
// tasks costs more than it saves. Each range writes only its own outputs, so results do not
// depend on the number of threads.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadetool::normals_detail {

constexpr std::size_t kSerialBelow = 1 << 15;

template <class Body>
void parallel_ranges(std::size_t n, const Body& body, std::size_t grain = 1 << 13) {
  if (n < kSerialBelow) {
    if (n > 0) body(std::size_t(0), n);
    return;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}

// parallel_blocks(n, body): body(b) for every block index b in [0, n), blocks in parallel (each
// block is already a sizeable piece of work chosen by the caller; one block runs inline).
template <class Body>
void parallel_blocks(std::size_t n, const Body& body) {
  if (n == 1) {
    body(std::size_t(0));
    return;
  }
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t b) { body(b); });
}

}  // namespace shadetool::normals_detail
