// progress.h: how far a long stage has gone (reading a large file, occlusion, shadows, render,
// repair), for a display that shows a fraction and the time left (core/time_left.h).
//
// A kernel that can run for seconds takes a `ProgressSink*` (null by default: nobody listens) and
//   report_begin(sink, "occlusion", total)   once, on the calling thread, before the work;
//                                            `stage` is a string literal (kept as a pointer),
//                                            `total` the stage's units (points, rows, bytes); 0:
//                                            no fraction is known, only the name
//   report_advance(sink, units)              from any thread (TBB workers), once per block of
//                                            work, never per element; the units advanced over
//                                            the stage add up to exactly `total`
// With a null sink both are one predicted branch: a kernel's cost without a listener is unchanged
// (bench/core/results.md has the measured ratio). A kernel never waits for, or is stopped by, a
// sink: progress is reporting only, there is no cancellation.
//
// ProgressMeter is the sink a display polls: advance() is a relaxed atomic add (safe and cheap
// from many threads at once), snapshot() reads the stage, units done and total, and the seconds
// since the stage began by the meter's clock (a function, so tests drive it by hand). Snapshots
// are consistent per stage: a snapshot never mixes one stage's name with another's total.
//
// ProgressCursor turns a serial reader's position (bytes consumed) into advances: at(pos) advances
// by pos minus the last position reported.
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  virtual void begin(const char* stage, std::uint64_t total) = 0;
  virtual void advance(std::uint64_t units) = 0;
};

inline void report_begin(ProgressSink* sink, const char* stage, std::uint64_t total) {
  if (sink) sink->begin(stage, total);
}
inline void report_advance(ProgressSink* sink, std::uint64_t units) {
  if (sink) sink->advance(units);
}

// Seconds on std::chrono::steady_clock (the meter's default clock).
double steady_seconds();

class ProgressMeter final : public ProgressSink {
 public:
  using Clock = double (*)();
  explicit ProgressMeter(Clock clock = steady_seconds) : clock_(clock) {}

  void begin(const char* stage, std::uint64_t total) override;
  void advance(std::uint64_t units) override { done_.fetch_add(units, std::memory_order_relaxed); }

  struct Snapshot {
    const char* stage = nullptr;   // null before the first begin()
    std::uint64_t done = 0, total = 0;
    std::uint64_t generation = 0;  // counts begin() calls: a new stage restarts its estimate
    double elapsed = 0;            // seconds since the stage began
    bool has_fraction() const { return total > 0; }
    // done/total in [0, 1] (done is capped at total); 0 without a total.
    double fraction() const;
  };
  Snapshot snapshot() const;

 private:
  Clock clock_;
  mutable std::mutex mutex_;  // begin() and snapshot(); advance() does not take it
  const char* stage_ = nullptr;
  std::uint64_t total_ = 0, generation_ = 0;
  double started_ = 0;
  std::atomic<std::uint64_t> done_{0};
};

class ProgressCursor {
 public:
  ProgressCursor() = default;
  explicit ProgressCursor(ProgressSink* sink) : sink_(sink) {}
  ProgressSink* sink() const { return sink_; }
  void at(std::uint64_t position) {
    if (!sink_ || position <= reported_) return;
    sink_->advance(position - reported_);
    reported_ = position;
  }

 private:
  ProgressSink* sink_ = nullptr;
  std::uint64_t reported_ = 0;
};

}  // namespace shadetool
#pragma GCC visibility pop
