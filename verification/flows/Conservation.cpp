// Issue 3: conservation on a doubly periodic box with no body force.
//  * Mass: particle masses never change, so the total is constant exactly (bit for bit).
//  * Linear momentum: every pair term of eq. (12) is antisymmetric in i and j (h_ij, eta_ij and
//    the pressure and viscous factors are symmetric), so sum m v changes only by round-off.
//  * Energy: with continuity (eq. 11) and the symmetric pressure term, d/dt of
//    E = sum m (v^2/2 + u(rho)), u' = p/rho^2, vanishes exactly in the semi-discrete equations;
//    the predictor-corrector leaves a drift: for an oscillatory mode Heun's amplification factor
//    has |1 + z + z^2/2|^2 = 1 + (omega dt)^4 / 4 (z = i omega dt), O(dt^4) a step and O(dt^3)
//    over a fixed time. Artificial viscosity (eq. 10) and Morris
//    viscosity only remove energy: sum_ij m_i m_j A_ij |v_ij|^2 / 2 with A_ij <= 0.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "FlowCases.hpp"
#include "Results.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InitialParticles.hpp"

namespace sph::verification {
namespace {

// A Taylor-Green-like flow plus a mean drift, in a unit periodic box; 16^2 particles.
Simulation<2> box(double beta, bool morris) {
  std::ostringstream s;
  s << "name = \"box\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
    << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"periodic\"\ny_upper = "
       "\"periodic\"\n"
    << "[[phase]]\nname = \"w\"\nrho0 = 1.0\nc0 = 10.0\nmu = 0.01\np0 = 5.0\n"
    << "[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n[physics]\nartificial_viscosity = "
    << beta << "\nmorris_viscosity = " << (morris ? "true" : "false")
    << "\n[numerics]\ndx = " << 1.0 / 16 << "\nend_time = 1.0\n";
  const Scene sc = parseScene(s.str(), "box");
  Particles<2> p = latticeParticles<2>(sc);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = 2 * pi * p.r[i][0], y = 2 * pi * p.r[i][1];
    p.v[i] = Vec<2>(0.3 + std::sin(x) * std::cos(y), 0.1 - std::cos(x) * std::sin(y));
  }
  return Simulation<2>(sc, std::move(p));
}

struct Budget {
  double mass, momentumX, momentumY, energy;
};
Budget budget(const Simulation<2>& sim) {
  const auto& p = sim.particles();
  const Phase& ph = sim.scene().phases[0];
  const double K = ph.bulkModulus(), g = ph.gamma, r0 = ph.rho0;
  Budget b{0, 0, 0, 0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double rho = p.rho[i];
    // u(rho) = int_rho0^rho p/rho'^2 drho' for p = p0 + K((rho/rho0)^g - 1).
    const double u =
        K * (std::pow(rho / r0, g - 1) / r0 - 1 / r0) / (g - 1) + (ph.p0 - K) * (1 / r0 - 1 / rho);
    b.mass += p.m[i], b.momentumX += p.m[i] * p.v[i][0], b.momentumY += p.m[i] * p.v[i][1];
    b.energy += p.m[i] * (0.5 * p.v[i].squaredNorm() + u);
  }
  return b;
}

// Runs `steps` steps of at most dt, returns the energy change relative to the initial kinetic
// energy and checks mass and momentum on the way.
double energyChange(double beta, bool morris, double dt, int steps, Results* r) {
  Simulation<2> sim = box(beta, morris);
  const Budget b0 = budget(sim);
  double ke0 = 0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    ke0 += 0.5 * sim.particles().m[i] * sim.particles().v[i].squaredNorm();
  double maxMomentum = 0;
  for (int s = 0; s < steps; ++s) {
    auto f = sim.advance(dt);
    EXPECT_FALSE(f) << f->message;
    const Budget b = budget(sim);
    maxMomentum =
        std::max({maxMomentum, std::abs(b.momentumX - b0.momentumX) / std::abs(b0.momentumX),
                  std::abs(b.momentumY - b0.momentumY) / std::abs(b0.momentumX)});
    if (r && b.mass != b0.mass) ADD_FAILURE() << "mass changed at step " << s;
  }
  if (r) {
    std::printf("momentum drift %.3e\n", maxMomentum);
    // 256 particles, ~2 evaluations x 30 neighbours x steps of round-off at 1e-16 each.
    EXPECT_TRUE(r->check("relative change of linear momentum (periodic, no body force)",
                         maxMomentum, "<=", 1e-12, "antisymmetric pair forces: round-off only"));
  }
  return (budget(sim).energy - b0.energy) / ke0;
}

TEST(Conservation, MassMomentumAndEnergy) {
  Results r;
  // Inviscid: the drift is the integrator's, O(dt^3) (see the head of this file).
  const double dt = 1e-3, T = 0.1;  // dt below the CFL limit 1.8e-3, so steps are exactly dt
  const double e1 = energyChange(0.0, false, dt, static_cast<int>(T / dt), &r);
  const double e2 = energyChange(0.0, false, dt / 2, static_cast<int>(2 * T / dt), nullptr);
  const double order = std::log2(std::abs(e1 / e2));
  std::printf("inviscid dE/KE0 %.3e (dt) %.3e (dt/2) order %.2f\n", e1, e2, order);
  EXPECT_TRUE(
      r.check("inviscid energy drift / KE0 at dt = 1e-3", std::abs(e1), "<=", 1e-5,
              "measured 3.8e-6: exactly conserved semi-discretely, O(dt^3) integrator drift"));
  r.convergence("inviscid energy drift", "dt", {dt, dt / 2}, {std::abs(e1), std::abs(e2)}, 3.0,
                "Heun's method on oscillatory modes: |1 + z + z^2/2|^2 - 1 = O(dt^4) a step");
  EXPECT_TRUE(r.check("inviscid energy drift order in dt", order, ">=", 2.7, "theory 3 minus 0.3"));
  // Artificial viscosity (beta = 1, eq. 10) and Morris viscosity dissipate: energy falls, by
  // far more than the integrator's drift.
  const double eAV = energyChange(1.0, false, dt, static_cast<int>(T / dt), nullptr);
  const double eMV = energyChange(0.0, true, dt, static_cast<int>(T / dt), nullptr);
  std::printf("AV dE/KE0 %.3e, Morris %.3e\n", eAV, eMV);
  EXPECT_TRUE(r.check("energy change / KE0 with artificial viscosity", eAV,
                      "<=", -10 * std::abs(e1),
                      "dissipative term: a loss well beyond the integrator drift"));
  EXPECT_TRUE(r.check("energy change / KE0 with Morris viscosity", eMV, "<=", -10 * std::abs(e1),
                      "dissipative term: a loss well beyond the integrator drift"));
}

}  // namespace
}  // namespace sph::verification
