// Issue 6: the fixed wall particles of Adami, Hu & Adams (2012) (solver/include/sph/FixedWalls.hpp)
// and the hydrostatic trapezoidal tank of Colagrossi et al. (2012), section 3.1, run with them
// (quick tier).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "Results.hpp"
#include "TankRuns.hpp"
#include "sph/FixedWalls.hpp"

namespace sph::packing {
namespace {

// Eq. (27) is exact for a linear pressure field: with p_f = rho0 g (H - y_f) and rho_f = rho0,
// p_w = rho0 g (H - ybar) + rho0 g (ybar - y_w) = rho0 g (H - y_w), ybar the W-weighted mean of
// y_f. The fluid's density from the inverse EOS differs from rho0 by at most gH/c0^2 / gamma
// ~ 1.4e-3 here, so |p_w / (rho0 g (H - y_w)) - 1| <= 2e-3 is the formula, not luck.
TEST(FixedWalls, HydrostaticPressureExtrapolatedIntoTheWall) {
  Phase water;
  water.rho0 = 1000.0, water.c0 = 31.3;
  const double g = 9.81, H = 1.0, dx = 0.04, h = 2.0 * dx;
  std::vector<Vec<2>> wall;
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 25; ++i) wall.emplace_back((i + 0.5) * dx, -(k + 0.5) * dx);
  wall.emplace_back(10.0, 10.0);  // far from any fluid: in no pair, left out of the set
  FixedWalls<2> walls(wall, dx * dx, h, KernelKind::wendland_c2, {water}, Vec<2>(0.0, -g));
  InteractionSet<2> set;
  for (int j = 0; j < 25; ++j)
    for (int i = 0; i < 25; ++i) {
      const double y = (j + 0.5) * dx, p = water.rho0 * g * (H - y);
      set.x.emplace_back((i + 0.5) * dx, y), set.v.push_back(Vec<2>::Zero());
      set.p.push_back(p), set.rho.push_back(TaitEquationOfState::density(p, water));
      set.m.push_back(set.rho.back() * dx * dx), set.h.push_back(h), set.mu.push_back(0.0);
      set.source.push_back(static_cast<int>(set.source.size()));
    }
  set.nFluid = set.size();
  walls.append(set, 2.0 * h, HaloMembers::rescan);  // pairs within 2 h: no skin
  ASSERT_EQ(set.size(), set.nFluid + wall.size() - 1);
  EXPECT_EQ(set.leftOut.count, 1u);
  EXPECT_EQ(set.leftOut.hi, Vec<2>(10.0, 10.0));
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < wall.size(); ++k) {
    const std::size_t e = set.nFluid + k;
    // The fourth layer, at 3.5 dx, is exactly 2h from the first fluid row: no fluid in reach.
    if (k >= 3 * 25) {
      EXPECT_EQ(set.p[e], water.p0);
      continue;
    }
    const double exact = water.rho0 * g * (H - set.x[e].y());
    worst = std::max(worst, std::abs(set.p[e] / exact - 1.0));
    EXPECT_NEAR(set.rho[e], TaitEquationOfState::density(set.p[e], water), 1e-12);
    EXPECT_DOUBLE_EQ(set.m[e], set.rho[e] * dx * dx);
    EXPECT_EQ(set.v[e], Vec<2>::Zero());
  }
  verification::Results r;
  EXPECT_TRUE(r.check("max |p_w / (rho0 g (H - y_w)) - 1|, flat wall under a hydrostatic lattice",
                      worst, "<=", 2e-3, "Adami et al. 2012 eq. 27, exact for linear p"));
}

// A fluid particle that ends a step beyond the wall is a wall_penetration failure that names it.
TEST(FixedWalls, PenetrationIsAFailure) {
  PackingScene s = trapezoidalTankScene(25.0);
  TankRun run(s, TankRunOptions{});
  run.simulation().particles().r[7] = Vec<2>(0.3, -0.1);  // below the bottom, in the wall band
  run.simulation().particles().v[7] = Vec<2>::Zero();
  const auto failure = run.runTo(1.0);
  ASSERT_TRUE(failure.has_value());
  EXPECT_EQ(failure->cause, FailureCause::wall_penetration);
  EXPECT_EQ(failure->particle, 7);
  EXPECT_NE(failure->message.find("beyond the tank's wall"), std::string::npos) << failure->message;
}

