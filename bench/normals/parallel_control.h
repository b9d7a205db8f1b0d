// parallel_control.h: a trivially parallel loop (two halves of 2.5M square roots each, one per TBB
// task) timed beside the kernels. Its 2-thread speed-up is the best this machine gives during the
// run: near 1 means the second core was busy, and 2-thread rows of that run mean little.
#pragma once

#include <cmath>

#include <tbb/parallel_for.h>

// Returns the sum so that the work cannot be optimised away; callers add it to a sink.
inline double parallel_sqrt_control() {
  double part[2] = {0, 0};
  tbb::parallel_for(0, 2, [&](int k) {
    double acc = 0;
    for (int i = 0; i < 2500000; ++i) acc += std::sqrt(double(i + k));
    part[k] = acc;
  });
  return part[0] + part[1];
}
