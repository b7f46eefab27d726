#pragma once
// How long an idle OpenMP thread of `sph` spins before it sleeps, chosen by the program.
//
// A step of a small scene holds a few parallel regions a few tens of microseconds apart. A thread
// that sleeps between them is woken for each (about 20 us); one that spins through the gaps costs
// nothing on an idle machine. When other work wants the cores, each microsecond a thread spins is
// one that work, or this program's thread that shares its core, does not get, and the scheduler
// counts it against the spinning thread. The dam break at dx 0.01 on two threads every step
// (--fixed-threads), 2-vCPU VM, a pause there 26 ns:
// * idle (quiet moments of a shared machine): spinning without end (OMP_WAIT_POLICY=active)
//   1.9-2.2 s, 1,000 pauses (26 us) 1.9-2.1 s, 400 (10 us) 2.3 s, sleeping at once (passive)
//   3.8 s, against 3.3 s on one thread;
// * a busy loop on the second core: 300,000 pauses (libgomp's default, 8 ms, longer than the
//   scheduler's slices) 421 s, 7,700 (200 us) 76 s, 1,900 (50 us) 25 s, 400 9.2 s, passive 4.9 s.
// So the spin is just long enough for the gaps of an idle machine, and the thread tuner
// (ThreadTuner.hpp) runs one thread when the machine is not idle.
//
// libgomp reads GOMP_SPINCOUNT and OMP_WAIT_POLICY once, when it initialises, before main, so the
// program sets the spin count and executes itself again. A spin count is a number of pauses, whose
// length differs by machine (26 ns in this VM, 10-140 ns elsewhere), so it is computed from a
// timed loop of pauses. Either variable set by the user is left as it is, and there is no second
// exec: the re-executed program finds GOMP_SPINCOUNT set.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>

namespace sph {

// Spin this long before sleeping: a little more than the 26 us that ran the dam break as fast as
// spinning without end (above).
inline constexpr double spinMicroseconds = 30.0;

// One pause instruction [ns]: the fastest of a few short timed loops (a loop that lost its core
// part-way reads slower, never faster).
inline double pauseNanoseconds() {
  using clock = std::chrono::steady_clock;
  constexpr int pauses = 2000;
  double best = 1e9;
  for (int trial = 0; trial < 5; ++trial) {
    const auto start = clock::now();
    for (int k = 0; k < pauses; ++k) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#else
      asm volatile("" ::: "memory");
#endif
    }
    best = std::min(best, std::chrono::duration<double, std::nano>(clock::now() - start).count());
  }
  return best / pauses;
}

// Sets GOMP_SPINCOUNT for spinMicroseconds and executes this program again with the same
// arguments; returns when the user chose the wait policy, or the exec failed (then OpenMP's default
// stays).
inline void chooseWaitPolicy(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  const double pauses = spinMicroseconds * 1000.0 / std::max(1.0, pauseNanoseconds());
  const std::string count = std::to_string(static_cast<long>(std::max(1.0, pauses)));
  if (setenv("GOMP_SPINCOUNT", count.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("GOMP_SPINCOUNT");  // no exec: say nothing the running library does not do
}

}  // namespace sph
