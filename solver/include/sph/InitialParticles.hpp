#pragma once
// Fluid blocks filled on a Cartesian lattice of spacing dx (cell-centred, so a block of
// n dx holds n particles per axis); mass m = rho dx^D, so each particle starts with volume dx^D.
// A block with initial = "packed" starts from its lattice nodes packed by the Colagrossi et al.
// (2012) algorithm instead, with m = rho V0, V0 = block volume / N. Velocity: the block's
// uniform velocity plus its linear field G (x - c); density from the block's initial pressure
// (zero, hydrostatic or stretching; Scene.hpp) through the inverse equation of state.
#include <cstddef>
#include <vector>

#include "sph/Particles.hpp"
#include "sph/Scene.hpp"
#include "sph/packing/ParticlePacking.hpp"

namespace sph {

// What the packing of one block did: a record per iteration (T/beta, max |grad Gamma|), and whether
// T / (N beta) fell below the block's stop_kinetic_energy before max_iterations.
struct PackedBlock {
  std::size_t block = 0;  // index into Scene::fluids
  bool converged = false;
  std::vector<packing::PackingRecord> history;
};

// The lattice nodes along an axis of a block `width` wide: round(width / dx), so a block of n dx
// holds n and one thinner than dx/2 none. Throws std::overflow_error where the count would not
// be exact in a double (RunBudget refuses such a dx before any particle is made).
long latticeCount(double width, double dx);

// Whether the packing of block `b` (initial = "packed") moves it off its lattice: noise does, and
// so do solid layers that follow a 2-D circle's curve (one away from the walls). Otherwise every
// node is in balance under eq. (2.16), and the packing keeps the lattice, stable or not.
template <int D>
bool packingLeavesLattice(const FluidBlock& b, const Scene& scene);

// `packed`, when given, receives one entry per block with initial = "packed".
template <int D>
Particles<D> latticeParticles(const Scene& scene, std::vector<PackedBlock>* packed = nullptr);

}  // namespace sph
