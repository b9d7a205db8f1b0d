// time_left.cpp
#include <shadetool/core/time_left.h>

#include <algorithm>
#include <cmath>

namespace shadetool {

std::optional<double> TimeLeft::update(std::uint64_t generation, double elapsed, double fraction) {
  if (generation != generation_) {  // a new stage: what was learnt about the last one is void
    generation_ = generation;
    has_estimate_ = false;
  }
  if (!std::isfinite(elapsed) || !std::isfinite(fraction)) return std::nullopt;
  if (fraction >= 1) return 0.0;
  if (fraction < kTimeLeftMinFraction || elapsed < kTimeLeftMinSeconds) return std::nullopt;
  const double raw = elapsed * (1 - fraction) / fraction;  // divisor checked: fraction >= 1%
  if (!has_estimate_) {
    estimate_ = raw;
  } else {
    const double carried = std::max(0.0, estimate_ - (elapsed - estimated_at_));
    estimate_ = carried + kTimeLeftSmoothing * (raw - carried);
  }
  has_estimate_ = true;
  estimated_at_ = elapsed;
  estimate_ = std::max(0.0, estimate_);
  return estimate_;
}

}  // namespace shadetool
