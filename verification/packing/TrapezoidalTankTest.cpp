// Colagrossi et al. (2012), section 3.1, Figs. 5 and 6, at H/dx = 25 (quick tier).
#include <gtest/gtest.h>

#include "Results.hpp"
#include "TrapezoidalTank.hpp"

namespace sph::packing {
namespace {

TEST(TrapezoidalTank, PacksAtHOverDx25) {
  // alpha = 5e-3, the top of the paper's range: T decays like exp(-alpha n) per iteration n
  // (E loses 2 zeta T dt per step, eq. B.33, and T is about half of E), so the paper's ~2,500
  // iterations from T ~ 1e-2 beta to 1e-8 beta (14 e-folds) need alpha near 5e-3; at alpha = 2e-3
  // this tank takes ~6,900 iterations (nightly suite).
  const TankFigures f = packTank(25.0, 5e-3, 6000);
  verification::Results r;
  // Paper, Fig. 6: "particle are practically motionless after 2,500 iterations when ... less than
  // 1e-8 beta". Threshold 4,000: the paper's figure plus the margin that its unstated h/dx and
  // alpha leave; measured 3,326 (T, eq. 2.18) and 2,082 (T/N).
  EXPECT_TRUE(r.check("iterations to T/beta < 1e-8 (T = sum, eq. 2.18), H/dx = 25, alpha = 5e-3",
                      f.iterations, "<=", 4000, "Colagrossi et al. 2012 Fig. 6 (about 2,500)"));
  EXPECT_TRUE(r.check("iterations to T/(N beta) < 1e-8, H/dx = 25, alpha = 5e-3", f.iterationsMean,
                      "<=", 3000, "Colagrossi et al. 2012 Fig. 6 (about 2,500)"));
  // Fig. 5, left: H |grad Gamma| of order 1 along the slope on the Cartesian lattice (colour
  // scale 0 .. 2); measured 2.49. Below 0.1 would mean the solid layers copy the lattice.
  EXPECT_TRUE(r.check("H max|grad Gamma|, Cartesian lattice, H/dx = 25", f.gradStart, ">=", 0.1,
                      "Colagrossi et al. 2012 Fig. 5 left: O(1)"));
  // Fig. 5, right, and section 3.1: "drastically reduces the magnitude" to about 1e-3 (order of
  // magnitude); required here: at least two orders below the lattice's value.
  EXPECT_TRUE(r.check("H max|grad Gamma| after packing / before, H/dx = 25",
                      f.gradEnd / f.gradStart, "<=", 1e-2,
                      "Colagrossi et al. 2012 section 3.1: orders smaller after packing"));
  // The solid layers must hold the fluid: no fluid particle ends outside the tank (a gap in the
  // solid lets particles through the band and away, where Gamma = 0; see solidLayers()).
  EXPECT_TRUE(r.check("fluid particles outside the fluid region after packing, H/dx = 25",
                      f.outside, "<=", 0,
                      "section 2: the domain is closed by the fixed solid particles"));
}

}  // namespace
}  // namespace sph::packing
