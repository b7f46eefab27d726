#pragma once
// Hydrostatic tank runs of Colagrossi et al. (2012), sections 3.1-3.2 (TankRun), sampled for the
// tests: max|u| and kinetic energy histories, the pressure next to the sloping wall, how far any
// fluid particle got beyond the wall line, and the reflections back across it.
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "sph/packing/TankRun.hpp"

namespace sph::packing {

inline PackingScene tankScene(const std::string& file, double HOverDx) {
  PackingScene s = readPackingScene(std::string(SPH_SOURCE_DIR) + "/validation/packing/" + file);
  s.dx = s.lengthScale / HOverDx;
  return s;
}
inline PackingScene trapezoidalTankScene(double HOverDx) {
  return tankScene("trapezoidal_tank.toml", HOverDx);
}

struct TankHistory {
  std::vector<double> t, maxSpeed, kinetic;  // sampled every `every` in t sqrt(g/H)
  double maxSpeedOverall = 0.0;              // over all steps
  double slopePressureError = 0.0;           // at the end, see slopePressureError()
  double maxDepth = 0.0;                     // deepest position beyond the wall line [m]
  long reflections = 0;                      // TankRun::wallReflections
  double maxReflectionDepth = 0.0;           // TankRun::maxReflectionDepth [m]
  double dx = 0.0, seconds = 0.0;
  int packingIterations = 0;
  long steps = 0;
  std::optional<Failure> failure;
};

// max |p - rho0 g (H - y)| / (rho0 g H) over the fluid particles within 2 dx of the trapezoidal
// tank's 45-degree wall (the line x - y = H/2) and below y = 0.8 H.
inline double slopePressureError(const TankRun& run, const PackingScene& s) {
  const Particles<2>& y = run.simulation().particles();
  const double H = run.H(), rhogH = s.phase.rho0 * s.gravity * H;
  double worst = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double d = (y.r[i].x() - y.r[i].y() - 0.5 * H) / std::sqrt(2.0);
    if (std::abs(d) > 2.0 * s.dx || y.r[i].y() > 0.8 * H) continue;
    const double exact = s.phase.rho0 * s.gravity * (s.surface - y.r[i].y());
    worst = std::max(worst, std::abs(y.p[i] - exact) / rhogH);
  }
  return worst;
}

inline TankHistory runTank(const PackingScene& s, TankRunOptions o, double tEnd,
                           double every = 0.25) {
  const auto start = std::chrono::steady_clock::now();
  TankRun run(s, o);
  TankHistory h;
  h.dx = s.dx;
  h.packingIterations = run.packingIterations();
  const Region container(s.container);
  double next = 0.0;
  h.failure = run.runTo(tEnd, [&](const TankSample& x) {
    const Particles<2>& y = run.simulation().particles();
    for (const auto& r : y.r)
      if (!container.contains(r)) h.maxDepth = std::max(h.maxDepth, container.distance(r));
    h.maxSpeedOverall = std::max(h.maxSpeedOverall, x.maxSpeed);
    if (x.t + 1e-12 >= next) {
      h.t.push_back(x.t), h.maxSpeed.push_back(x.maxSpeed);
      h.kinetic.push_back(x.kinetic);
      next += every;
    }
  });
  h.slopePressureError = slopePressureError(run, s);
  h.steps = run.simulation().step();
  h.reflections = run.wallReflections();
  h.maxReflectionDepth = run.maxReflectionDepth();
  h.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return h;
}

inline TankHistory runTrapezoidalTank(double HOverDx, bool packed, double tEnd,
                                      double every = 0.25) {
  TankRunOptions o;
  o.packed = packed;
  return runTank(trapezoidalTankScene(HOverDx), o, tEnd, every);
}

// Mean of y over the samples with t in [t0, t1].
inline double meanOver(const TankHistory& h, const std::vector<double>& y, double t0, double t1) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < h.t.size(); ++k)
    if (h.t[k] >= t0 && h.t[k] <= t1) sum += y[k], ++n;
  return n ? sum / n : NAN;
}

}  // namespace sph::packing
