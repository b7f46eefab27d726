// Issue 32, part 5: the lattice start (InitialParticles.hpp) puts every particle inside its block.
// A rectangle thinner than dx/2 along an axis got one particle at lower + dx/2 there, outside it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sph/EquationOfState.hpp"
#include "sph/InitialParticles.hpp"

namespace {

// A 2-D box with one rectangular block [0, 0.1] x [0, height] at dx = 0.01.
sph::Scene block(const std::string& height) {
  return sph::parseScene(R"(
name = "lattice"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [0.2, 0.2]
[[phase]]
name = "water"
rho0 = 1000.0
c0 = 20.0
[[fluid]]
lower = [0.0, 0.0]
upper = [0.1, )" + height + R"(]
[numerics]
dx = 0.01
end_time = 0.01
)",
                         "lattice");
}

// Every particle inside [lower, upper] of the block, to round-off (1e-12 dx).
void expectInside(const sph::Scene& s, std::size_t expected) {
  const sph::Particles<2> p = sph::latticeParticles<2>(s);
  EXPECT_EQ(p.size(), expected);
  const auto& b = s.fluids[0];
  const double tol = 1e-12 * s.dx;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 2; ++a) {
      EXPECT_GE(p.r[i][a], b.lower[a] - tol) << "particle " << i << " axis " << a;
      EXPECT_LE(p.r[i][a], b.upper[a] + tol) << "particle " << i << " axis " << a;
    }
}

TEST(LatticeStart, BlockThinnerThanHalfDxHoldsNoParticle) {
  // 0.004 = 0.4 dx: round(0.4) = 0 nodes across, so none at all.
  sph::Scene s = block("0.1");
  s.fluids[0].upper[1] = 0.004;
  expectInside(s, 0);
}

TEST(LatticeStart, BlockOfHalfToOneDxHoldsOneRow) {
  sph::Scene s = block("0.1");
  s.fluids[0].upper[1] = 0.006;  // 0.6 dx: one row at y = 0.005
  expectInside(s, 10);
}

TEST(LatticeStart, BlockOfWholeSpacings) {
  expectInside(block("0.1"), 100);
}

// The hydrostatic start takes its depth along the body acceleration, whichever way it points:
// p = p0 + rho0 |g| (z_s - z), z = -g.x/|g|, z_s the block's highest point. Gravity along -y is
// the upright tank (y_s the block's top, to the bit); along -x the same tank on its side, where
// the start used to be the upright's, so that a tank at rest sloshed (`sph run`, H/dx 20, named
// model: max|u| 0.085 sqrt(gH), against 0.0013 now, as upright). Tilted by 30
// degrees, the deepest corner is the one g points to. Tolerance: the EOS's inverse and back, 1e-9
// of the largest pressure.
TEST(LatticeStart, HydrostaticStartFollowsTheGravitysDirection) {
  const double g = 9.81, rho0 = 1000.0;
  for (const double angle : {0.0, 90.0, 30.0, 180.0}) {  // of g from -y, towards -x
    sph::Scene s = block("0.1");
    s.fluids[0].hydrostatic = true;
    const double t = angle * std::acos(-1.0) / 180.0;
    s.bodyAcceleration = {-g * std::sin(t), -g * std::cos(t)};
    // z_s: the highest corner of [0, 0.1]^2 against g (readScene sets it where `surface` is absent;
    // heightRange is its rule).
    double lowest = 0;
    sph::heightRange(s, s.fluids[0], lowest, s.fluids[0].surface);
    const double up[2] = {std::sin(t), std::cos(t)};
    const double zs = std::max({0.0, 0.1 * up[0], 0.1 * up[1], 0.1 * (up[0] + up[1])});
    EXPECT_NEAR(s.fluids[0].surface, zs, 1e-15) << angle;
    const sph::Particles<2> p = sph::latticeParticles<2>(s);
    double worst = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double z = up[0] * p.r[i][0] + up[1] * p.r[i][1];
      worst = std::max(worst, std::abs(p.p[i] - rho0 * g * (zs - z)));
    }
    EXPECT_LE(worst, 1e-9 * rho0 * g * 0.2) << "gravity " << angle << " degrees from -y";
    if (angle == 0.0)  // the upright tank: the top of the block, y itself
      for (std::size_t i = 0; i < p.size(); ++i)
        EXPECT_EQ(p.p[i],
                  sph::TaitEquationOfState::pressure(
                      sph::TaitEquationOfState::density(rho0 * g * (0.1 - p.r[i][1]), s.phases[0]),
                      s.phases[0]));
  }
}

// A count that would not be exact in a double (or overflow lround) is refused, not wrapped.
TEST(LatticeStart, CountBeyondTwoToThe53IsRefused) {
  EXPECT_EQ(sph::latticeCount(1.0, 0.25), 4);
  EXPECT_THROW(sph::latticeCount(1.0, 1e-30), std::overflow_error);
  EXPECT_THROW(sph::latticeCount(1.0, 5e-324), std::overflow_error);
}

}  // namespace
