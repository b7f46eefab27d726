#pragma once
// Arrays that threads write in shares (the particles' fields, the interaction set, the rates, the
// pair loop's copies and lists) start on a cache line and end on one. From the heap, one array's
// end and the next array's start shared a line; the last thread writes every array's end and the
// first thread its start, so such lines went from core to core in every loop of a step. The dam
// break at dx 0.01 on two threads whose vCPUs do not share a cache: 2.81-3.33 s (median 2.90 s,
// 14 runs) -> 2.51-2.84 s (median 2.67 s, 11 runs), alternated with the parent; the same bits; no
// change when they share one.
#include <cstddef>
#include <new>
#include <vector>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sph {

inline constexpr std::size_t cacheLine = 64;
// Arrays of 4 MiB and more (a field of 5e5 particles and more) on 2 MiB pages where the kernel
// gives them (transparent huge pages in madvise mode, as here), so that a sweep over the
// particles misses the TLB less. The force evaluation at 1e6 particles (makeBlock, best of 7,
// medians of 6 alternated runs): one thread 137.5 -> 132.0 ns a particle with lists built,
// 95.0 -> 92.4 kept; two threads 71.7 -> 69.1 built, 49.4 -> 48.8 kept.
inline constexpr std::size_t hugePage = std::size_t{2} << 20, hugeFrom = std::size_t{4} << 20;

template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  constexpr CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {  // whole lines, so that no other allocation shares the last one
    const std::size_t bytes = (n * sizeof(T) + cacheLine - 1) / cacheLine * cacheLine;
    if (bytes < hugeFrom)
      return static_cast<T*>(::operator new (bytes, std::align_val_t{cacheLine}));
    const std::size_t whole = (bytes + hugePage - 1) / hugePage * hugePage;
    void* p = ::operator new (whole, std::align_val_t{hugePage});
#if defined(__linux__)
    madvise(p, whole, MADV_HUGEPAGE);  // a hint: where the kernel has none to give, no change
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = (n * sizeof(T) + cacheLine - 1) / cacheLine * cacheLine;
    ::operator delete (p, std::align_val_t{bytes < hugeFrom ? cacheLine : hugePage});
  }
  template <class U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using LineVector = std::vector<T, CacheLineAllocator<T>>;

}  // namespace sph
