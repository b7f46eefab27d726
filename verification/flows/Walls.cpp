// Issue 3, walls (ghost particles: Libersky et al. 1993, Colagrossi & Landrini 2003):
//  * a block of fluid thrown at a free-slip wall does not cross it;
//  * a uniform tangential flow along free-slip walls keeps its speed exactly (the ghosts carry
//    the same tangential velocity, so every v_ij vanishes), while no-slip walls decelerate it as
//    the start-up series of a channel predicts;
//  * ghosts held at p0 or above ([walls] tensile = false) hold a drop's run-up at the walls.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "FlowCases.hpp"
#include "Results.hpp"
#include "WallCases.hpp"

namespace sph::verification {
namespace {

TEST(Walls, BlockThrownAtAWallDoesNotCrossIt) {
  Results r;
  // The dam-break settings (validation/scenes/dam_break.toml): beta = 1, water viscosity, h =
  // 1.33 dx; a 0.2 m square block at 2 m/s, 0.1 m from the wall; c0 = 10 x 2 m/s (Mach 0.1).
  const std::string text = R"(
name = "thrown_block"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [0.6, 0.5]
x_lower = "free_slip"
x_upper = "free_slip"
y_lower = "free_slip"
y_upper = "free_slip"
[[phase]]
name = "water"
rho0 = 1000.0
c0 = 20.0
mu = 8.9e-4
[[fluid]]
lower = [0.1, 0.15]
upper = [0.3, 0.35]
velocity = [-2.0, 0.0]
[physics]
artificial_viscosity = 1.0
morris_viscosity = true
[numerics]
dx = 0.01
end_time = 0.15
)";
  Simulation<2> sim(parseScene(text, "thrown_block"));
  double closest = 1e300;  // smallest distance of any particle to the wall x = 0
  while (sim.time() < 0.15) {
    auto f = sim.advance();
    ASSERT_FALSE(f) << f->message;
    for (const auto& x : sim.particles().r) closest = std::min(closest, x[0]);
  }
  double meanU = 0;
  for (const auto& v : sim.particles().v) meanU += v[0] / sim.particles().size();
  std::printf("closest %.4e m (dx = 0.01), reflections %ld, mean u at end %.3f\n", closest,
              sim.wallReflections(), meanU);
  EXPECT_TRUE(r.check("closest approach to the wall / dx", closest / 0.01, ">", 0.0,
                      "a particle may not cross the wall"));
  // Finding: the paper's mirror ghosts give a finite repulsion as a particle nears its own ghost
  // (the kernel's slope at q = 0 is finite and the ghost carries the particle's own, near-zero,
  // pressure at the block's free corners), so some particle-steps end a little beyond the wall
  // and the solver reflects them back (Simulation::reflectAtWalls). Measured: 44 reflections, at
  // most 0.008 dx deep; the thresholds bound a regression.
  std::printf("deepest crossing %.3f dx\n", sim.maxReflectionDepth() / 0.01);
  EXPECT_TRUE(r.check("particle-steps reflected back at the wall", sim.wallReflections(), "<=", 100,
                      "measured 44 (finite ghost repulsion, see comment); regression bound"));
  EXPECT_TRUE(r.check("deepest crossing before reflection / dx", sim.maxReflectionDepth() / 0.01,
                      "<=", 0.05,
                      "measured 0.008; the solver fails a run beyond 0.5 (Simulation.hpp)"));
  // The block has hit and turned back: the wall pushed (its mean velocity changed sign).
  EXPECT_TRUE(r.check("mean u after the impact [m/s]", meanU, ">", -1.0,
                      "the wall's ghosts must decelerate the block"));
}

// Fluid layer of height L = 0.1 m between walls at y = 0 and L, periodic in x, moving at U.
std::string layer(const std::string& wall) {
  std::ostringstream s;
  s << "name = \"layer\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [0.2, 0.1]\n"
    << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"" << wall << "\"\ny_upper = \""
    << wall << "\"\n[[phase]]\nname = \"w\"\nrho0 = 1000.0\nc0 = 10.0\nmu = 1.0\n"
    << "[[fluid]]\nlower = [0.0, 0.0]\nupper = [0.2, 0.1]\nvelocity = [1.0, 0.0]\n"
    << "[physics]\nmorris_viscosity = true\n[numerics]\ndx = 0.01\nend_time = 0.5\n";
  return s.str();
}

double meanSpeed(const Simulation<2>& sim) {
  double u = 0;
  for (const auto& v : sim.particles().v) u += v[0];
  return u / sim.particles().size();
}

TEST(Walls, TangentialFlowFreeSlipKeepsSpeedNoSlipDecelerates) {
  Results r;
  const double T = 0.5, L = 0.1, nu = 1e-3;  // nu T / L^2 = 0.05: the wall layers span 2 dx
  Simulation<2> freeSlip(parseScene(layer("free_slip"), "layer"));
  Simulation<2> noSlip(parseScene(layer("no_slip"), "layer"));
  ASSERT_TRUE(runTo(freeSlip, T));
  ASSERT_TRUE(runTo(noSlip, T));
  // Mean of the start-up series for a layer at U between resting plates (the Couette series of
  // reference_data/README.md with the plates at rest and the fluid started at U).
  double exact = 0;
  for (int n = 0; n < 200; ++n) {
    const double k = 2 * n + 1;
    exact += 8 / (pi * pi * k * k) * std::exp(-k * k * pi * pi * nu * T / (L * L));
  }
  const double uFree = meanSpeed(freeSlip), uNo = meanSpeed(noSlip);
  std::printf("free slip %.15f, no slip %.5f, series %.5f\n", uFree, uNo, exact);
  EXPECT_TRUE(r.check("free slip: |mean u - U| / U", std::abs(uFree - 1), "<=", 1e-12,
                      "every v_ij is zero: round-off only"));
  EXPECT_TRUE(r.check("no slip: mean u / U at t = 0.1 s", uNo, "<", 0.95,
                      "the series gives 0.75: the wall must decelerate the layer"));
  EXPECT_TRUE(r.check("no slip: |mean u - series| / U at t = 0.1 s, L/dx = 10",
                      std::abs(uNo - exact), "<=", 0.03,
                      "Couette start-up at L/dx = 10 (ChannelFlows) errs by up to 3 % of V0"));
}

// The paper's drop into a pool at dx 0.002 (validation/scenes/drop_into_pool_dx0.002.toml): the
// run-up sheets along the side walls are in tension (p down to -5 kPa), and the paper's ghosts,
// which mirror that pressure, pull them into the walls: particles are put back across them (38
// measured here, 16 by `sph run`, whose steps end at other times; 2026-12-05). With the ghosts
// held at p0 or above ([walls] tensile = false, solver/SCENES.md) none reaches a wall (0 measured
// both ways): the issue-31 bar for this scene.
TEST(Walls, GhostsWithoutTensionHoldTheDropsRunUp) {
  Results r;
  std::ifstream in(std::string(SPH_SOURCE_DIR) + "/validation/scenes/drop_into_pool_dx0.002.toml");
  std::stringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty());
  const WallRun paper = runWalls<2>(parseScene(text.str(), "drop_into_pool_dx0.002.toml"));
  const WallRun held = runWalls<2>(
      parseScene(text.str() + "\n[walls]\ntensile = false\n", "drop_into_pool_dx0.002.toml"));
  ASSERT_TRUE(paper.stable) << paper.failure;
  ASSERT_TRUE(held.stable) << held.failure;
  std::printf("wall reflections: paper's ghosts %ld (deepest %.2e m), tensile = false %ld\n",
              paper.reflections, paper.deepest, held.reflections);
  EXPECT_TRUE(r.check("wall reflections with ghosts held at p0 or above", held.reflections, "<=", 0,
                      "issue 31: no wall reflections needed by the drop into a pool"));
  EXPECT_TRUE(r.check("wall reflections with the paper's ghosts", paper.reflections, ">=", 1,
                      "38 measured: without the option the case does need them"));
}

}  // namespace
}  // namespace sph::verification
