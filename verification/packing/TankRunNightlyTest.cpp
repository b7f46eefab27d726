// Issue 6, nightly tier: the hydrostatic tanks of Colagrossi et al. (2012), sections 3.1, 3.1.1
// and 3.2, run with the SPH scheme and the fixed walls of Adami et al. (2012) from a Cartesian
// and a packed start, to t sqrt(g/H) = 100 (Figs. 8, 10, 12). H/dx = 25: H/dx = 50 (the paper's)
// takes about eight times as long (four times the particles, twice the steps), beyond the few
// minutes per nightly test; its figures were measured once by hand (report of issue 6).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "Results.hpp"
#include "TankRuns.hpp"

namespace sph::packing {
namespace {

constexpr double tEnd = 100.0;  // t sqrt(g/H), Figs. 8, 10 and 12

void record(verification::Results& r, const std::string& what, const TankHistory& h) {
  r.history("max|u|/sqrt(gH), " + what, "t sqrt(g/H)", h.t, "max|u|/sqrt(gH)", h.maxSpeed,
            "Colagrossi et al. 2012 Figs. 8, 10");
  r.history("E_k/(rho0 g H V), " + what, "t sqrt(g/H)", h.t, "E_k/(rho0 g H V_tot)", h.kinetic,
            "Colagrossi et al. 2012 Figs. 9, 12");
  r.figure("run time [s], " + what, h.seconds, "this machine");
  r.figure("time steps, " + what, static_cast<double>(h.steps), "");
  r.figure("deepest excursion beyond the wall line / dx, " + what, h.maxDepth / h.dx, "");
  std::printf("%s: %.1f s, %ld steps, packing %d iterations\n", what.c_str(), h.seconds, h.steps,
              h.packingIterations);
  for (std::size_t k = 0; k < h.t.size(); k += 20)
    std::printf("  t = %6.2f  max|u| = %.3e  E_k = %.3e\n", h.t[k], h.maxSpeed[k], h.kinetic[k]);
}

// Section 3.1, Fig. 8: "the maximum intensity of velocity after the use of packing algorithm is
// at least two orders of magnitude smaller than ... on a Cartesian grid".
TEST(TrapezoidalTankRun, CartesianVersusPackedToT100) {
  const TankHistory cart = runTrapezoidalTank(25.0, false, tEnd);
  const TankHistory packed = runTrapezoidalTank(25.0, true, tEnd);
  verification::Results r;
  ASSERT_FALSE(cart.failure) << cart.failure->message;
  ASSERT_FALSE(packed.failure) << packed.failure->message;
  record(r, "trapezoidal tank, Cartesian start, H/dx = 25", cart);
  record(r, "trapezoidal tank, packed start, H/dx = 25", packed);
  // Late-time means (t sqrt(g/H) in [50, 100]) of max|u|: the settled level of Fig. 8.
  const double c = meanOver(cart, cart.maxSpeed, 50, 100);
  const double p = meanOver(packed, packed.maxSpeed, 50, 100);
  const double c10 = meanOver(cart, cart.maxSpeed, 9, 11);
  const double p10 = meanOver(packed, packed.maxSpeed, 9, 11);
  r.figure("mean max|u|/sqrt(gH), t sqrt(g/H) in [9, 11], Cartesian", c10,
           "paper Fig. 7 left: about 0.1 at t sqrt(g/H) = 10 (H/dx = 50)");
  r.figure("mean max|u|/sqrt(gH), t sqrt(g/H) in [9, 11], packed", p10, "paper Fig. 7 right");
  r.figure("mean max|u|/sqrt(gH), t sqrt(g/H) in [50, 100], Cartesian", c, "paper Fig. 8");
  r.figure("mean max|u|/sqrt(gH), t sqrt(g/H) in [50, 100], packed", p, "paper Fig. 8");
  // Measured 11 (2.9e-4 against 2.7e-5 sqrt(gH)): short of the paper's two orders. The Cartesian
  // start's late max|u| is a few particles near the walls still creeping (the lattice start also
  // ends 0.24 dx beyond the wall line, the packed one never); the viscosity alpha = 0.1 that the
  // time integrator needs (TankRun.hpp) damps at H/dx = 25 the bulk currents that the paper's
  // delta-SPH keeps at 1e-2 sqrt(gH). At H/dx = 50 (h halved, so nu too) the Cartesian start keeps
  // 1.6e-2 sqrt(gH) until a particle crosses the slope (wall_penetration at t sqrt(g/H) = 34;
  // measured once by hand, `sph tank`), the packed start 1.6e-5 to 100. Bound 5: half the
  // measurement, for the chaotic late motion.
  EXPECT_TRUE(r.check("mean max|u| Cartesian / packed, t sqrt(g/H) in [50, 100], H/dx = 25", c / p,
                      ">=", 5.0,
                      "measured; Colagrossi et al. 2012 Fig. 8 reports >= 100 (H/dx = 50)"));
}

// Section 3.1.1, Figs. 9-10: settling with the linear damping term -zeta u in the SPH scheme
// itself, from the Cartesian start, for t sqrt(g/H) = 20 (about 10,000 steps, the span of Fig. 9),
// then the undamped run for 100 more (Fig. 10). The histories cover both; the figure compares the
// late level with the packed start of CartesianVersusPackedToT100 (paper: damping "only leads to
// minor improvements"). Measured at H/dx = 25: 2.3e-4 (zeta H/c0 = 1) and 2.5e-4 (0.1) against
// 2.9e-4 undamped from the lattice and 2.7e-5 packed. Figures, not asserted: the settling is the
// paper's baseline, not a requirement.
TEST(TrapezoidalTankRun, LinearDampingBaseline) {
  verification::Results r;
  const double settle = 20.0;
  for (double zeta : {1.0, 0.1}) {
    TankRunOptions o;
    o.dampingZeta = zeta, o.dampingTime = settle;
    const TankHistory h = runTank(trapezoidalTankScene(25.0), o, settle + tEnd);
    ASSERT_FALSE(h.failure) << h.failure->message;
    char what[96];
    std::snprintf(what, sizeof what,
                  "damped settling zeta H/c0 = %g to t sqrt(g/H) = 20, H/dx = 25", zeta);
    record(r, what, h);
    r.figure(std::string("mean max|u|/sqrt(gH), t sqrt(g/H) in [50, 100] after ") + what,
             meanOver(h, h.maxSpeed, settle + 50, settle + 100),
             "paper Fig. 10: about 1e-2 at t sqrt(g/H) = 100 for zeta H/c0 <= 0.1");
  }
}

// Section 3.2, Fig. 12: the complex tank (validation/packing/complex_tank.toml), kinetic energy
// histories from both starts. H = 2 m (the surface over the lowest point); H/dx = 20 (dx = 0.1 m:
// at 0.08 m the lattice puts nodes on the left wall).
TEST(ComplexTankRun, KineticEnergyFromBothStarts) {
  verification::Results r;
  const PackingScene s = tankScene("complex_tank.toml", 20.0);
  // To t sqrt(g/H) = 50, not the paper's 100: from the Cartesian start one particle pushes
  // through the round bottom next to the step (at (0.95, -0.44), dx/2 beyond the wall line) at
  // t sqrt(g/H) = 73 (wall_penetration; measured once with `sph tank`); the packed start runs to
  // 100 cleanly.
  const double tComplex = 50.0;
  TankRunOptions o;
  const TankHistory cart = runTank(s, o, tComplex);
  o.packed = true;
  const TankHistory packed = runTank(s, o, tComplex);
  ASSERT_FALSE(cart.failure) << cart.failure->message;
  ASSERT_FALSE(packed.failure) << packed.failure->message;
  record(r, "complex tank, Cartesian start, H/dx = 20", cart);
  record(r, "complex tank, packed start, H/dx = 20", packed);
  const double c = meanOver(cart, cart.kinetic, 0.5 * tComplex, tComplex);
  const double p = meanOver(packed, packed.kinetic, 0.5 * tComplex, tComplex);
  r.figure("mean E_k/(rho0 g H V), second half, complex tank, Cartesian", c, "paper Fig. 12");
  r.figure("mean E_k/(rho0 g H V), second half, complex tank, packed", p, "paper Fig. 12");
  // Measured 6.0e3 (9.1e-7 against 1.5e-10). Bound 200: the Cartesian start's E_k swings by 10x
  // over t sqrt(g/H) = 20-50 (bursts near the corners), and the packed level moved 4x with the
  // choice of wall layers above the surface.
  EXPECT_TRUE(r.check("mean E_k Cartesian / packed, second half, complex tank", c / p, ">=", 200.0,
                      "measured; paper Fig. 12: several orders"));
}

}  // namespace
}  // namespace sph::packing
