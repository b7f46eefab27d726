#pragma once
// Fluid blocks filled on a Cartesian lattice of spacing dx (cell-centred, so a block of
// n dx holds n particles per axis); mass m = rho dx^D, so each particle starts with volume dx^D.
// A block with initial = "packed" (2-D) starts from its lattice nodes packed by the Colagrossi et
// al. (2012) algorithm instead, with m = rho V0, V0 = block area / N. Velocity: the block's
// uniform velocity plus its linear field G (x - c); density from the block's initial pressure
// (zero, hydrostatic or stretching; Scene.hpp) through the inverse equation of state.
#include "sph/Particles.hpp"
#include "sph/Scene.hpp"

namespace sph {

template <int D>
Particles<D> latticeParticles(const Scene& scene);

}  // namespace sph
