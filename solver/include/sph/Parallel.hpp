#pragma once
// When a loop over particles is worth a team of threads, and how the team splits it.
#include <omp.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace sph {

// Loops that cost a few ns a particle (the time step's maxima, the predictor and corrector, the
// interaction set, the cell list's counting sort) run on one thread below this many particles.
// What a parallel region costs depends on whether idle threads sleep or spin:
// * OMP_WAIT_POLICY=passive (the scripts set it for ctest -j2): waking a sleeping thread costs
//   about 20 us a region on the 2-core machine (measured with an empty region), so 8,192;
// * otherwise (active, or OpenMP's default, which spins a while before sleeping) about a
//   microsecond, so 1,024: the dam break at dx 0.005 (5,000 particles, 2 threads, active, to
//   t = 0.4 s) took 5.5 s instead of 8.4 s with these loops parallel from 512 particles, and at
//   dx 0.01 (1,250) 3.1 s either way (best of three interleaved runs each).
// The loops' results do not depend on the thread count either way
// (verification/core/ParallelStepTest.cpp).
inline std::int64_t parallelFrom() {
  static const std::int64_t from = [] {
    const char* policy = std::getenv("OMP_WAIT_POLICY");
    std::string p = policy ? policy : "";
    for (char& c : p) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return p == "passive" ? std::int64_t{8192} : std::int64_t{1024};
  }();
  return from;
}

// Thread t's share of a loop over [0, n) split into contiguous ranges, one a thread. Every loop
// over the particles in a step uses this split, so that a thread reads what it wrote before.
struct Share {
  std::int64_t begin, end;
};
inline Share shareOf(std::int64_t n, int t, int nt) {
  return {n * t / nt, n * (t + 1) / nt};
}

// The same over [0, n) where only [0, leading) is split evenly and the last thread also takes
// [leading, n): the shares of a loop over the interaction set (the fluid, then the halo of
// images) that match the fluid's, so that a thread reads the fluid entries it wrote.
inline Share shareOf(std::int64_t n, std::int64_t leading, int t, int nt) {
  return {leading * t / nt, t + 1 < nt ? leading * (t + 1) / nt : n};
}

// Walks a share up to its last `prefetchTail` items, then down. Walked up to its end, a share has
// the core's hardware prefetcher read on into the next share, so that the next thread finds the
// lines it is about to write in the other core's cache, at every loop. Measured on the 2-core
// machine (vCPUs on cores that share a cache): a loop over seven arrays of 1,250 items, split in
// two, took the second half's thread 49 ms against the first's 37 ms (20,000 passes), either
// thread, 37-40 ms with the first half's last 64 items walked down; in the dam break at dx 0.01
// on 2 threads, walking every loop of a step so cut it from 3.40-3.53 s to 2.93-3.00 s with the
// vCPUs on cores that do not share a cache, and from 1.97-2.05 s to 1.90-1.96 s when they do.
inline constexpr std::int64_t prefetchTail = 256;  // twice the 128 that took all of the 49 - 37 ms
// (f is copied: the loop's own copy, which no store can change, keeps what it captured by value
// in registers.)
template <class F>
void walk(Share s, const F& body) {
  F f = body;
  const std::int64_t turn = std::max(s.begin + (s.end - s.begin) / 2, s.end - prefetchTail);
  for (std::int64_t i = s.begin; i < turn; ++i) f(i);
  for (std::int64_t i = s.end; i-- > turn;) f(i);
}

// f(i) for every i in [0, n), each thread of the team its share (one thread below parallelFrom).
template <class F>
void forEachInShares(std::int64_t n, F&& f) {
#pragma omp parallel if (n >= parallelFrom())
  walk(shareOf(n, omp_get_thread_num(), omp_get_num_threads()), f);
}

}  // namespace sph
