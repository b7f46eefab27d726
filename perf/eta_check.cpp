// Issue 37: the progress line's ETA on a real run. Steps a scene as `sph run` does (the thread
// tuner choosing the count, the diagnostics every series_every steps; no run file), feeds
// RemainingTime as sph run does, and prints at 5, 10, 25, 50 and 75 % of the simulated time the
// ETA the progress line would show, the wall time that was really left, and what an average since
// program start over the simulated time so far would have shown.
//
//   eta_check SCENE [--threads N]
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "sph/Diagnostics.hpp"
#include "sph/InitialParticles.hpp"
#include "sph/RemainingTime.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"
#include "sph/ThreadTuner.hpp"
#include "sph/WaitPolicy.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Mark {
  double fraction, wall, eta, sinceStart;
};

template <int D>
int run(const sph::Scene& scene) {
  const auto start = Clock::now();
  auto since = [&](Clock::time_point t) {
    return std::chrono::duration<double>(t - start).count();
  };
  sph::Simulation<D> sim(scene, sph::latticeParticles<D>(scene));
  sim.keepCellOrder(10);  // as sph run
  sim.prepare();
  sph::RemainingTime remaining(scene.endTime);
  remaining.observe(since(Clock::now()), sim.time(), sim.step());
  const int maxThreads = omp_get_max_threads();
  sph::ThreadTuner tuner(maxThreads);
  std::vector<Mark> marks;
  for (double f : {0.05, 0.10, 0.25, 0.50, 0.75}) marks.push_back({f, 0, 0, 0});
  std::size_t next = 0;
  while (sim.time() < scene.endTime * (1 - 1e-12)) {
    omp_set_num_threads(tuner.threads());
    const auto stepStart = Clock::now();
    if (sim.advance(scene.endTime - sim.time())) {
      std::fprintf(stderr, "eta_check: %s failed at t = %g\n", scene.file.c_str(), sim.time());
      return 3;
    }
    const auto stepEnd = Clock::now();
    tuner.took(std::chrono::duration<double>(stepEnd - stepStart).count());
    const double wall = since(stepEnd);
    remaining.observe(wall, sim.time(), sim.step());
    if (sim.step() % scene.seriesEvery == 0)
      (void)sph::diagnose<D>(scene, sim.particles(), sim.interactionSet());
    if (next < marks.size() && sim.time() >= marks[next].fraction * scene.endTime) {
      marks[next].wall = wall, marks[next].eta = remaining.seconds();
      marks[next].sinceStart = wall * (scene.endTime - sim.time()) / sim.time();
      ++next;
    }
  }
  const double total = since(Clock::now());
  std::printf("%s: %zu particles, %ld steps, %.2f s, %.0f %% of the steps on %d threads\n",
              scene.name.c_str(), sim.particles().size(), sim.step(), total,
              100 * tuner.shareOnAll(), maxThreads);
  std::printf("| done | ETA [s] | left [s] | ETA / left | average since start [s] |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const Mark& m : marks)
    std::printf("| %.0f %% | %.2f | %.2f | %.2f | %.2f |\n", 100 * m.fraction, m.eta,
                total - m.wall, m.eta / (total - m.wall), m.sinceStart);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  sph::chooseWaitPolicy(argv);  // as sph does
  if (argc < 2) {
    std::fprintf(stderr, "usage: eta_check SCENE [--threads N]\n");
    return 2;
  }
  for (int a = 2; a + 1 < argc; ++a)
    if (std::strcmp(argv[a], "--threads") == 0) omp_set_num_threads(std::stoi(argv[a + 1]));
  const sph::Scene scene = sph::readScene(argv[1]);
  switch (scene.dimension) {
    case 1:
      return run<1>(scene);
    case 2:
      return run<2>(scene);
    default:
      return run<3>(scene);
  }
}
