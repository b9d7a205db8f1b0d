// bulk_reserve.h: capacity for a large array that a reader is about to fill in one go.
//
// Inputs:  v  a vector (its contents are kept), n  the capacity wanted
// Reserves n elements and, for blocks of 4 MiB or more on Linux, asks the kernel to back them
// with transparent huge pages (madvise MADV_HUGEPAGE) before anything is written. Filling fresh
// memory is most of the cost of reading a binary mesh: with 4 KiB pages every 4 KiB written
// is one page fault (measured on the development VM: 24 MB of new arrays took 16 ms in 4 KiB
// pages, 3-8 ms in huge pages; bench/io). Where huge pages are off or unavailable the advice is
// ignored and nothing changes. Only the 2 MiB-aligned interior of the block is advised.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shadetool {

template <class T>
void reserve_bulk(std::vector<T>& v, std::size_t n) {
  const bool fresh = v.capacity() < n;
  v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(1) << 21;
  if (!fresh || n * sizeof(T) < 2 * kHuge) return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t end = begin + n * sizeof(T);
  const std::uintptr_t b = (begin + kHuge - 1) & ~(kHuge - 1), e = end & ~(kHuge - 1);
  if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
  (void)fresh;
#endif
}

}  // namespace shadetool
