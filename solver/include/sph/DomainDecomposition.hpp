#pragma once
// The fluid spread over several processes (MPI ranks): each owns the particles of one slab of
// the domain and holds copies of the other processes' particles near its own (the halo). With
// the halo in the interaction set in the order one process would have it, and the cells of the
// whole domain (ForceEvaluation::frameGrid), every owned particle's sums take the same entries in
// the same order as in one process: the run is bit-identical to one process (Simulation.cpp).
//
// A particle's key is its index in the one-process run's storage (Simulation::keepCellOrder
// renumbers it); every process keeps its owned particles, and its halo, in ascending key.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sph/Particles.hpp"

namespace sph {

struct Scene;

template <int D>
class DomainDecomposition {
 public:
  virtual ~DomainDecomposition() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  // Each of the n values becomes its maximum (minimum, sum) over the processes. Min and max are
  // exact in any order; the sum is of integers.
  virtual void maxAll(double* v, int n) const = 0;
  virtual void minAll(double* v, int n) const = 0;
  virtual std::int64_t sumAll(std::int64_t) const = 0;
  // `s` of process `from` on every process.
  virtual void broadcast(std::string& s, int from) const = 0;

  // Of all particles (the same on every process, keys 0, 1, ...), keeps this process's slab.
  virtual void keepOwn(Particles<D>& particles, std::vector<int>& ids,
                       std::vector<std::int64_t>& keys) = 0;
  // Sends each owned particle whose position lies in another process's slab there, after
  // cutting the slabs anew if the processes' counts have drifted apart. `riders`: `width`
  // numbers a particle (owned particle i's at i * width) that go where it goes.
  virtual void migrate(Particles<D>& owned, std::vector<int>& ids, std::vector<std::int64_t>& keys,
                       std::vector<double>* riders = nullptr, int width = 0) = 0;
  // The halo: the other processes' particles within `width` of this one's owned particles along
  // the cut axis (periodic there if the domain is). `rescan` chooses them anew; otherwise the
  // members of the last rescan, in their current state.
  virtual void exchangeHalo(const Particles<D>& owned, const std::vector<std::int64_t>& keys,
                            double width, bool rescan, Particles<D>& halo,
                            std::vector<std::int64_t>& haloKeys) = 0;
  // New keys: the owned particles of every process numbered together by (cell, key) ascending,
  // as one process stores its particles in cell order.
  virtual void renumber(const std::vector<std::int64_t>& cells,
                        std::vector<std::int64_t>& keys) const = 0;
  // What this process has sent and waited for so far (the scaling benchmark, perf/).
  struct Traffic {
    double haloSeconds = 0, migrationSeconds = 0;
    std::int64_t haloSent = 0, migrated = 0, rebalances = 0;  // particles; cuts made anew
  };
  virtual Traffic traffic() const = 0;
  // Every process's owned particles on process 0 in key order (elsewhere `all` is left empty).
  virtual void gather(const Particles<D>& owned, const std::vector<int>& ids,
                      const std::vector<std::int64_t>& keys, Particles<D>& all,
                      std::vector<int>& allIds) const = 0;
  // The same for `width` numbers a particle (`rows`, owned particle i's at i * width).
  virtual void gather(const std::vector<double>& rows, int width,
                      const std::vector<std::int64_t>& keys, std::vector<double>& all) const = 0;
};

// The slabs of MPI_COMM_WORLD across the scene's longest axis, or none when the run has one
// process or the build has no MPI (SPH_WITH_MPI).
template <int D>
std::shared_ptr<DomainDecomposition<D>> slabDecomposition(const Scene& scene);

// The processes a launcher (mpirun) started this one among, from its environment (OpenMPI's
// OMPI_COMM_WORLD_SIZE, MPICH's PMI_SIZE; 1 without one), and this one's place among them.
int launchedProcesses();
int launchedRank();

// MPI for a program a launcher started among others (launchedProcesses() > 1): started here,
// finished when this goes. Throws std::invalid_argument (bad input) where the build has no MPI.
class Processes {
 public:
  Processes();
  ~Processes();
  Processes(const Processes&) = delete;
  Processes& operator=(const Processes&) = delete;

 private:
  bool started_ = false;
};

}  // namespace sph
