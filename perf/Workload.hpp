#pragma once
// Benchmark workloads (issue 7): a 2-D block of water on a randomly perturbed square lattice in
// the corner of a box with free-slip walls on its lower x and y faces, so that the interaction set
// carries ghosts as in the dam break. Density, velocity and smoothing length vary from particle
// to particle so that every term of the menu has work to do (approaching and receding pairs,
// h_ij != h_i).
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "sph/EquationOfState.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Particles.hpp"
#include "sph/terms/Menu.hpp"

namespace sph::perf {

struct Block2D {
  Particles<2> fluid;
  std::vector<Phase> phases;
  Boundaries<2> bounds;
  double dx = 0.0, hMax = 0.0;
  InteractionSet<2> set;
  Derivatives<2> out;
};

// About n fluid particles (a square lattice, side round(sqrt(n))), h = 1.33 dx as in the dam break.
inline Block2D makeBlock(std::size_t n, unsigned seed = 1) {
  Block2D b;
  const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(n)))));
  b.dx = 1.0 / side;
  Phase water;
  water.name = "water", water.rho0 = 1000.0, water.c0 = 24.4, water.mu = 8.9e-4;
  b.phases = {water};
  b.bounds.lower = Vec<2>(0.0, 0.0), b.bounds.upper = Vec<2>(2.0, 2.0);
  b.bounds.face[0] = {FaceKind::free_slip, FaceKind::open};
  b.bounds.face[1] = {FaceKind::free_slip, FaceKind::open};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  b.fluid.resize(static_cast<std::size_t>(side) * side);
  std::size_t k = 0;
  for (int iy = 0; iy < side; ++iy)
    for (int ix = 0; ix < side; ++ix, ++k) {
      b.fluid.r[k] = Vec<2>((ix + 0.5 + 0.1 * u(rng)) * b.dx, (iy + 0.5 + 0.1 * u(rng)) * b.dx);
      b.fluid.v[k] = Vec<2>(0.5 * u(rng), 0.5 * u(rng));
      b.fluid.rho[k] = 1000.0 * (1.0 + 0.01 * u(rng));
      b.fluid.m[k] = 1000.0 * b.dx * b.dx;
      b.fluid.h[k] = 1.33 * b.dx * (1.0 + 0.02 * u(rng));
      b.fluid.phase[k] = 0;
      b.fluid.p[k] = TaitEquationOfState::pressure(b.fluid.rho[k], water);
      b.hMax = std::max(b.hMax, b.fluid.h[k]);
    }
  buildInteractionSet(b.fluid, b.phases, b.bounds, 2.0 * b.hMax, Vec<2>(0.0, -9.81), b.set);
  return b;
}

// Pairs (i fluid, j any, 0 < r_ij < 2 h_ij) of the block's interaction set, by brute force over
// the cell list's 3x3 cells: the work count behind the flop bound.
inline std::size_t countPairs(const InteractionSet<2>& set) {
  CellList<2> cells;
  double hMax = 0.0;
  for (double h : set.h) hMax = std::max(hMax, h);
  cells.build(set.x, 2.0 * hMax);
  const auto& order = cells.order();
  std::size_t pairs = 0;
  for (std::int64_t c = 0; c < cells.cells(); ++c)
    for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
      const int i = order[k];
      if (static_cast<std::size_t>(i) >= set.nFluid) continue;
      cells.forEachAdjacentRange(c, [&](int begin, int end) {
        for (int l = begin; l < end; ++l) {
          const int j = order[l];
          const double r2 = (set.x[i] - set.x[j]).squaredNorm();
          const double reach = set.h[i] + set.h[j];  // 2 h_ij
          pairs += r2 > 0.0 && r2 < reach * reach;
        }
      });
    }
  return pairs;
}

// Flops of the 2-D pair body with the quadratic kernel, as each term counts its own from its
// source (terms/*.hpp: add, sub, mul, compare-select 1 each; div and sqrt 1 each, though they
// cost 4-20 times the cycles, so the bound is generous). The loop visits each pair once: the
// `shared` part (the kernel, the reciprocals, the viscosities' pair factors) is computed once for
// the pair, the `sided` part (each particle's mass-weighted sums) once for each of its two
// particles. of(t) is the count per ordered pair (i fluid, j any; countPairs), (shared + 2 sided)
// / 2, which counts a fluid-halo pair at half of what the loop spends on it: the fraction of the
// bound is not overstated. The packing pass over the candidates (about 9 flops each, 2 candidates
// per pair) is overhead, not counted as useful work.
struct PairFlops {
  static terms::Flops sum(TermSwitches t) { return pairFlops(t); }
  static double of(TermSwitches t) {
    const terms::Flops s = pairFlops(t);
    return 0.5 * (s.shared + 2 * s.sided);
  }
};

// The menu entries the benchmarks time one by one: t = artificial viscosity + 2 Morris viscosity
// + 4 variable h + 8 x density diffusion form (1 Molteni & Colagrossi, 2 Fourtakas et al., 3
// Fourtakas et al.'s within each phase, 4 Antuono et al.), and 40 + form for all three with
// particle shifting's pair sums (t < terms::menuSize, 45).
inline TermSwitches menuEntry(int t) {
  constexpr int rates = static_cast<int>(terms::ratesEntries);
  static_assert(rates == 40 && terms::menuSize == 45);
  if (t >= rates) return {true, true, true, static_cast<DensityDiffusion>(t - rates), true};
  return {(t & 1) != 0, (t & 2) != 0, (t & 4) != 0, static_cast<DensityDiffusion>(t / 8)};
}
// The terms' parameters for the block: beta 1, density diffusion's delta 0.1 (Molteni &
// Colagrossi 2009) with the block's c0 and EOS, g downwards.
inline terms::TermParameters termParameters(const Block2D& b) {
  return {.beta = 1.0,
          .diffusionDelta = 0.1,
          .soundSpeed = b.phases[0].c0,
          .rho0 = b.phases[0].rho0,
          .bulkModulus = b.phases[0].bulkModulus(),
          .gammaInteger = 7,
          .g = {0.0, -9.81, 0.0},
          .spacing = b.dx};
}

}  // namespace sph::perf
