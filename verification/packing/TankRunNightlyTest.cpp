// Issue 6, nightly tier: the hydrostatic tanks of Colagrossi et al. (2012), sections 3.1, 3.1.1
// and 3.2, run with the SPH scheme and the fixed walls of Adami et al. (2012) from a Cartesian
// and a packed start, to t sqrt(g/H) = 100 (Figs. 8, 10, 12): the trapezoidal tank at H/dx = 25
// (both starts in one test) and at the paper's H/dx = 50 (one test per start, so that ctest -j
// runs them side by side: 190-215 s each on one core), the complex tank at H/dx = 20.
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
  r.figure("wall reflections, " + what, static_cast<double>(h.reflections),
           "TankRun::wallReflections: crossings of the wall line by <= dx/2, put back");
  r.figure("deepest reflected crossing / dx, " + what, h.maxReflectionDepth / h.dx, "");
  std::printf(
      "%s: %.1f s, %ld steps, packing %d iterations, %ld wall reflections (deepest %.2e dx)\n",
      what.c_str(), h.seconds, h.steps, h.packingIterations, h.reflections,
      h.maxReflectionDepth / h.dx);
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
  // Measured 21 (5.8e-4 against 2.8e-5 sqrt(gH)): short of the paper's two orders at this
  // resolution. The viscosity alpha = 0.1 that the time integrator needs (TankRun.hpp) damps at
  // H/dx = 25 the bulk currents that the paper's delta-SPH keeps at 1e-2 sqrt(gH); the late
  // max|u| of the Cartesian start is particles within 2 dx of the walls still creeping. Before
  // TankRun put particles back at the wall line: 11 (2.9e-4 against 2.7e-5), with lattice
  // particles resting 0.24 dx beyond it. At H/dx = 50 (h, and so nu, halved) the ratio is 660:
  // the two tests below. Bound 10: half the measurement, for the chaotic late motion.
  EXPECT_TRUE(r.check("mean max|u| Cartesian / packed, t sqrt(g/H) in [50, 100], H/dx = 25", c / p,
                      ">=", 10.0,
                      "measured; Colagrossi et al. 2012 Fig. 8 reports >= 100 (H/dx = 50)"));
  // The packed start never reaches the wall line (measured at H/dx = 20, 25 and 50 to t sqrt(g/H)
  // = 100), so the reflection at the walls (TankRun) never touches it.
  EXPECT_TRUE(r.check("wall reflections, packed start, H/dx = 25",
                      static_cast<double>(packed.reflections), "<=", 0.0,
                      "measured: packed starts stay inside the wall line"));
}

// Fig. 8 at the paper's resolution, H/dx = 50: one test per start, each asserting its own late
// level, the two bounds 100 apart: the paper's "at least two orders of magnitude". Measured means
// of max|u| over t sqrt(g/H) in [50, 100]: Cartesian 1.14e-2, packed 1.72e-5 sqrt(gH), ratio 660
// (without the put-back at the wall line the Cartesian start failed with wall_penetration at
// t sqrt(g/H) = 34).
TEST(TrapezoidalTankRun, CartesianStartAtHOverDx50ToT100) {
  const TankHistory cart = runTrapezoidalTank(50.0, false, tEnd);
  verification::Results r;
  ASSERT_FALSE(cart.failure) << cart.failure->message;
  record(r, "trapezoidal tank, Cartesian start, H/dx = 50", cart);
  r.figure("mean max|u|/sqrt(gH), t sqrt(g/H) in [9, 11], Cartesian, H/dx = 50",
           meanOver(cart, cart.maxSpeed, 9, 11),
           "paper Fig. 7 left: about 0.1 at t sqrt(g/H) = 10");
  // Measured 1.14e-2: 1.4-1.9e-2 (decade means) until t sqrt(g/H) = 80, when the start's
  // currents die down (E_k from 3.5e-6 to 3e-7), then 5.3e-3 and 4.0e-3 over [80, 90] and [90,
  // 100]. Bound 2.5e-3: below that settled level, so it holds wherever in [50, 100] the currents
  // die down; 100 times the packed start's bound below.
  EXPECT_TRUE(r.check("mean max|u|/sqrt(gH), t sqrt(g/H) in [50, 100], Cartesian, H/dx = 50",
                      meanOver(cart, cart.maxSpeed, 50, 100), ">=", 2.5e-3,
                      "measured; paper Fig. 8: about 1e-2 at t sqrt(g/H) = 100"));
}

