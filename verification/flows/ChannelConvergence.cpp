// Issue 3 (nightly): start-up Poiseuille and Couette flow (Morris, Fox & Zhu 1997) at L/dx = 10,
// 20, 40 with h/dx = 1.33, the quadratic kernel and dt from the viscous limit (dt ~ dx^2).
// Theory for a consistent second-order discretisation: order 2. What limits it here: the Morris
// viscous operator (eq. 9) on a lattice with h/dx fixed carries the kernel's discretisation
// error (it does not vanish as dx -> 0, Quinlan et al. 2006) and the anti-crossing eta^2 =
// 0.01 h^2 biases r.gradW / (r^2 + eta^2) by O(eta^2 / dx^2) = O(1 %), also independent of dx.
// A linear profile (Couette's steady state) is reproduced exactly by the lattice's symmetry;
// a quadratic one (Poiseuille's) is not, so Poiseuille's steady error is that floor.
#include <gtest/gtest.h>

#include <cstdio>

#include "ChannelCommon.hpp"
#include "Results.hpp"

namespace sph::verification {
namespace {

void study(bool couette) {
  Results r;
  const std::string what = couette ? "Couette" : "Poiseuille";
  const std::vector<int> res{10, 20, 40};
  std::vector<std::vector<ProfileError>> all;
  for (int n : res) {
    all.push_back(channelErrors(couette, n, kMorrisTimes));
    ASSERT_EQ(all.back().size(), kMorrisTimes.size()) << all.back().back().failure;
  }
  std::vector<double> dx;
  for (int n : res) dx.push_back(ChannelFlow::L / n);
  for (std::size_t k = 0; k < kMorrisTimes.size(); ++k) {
    std::vector<double> l2, linf;
    for (std::size_t m = 0; m < res.size(); ++m)
      l2.push_back(all[m][k].l2), linf.push_back(all[m][k].linf);
    const std::string at = " at t = " + std::to_string(kMorrisTimes[k]) + " s";
    const double o2 =
        r.convergence(what + " L2 error / v_max" + at, "dx [m]", dx, l2, 2.0,
                      "Morris, Fox & Zhu 1997; second-order consistent discretisation");
    const double oi =
        r.convergence(what + " Linf error / v_max" + at, "dx [m]", dx, linf, 2.0,
                      "Morris, Fox & Zhu 1997; second-order consistent discretisation");
    std::printf("%s t=%-7g L2 %.3e %.3e %.3e (order %.2f)  Linf %.3e %.3e %.3e (order %.2f)\n",
                what.c_str(), kMorrisTimes[k], l2[0], l2[1], l2[2], o2, linf[0], linf[1], linf[2],
                oi);
    // Every profile within 3.5 % of v_max at every resolution: the level Morris et al. report
    // (their Figs. 2-3 show agreement to within the symbol size, a few per cent).
    for (std::size_t m = 0; m < res.size(); ++m)
      EXPECT_TRUE(r.check(what + " Linf error / v_max" + at + ", L/dx = " + std::to_string(res[m]),
                          linf[m], "<=", 0.035,
                          "Morris et al. 1997 Figs. 2-3: within a few per cent"));
    // Observed orders (measured, c0 = 10 v_max): Poiseuille L2 2.09, 2.15, 1.94, 1.65, 2.10 at
    // the five times; Couette 2.50 and 2.20 at the first two, then 1.4 and 1.3 as its error
    // reaches a floor of 3e-4 v_max at L/dx = 40 (the sliding rows' pressure noise: it does not
    // depend on c0, 100 v_max gave the same), and at steady state the error is below 4e-5 v_max
    // at every resolution: a linear profile is exact on the lattice. Asserted: 0.5 below theory
    // where the error is above that floor.
    const bool aboveFloor = !couette || kMorrisTimes[k] < 0.1;
    if (aboveFloor)
      EXPECT_TRUE(r.check(what + " L2 observed order" + at, o2, ">=", 1.5,
                          "theory 2 minus 0.5 (three resolutions, pre-asymptotic)"));
    else
      EXPECT_TRUE(r.check(what + " L2 error / v_max at L/dx = 40" + at, l2[2], "<=", 1e-3,
                          "the floor measured at 3e-4 v_max, with a factor of 3"));
  }
  for (std::size_t m = 0; m < res.size(); ++m)
    std::printf("%s L/dx %d max |rho/rho0-1| %.2e\n", what.c_str(), res[m],
                all[m].back().densityDeviation);
}

TEST(ChannelConvergence, Poiseuille) {
  study(false);
}
TEST(ChannelConvergence, Couette) {
  study(true);
}

}  // namespace
}  // namespace sph::verification
