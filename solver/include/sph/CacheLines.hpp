#pragma once
// Arrays that threads write in shares (the particles' fields, the interaction set, the rates, the
// pair loop's copies and lists) start on a cache line and end on one. From the heap, one array's
// end and the next array's start shared a line; the last thread writes every array's end and the
// first thread its start, so such lines went from core to core in every loop of a step. The dam
// break at dx 0.01 on two threads whose vCPUs do not share a cache: 2.81-3.33 s (median 2.90 s,
// 14 runs) -> 2.51-2.84 s (median 2.67 s, 11 runs), alternated with the parent; the same bits; no
// change when they share one.
#include <cstddef>
#include <limits>
#include <new>
#include <utility>
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
    if (n > (std::numeric_limits<std::size_t>::max() / 2 - hugePage) / sizeof(T))
      throw std::bad_array_new_length();  // (the rounding below would overflow)
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

// The same for an array whose items are all stored before they are read: resize() leaves the new
// items unset (no pass that zeroes them, no page touched before its first store), so that a
// thread's copy of a part of a large array costs memory for that part only.
template <class T>
struct UnsetLineAllocator : CacheLineAllocator<T> {
  UnsetLineAllocator() = default;
  template <class U>
  constexpr UnsetLineAllocator(const UnsetLineAllocator<U>&) noexcept {}
  template <class U>
  struct rebind {
    using other = UnsetLineAllocator<U>;
  };
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};
template <class T>
using UnsetLineVector = std::vector<T, UnsetLineAllocator<T>>;

}  // namespace sph