TEST(TrapezoidalTankRun, PackedStartAtHOverDx50ToT100) {
  const TankHistory packed = runTrapezoidalTank(50.0, true, tEnd);
  verification::Results r;
  ASSERT_FALSE(packed.failure) << packed.failure->message;
  record(r, "trapezoidal tank, packed start, H/dx = 50", packed);
  r.figure("mean max|u|/sqrt(gH), t sqrt(g/H) in [9, 11], packed, H/dx = 50",
           meanOver(packed, packed.maxSpeed, 9, 11), "paper Fig. 7 right");
  // Measured 1.72e-5, falling steadily (decade means 3.9e-5 over [20, 30], 1.4e-5 over [90,
  // 100]). Bound 2.5e-5: the Cartesian start's bound / 100 (paper Fig. 8), 1.45 times the
  // measurement.
  EXPECT_TRUE(r.check("mean max|u|/sqrt(gH), t sqrt(g/H) in [50, 100], packed, H/dx = 50",
                      meanOver(packed, packed.maxSpeed, 50, 100), "<=", 2.5e-5,
                      "Cartesian start's bound 2.5e-3 / 100: paper Fig. 8, >= 100"));
  EXPECT_TRUE(r.check("wall reflections, packed start, H/dx = 50",
                      static_cast<double>(packed.reflections), "<=", 0.0,
                      "measured: packed starts stay inside the wall line"));
}

// Section 3.1.1, Figs. 9-10: settling with the linear damping term -zeta u in the SPH scheme
// itself, from the Cartesian start, for t sqrt(g/H) = 20 (about 10,000 steps, the span of Fig. 9),
// then the undamped run for 100 more (Fig. 10). The histories cover both; the figure compares the
// late level with the packed start of CartesianVersusPackedToT100 (paper: damping "only leads to
// minor improvements"). Measured at H/dx = 25: 5.7e-4 (zeta H/c0 = 1) and 5.0e-4 (0.1) against
// 5.8e-4 undamped from the lattice and 2.8e-5 packed. Figures, not asserted: the settling is the
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
// histories from both starts to t sqrt(g/H) = 100. H = 2 m (the surface over the lowest point);
// H/dx = 20 (dx = 0.1 m: at 0.08 m the lattice puts nodes on the left wall).
TEST(ComplexTankRun, KineticEnergyFromBothStarts) {
  verification::Results r;
  const PackingScene s = tankScene("complex_tank.toml", 20.0);
  TankRunOptions o;
  const TankHistory cart = runTank(s, o, tEnd);
  o.packed = true;
  const TankHistory packed = runTank(s, o, tEnd);
  ASSERT_FALSE(cart.failure) << cart.failure->message;
  ASSERT_FALSE(packed.failure) << packed.failure->message;
  record(r, "complex tank, Cartesian start, H/dx = 20", cart);
  record(r, "complex tank, packed start, H/dx = 20", packed);
  const double c = meanOver(cart, cart.kinetic, 0.5 * tEnd, tEnd);
  const double p = meanOver(packed, packed.kinetic, 0.5 * tEnd, tEnd);
  r.figure("mean E_k/(rho0 g H V), second half, complex tank, Cartesian", c, "paper Fig. 12");
  r.figure("mean E_k/(rho0 g H V), second half, complex tank, packed", p, "paper Fig. 12");
  // Measured 3.6e3 (4.4e-8 against 1.2e-11 over [50, 100]). Before TankRun put particles back
  // at the wall line the Cartesian start crossed the round bottom by the step at t sqrt(g/H) = 73
  // (wall_penetration), and this test stopped at 50 (6.0e3 over [25, 50]). Bound 200: the
  // Cartesian start's E_k swings by 10x over t sqrt(g/H) = 20-50 (bursts near the corners), and
  // the packed level moved 4x with the choice of wall layers above the surface.
  EXPECT_TRUE(r.check("mean E_k Cartesian / packed, second half, complex tank", c / p, ">=", 200.0,
                      "measured; paper Fig. 12: several orders"));
  EXPECT_TRUE(r.check("wall reflections, packed start, complex tank",
                      static_cast<double>(packed.reflections), "<=", 0.0,
                      "measured: packed starts stay inside the wall line"));
}

}  // namespace
}  // namespace sph::packing
