// A ProgressSink (core/progress.h) for tests: it records every stage a kernel begins and checks,
// at every advance, what a display relies on: no advance outside a stage, the units done never
// beyond the stage's total (a fraction above 1), and (in done()) every stage ending at exactly its
// total (a fraction of exactly 1). Advances come from TBB workers: a mutex guards the record.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include <shadetool/core/progress.h>

namespace shadetool::testing {

class RecordingProgress final : public ProgressSink {
 public:
  struct Stage {
    std::string name;
    std::uint64_t total = 0, done = 0;
    std::size_t advances = 0;
    std::vector<double> fractions;  // after each advance, in the order the advances arrived
  };

  void begin(const char* stage, std::uint64_t total) override {
    std::lock_guard<std::mutex> lock(mutex_);
    stages_.push_back({stage, total, 0, 0, {}});
  }
  void advance(std::uint64_t units) override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stages_.empty()) {
      ++advances_outside_a_stage_;
      return;
    }
    Stage& s = stages_.back();
    s.done += units;
    ++s.advances;
    if (s.done > s.total) ++overshoots_;
    s.fractions.push_back(s.total > 0 ? double(s.done) / double(s.total) : 0.0);  // divisor checked
  }

  const std::vector<Stage>& stages() const { return stages_; }
  std::size_t overshoots() const { return overshoots_; }
  std::size_t advances_outside_a_stage() const { return advances_outside_a_stage_; }
  // Every stage's fractions never fall and end at exactly 1 (done == total).
  bool every_stage_monotone_and_complete() const {
    for (const Stage& s : stages_) {
      if (s.done != s.total) return false;
      for (std::size_t i = 1; i < s.fractions.size(); ++i)
        if (s.fractions[i] < s.fractions[i - 1]) return false;
      if (!s.fractions.empty() && s.fractions.back() != 1.0) return false;
    }
    return true;
  }

 private:
  std::mutex mutex_;
  std::vector<Stage> stages_;
  std::size_t overshoots_ = 0, advances_outside_a_stage_ = 0;
};

}  // namespace shadetool::testing
