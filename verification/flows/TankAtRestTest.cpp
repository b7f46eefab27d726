// Issue 31 (quick tier): the tank at rest of TankAtRest.hpp at H/dx 20, aspect 1:1, with the
// named model (the paper's terms with Fourtakas et al.'s density diffusion, delta 0.1) and
// Wendland C2 at h/dx 2, its energy budget checked as `sph run` checks it. The named model itself
// to the bar's t sqrt(g/H) = 100 (some 20 s of one core): it is what a user's `sph run` of a tank
// does, and the budget's check stopped it at 45 before a density diffusion's lift went uncharged
// (EnergyBudget.cpp). Its variants to 30 (the full horizon and the matrix over kernels, aspects
// and resolutions are in TankAtRestNightlyTest.cpp). Measured to 100: max|u| 3.8e-3 sqrt(gH),
// bottom pressure 0.24 % off the column's weight (0.73 % off rho0 g H: TankAtRest.hpp); the second
// half of the short horizon starts at 15, after the start's acoustic transient has decayed (max|u|
// 1e-3 by t sqrt(g/H) = 4).
#include <gtest/gtest.h>

#include <cstdio>

#include "Results.hpp"
#include "TankAtRest.hpp"

namespace sph::verification::tank_at_rest {
namespace {

// The run's outcome, for further checks, which go into the same `r` (a Results writes the test's
// one file when it is destroyed: a second one would replace the first's).
Outcome expectStill(Results& r, const Model& m, Case c = {1.0, 20, wendland, 30.0}) {
  const Outcome o = run(c, m);
  std::printf("%s: ran %d to %.1f, max|u|/sqrt(gH) %.3e, bottom pressure %.3e, %.1f s\n",
              m.name.c_str(), o.ran, o.stoppedAt, o.speed, o.bottom, o.seconds);
  EXPECT_TRUE(o.ran) << o.why;
  if (!o.ran) return o;
  const std::string what = "tank at rest" + std::string(c.dimension == 3 ? " (3-D)" : "") +
                           ", H/dx " + std::to_string(c.cells) + ", 1:1, wendland_c2, " + m.name;
  const std::string half = "second half of t sqrt(g/H) = " + std::to_string(int(c.horizon));
  EXPECT_TRUE(r.check(what + ": max|u| / sqrt(gH), " + half, o.speed, "<", speedBar,
                      "issue 31's bar (0.01 sqrt(gH))"));
  EXPECT_TRUE(r.check(what + ": max |p_bottom / (g M / A) - 1|, " + half, o.bottom, "<",
                      bottomPressureBar, "issue 31's bar (1 % of rho g H)"));
  return o;
}
Outcome expectStill(const Model& m, Case c = {1.0, 20, wendland, 30.0}) {
  Results r;
  return expectStill(r, m, c);
}

TEST(TankAtRest, NamedModelHoldsStillAtHOverDx20) {
  expectStill(fourtakas, {1.0, 20, wendland, 100.0});
}

// The named model in 3-D, a tank 1 x 1 x 1 H at H/dx 10 to t sqrt(g/H) = 20 (some 16 s of one
// core): measured max|u| 7.0e-4 sqrt(gH), bottom pressure 0.07 % off. The 3-D tank at H/dx 20 to
// 100 is in TankAtRestNightlyTest.cpp (on the lattice it starts to move at 49).
TEST(TankAtRest, NamedModelHoldsStillIn3DAtHOverDx10) {
  expectStill(fourtakas, {1.0, 10, wendland, 20.0, 0.25, 3});
}

// Antuono et al.'s (2010) diffusion in place of Fourtakas et al.'s, to t sqrt(g/H) = 100: the
// tank holds still longer. Measured max|u| 2.3e-4 sqrt(gH), bottom pressure 0.25 % over the
// second half (Fourtakas et al.'s: 3.8e-3, 0.24 %; the 4:1 tank at H/dx 40 passes 1e-3 at
// t sqrt(g/H) = 80 with it, 52 with theirs: verification/README.md). Besides the bars, its speed
// must stay below 1e-3 sqrt(gH), the level at which the README reads a tank's onset of motion,
// which Fourtakas et al.'s form passes here.
TEST(TankAtRest, AntuonoDiffusionHoldsStillLongerAtHOverDx20) {
  Results r;
  const Outcome o = expectStill(r, antuono, {1.0, 20, wendland, 100.0});
  EXPECT_TRUE(r.check("tank at rest, H/dx 20, 1:1, wendland_c2, " + antuono.name +
                          ": max|u| / sqrt(gH), second half of t sqrt(g/H) = 100",
                      o.speed, "<", 1e-3,
                      "the onset level of verification/README.md (Fourtakas et al.: 3.8e-3)"));
}

// The paper's kernel and the cubic spline at an h/dx where their square lattice holds under
// pressure (the map of LatticeUnderPressureTest.cpp: 1.20-1.24 and 1.20-1.22, not the paper's
// 1.33, where the quadratic kernel's 4:1 tank gives way inside), with Antuono et al.'s diffusion,
// to t sqrt(g/H) = 100 (some 10 s of one core each). Measured max|u| 4.8e-4 and 1.9e-3 sqrt(gH);
// at h/dx 1.33 the quadratic kernel's 4:1 tank reached 0.018 (Fourtakas et al.) and 0.024
// (Antuono et al.). Their bottom pressure, 0.68 % and 0.99 % off the column's weight (on the
// lattice their gradient of a linear field is 0.9964 and 0.9947 of the true one), meets the 1 %
// bar; the cubic spline's, at the bar, is held under a regression bound of 2.5 times.
TEST(TankAtRest, OtherKernelsHoldStillWhereTheirLatticeHolds) {
  struct Other {
    Kernel kernel;
    double bottomBound;
    std::string source;
  };
  Results r;  // one for the test: each Results writes the test's one file when destroyed
  for (const Other& k :
       {Other{{"quadratic", 1.2}, bottomPressureBar, "issue 31's bar (1 % of rho g H)"},
        Other{{"cubic_spline", 1.22},
              2.5 * 0.0099,
              "finding: regression bound, 2.5 x the measured 0.99 % (bar 1 %)"}}) {
    const Outcome o = run({1.0, 20, k.kernel, 100.0}, antuono);
    const std::string what = "tank at rest, H/dx 20, 1:1, " + k.kernel.name + " at h/dx " +
                             std::to_string(k.kernel.hOverDx).substr(0, 4) + ", " + antuono.name;
    std::printf("%s: ran %d to %.1f, max|u|/sqrt(gH) %.3e, bottom pressure %.3e, %.1f s\n",
                what.c_str(), o.ran, o.stoppedAt, o.speed, o.bottom, o.seconds);
    ASSERT_TRUE(o.ran) << what << ": " << o.why;
    EXPECT_TRUE(r.check(what + ": max|u| / sqrt(gH), second half of t sqrt(g/H) = 100", o.speed,
                        "<", speedBar, "issue 31's bar (0.01 sqrt(gH))"));
    EXPECT_TRUE(r.check(what + ": max |p_bottom / (g M / A) - 1|, second half", o.bottom, "<",
                        k.bottomBound, k.source));
  }
}

// The same with position Verlet at the default acoustic CFL 0.25.
TEST(TankAtRest, NamedModelWithPositionVerletHoldsStillAtHOverDx20) {
  expectStill(fourtakasVerlet);
}

// The same with velocity Verlet at the default acoustic CFL 0.25: one force evaluation a step, the
// rates of each state taken from its prediction (VelocityVerlet.hpp).
TEST(TankAtRest, NamedModelWithVelocityVerletHoldsStillAtHOverDx20) {
  expectStill(fourtakasVelocityVerlet);
}

// The same with Lind et al.'s particle shifting (ParticleShifting.hpp, A = 2). Measured to 30:
// max|u| 2.8e-4 sqrt(gH), bottom pressure 0.14 % off, as without shifting (to 100 both read 3.8e-3
// and 0.73 % off rho0 g H): at rest D = A h |u| dt is small and the shift with it.
TEST(TankAtRest, NamedModelWithLindShiftingHoldsStillAtHOverDx20) {
  expectStill(fourtakasLind);
}

}  // namespace
}  // namespace sph::verification::tank_at_rest
