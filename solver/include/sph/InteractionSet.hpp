#pragma once
// Everything a fluid particle interacts with: the fluid particles themselves (first nFluid
// entries), then their periodic images and ghost-wall mirrors (the halo), then any fixed wall
// particles (FixedWalls.hpp). Rebuilt before every force evaluation from the current fluid state
// by the scene's boundary (boundaries/Boundary.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "sph/Boundaries.hpp"
#include "sph/CacheLines.hpp"
#include "sph/Particles.hpp"

namespace sph {

struct Phase;

template <int D>
struct InteractionSet {
  LineVector<Vec<D>> x, v;
  LineVector<double> rho, p, m, h, mu;
  LineVector<double> rho0;  // the rest density of each entry's phase
  LineVector<int> phase;    // that phase's place in the scene's list
  LineVector<int> source;   // the fluid particle an entry stands for
  std::size_t nFluid = 0;
  // Scratch of the halo build: per thread, the entries near a face (kept: no allocation a step;
  // a cache line each, so that two threads' appends do not contend for one), and the runs of
  // entries the thread wrote, scanned for the current axis: where each begins and how many of
  // `entries` are its.
  struct alignas(64) NearFace {
    std::vector<std::int64_t> entries;
    int runs = 0;
    std::array<std::int64_t, 4> runBegin{}, runCount{};
  };
  std::vector<NearFace> nearFace;
  // The halo's members by axis: 2 k + side for entry k's image across that axis's lower (0) or
  // upper (1) face, in the order the images follow the fluid.
  std::array<std::vector<std::int64_t>, D> halo;
  // The fixed wall particles in the set (FixedWalls.hpp), by their index there, ascending: those
  // within a pair's support plus the skin of a fluid entry. The others are in no pair and are
  // left out; the pair loop lays out its cells as if they were in (their count, a box holding
  // them, their h), so that which ones are left out changes no cell, no order and no sum.
  std::vector<std::int64_t> walls;
  struct LeftOut {
    std::size_t count = 0;
    Vec<D> lo = Vec<D>::Constant(1e300), hi = Vec<D>::Constant(-1e300);
    double h = 0.0;
  } leftOut;
  // The fluid entries near each of `walls`, listed when they are chosen and kept with them: those
  // within the wall particle's support plus half the skin, in the order its sums take them
  // (FixedWalls.hpp). List q is wallNeighbours[wallNeighboursAt[q] .. wallNeighboursAt[q + 1]).
  std::vector<std::int32_t> wallNeighbours;
  std::vector<std::size_t> wallNeighboursAt;
  // Over several processes, the process's own particle that each fluid entry is (-1: a copy of
  // another process's, which that process evaluates), and how many are its own; empty: fluid
  // entry k is particle k. The force evaluation writes the rates of these particles only.
  std::vector<int> ownedParticle;
  std::size_t nOwned = 0;

  std::size_t size() const { return x.size(); }
  // Where the fluid and its halo end: entries appended after them (fixed wall particles) begin.
  std::size_t haloEnd() const {
    std::size_t n = nFluid;
    for (const auto& h : halo) n += h.size();
    return n;
  }
  // How many particles the force evaluation writes rates for.
  std::size_t owned() const { return ownedParticle.empty() ? nFluid : nOwned; }
  void clear() {
    resize(0), walls.clear(), leftOut = {}, ownedParticle.clear(), nOwned = 0;
    wallNeighbours.clear(), wallNeighboursAt.clear();
  }
  void resize(std::size_t n) {
    x.resize(n), v.resize(n), rho.resize(n), p.resize(n), m.resize(n), h.resize(n), mu.resize(n);
    rho0.resize(n), phase.resize(n), source.resize(n);
  }
};

// The fluid a set is built from: the particles of one store in their order, or over several
// processes a process's own particles and the halo it received, placed together in key order:
// the set's fluid entry k is owned particle from[k] where from[k] >= 0, else halo particle
// -1 - from[k] (Simulation::placeHalo).
template <int D>
struct SetFluid {
  SetFluid(const Particles<D>& all) : owned(all), count(all.size()) {}  // NOLINT: one store
  SetFluid(const Particles<D>& own, const Particles<D>& received, const std::vector<int>& placed)
      : owned(own), halo(&received), from(placed.data()), count(placed.size()) {}
  const Particles<D>& owned;
  const Particles<D>* halo = nullptr;
  const int* from = nullptr;
  std::size_t count;
  std::size_t size() const { return count; }
};

// A wall ghost's pressure: its source's plus rho g . (x_g - x) (`gravity` zero: the paper's ghost),
// and not below `floor` ([walls] tensile = false: a wall pushes the fluid and never pulls it;
// -inf: the paper's mirror, which pulls fluid in tension toward the wall, solver/SCENES.md).
template <int D>
struct GhostPressure {
  Vec<D> gravity;
  double floor = -std::numeric_limits<double>::infinity();
  // A gravity alone (any Eigen expression of one, Vec<D>::Zero() too) is the paper's rule.
  template <class G>
  // NOLINTNEXTLINE(google-explicit-constructor)
  GhostPressure(const Eigen::MatrixBase<G>& g) : gravity(g) {}
  GhostPressure(const Vec<D>& g, double least) : gravity(g), floor(least) {}
};

// Copies the fluid state (pressure from the Tait EOS, viscosity and rest density from the phase)
// into `set`, then appends the halo: for each axis in turn, every entry so far within `reach` of a
// periodic face gets an image shifted by the period, and of a wall face a ghost mirrored across it
// (Libersky et al. 1993; Colagrossi & Landrini 2003). Working axis by axis mirrors ghosts again at
// corners. A ghost keeps its source's density and pressure; free slip reverses the normal velocity,
// no slip the whole velocity, both relative to the wall's own velocity. `ghost.gravity` zero gives
// the paper's ghost (the source's pressure); the body acceleration g gives the ghost the
// hydrostatic correction p_g = p + rho g . (x_g - x), which supplies the rho g that a mirrored,
// even pressure field lacks at the wall (without it a particle at a free surface next to the wall,
// where p ~ 0, is held up by nothing but artificial viscosity). HaloMembers::same keeps the last
// build's halo members (the same entries, their state recomputed; `reach` unused) for a pair loop
// that reuses its neighbour lists: the fluid must be as many particles as then, and a member's
// image is then in the same place of the set.
enum class HaloMembers { rescan, same };
// (`ghost` takes no part in deducing D, so that a gravity alone converts to its rule.)
template <int D>
void buildInteractionSet(const SetFluid<D>& fluid, const std::vector<Phase>& phases,
                         const Boundaries<D>& bounds, double reach,
                         const std::type_identity_t<GhostPressure<D>>& ghost,
                         InteractionSet<D>& set, HaloMembers members = HaloMembers::rescan);
template <int D>
void buildInteractionSet(const Particles<D>& fluid, const std::vector<Phase>& phases,
                         const Boundaries<D>& bounds, double reach,
                         const std::type_identity_t<GhostPressure<D>>& ghost,
                         InteractionSet<D>& set, HaloMembers members = HaloMembers::rescan) {
  buildInteractionSet(SetFluid<D>(fluid), phases, bounds, reach, ghost, set, members);
}

}  // namespace sph
