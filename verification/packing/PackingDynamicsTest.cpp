// The packing dynamics of Colagrossi et al. (2012), eq. (2.16), against its own theory
// (Appendix B): the force is minus the gradient of the potential V of eq. (B.34); without damping
// E = T + V is conserved; with damping dE/dt = -2 zeta T (eq. B.33), so E never increases.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Results.hpp"
#include "sph/packing/Geometry.hpp"
#include "sph/packing/ParticlePacking.hpp"

namespace sph::packing {
namespace {

// The trapezoidal tank of section 3.1 at a coarse H/dx, closed by solid layers along walls and
// surface: a small system with a real sloping wall, acute and obtuse corners.
struct SmallTank {
  std::vector<Vec2> fluid, solid;
  double V0 = 0.0, dx = 0.0;
};
SmallTank smallTank(double HOverDx, double hOverDx = 2.0) {
  const double H = 1.0;
  const std::vector<Piece> container = {
      segment({0.0, 1.2}, {0.0, 0.0}), segment({0.0, 0.0}, {0.5, 0.0}),
      segment({0.5, 0.0}, {1.7, 1.2}), segment({1.7, 1.2}, {0.0, 1.2})};
  const Region region = belowSurface(container, H);
  SmallTank t;
  t.dx = H / HOverDx;
  t.fluid = latticeInside(region, t.dx, Vec2::Zero());
  t.solid = solidLayers(region, t.dx, static_cast<int>(std::ceil(2.0 * hOverDx))).position;
  t.V0 = region.area() / static_cast<double>(t.fluid.size());
  return t;
}

TEST(PackingDynamics, ForceIsMinusGradientOfPotential) {
  // beta grad Gamma_i must equal dV/dr_i (eq. B.34); central differences with step eps have error
  // O(eps^2 V''') plus round-off O(|V| 1e-16 / eps). |V| ~ beta N ~ 1e2 here, eps = 1e-6 dx:
  // round-off ~ 1e-8 / dx against forces of order 1/dx. Tolerance 1e-6 relative to max |force|.
  SmallTank t = smallTank(8.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-0.2 * t.dx, 0.2 * t.dx);
  for (Vec2& x : t.fluid) x += Vec2(noise(rng), noise(rng));
  PackingParameters p;
  p.beta = 2.0;
  const ParticlePacking base(t.fluid, t.solid, t.V0, t.dx, p);
  double maxForce = 0.0, maxError = 0.0;
  for (const Vec2& g : base.gradGamma()) maxForce = std::max(maxForce, p.beta * g.norm());
  const double eps = 1e-6 * t.dx;
  for (std::size_t i = 0; i < t.fluid.size(); i += 7) {
    for (int a = 0; a < 2; ++a) {
      std::vector<Vec2> plus = t.fluid, minus = t.fluid;
      plus[i][a] += eps, minus[i][a] -= eps;
      const double Vp = p.beta * ParticlePacking(plus, t.solid, t.V0, t.dx, p).record().potential;
      const double Vm = p.beta * ParticlePacking(minus, t.solid, t.V0, t.dx, p).record().potential;
      maxError =
          std::max(maxError, std::abs((Vp - Vm) / (2.0 * eps) - p.beta * base.gradGamma()[i][a]));
    }
  }
  verification::Results r;
  EXPECT_TRUE(r.check(
      "max |dV/dr_i - beta grad Gamma_i| / max |beta grad Gamma|", maxError / maxForce, "<=", 1e-6,
      "eq. (B.34): V is the potential of eq. (2.16); finite-difference error bound, see test"));
}

// max |E_n - E_0| / max_n T_n over a fixed time span, undamped, at the given CFL.
double energyError(double cfl, double span) {
  SmallTank t = smallTank(10.0);
  PackingParameters p;
  p.alpha = 0.0, p.cfl = cfl;
  ParticlePacking packing(t.fluid, t.solid, t.V0, t.dx, p);
  const double E0 = packing.record().kinetic + packing.record().potential;
  double maxDev = 0.0, maxT = 0.0;
  const int steps = static_cast<int>(std::lround(span / packing.dt()));
  for (int n = 0; n < steps; ++n) {
    packing.step();
    const PackingRecord rec = packing.record();
    maxDev = std::max(maxDev, std::abs(rec.kinetic + rec.potential - E0));
    maxT = std::max(maxT, rec.kinetic);
  }
  return maxDev / maxT;
}

TEST(PackingDynamics, EnergyConservedWithoutDamping) {
  // zeta = 0: eq. (2.16) is Lagrangian (Appendix B) and E = T + V constant. Velocity Verlet is
  // symplectic and second order: the discrete E oscillates by O(dt^2) with no drift. The error is
  // measured relative to max T, the energy that actually moves between T and V (|V| itself is
  // ~1e4 times larger and would hide it). Span: 1000 iterations at CFL = 1.
  SmallTank probe = smallTank(10.0);
  const double span = 1000.0 * std::sqrt(probe.V0);  // beta = 1: dt = CFL sqrt(V0)
  const std::vector<double> cfl = {1.0, 0.5, 0.25};
  std::vector<double> error;
  for (double c : cfl) error.push_back(energyError(c, span));
  verification::Results r;
  const double order =
      r.convergence("undamped packing: max|E - E0| / max T", "CFL", cfl, error, 2.0,
                    "velocity Verlet, second order (Hairer, Lubich & Wanner 2006)");
  // Order 2 +- 0.3 (Verlet theory); measured 1.99 over CFL = 1, 1/2, 1/4.
  EXPECT_NEAR(order, 2.0, 0.3);
  // At the paper's CFL = 1: measured 0.063, 0.016 and 0.0040 at CFL = 1, 1/2, 1/4; threshold
  // 0.1 at CFL = 1, while a sign or factor error in the force breaks conservation at O(1).
  EXPECT_TRUE(r.check("max|E - E0| / max T at CFL = 1", error[0], "<=", 0.1,
                      "Appendix B energy conservation; measured 2nd-order convergence, see test"));
}

TEST(PackingDynamics, DampedEnergyDecreasesAsEqB33) {
  // zeta > 0: dE/dt = -2 zeta T (eq. B.33). Checked two ways: E sampled every 25 iterations never
  // rises (the O(dt^2) Verlet oscillation of E is ~3e-3 max T per the test above, while 25
  // iterations of damping remove 2 alpha 25 T = 0.1 T at alpha = 2e-3), and the total loss
  // E_0 - E_N matches the integral of 2 zeta T dt to within 0.1 max T: the bound on the Verlet
  // oscillation of E measured without damping (0.063 max T at CFL = 1, test above).
  SmallTank t = smallTank(10.0);
  PackingParameters p;
  p.alpha = 2e-3;
  ParticlePacking packing(t.fluid, t.solid, t.V0, t.dx, p);
  PackingRecord prev = packing.record();
  const double E0 = prev.kinetic + prev.potential;
  double Elast = E0, dissipated = 0.0, maxRise = -INFINITY, maxT = 0.0;
  for (int n = 1; n <= 2000; ++n) {
    packing.step();
    const PackingRecord rec = packing.record();
    dissipated += 2.0 * packing.zeta() * 0.5 * (rec.kinetic + prev.kinetic) * packing.dt();
    maxT = std::max(maxT, rec.kinetic);
    prev = rec;
    if (n % 25 == 0) {
      const double E = rec.kinetic + rec.potential;
      maxRise = std::max(maxRise, E - Elast);
      Elast = E;
    }
  }
  const double loss = E0 - Elast;
  verification::Results r;
  EXPECT_TRUE(r.check("max rise of E over 25 iterations / max T", maxRise / maxT, "<", 0.0,
                      "eq. (B.33): dE/dt = -2 zeta T <= 0"));
  EXPECT_TRUE(r.check("|(E0 - E_N) - integral 2 zeta T dt| / max T",
                      std::abs(loss - dissipated) / maxT, "<=", 0.1,
                      "eq. (B.33); quadrature and Verlet oscillation bound, see test"));
}

}  // namespace
}  // namespace sph::packing
