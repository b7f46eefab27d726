#pragma once
// The lid-driven cavity (and other closed boxes of no-slip faces): its scene, a run measured for
// its volume, and the velocity at a point, for NoSlipWallsTest.cpp and NoSlipWallsNightlyTest.cpp.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "FlowCases.hpp"

namespace sph::verification {

// The unit square, every face no slip, the lid (y = 1) sliding at U = 1 m/s: Re = U L / nu = 100
// (rho 1, mu 0.01), c0 = 10 U, a background pressure p0 = 10 Pa (0.1 rho c0^2; with p0 = 0 the
// vortex's low pressure puts the fluid in tension and the run stops), Wendland C2 at h/dx 2,
// Morris viscosity only (no artificial viscosity), Fourtakas et al.'s diffusion (no gravity:
// Molteni & Colagrossi's form), fixed h; `model` the walls.
inline std::string cavity(int cells, double endTime, const std::string& model = "mirror_ghosts") {
  std::ostringstream s;
  s.precision(17);
  s << "name = \"cavity\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
    << "x_lower = \"no_slip\"\nx_upper = \"no_slip\"\ny_lower = \"no_slip\"\ny_upper = "
       "\"no_slip\"\n"
    << "[domain.wall_velocity]\ny_upper = [1.0, 0.0]\n[walls]\nmodel = \"" << model << "\"\n"
    << "[[phase]]\nname = \"fluid\"\nrho0 = 1.0\nc0 = 10.0\nmu = 0.01\np0 = 10.0\n"
    << "[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
    << "[physics]\nmorris_viscosity = true\ndensity_diffusion = 0.1\n"
    << "density_diffusion_form = \"fourtakas\"\n[numerics]\nkernel = \"wendland_c2\"\n"
    << "h_over_dx = 2.0\ndx = " << 1.0 / cells << "\nend_time = " << endTime << "\n";
  return s.str();
}

inline double volume(const Particles<2>& p) {
  double v = 0;
  for (std::size_t i = 0; i < p.size(); ++i) v += p.m[i] / p.rho[i];
  return v;
}

// The velocity at a point: the particles' average weighted by (1 - d / 2dx)^2 within 2 dx.
inline double velocityAt(const Particles<2>& p, double x, double y, int component, double dx) {
  double sum = 0, weight = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double d = std::hypot(p.r[i][0] - x, p.r[i][1] - y) / (2 * dx);
    if (d >= 1) continue;
    const double w = (1 - d) * (1 - d);
    sum += w * p.v[i][component], weight += w;
  }
  return sum / weight;
}

struct CavityRun {
  bool stable = true;
  std::string failure;
  double volumeVariation = 0;  // max |V / V(0) - 1| over 20 samples
  long reflections = 0;
  Particles<2> last;
};

inline CavityRun runCavity(const std::string& text, double endTime) {
  Simulation<2> sim(parseScene(text, "cavity"));
  const double v0 = volume(sim.particles());
  CavityRun out;
  for (int k = 1; k <= 20 && out.stable; ++k) {
    out.stable = runTo(sim, endTime * k / 20, &out.failure);
    out.volumeVariation = std::max(out.volumeVariation, std::abs(volume(sim.particles()) / v0 - 1));
  }
  out.reflections = sim.wallReflections(), out.last = sim.particles();
  return out;
}

}  // namespace sph::verification
