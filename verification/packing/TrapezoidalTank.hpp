#pragma once
// The trapezoidal tank of Colagrossi et al. (2012), section 3.1, packed from its scene file
// (validation/packing/trapezoidal_tank.toml) at a chosen H/dx and alpha.
#include <cmath>
#include <string>

#include "sph/packing/PackingScene.hpp"

namespace sph::packing {

struct TankFigures {
  std::size_t fluid = 0;
  // First iteration with T/beta < 1e-8, T = sum (eq. 2.18), and with T/(N beta) < 1e-8, the
  // per-particle mean; max_iterations + 1 where it never fell below.
  int iterations = -1, iterationsMean = -1;
  int outside = 0;  // fluid particles ending outside the region by more than dx/2
  double gradStart = 0.0, gradEnd = 0.0;  // H max |grad Gamma| on the lattice and after packing
};

inline TankFigures packTank(double HOverDx, double alpha, int maxIterations) {
  PackingScene s =
      readPackingScene(std::string(SPH_SOURCE_DIR) + "/validation/packing/trapezoidal_tank.toml");
  s.dx = s.lengthScale / HOverDx;
  s.parameters.alpha = alpha;
  s.parameters.maxIterations = maxIterations;
  const double threshold = 1e-8;  // the paper's, for T / beta and for T / (N beta)
  const PackingSetup setup = setUp(s);
  // The packing stops on T / (N beta); at threshold / N that is T / beta < threshold, the later
  // of the two (T is never below T / N), so both are seen.
  s.parameters.stopKineticEnergy = threshold / static_cast<double>(setup.fluid.size());
  ParticlePacking packing(setup.fluid, setup.solid.position, setup.V0, s.dx, s.parameters);
  TankFigures f;
  f.fluid = setup.fluid.size();
  packing.run([&](const PackingRecord& r) {
    if (r.iteration == 0) f.gradStart = s.lengthScale * r.maxGradGamma;
    if (r.iteration > 0 && f.iterations < 0 && r.kinetic < threshold) f.iterations = r.iteration;
    if (r.iteration > 0 && f.iterationsMean < 0 && r.kineticMean < threshold)
      f.iterationsMean = r.iteration;
    f.gradEnd = s.lengthScale * r.maxGradGamma;
  });
  for (const Vec2& x : packing.positions())
    if (!setup.region.contains(x) && setup.region.distance(x) > 0.5 * s.dx) ++f.outside;
  if (f.iterations < 0) f.iterations = maxIterations + 1;
  if (f.iterationsMean < 0) f.iterationsMean = maxIterations + 1;
  return f;
}

}  // namespace sph::packing
