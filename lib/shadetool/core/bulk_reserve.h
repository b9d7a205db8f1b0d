// bulk_reserve.h: memory plumbing for large arrays: capacity for an array a reader is about to fill in
// one go, and BulkVector (unzeroed, huge-page) arrays, which public result types (EdgeAdjacency,
// ConsistentWinding) hold, so this header is public.
//
// Inputs:  v  a vector (its contents are kept), n  the capacity wanted
// Reserves n elements and, for blocks of 4 MiB or more on Linux, asks the kernel to back them
// with transparent huge pages (madvise MADV_HUGEPAGE) before anything is written. Filling fresh
// memory is most of the cost of reading a binary mesh: with 4 KiB pages every 4 KiB written
// is one page fault (bench/io/results.md). Where huge pages are off or unavailable the advice is
// ignored and nothing changes. Only the 2 MiB-aligned interior of the block is advised.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// Asks the kernel to back the 2 MiB-aligned interior of [p, p + bytes) with transparent huge pages
// (madvise MADV_HUGEPAGE), for blocks of 4 MiB or more on Linux; call it before the block is first
// written. Elsewhere, or where huge pages are off, nothing changes. The one home of the advice:
// reserve_bulk, the fit's blocks (fit/least_squares_fit.cpp) and the glTF writer call it.
inline void advise_huge_pages(const void* p, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(1) << 21;
  if (!p || bytes < 2 * kHuge) return;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(p), end = begin + bytes;
  const std::uintptr_t b = (begin + kHuge - 1) & ~(kHuge - 1), e = end & ~(kHuge - 1);
  if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

template <class T, class Allocator>
void reserve_bulk(std::vector<T, Allocator>& v, std::size_t n) {
  const bool fresh = v.capacity() < n;
  v.reserve(n);
  if (fresh) advise_huge_pages(v.data(), n * sizeof(T));
}

// An allocator for large scratch and output arrays: value-initialisation is default-initialisation
// (resize(n) on a vector of a trivial type leaves the new elements unwritten: no serial memset of
// memory that the next pass overwrites in full, a cost on top of the page faults),
// and blocks of 1 MiB or more are 2 MiB-aligned and advised as huge pages as a whole (one fault
// and one kernel-zeroed page per 2 MiB instead of 512 faults; reserve_bulk can only advise the
// aligned interior of a block malloc placed); without it the pairing of bench/repair spent much of
// its time in the kernel faulting in 4 KiB pages (bench/repair/results.md).
// Copies, comparisons and data() are as for std::vector (same element type; only the allocator
// differs).
template <class T>
struct UninitializedAllocator {
  using value_type = T;
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  static constexpr std::size_t kHuge = std::size_t(1) << 21;
  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHuge / 2) return std::allocator<T>().allocate(n);
    if (bytes > std::size_t(-1) - kHuge) throw std::bad_alloc();  // the rounding below would wrap
    const std::size_t rounded = (bytes + kHuge - 1) & ~(kHuge - 1);
    void* p = nullptr;
    if (posix_memalign(&p, kHuge, rounded) != 0) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    ::madvise(p, rounded, MADV_HUGEPAGE);
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < kHuge / 2) std::allocator<T>().deallocate(p, n);
    else std::free(p);
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) == 0) ::new (static_cast<void*>(p)) U;
    else ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const UninitializedAllocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const UninitializedAllocator<U>&) const noexcept { return false; }
};

template <class T>
using BulkVector = std::vector<T, UninitializedAllocator<T>>;

}  // namespace shadetool
#pragma GCC visibility pop
