// progress.cpp
#include <shadetool/core/progress.h>

#include <algorithm>
#include <chrono>

namespace shadetool {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void ProgressMeter::begin(const char* stage, std::uint64_t total) {
  std::lock_guard<std::mutex> lock(mutex_);
  stage_ = stage;
  total_ = total;
  ++generation_;
  started_ = clock_();
  done_.store(0, std::memory_order_relaxed);
}

double ProgressMeter::Snapshot::fraction() const {
  if (total == 0) return 0;
  return double(std::min(done, total)) / double(total);  // divisor checked
}

ProgressMeter::Snapshot ProgressMeter::snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  Snapshot s;
  s.stage = stage_;
  s.total = total_;
  s.generation = generation_;
  s.done = done_.load(std::memory_order_relaxed);
  s.elapsed = stage_ ? clock_() - started_ : 0;
  return s;
}

}  // namespace shadetool
