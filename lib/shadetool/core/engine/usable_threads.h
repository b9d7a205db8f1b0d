// usable_threads.h: how many threads a parallel pass can count on here and now: the current TBB
// arena's concurrency, capped by a global_control limit (shadetool's -j / --threads, or a
// benchmark's). Passes that split work into one part per thread use it to pick the number of
// parts; a pass whose result must not depend on it documents why it does not.
#pragma once

#include <algorithm>
#include <cstddef>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

namespace shadetool {

inline std::size_t usable_threads() {
  return std::min<std::size_t>(std::size_t(tbb::this_task_arena::max_concurrency()),
                               tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
}

}  // namespace shadetool