// A fluid particle that ends a step less than dx/2 beyond the wall line is put back and counted
// (TankRun::wallReflections): by default onto the wall line with its normal velocity removed
// (restitution 0), with restitution 1 mirrored across it with the normal velocity reversed, as
// at the box walls (Simulation::reflectAtWalls); switched off, it is left where it is.
TEST(FixedWalls, ShallowCrossingIsPutBack) {
  const PackingScene s = trapezoidalTankScene(25.0);
  const double dx = s.dx;
  // Particle 7, 0.3 dx below the bottom, moving down; one step moves it by about 1e-3 dx.
  auto stepFrom = [&](const TankRunOptions& o) {
    auto run = std::make_unique<TankRun>(s, o);
    run->simulation().particles().r[7] = Vec<2>(0.3, -0.3 * dx);
    run->simulation().particles().v[7] = Vec<2>(0.0, -0.05);
    EXPECT_FALSE(run->simulation().advance());
    return run;
  };
  TankRunOptions o;
  const auto put = stepFrom(o);
  EXPECT_GE(put->wallReflections(), 1);
  EXPECT_NEAR(put->maxReflectionDepth(), 0.3 * dx, 0.01 * dx);
  EXPECT_EQ(put->simulation().particles().r[7].y(), 0.0);  // on the bottom's line
  EXPECT_NEAR(put->simulation().particles().r[7].x(), 0.3, 0.01 * dx);
  EXPECT_NEAR(put->simulation().particles().v[7].y(), 0.0, 1e-12);
  o.restitution = 1.0;
  const auto mirrored = stepFrom(o);
  EXPECT_GE(mirrored->wallReflections(), 1);
  EXPECT_NEAR(mirrored->simulation().particles().r[7].y(), 0.3 * dx, 0.01 * dx);
  EXPECT_GT(mirrored->simulation().particles().v[7].y(), 0.0);
  o.reflect = false;
  const auto plain = stepFrom(o);
  EXPECT_LT(plain->simulation().particles().r[7].y(), -0.29 * dx);
  EXPECT_EQ(plain->wallReflections(), 0);
}

// Colagrossi et al. (2012), section 3.1: from a packed start the hydrostatic tank stays still
// (to t sqrt(g/H) = 10, about 10 s here).
TEST(TrapezoidalTankRun, PackedStartHoldsStillAtHOverDx25) {
  const TankHistory t = runTrapezoidalTank(25.0, true, 10.0, 0.05);
  verification::Results r;
  ASSERT_FALSE(t.failure) << t.failure->message;
  r.history("max|u|/sqrt(gH), packed start, H/dx = 25", "t sqrt(g/H)", t.t, "max|u|/sqrt(gH)",
            t.maxSpeed, "Colagrossi et al. 2012 Fig. 8");
  // The start is not quite at rest: the packing (free surface closed by solid layers, section 2)
  // leaves particles in the tip of the 45-degree corner that in the run slide down the slope, at
  // up to 1.1e-2 sqrt(gH) (measured, t sqrt(g/H) < 1). Recorded, not asserted.
  r.figure("max over t sqrt(g/H) <= 10 of max|u|/sqrt(gH), packed start, H/dx = 25",
           t.maxSpeedOverall, "measured: the particles in the acute corner, see comment");
  // Holding still: max|u| over t sqrt(g/H) in [9, 10], the time of the paper's Fig. 7; measured
  // 7.8e-4. The paper's packed start (delta-SPH, H/dx = 50, Fig. 8) stays between 1e-4 and
  // 1e-3 sqrt(gH); bound 3e-3, room for the slow motion in the acute corner that sets it, still
  // 30 times below the Cartesian start's 0.1 sqrt(gH) at that time in the paper (Fig. 7 left).
  double late = 0.0;
  for (std::size_t k = 0; k < t.t.size(); ++k)
    if (t.t[k] >= 9.0) late = std::max(late, t.maxSpeed[k]);
  EXPECT_TRUE(r.check("max|u|/sqrt(gH) over t sqrt(g/H) in [9, 10], packed start, H/dx = 25", late,
                      "<=", 3e-3, "measured, see comment; Colagrossi et al. 2012 Figs. 7-8"));
  // Hydrostatic pressure next to the sloping wall (within 2 dx of it, below y = 0.8 H, away from
  // the free surface): max |p - rho0 g (H - y)| / (rho0 g H) at t sqrt(g/H) = 10; measured 7.4e-3.
  // That is the acoustic pressure rho0 c0 u of the motion left (u = 7.8e-4 sqrt(gH), c0 = 10
  // sqrt(gH): 7.8e-3 rho0 g H). Bound 0.02: the same for 2.5 times that motion.
  EXPECT_TRUE(r.check("max |p - p_hydrostatic| / (rho0 g H) within 2 dx of the 45-degree wall",
                      t.slopePressureError, "<=", 0.02,
                      "acoustic pressure rho0 c0 max|u|, see comment"));
  EXPECT_TRUE(r.check("deepest excursion beyond the wall line / dx", t.maxDepth / t.dx, "<=", 0.0,
                      "fluid stays inside the tank (wall_penetration beyond dx/2)"));
  // Nor does it reach the wall line and get reflected (TankRun::wallReflections).
  EXPECT_TRUE(r.check("wall reflections, packed start, H/dx = 25",
                      static_cast<double>(t.reflections), "<=", 0.0,
                      "fluid stays inside the tank (measured: packed starts never cross)"));
}

}  // namespace
}  // namespace sph::packing
