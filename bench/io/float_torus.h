// float_torus.h: the I/O benchmarks' shared test mesh and timer (bench/io, bench/gltf).
//   float_torus(nu, nv)  a closed torus (R 1, r 0.4) of nu x nv vertices and 2 nu nv triangles,
//                        positions rounded to float (so every format stores them exactly)
//   median_ms(reps, f)   the median wall time of `reps` calls of f, in milliseconds
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <shadetool/core/math_constants.h>
#include <shadetool/core/mesh.h>

namespace shadetool::bench {

inline Mesh float_torus(int nu, int nv) {
  Mesh m;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = kTwoPi * i / nu, v = kTwoPi * j / nv;
      m.add_vertex({double(float((1 + 0.4 * std::cos(v)) * std::cos(u))), double(float((1 + 0.4 * std::cos(v)) * std::sin(u))),
                    double(float(0.4 * std::sin(v)))});
    }
  auto id = [&](int i, int j) { return std::uint32_t((j % nv) * nu + (i % nu)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  m.precision = ValuePrecision::Float;
  return m;
}

inline double median_ms(int reps, const std::function<void()>& f) {
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

}  // namespace shadetool::bench
