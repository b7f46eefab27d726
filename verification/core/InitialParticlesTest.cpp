// Issue 32, part 5: the lattice start (InitialParticles.hpp) puts every particle inside its block.
// A rectangle thinner than dx/2 along an axis got one particle at lower + dx/2 there, outside it.
#include <gtest/gtest.h>

#include <string>

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

// A count that would not be exact in a double (or overflow lround) is refused, not wrapped.
TEST(LatticeStart, CountBeyondTwoToThe53IsRefused) {
  EXPECT_EQ(sph::latticeCount(1.0, 0.25), 4);
  EXPECT_THROW(sph::latticeCount(1.0, 1e-30), std::overflow_error);
  EXPECT_THROW(sph::latticeCount(1.0, 5e-324), std::overflow_error);
}

}  // namespace
