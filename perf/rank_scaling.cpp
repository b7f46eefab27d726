// rank_scaling SCENE PARTICLES STEPS [weak|strong]: the scaling of a run over the processes of
// mpirun (sph/DomainDecomposition.hpp). SCENE at the dx that gives it about PARTICLES particles a
// process (weak) or in all (strong), STEPS steps after 20 unmeasured ones; rank 0 prints one JSON
// line: processes, threads a process, whether they outnumber the cores (oversubscribed), the
// particles, wall seconds of the measured steps (the slowest process's), particle-steps per
// second, and per step the halo exchange's and the migration's seconds (the slowest process's)
// and the halo particles sent (all processes), and the largest process's peak resident memory
// per particle it owns.
#include <mpi.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <regex>
#include <string>
#include <thread>

#include "sph/DomainDecomposition.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace {

using namespace sph;

constexpr long warmUp = 20;

template <int D>
int measure(const Scene& scene, long steps, int ranks, int rank) {
  Simulation<D> sim(scene);
  sim.keepCellOrder(10);  // as sph run keeps it (Run.cpp)
  sim.distribute(slabDecomposition<D>(scene));
  for (long s = 0; s < warmUp; ++s)
    if (sim.advance()) return 1;
  using Traffic = typename DomainDecomposition<D>::Traffic;
  const Traffic before = sim.decomposition() ? sim.decomposition()->traffic() : Traffic{};
  MPI_Barrier(MPI_COMM_WORLD);
  const double began = MPI_Wtime();
  for (long s = 0; s < steps; ++s)
    if (auto f = sim.advance()) {
      std::cerr << "rank " << rank << ": " << f->message << "\n";
      return 1;
    }
  double t[3] = {MPI_Wtime() - began, 0, 0};
  const Traffic after = sim.decomposition() ? sim.decomposition()->traffic() : Traffic{};
  t[1] = after.haloSeconds - before.haloSeconds;
  t[2] = after.migrationSeconds - before.migrationSeconds;
  rusage use{};
  getrusage(RUSAGE_SELF, &use);  // ru_maxrss in KiB (Linux)
  double perOwned = 1024.0 * use.ru_maxrss / std::max<std::size_t>(sim.particles().size(), 1);
  MPI_Allreduce(MPI_IN_PLACE, t, 3, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &perOwned, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  long long counts[4] = {static_cast<long long>(sim.particles().size()),
                         after.haloSent - before.haloSent, after.migrated - before.migrated,
                         after.rebalances - before.rebalances};
  MPI_Allreduce(MPI_IN_PLACE, counts, 4, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (rank == 0) {
    const int threads = omp_get_max_threads();
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    std::printf(
        "{\"scene\": \"%s\", \"processes\": %d, \"threads\": %d, \"oversubscribed\": %s, "
        "\"particles\": %lld, \"dx\": %.6g, \"steps\": %ld, \"wall_s\": %.4f, "
        "\"particle_steps_per_s\": %.5g, \"halo_s_per_step\": %.4g, "
        "\"migration_s_per_step\": %.4g, \"halo_sent_per_step\": %.1f, \"migrated\": %lld, "
        "\"rebalances\": %lld, \"peak_rss_bytes_per_particle\": %.0f}\n",
        scene.name.c_str(), ranks, threads, ranks * threads > int(cores) ? "true" : "false",
        counts[0], scene.dx, steps, t[0], double(counts[0]) * steps / t[0], t[1] / steps,
        t[2] / steps, double(counts[1]) / steps, counts[2], counts[3] / ranks, perOwned);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1, code = 2;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const std::string mode = argc == 5 ? argv[4] : "weak";
  if ((argc != 4 && argc != 5) || (mode != "weak" && mode != "strong")) {
    if (rank == 0) std::cerr << "usage: rank_scaling SCENE PARTICLES STEPS [weak|strong]\n";
  } else {
    try {
      const Scene first = readScene(argv[1]);
      const double wanted = std::stod(argv[2]) * (mode == "weak" ? ranks : 1);
      // The dx for `wanted` particles from the count at the scene's own dx (N ~ dx^-D).
      std::size_t n0 = 0;
      if (first.dimension == 2) n0 = Simulation<2>(first).particles().size();
      if (first.dimension == 3) n0 = Simulation<3>(first).particles().size();
      if (n0 == 0) throw std::invalid_argument("a 2-D or 3-D scene with fluid");
      const double dx = first.dx * std::pow(double(n0) / wanted, 1.0 / first.dimension);
      char line[64];
      std::snprintf(line, sizeof line, "dx = %.9g", dx);
      const std::string text =
          std::regex_replace(first.text, std::regex("^dx *=.*$", std::regex::multiline), line);
      const Scene scene = parseScene(text, first.file);
      const long steps = std::stol(argv[3]);
      code = scene.dimension == 2 ? measure<2>(scene, steps, ranks, rank)
                                  : measure<3>(scene, steps, ranks, rank);
    } catch (const std::exception& e) {
      std::cerr << "rank_scaling: " << e.what() << "\n";
      code = 2;
    }
  }
  MPI_Finalize();
  return code;
}
