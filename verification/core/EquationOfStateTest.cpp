// Issue 2, part 4: the Tait equation of state (Lobovsky & Kren eq. 8) and its inverse.
#include <gtest/gtest.h>

#include <cmath>

#include "Results.hpp"
#include "sph/EquationOfState.hpp"

namespace {

TEST(EquationOfState, RoundTrip) {
  sph::Phase water{"water", 1000.0, 24.4, 8.9e-4, 0.0, 7.0};
  sph::Phase heavy{"heavy", 1500.0, 60.0, 1e-3, 2.5e4, 7.0};
  sph::Phase other{"other", 1.2, 340.0, 0.0, -50.0, 1.4};
  double worst = 0.0;
  for (const auto& ph : {water, heavy, other}) {
    // p = p0 at rho = rho0 exactly: the reference state of eq. (8).
    EXPECT_EQ(sph::TaitEquationOfState::pressure(ph.rho0, ph), ph.p0);
    for (int k = 0; k <= 100; ++k) {
      const double rho = ph.rho0 * (0.8 + 0.4 * k / 100.0);  // the default density band
      const double p = sph::TaitEquationOfState::pressure(rho, ph);
      const double back = sph::TaitEquationOfState::density(p, ph);
      worst = std::max(worst, std::abs(back / rho - 1.0));
    }
  }
  sph::verification::Results results;
  // pow(pow(x, 7), 1/7) loses a few ulp per call and the subtraction of K is benign on
  // [0.8, 1.2] rho0 (|(rho/rho0)^7 - 1| >= 0 with no cancellation against p0 here beyond
  // |p0|/K <~ 1); 1e-12 is the requirement, ~1e4 ulp.
  EXPECT_TRUE(results.check("max |rho(p(rho))/rho - 1| over [0.8, 1.2] rho0", worst, "<=", 1e-12,
                            "issue 2 requirement; round-off of pow"));
}

}  // namespace
