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
  double volume = 0;                // sum m/rho over all fluid
  std::vector<double> phaseVolume;  // the same per phase
  std::vector<double> probes;       // in the order of Scene::probes
};

template <int D>
Diagnostics diagnose(const Scene& scene, const Particles<D>& s, const InteractionSet<D>& set);

// Probes (DESIGN.md section 3, issue 4; issue 36 for the last two):
//   surge_front    the largest x of any fluid particle [m]
//   column_height  the largest y of particles within [lower x, x] of the domain, minus the
//                  floor [m]
//   water_level    the largest y of particles within dx of the gauge x, plus dx/2, minus the
//                  floor [m]
//   pressure       Shepard-normalised kernel interpolation of p at a point, ghosts included [Pa]
//   wall_pressure  the pressure a transducer flush with a solid face reads at its point x [Pa]:
//                  Adami et al.'s (2012) eq. (27) wall pressure taken at x, from the fluid
//                  particles f alone (no ghost or wall particle), volume-weighted:
//                    p(x) = (sum_f V_f p_f W_xf + g . sum_f m_f (x - r_f) W_xf) / sum_f V_f W_xf,
//                    V_f = m_f / rho_f, W_xf = W(|x - r_f|, h_f), g the body acceleration;
//                  the g term carries the hydrostatic part from the fluid's centroid, up to 2 h
//                  inside the fluid, to the face. Dry (0) while sum_f V_f W_xf < 0.1: a wetted
//                  flat face has 1/2 (its half of the support), one particle touching it ~0.08
//                  at h/dx 1.33, so a point in spray reads nothing rather than one drop's pressure.
//   water_height   at the vertical line through the position's D - 1 horizontal coordinates, the
//                  highest z above the floor (the domain's lower face) where the fluid fraction
//                  phi(z) = sum_f V_f W(|x(z) - r_f|, h_f) is at least 1/2 [m]: phi is 1 inside
//                  a wet column and falls through 1/2 at its free surface; a lone droplet (phi at
//                  most V W(0) ~ 0.13 at h/dx 1.33) does not count. Where the floor is a wall,
//                  each particle's mirror image beneath it is in the sum too, so that a film of
//                  one layer reads its depth (the cut support would leave its phi below 1/2).
//                  phi is sampled every dx/8 and the crossing interpolated linearly; 0 when dry.
template <int D>
double probe(const Scene& scene, const Probe& p, const Particles<D>& s,
             const InteractionSet<D>& set);

}  // namespace sph
