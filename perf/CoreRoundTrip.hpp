#pragma once
// Which cores the two threads run on, as far as it shows in timings. A VM's host may place the two
// vCPUs on cores that share a cache or on cores that do not, and may change that while a benchmark
// runs. On the 2-core machine a cache line's round trip between the two threads took either 50-80
// ns or 310-380 ns, changing every few seconds to minutes, and every 2-thread figure follows it:
// the force evaluation at 1,024 particles (a 2-D block, all terms) took 70 us in the first case
// and 100-110 us in the second, one thread 108 us; the dam break at dx 0.01 on two threads 2.5-2.8
// s or 4.3-4.7 s (issue 7). The benchmarks print it beside their 2-thread figures.
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <vector>

namespace sph::perf {

// The round trip of one cache line between threads 0 and 1 of a team [ns]: the median of 5 runs
// of 20,000 trips; -1 where the team has no second thread.
inline double coreRoundTrip() {
  using Clock = std::chrono::steady_clock;
  constexpr long trips = 20000;
  struct alignas(64) Line {  // a cache line of its own, on no thread's stack
    std::atomic<long> value{0};
  };
  static Line line;
  std::atomic<long>& flag = line.value;
  std::vector<double> runs;
  for (int run = 0; run < 5; ++run) {
    flag = 0;
    double ns = -1;
#pragma omp parallel num_threads(2)
    if (omp_get_num_threads() == 2) {
      if (omp_get_thread_num() == 0) {
        const auto t0 = Clock::now();
        for (long k = 0; k < trips; ++k) {
          flag.store(2 * k + 1, std::memory_order_release);
          while (flag.load(std::memory_order_acquire) != 2 * k + 2) {
          }
        }
        ns = 1e9 * std::chrono::duration<double>(Clock::now() - t0).count() / trips;
      } else {
        for (long k = 0; k < trips; ++k) {
          while (flag.load(std::memory_order_acquire) != 2 * k + 1) {
          }
          flag.store(2 * k + 2, std::memory_order_release);
        }
      }
    }
    runs.push_back(ns);
  }
  std::sort(runs.begin(), runs.end());
  return runs[runs.size() / 2];
}

}  // namespace sph::perf
