// Issue 6: the elliptical drop (Monaghan 1994; Colagrossi et al. 2012, section 3.4) at R/dx = 20,
// Cartesian and packed starts (the nightly suite: R/dx = 40 and 80). Tolerances: see
// checkDropErrors in EllipticalDropCommon.hpp.
#include "EllipticalDropCommon.hpp"

namespace sph::verification {
namespace {

TEST(EllipticalDrop, OdeConservesAreaAndEnergy) {
  // Two invariants of the ODE: the area, a b = R^2 (d(ab)/dt = A ab - A ab = 0), and the kinetic
  // energy rho pi a b A^2 (a^2 + b^2)/8 of u = A x, v = -A y over the ellipse, conserved with
  // p = 0 on the free surface: d/dt[A^2 (a^2 + b^2)] = 2 A^3 (b^2 - a^2) + 2 A^3 (a^2 - b^2) = 0,
  // which tests dA/dt too. The solver's tolerance is 1e-13; threshold 1e-10.
  const std::vector<DropAxes> s = dropOde(100.0, 1.0, {0.0, 0.0025, 0.0076, 0.02});
  Results r;
  double area = 0.0, energy = 0.0;
  for (const DropAxes& x : s) {
    area = std::max(area, std::abs(x.a * x.b - 1.0));
    energy = std::max(energy, std::abs(x.A * x.A * (x.a * x.a + x.b * x.b) / (2.0 * 1e4) - 1.0));
  }
  EXPECT_TRUE(r.check("ODE: max |a b / R^2 - 1|", area, "<=", 1e-10,
                      "incompressibility, exact; GSL rk8pd at 1e-13 tolerance"));
  EXPECT_TRUE(r.check("ODE: max |A^2 (a^2 + b^2) / (2 A0^2 R^2) - 1|", energy, "<=", 1e-10,
                      "kinetic energy conserved, exact; GSL rk8pd at 1e-13 tolerance"));
}

TEST(EllipticalDrop, CartesianAndPackedStartsROverDx20) {
  Results r;
  const DropRun cartesian = dropRun("Cartesian", 20.0, kDropTimes, r);
  const DropRun packed = dropRun("packed", 20.0, kDropTimes, r);
  checkDropErrors(r, 20.0, cartesian, packed);
}

}  // namespace
}  // namespace sph::verification
