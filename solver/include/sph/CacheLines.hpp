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

namespace sph {

inline constexpr std::size_t cacheLine = 64;

template <class T>
struct CacheLineAllocator {
  using value_type = T;
  CacheLineAllocator() = default;
  template <class U>
  constexpr CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {  // whole lines, so that no other allocation shares the last one
    const std::size_t bytes = (n * sizeof(T) + cacheLine - 1) / cacheLine * cacheLine;
    return static_cast<T*>(::operator new (bytes, std::align_val_t{cacheLine}));
  }
  void deallocate(T* p, std::size_t) noexcept {
    ::operator delete (p, std::align_val_t{cacheLine});
  }
  template <class U>
  bool operator==(const CacheLineAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using LineVector = std::vector<T, CacheLineAllocator<T>>;

}  // namespace sph
