#pragma once
// When a loop over particles is worth a team of threads.
#include <cstdint>

namespace sph {

// Loops that cost a few ns a particle (the time step's maxima, the predictor and corrector, the
// cell list's counting sort) run on one thread below this many particles: there they take less
// than it costs to wake a sleeping thread (OMP_WAIT_POLICY=passive, which the scripts set: about
// 20 us a parallel region on the 2-core machine, measured with an empty region).
constexpr std::int64_t parallelFrom = 8192;

}  // namespace sph
