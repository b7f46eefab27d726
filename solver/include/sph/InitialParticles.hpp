#pragma once
// Fluid blocks filled on a Cartesian lattice of spacing dx (cell-centred, so a block of
// n dx holds n particles per axis); mass m = rho dx^D, so each particle starts with volume dx^D.
#include "sph/Particles.hpp"
#include "sph/Scene.hpp"

namespace sph {

template <int D>
Particles<D> latticeParticles(const Scene& scene);

}  // namespace sph
