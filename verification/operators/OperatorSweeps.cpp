// Issue 3 (nightly): the operator errors of Operators.cpp for every kernel at h/dx = 1.33 and 2,
// n = 16..128: where each kernel's discretisation floor lies (Quinlan et al. 2006).
#include <gtest/gtest.h>

#include <cstdio>

#include "Results.hpp"
#include "SphOperators.hpp"

namespace sph::verification {
namespace {

TEST(OperatorSweeps, KernelsAndHOverDx) {
  Results r;
  for (KernelKind kind : {KernelKind::quadratic, KernelKind::cubic_spline, KernelKind::wendland_c2})
    for (double hdx : {1.33, 2.0}) {
      std::vector<double> dx, eI, eG;
      for (int n : {16, 32, 64, 128}) {
        const PeriodicLattice L(n);
        const auto o = applyOperators(L, kind, hdx * L.dx, field);
        std::vector<double> f(L.x.size());
        std::vector<V2> g(L.x.size());
        for (std::size_t k = 0; k < L.x.size(); ++k)
          f[k] = field(L.x[k]), g[k] = fieldGradient(L.x[k]);
        dx.push_back(L.dx), eI.push_back(relativeMaxError(o.interpolation, f));
        eG.push_back(relativeMaxError(o.difference, g));
      }
      const std::string k =
          std::string(name(kind)) + ", h/dx = " + std::to_string(hdx).substr(0, 4);
      const double oI = r.convergence("interpolation, " + k, "dx", dx, eI, 2.0,
                                      "Quinlan et al. 2006: O(h^2) until the floor");
      const double oG = r.convergence("difference-form gradient, " + k, "dx", dx, eG, 2.0,
                                      "Quinlan et al. 2006: O(h^2) until the floor");
      std::printf("%s: interp %.2e..%.2e (order %.2f), grad %.2e..%.2e (order %.2f)\n", k.c_str(),
                  eI.front(), eI.back(), oI, eG.front(), eG.back(), oG);
      // Measured orders over n = 16..128 (gradient): quadratic 1.09 / 1.22, cubic spline 0.71 /
      // 1.84, Wendland C2 0.69 / 1.85 at h/dx = 1.33 / 2: second order until the floor, which at
      // h/dx = 1.33 lies at 1-2 % and is reached by n = 32..64. Asserted: the error falls at
      // least 3x from n = 16 to 128 (measured 4.3x to 45x), whatever the floor.
      EXPECT_TRUE(r.check(
          "difference-form gradient error n = 128 / n = 16, " + k, eG.back() / eG.front(),
          "<=", 0.3, "theory: O(h^2) until the floor (Quinlan et al. 2006); measured <= 0.24"));
      // The interpolation error never exceeds its coarsest value: refinement does not hurt.
      EXPECT_TRUE(r.check("interpolation error n = 128 / n = 16, " + k, eI.back() / eI.front(),
                          "<=", 1.0, "O(h^2) falls until the floor, which it then keeps"));
    }
}

}  // namespace
}  // namespace sph::verification
