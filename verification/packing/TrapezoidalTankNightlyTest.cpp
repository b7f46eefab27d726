// Colagrossi et al. (2012), section 3.1, Fig. 6: the trapezoidal tank at H/dx = 50 and 100, with
// alpha = 2e-3 (this project's default) and 5e-3 (the top of the paper's range).
#include <gtest/gtest.h>

#include "Results.hpp"
#include "TrapezoidalTank.hpp"

namespace sph::packing {
namespace {

void packAt(double HOverDx, double alpha, int limit) {
  const TankFigures f = packTank(HOverDx, alpha, 2 * limit);
  verification::Results r;
  const std::string tag = ", H/dx = " + std::to_string(static_cast<int>(HOverDx)) + ", alpha = " +
                          (alpha == 5e-3 ? std::string("5e-3") : std::string("2e-3"));
  // T decays like exp(-alpha n) (see TrapezoidalTankTest.cpp): the iteration limits scale as
  // 1/alpha from the paper's ~2,500 at the top of its alpha range, with the quick test's margin.
  // Asserted on T/(N beta): Fig. 6 shows the three resolutions alike ("weakly influenced by the
  // adopted spatial resolution"), which a per-particle T gives and the plain sum of eq. (2.18),
  // growing with N, does not (measured: the sum misses 1e-8 within 8,000 iterations at H/dx = 100,
  // alpha = 5e-3, while the mean reaches it at 3,537).
  EXPECT_TRUE(r.check("iterations to T/(N beta) < 1e-8" + tag, f.iterationsMean, "<=", limit,
                      "Colagrossi et al. 2012 Fig. 6 (about 2,500), scaled by 5e-3/alpha"));
  // Recorded, not asserted: the same with T the plain sum of eq. (2.18) (max_iterations + 1 =
  // 2 limit + 1 is recorded when it never fell below).
  r.figure("iterations to T/beta < 1e-8, T = sum of eq. 2.18" + tag, f.iterations,
           "Colagrossi et al. 2012 Fig. 6; 2 limit + 1 = never within the run");
  EXPECT_TRUE(r.check("H max|grad Gamma|, Cartesian lattice" + tag, f.gradStart, ">=", 0.1,
                      "Colagrossi et al. 2012 Fig. 5 left: O(1)"));
  EXPECT_TRUE(r.check("H max|grad Gamma| after / before" + tag, f.gradEnd / f.gradStart, "<=", 1e-2,
                      "Colagrossi et al. 2012 section 3.1: orders smaller after packing"));
  EXPECT_TRUE(r.check("fluid particles outside the fluid region after packing" + tag, f.outside,
                      "<=", 0, "section 2: the domain is closed by the fixed solid particles"));
}

TEST(TrapezoidalTankNightly, HOverDx50Alpha5e3) {
  packAt(50.0, 5e-3, 4000);
}
TEST(TrapezoidalTankNightly, HOverDx100Alpha5e3) {
  packAt(100.0, 5e-3, 4000);
}
TEST(TrapezoidalTankNightly, HOverDx50Alpha2e3) {
  packAt(50.0, 2e-3, 10000);
}
TEST(TrapezoidalTankNightly, HOverDx100Alpha2e3) {
  packAt(100.0, 2e-3, 10000);
}

}  // namespace
}  // namespace sph::packing
