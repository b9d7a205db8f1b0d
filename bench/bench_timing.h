// bench_timing.h: the two timing helpers the benchmarks share (bench/fit, bench/visibility).
//   now_ms   the steady clock in milliseconds (differences only: its epoch is unspecified)
//   cpu_ms   this process's CPU time in milliseconds, every thread's (on a machine shared with other
//            jobs it moves less than the wall clock; for parallel code it is the work, not the wait)
//   median   the median of a set of times (upper median for an even count; the set is copied)
#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

inline double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
