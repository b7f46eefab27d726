#pragma once
// Start-up Poiseuille and Couette flow (Morris, Fox & Zhu 1997, J. Comput. Phys. 136, 214,
// section 4.1 and Figs. 2-3): the SPH velocity of every particle against the series solution at
// the particle's own height.
#include <algorithm>
#include <cmath>
#include <vector>

#include "FlowCases.hpp"

namespace sph::verification {

struct ProfileError {
  double l2 = 0, linf = 0;      // relative to v_max = 2.5e-5 m/s
  double densityDeviation = 0;  // max |rho/rho0 - 1| over the run's sampled times
  bool ok = true;
  std::string failure;
};

// Errors at each of `times` for one resolution.
inline std::vector<ProfileError> channelErrors(bool couette, int cellsAcross,
                                               const std::vector<double>& times,
                                               const std::string& kernel = "quadratic",
                                               double hOverDx = 1.33, double machInverse = 10) {
  using C = ChannelFlow;
  Simulation<2> sim(
      parseScene(C::scene(couette, cellsAcross, times.back(), kernel, hOverDx, machInverse),
                 couette ? "couette" : "poiseuille"));
  std::vector<ProfileError> out;
  double rhoDev = 0;
  for (double t : times) {
    ProfileError e;
    if (!runTo(sim, t, &e.failure)) {
      e.ok = false;
      out.push_back(e);
      return out;
    }
    const auto& p = sim.particles();
    double s2 = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double y = p.r[i][1];
      const double exact = couette ? C::couette(y, t) : C::poiseuille(y, t);
      const double d = std::hypot(p.v[i][0] - exact, p.v[i][1]) / C::vMax;
      s2 += d * d, e.linf = std::max(e.linf, d);
      rhoDev = std::max(rhoDev, std::abs(p.rho[i] / C::rho0 - 1));
    }
    e.l2 = std::sqrt(s2 / p.size());
    e.densityDeviation = rhoDev;
    out.push_back(e);
  }
  return out;
}

// Morris et al. (1997) Figs. 2 and 3 show the profiles at these times; 1 s is steady to 5e-5
// v_max (the slowest mode decays as exp(-pi^2 nu t / L^2), rate 9.87 /s).
inline const std::vector<double> kMorrisTimes{0.0225, 0.045, 0.1125, 0.225, 1.0};

}  // namespace sph::verification
