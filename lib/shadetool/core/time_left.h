// time_left.h: the estimate of a stage's time left that a progress display shows (the one home of
// that rule; core/progress.h measures the fraction done and the time elapsed).
//
// Rule. After t seconds of a stage with fraction f done, at a steady rate the rest takes
//     raw = t * (1 - f) / f   seconds.
// No estimate before f >= kTimeLeftMinFraction (1%) and t >= kTimeLeftMinSeconds (1 s): the first
// blocks (caches, page faults, a BVH warming up) say little about the rate, and a number that
// starts at 300 s and falls to 8 s misleads more than none. Then the estimate is smoothed: at each
// update the previous estimate, less the time since it was made, moves a quarter of the way
// (kTimeLeftSmoothing) towards raw (exponential smoothing), so one slow or fast block does not make
// the number jump. At a steady rate raw equals the previous estimate less the time passed, so the
// estimate stays exact. It is never negative; at f = 1 it is 0.
//
// Inputs:  generation  the stage's number (ProgressMeter::Snapshot::generation): a new one restarts
//          elapsed     t, seconds since the stage began (>= 0)
//          fraction    f in [0, 1]
// Output:  seconds left, or nothing while there is no estimate.
// Degenerate: f <= 0, f or t not finite: no estimate (never a division by zero: f >= 1% is checked
// before raw is formed).
#pragma once

#include <cstdint>
#include <optional>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

constexpr double kTimeLeftMinFraction = 0.01;
constexpr double kTimeLeftMinSeconds = 1.0;
constexpr double kTimeLeftSmoothing = 0.25;

class TimeLeft {
 public:
  std::optional<double> update(std::uint64_t generation, double elapsed, double fraction);

 private:
  std::uint64_t generation_ = 0;
  bool has_estimate_ = false;
  double estimate_ = 0, estimated_at_ = 0;  // seconds left, and the elapsed time it was made at
};

}  // namespace shadetool
#pragma GCC visibility pop
