// Issue 3: angular momentum L = sum m x × v of a free, swirling drop (open domain, no walls, no
// body force), about its centre of mass.
//  * Pressure (eq. 12) and artificial viscosity (eq. 10) act along x_ij between each pair, so the
//    semi-discrete torque sum m x × a vanishes. Heun's predictor-corrector keeps that to O(dt^4) a
//    step: x' = x + dt v + dt^2/2 a, v' = v + dt/2 (a + a*), and sum m x* × a* = 0 at the predicted
//    x* = x + dt v gives sum m x × a* = -dt sum m v × a*. With a* = a + dt da/dt + O(dt^2), the
//    dt^2 terms of L' - L are (-1/2 + 1 - 1/2) sum m v × a = 0 and the dt^3 terms
//    (-1/2 + 1/2) sum m v × da/dt = 0, so the drift over a fixed time is O(dt^3).
//  * Morris viscosity (eq. 9) acts along v_ij, not x_ij: it exerts a torque of its own and the
//  drift
//    stays as dt -> 0 (Morris et al. 1997 trade angular momentum for the viscous Laplacian).
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "FlowCases.hpp"
#include "Results.hpp"
#include "sph/InitialParticles.hpp"

namespace sph::verification {
namespace {

// A drop of radius 0.25 in a swirl v = (1 + 4 r^2) (-y, x): not a rigid rotation, so the viscous
// terms act. Max speed 0.31, c0 = 10 (Mach 0.03); 1/32 spacing, about 200 particles.
Simulation<2> drop(double beta, bool morris) {
  std::ostringstream s;
  s << "name = \"swirl\"\ndimension = 2\n[domain]\nlower = [-1.0, -1.0]\nupper = [1.0, 1.0]\n"
    << "[[phase]]\nname = \"w\"\nrho0 = 1.0\nc0 = 10.0\nmu = 0.01\n"
    << "[[fluid]]\nshape = \"circle\"\ncenter = [0.0, 0.0]\nradius = 0.25\n"
    << "[physics]\nartificial_viscosity = " << beta
    << "\nmorris_viscosity = " << (morris ? "true" : "false") << "\n[numerics]\ndx = " << 1.0 / 32
    << "\nend_time = 1.0\n";
  const Scene sc = parseScene(s.str(), "swirl");
  Particles<2> p = latticeParticles<2>(sc);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = p.r[i][0], y = p.r[i][1];
    p.v[i] = (1 + 4 * (x * x + y * y)) * Vec<2>(-y, x);
  }
  return Simulation<2>(sc, std::move(p));
}

double angularMomentum(const Particles<2>& p) {
  double m = 0, cx = 0, cy = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    m += p.m[i], cx += p.m[i] * p.r[i][0], cy += p.m[i] * p.r[i][1];
  cx /= m, cy /= m;  // the centre of mass moves only by round-off (no external force)
  double L = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    L += p.m[i] * ((p.r[i][0] - cx) * p.v[i][1] - (p.r[i][1] - cy) * p.v[i][0]);
  return L;
}

// |L(T) - L(0)| / L(0) after T = 0.1 with steps of exactly dt (dt below the CFL limit 1e-3).
double drift(double beta, bool morris, double dt) {
  Simulation<2> sim = drop(beta, morris);
  const double L0 = angularMomentum(sim.particles());
  const int steps = static_cast<int>(0.1 / dt + 0.5);
  for (int s = 0; s < steps; ++s) {
    auto f = sim.advance(dt);
    EXPECT_FALSE(f) << f->message;
  }
  return std::abs(angularMomentum(sim.particles()) - L0) / std::abs(L0);
}

TEST(Conservation, AngularMomentum) {
  Results r;
  const double dt = 5e-4;
  const double c1 = drift(1.0, false, dt), c2 = drift(1.0, false, dt / 2);
  const double m1 = drift(0.0, true, dt), m2 = drift(0.0, true, dt / 2);
  const double order = std::log2(c1 / c2);
  std::printf("central terms: dL/L %.3e (dt) %.3e (dt/2) order %.2f; Morris %.3e %.3e\n", c1, c2,
              order, m1, m2);
  r.convergence("angular momentum drift, pressure + artificial viscosity", "dt", {dt, dt / 2},
                {c1, c2}, 3.0, "central pair forces; Heun O(dt^4) a step (head of this file)");
  EXPECT_TRUE(r.check("angular momentum drift order in dt, pressure + artificial viscosity", order,
                      ">=", 2.7, "theory 3 minus 0.3"));
  EXPECT_TRUE(r.check("angular momentum drift / L0 at dt = 2.5e-4, pressure + AV", c2, "<=", 1e-10,
                      "measured 1.1e-12 (this test) x 100: the integrator's O(dt^3) drift"));
  // Morris viscosity's own torque: the drift does not fall with dt, and stays far above the
  // central terms' drift.
  EXPECT_TRUE(r.check("Morris viscosity: drift(dt/2) / drift(dt)", m2 / m1, ">=", 0.8,
                      "non-central viscous force: a torque independent of dt (ratio 1)"));
  EXPECT_TRUE(r.check("Morris viscosity: drift / pressure+AV drift at dt/2", m2 / c2, ">=", 100.0,
                      "non-central viscous force: a torque of its own"));
}

}  // namespace
}  // namespace sph::verification
