// point_ranges.h: how visibility queries split their points over TBB threads (machinery).
//
// core/engine/parallel.h's threshold counts cheap elements (a face, a vertex); a visibility point
// costs `rays_per_point` BVH traversals (about a microsecond each), so here the serial threshold
// and the grain are counted in rays: a range holds about kRaysPerTask rays. Each point writes only
// its own outputs and its rays depend only on its own seed, so results are the same bits for any
// thread count and any split.
#pragma once

#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace shadetool::visibility_engine {

constexpr std::size_t kRaysPerTask = 2048;

template <class Body>
void parallel_point_ranges(std::size_t n, std::size_t rays_per_point, const Body& body) {
  const std::size_t per = std::max<std::size_t>(1, rays_per_point);
  if (n == 0) return;
  if (n * per <= kRaysPerTask) {
    body(std::size_t(0), n);
    return;
  }
  const std::size_t grain = std::max<std::size_t>(1, kRaysPerTask / per);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}

}  // namespace shadetool::visibility_engine
