// image.h: what the renderer produces: a linear float RGB image, row 0 at the top.
//
// Shape:  rgb  height * width * 3 floats, linear (not sRGB-encoded), unclamped; pixel (x, y) at
//              3 * (y * width + x). The writers (io/image_io.h: PNG, PFM) encode it.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// An allocator whose resize() leaves new floats uninitialised: the renderer writes every pixel
// exactly once, so zero-filling a 1920x1080 image first (25 MB) would only double the memory
// traffic (bench/render/results.md).
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) {}
  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

struct ImageRGB {
  int width = 0, height = 0;
  std::vector<float, DefaultInitAllocator<float>> rgb;

  float* pixel(int x, int y) { return rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x)); }
  const float* pixel(int x, int y) const {
    return rgb.data() + 3 * (std::size_t(y) * std::size_t(width) + std::size_t(x));
  }
};

}  // namespace shadetool
#pragma GCC visibility pop
