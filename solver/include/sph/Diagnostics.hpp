#pragma once
// What a run records as it goes: volume conservation per phase (the paper's figure of merit,
// V = sum m/rho), kinetic energy, speed and density extremes, and the scene's probes.
#include <string>
#include <vector>

#include "sph/InteractionSet.hpp"
#include "sph/Particles.hpp"
#include "sph/Scene.hpp"

namespace sph {

struct Diagnostics {
  double kineticEnergy = 0, maxSpeed = 0, rhoMin = 0, rhoMax = 0;
  double volume = 0;                 // sum m/rho over all fluid
  std::vector<double> phaseVolume;   // the same per phase
  std::vector<double> probes;        // in the order of Scene::probes
};

template <int D>
Diagnostics diagnose(const Scene& scene, const Particles<D>& s, const InteractionSet<D>& set);

// Probes (DESIGN.md section 3, issue 4):
//   surge_front    the largest x of any fluid particle [m]
//   column_height  the largest y of particles within [lower x, x] of the domain, minus the floor [m]
//   water_level    the largest y of particles within dx of the gauge x, plus dx/2, minus the floor [m]
//   pressure       Shepard-normalised kernel interpolation of p at a point, ghosts included [Pa]
template <int D>
double probe(const Scene& scene, const Probe& p, const Particles<D>& s, const InteractionSet<D>& set);

}  // namespace sph
