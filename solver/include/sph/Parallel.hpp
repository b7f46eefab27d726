#pragma once
// When a loop over particles is worth a team of threads.
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

}  // namespace sph
