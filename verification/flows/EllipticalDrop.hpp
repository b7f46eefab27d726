#pragma once
// The elliptical drop of Monaghan (1994, J. Comput. Phys. 110, 399) as in Colagrossi et al.
// (2012), section 3.4: a circular drop of radius R in u = A0 x, v = -A0 y with
// p = rho0 A0^2 (R^2 - r^2)/2 (eqs. 3.19-3.20) stays an ellipse whose semi-axes obey
//   da/dt = A a,  db/dt = -A b,  dA/dt = A^2 (b^2 - a^2)/(a^2 + b^2),  a = b = R, A = A0 at t = 0
// (incompressible and inviscid; a b = R^2 for all t). The ODE: EllipticalDropOde.hpp.
//
// Semi-axes from the particles: second moments about the centroid, weighted by the particle
// volumes m/rho: for a uniform ellipse <x^2> = a^2/4, <y^2> = b^2/4, so a = 2 sqrt(<x^2>). The
// moments see the whole drop, not its few outermost particles, and need no assumption about the
// spacing at the surface (which the stretching makes anisotropic). The outermost particles are
// recorded too: max |x - x_c| and max |y - y_c| against a and b (they lie about half a spacing
// inside), and the raggedness of the boundary: in 36 bins of the ellipse angle
// atan2(y/b, x/a), the outermost elliptic radius rho = sqrt((x/a)^2 + (y/b)^2) per bin, and its
// standard deviation over the bins (Fig. 16: the Cartesian start clumps into lines and filaments).
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "EllipticalDropOde.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace sph::verification {

struct DropSample {
  double t = 0.0;
  DropAxes ode;
  double aMoment = 0.0, bMoment = 0.0;  // 2 sqrt(<x^2>), 2 sqrt(<y^2>)
  double aExtent = 0.0, bExtent = 0.0;  // max |x - x_c|, max |y - y_c|
  double raggedness = 0.0;              // std of the outermost rho over 36 angle bins
  double errorMoment() const {          // max of the relative semi-axis errors
    return std::max(std::abs(aMoment / ode.a - 1.0), std::abs(bMoment / ode.b - 1.0));
  }
};

inline DropSample measureDrop(const Particles<2>& p, double t, const DropAxes& ode) {
  DropSample s;
  s.t = t, s.ode = ode;
  double V = 0.0;
  Vec<2> c = Vec<2>::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double v = p.m[i] / p.rho[i];
    V += v, c += v * p.r[i];
  }
  c /= V;
  double xx = 0.0, yy = 0.0;
  std::array<double, 36> outer{};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec<2> d = p.r[i] - c;
    const double v = p.m[i] / p.rho[i];
    xx += v * d.x() * d.x(), yy += v * d.y() * d.y();
    s.aExtent = std::max(s.aExtent, std::abs(d.x()));
    s.bExtent = std::max(s.bExtent, std::abs(d.y()));
    const double u = d.x() / ode.a, w = d.y() / ode.b;
    const double angle = std::atan2(w, u) + M_PI;  // 0 .. 2 pi
    const int bin = std::min(35, static_cast<int>(angle / (2.0 * M_PI) * 36.0));
    outer[bin] = std::max(outer[bin], std::hypot(u, w));
  }
  s.aMoment = 2.0 * std::sqrt(xx / V), s.bMoment = 2.0 * std::sqrt(yy / V);
  double mean = 0.0, var = 0.0;
  for (double o : outer) mean += o / 36.0;
  for (double o : outer) var += (o - mean) * (o - mean) / 36.0;
  s.raggedness = std::sqrt(var);
  return s;
}

// Runs a drop scene at R/dx to the last of `times`, measuring at each. Throws on a numerical
// failure (the test reports it).
inline std::vector<DropSample> runDrop(const std::string& scenePath, double ROverDx,
                                       const std::vector<double>& times, long* steps = nullptr) {
  Scene scene = readScene(scenePath);
  const FluidBlock& b = scene.fluids.at(0);
  const double R = b.radius, A0 = b.velocityGradient.at(0);
  scene.dx = R / ROverDx;
  scene.endTime = times.back();
  const std::vector<DropAxes> ode = dropOde(A0, R, times);
  Simulation<2> sim(scene);
  sim.prepare();
  std::vector<DropSample> out;
  for (std::size_t k = 0; k < times.size(); ++k) {
    while (sim.time() < times[k] * (1 - 1e-12))
      if (auto f = sim.advance(times[k] - sim.time())) throw std::runtime_error(f->message);
    out.push_back(measureDrop(sim.particles(), sim.time(), ode[k]));
  }
  if (steps) *steps = sim.step();
  return out;
}

}  // namespace sph::verification
