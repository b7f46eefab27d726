// Issue 3: start-up Poiseuille and Couette flow at the coarse resolution L/dx = 10, against the
// series solutions (Morris, Fox & Zhu 1997). The tolerances come from the convergence study in
// ChannelConvergence.cpp (nightly), which measured the errors at L/dx = 10, 20 and 40.
#include <gtest/gtest.h>

#include <cstdio>

#include "ChannelCommon.hpp"
#include "Results.hpp"

namespace sph::verification {
namespace {

void coarseChannel(bool couette, double l2Tol, double linfTol) {
  Results r;
  const auto errors = channelErrors(couette, 10, kMorrisTimes);
  ASSERT_EQ(errors.size(), kMorrisTimes.size()) << errors.back().failure;
  const std::string what = couette ? "Couette" : "Poiseuille";
  for (std::size_t k = 0; k < errors.size(); ++k) {
    std::printf("%s t=%g  L2 %.4e  Linf %.4e  drho %.2e\n", what.c_str(), kMorrisTimes[k],
                errors[k].l2, errors[k].linf, errors[k].densityDeviation);
    const std::string at = " at t = " + std::to_string(kMorrisTimes[k]) + " s, L/dx = 10";
    EXPECT_TRUE(r.check(what + " L2 error / v_max" + at, errors[k].l2, "<=", l2Tol,
                        "1.5x the L/dx = 10 error of the nightly study ChannelConvergence"));
    EXPECT_TRUE(r.check(what + " Linf error / v_max" + at, errors[k].linf, "<=", linfTol,
                        "1.5x the L/dx = 10 error of the nightly study ChannelConvergence"));
  }
  // c0 = 10 v_max: Mach 0.1, density variations of order Ma^2 = 1 % (Morris et al. 1997 sec. 2).
  EXPECT_TRUE(r.check(what + " max |rho/rho0 - 1|", errors.back().densityDeviation, "<=", 0.01,
                      "Ma = 0.1 gives density variations of order Ma^2 = 1 % (Monaghan 1994)"));
}

// Measured at L/dx = 10 (largest over the five times): Poiseuille L2 1.70e-2, Linf 2.05e-2;
// Couette L2 1.33e-2, Linf 3.11e-2. Tolerances 1.5x those.
TEST(ChannelFlow, PoiseuilleStartUpCoarse) {
  coarseChannel(false, 0.026, 0.031);
}
TEST(ChannelFlow, CouetteStartUpCoarse) {
  coarseChannel(true, 0.020, 0.047);
}

}  // namespace
}  // namespace sph::verification
