#pragma once
// The three regular tessellations of the plane that are equilibria of the packing dynamics
// (Colagrossi et al. 2012, section 2.1.1, Fig. 3): Cartesian (square), triangular and hexagonal
// (honeycomb), each filling a periodic box an exact number of periods.
#include <string_view>
#include <vector>

#include "sph/packing/ParticlePacking.hpp"

namespace sph::packing {

enum class LatticeKind { cartesian, triangular, hexagonal };
std::string_view name(LatticeKind);

// Nearest-neighbour distance of each lattice when every particle has volume V0 = dx^2:
// Cartesian dx; triangular dx sqrt(2/sqrt 3) (area sqrt(3)/2 a^2 per particle); hexagonal
// dx sqrt(4/(3 sqrt 3)) (area 3 sqrt(3)/4 b^2 per particle).
double nearestNeighbour(LatticeKind kind, double dx);

struct PeriodicLattice {
  std::vector<Vec2> position;
  PeriodicBox<2> box;
};

// The given lattice with nearest-neighbour distance `spacing` in a periodic box [0, Lx) x [0, Ly)
// of sides at least `minSide` that holds a whole number of the lattice's rectangular periods
// (a x a with 1 particle Cartesian, a x sqrt(3) a with 2 triangular, sqrt(3) b x 3 b with 4
// hexagonal), so that the periodic images continue the lattice exactly.
PeriodicLattice periodicLattice(LatticeKind kind, double spacing, double minSide);

}  // namespace sph::packing
