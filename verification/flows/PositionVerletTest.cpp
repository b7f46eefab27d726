// Issue 31: the energy of undamped oscillations under each time integrator. A periodic square of
// 16 x 16 particles, no viscosity, no gravity, so that the semi-discrete system keeps
// E = sum m (v^2/2 + e(rho)) exactly (EnergyBudget.hpp) and what E gains or loses over a run is
// the integrator's. Two oscillations:
//  * a standing sound wave (rho and v through continuity and the pressure): for the (rho, v) pair
//    position Verlet is the explicit midpoint rule, whose amplification |1 + z + z^2/2| > 1 is
//    Heun's (integrators/PositionVerlet.hpp), so E grows with both, at one rate;
//  * a lattice at a background pressure p0 with its particles displaced by dx/100: the force of
//    p0 on a disordered lattice depends on the positions (where position Verlet is symplectic),
//    but the displacements' divergence also moves rho through continuity.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <sstream>

#include "FlowCases.hpp"
#include "Results.hpp"
#include "sph/EnergyBudget.hpp"
#include "sph/InitialParticles.hpp"

namespace sph::verification {
namespace {

constexpr double kRho0 = 1000.0, kC0 = 10.0, kL = 1.0;
constexpr int kCells = 16;

std::string latticeScene(const std::string& integrator, double p0, double cfl) {
  std::ostringstream s;
  s.precision(17);
  s << "name = \"lattice\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [" << kL << ", "
    << kL << "]\nx_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"periodic\"\n"
    << "y_upper = \"periodic\"\n[[phase]]\nname = \"fluid\"\nrho0 = " << kRho0 << "\nc0 = " << kC0
    << "\nmu = 0.0\np0 = " << p0 << "\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [" << kL << ", " << kL
    << "]\n[numerics]\nkernel = \"wendland_c2\"\ndx = " << kL / kCells
    << "\nh_over_dx = 2.0\ncfl_acoustic = " << cfl << "\nintegrator = \"" << integrator
    << "\"\nend_time = 100.0\n";
  return s.str();
}

enum class Oscillation { sound, lattice };

struct EnergyHistory {
  double scale = 0;        // the oscillation's energy: max kinetic energy over the run
  double largestGain = 0;  // max (E(t) - E(0)) / scale
  double largestLoss = 0;  // max (E(0) - E(t)) / scale
  double finalChange = 0;  // (E(T) - E(0)) / scale
  long steps = 0;
  bool ran = true;
  std::string why;
};

// The energy over `periods` of the sound wave (L / c0 each), sampled 20 times a period.
EnergyHistory energyHistory(const std::string& integrator, Oscillation kind, double cfl,
                            double periods) {
  const double p0 = kind == Oscillation::lattice ? 0.5 * kRho0 * kC0 * kC0 / 7.0 : 0.0;
  const Scene sc = parseScene(latticeScene(integrator, p0, cfl), "lattice");
  Particles<2> p = latticeParticles<2>(sc);
  unsigned seed = 12345;
  auto uniform = [&seed] {  // in [-1, 1), a fixed sequence (no std distribution: portable)
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) * (2.0 / 16777216.0) - 1.0;
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (kind == Oscillation::sound) {
      p.v[i][0] = 0.01 * kC0 * std::sin(2 * pi * p.r[i][0] / kL);  // Mach 0.01
    } else {
      p.r[i][0] += 0.01 * sc.dx * uniform();  // Colagrossi et al. 2012, Table 1: dx/100
      p.r[i][1] += 0.01 * sc.dx * uniform();
    }
  }
  Simulation<2> sim(sc, std::move(p));
  const EnergyBudget<2> budget(sc, sim.particles());
  auto energy = [&](const Particles<2>& s) {
    const auto e = budget.parts(s);
    return e.kinetic + e.internal;
  };
  auto kinetic = [&](const Particles<2>& s) { return budget.parts(s).kinetic; };
  const double e0 = energy(sim.particles());
  EnergyHistory h;
  std::vector<double> changes;
  const double period = kL / kC0;
  const int samples = static_cast<int>(20 * periods);
  for (int k = 1; k <= samples; ++k) {
    if (!runTo(sim, period * periods * k / samples, &h.why)) {
      h.ran = false;
      break;
    }
    h.scale = std::max(h.scale, kinetic(sim.particles()));
    changes.push_back(energy(sim.particles()) - e0);
  }
  for (double c : changes) {
    h.largestGain = std::max(h.largestGain, c / h.scale);
    h.largestLoss = std::max(h.largestLoss, -c / h.scale);
  }
  if (!changes.empty()) h.finalChange = changes.back() / h.scale;
  h.steps = sim.step();
  std::printf("%-20s %-7s CFL %.2f, %g periods, %ld steps: E gain %.3e, loss %.3e, final %.3e%s\n",
              integrator.c_str(), kind == Oscillation::sound ? "sound" : "lattice", cfl, periods,
              sim.step(), h.largestGain, h.largestLoss, h.finalChange, h.ran ? "" : " (failed)");
  return h;
}

// Measured over 20 periods (E gain / max kinetic energy; Heun, position Verlet):
//   sound,   CFL 0.25: 0.1115, 0.1116;   CFL 0.5: 0.513, 0.513
//   lattice, CFL 0.25: 0.1442, 0.1442;   CFL 0.5: 1.068, 1.285
// Both gain energy at the same rate where the (rho, v) pair carries the oscillation, as the
// common amplification 1 + z + z^2/2 says; on the lattice at CFL 0.5, where the displaced
// positions matter, position Verlet gains more, not less. Asserted: each gains (more than 0.05
// of its energy: a conservative step would keep E to round-off) and, where theory makes them
// one, the two gains agree within 2 % (measured 0.1 % and below).
TEST(PositionVerlet, GainsEnergyAsHeunDoesInUndampedSoundWaves) {
  Results r;
  struct Point {
    Oscillation kind;
    double cfl;
    const char* what;
  };
  for (const Point& p : {Point{Oscillation::sound, 0.25, "sound wave, CFL 0.25"},
                         Point{Oscillation::sound, 0.5, "sound wave, CFL 0.5"},
                         Point{Oscillation::lattice, 0.25, "lattice at p0 = K/2, CFL 0.25"}}) {
    const EnergyHistory heun = energyHistory("predictor_corrector", p.kind, p.cfl, 20);
    const EnergyHistory verlet = energyHistory("position_verlet", p.kind, p.cfl, 20);
    ASSERT_TRUE(heun.ran && verlet.ran) << heun.why << verlet.why;
    const std::string what = std::string(p.what) + ", 20 periods: ";
    EXPECT_TRUE(r.check(what + "Heun's energy gain / max kinetic energy", heun.largestGain, ">",
                        0.05, "Heun amplifies undamped oscillations (|1 + z + z^2/2| > 1)"));
    EXPECT_TRUE(r.check(
        what + "position Verlet's energy gain / max kinetic energy", verlet.largestGain, ">", 0.05,
        "the (rho, v) pair is integrated by the midpoint rule (PositionVerlet.hpp)"));
    EXPECT_TRUE(r.check(what + "|gain ratio position Verlet / Heun - 1|",
                        std::abs(verlet.largestGain / heun.largestGain - 1), "<", 0.02,
                        "one amplification 1 + z + z^2/2 for both; measured 0.1 % and below"));
  }
  // Shown, not asserted: the lattice at CFL 0.5, where the two part.
  energyHistory("predictor_corrector", Oscillation::lattice, 0.5, 20);
  energyHistory("position_verlet", Oscillation::lattice, 0.5, 20);
}

// The energy gain of a linear oscillator (z = omega dt) over `steps` steps, relative to its energy:
// Heun's amplification g = 1 + i z - z^2/2; velocity Verlet's (VelocityVerlet.hpp) the larger root
// of xi^2 - (1 + 3/2 i z) xi + i z/2 = 0, the two-step Adams-Bashforth rule's.
double heunGain(double z, long steps) {
  return std::pow(std::norm(std::complex<double>(1 - z * z / 2, z)), steps) - 1;
}
double velocityVerletGain(double z, long steps) {
  const std::complex<double> a(0, z), b = 1.0 + 1.5 * a, root = std::sqrt(b * b - 2.0 * a);
  const double xi = std::max(std::abs((b + root) / 2.0), std::abs((b - root) / 2.0));
  return std::pow(xi * xi, steps) - 1;
}

// The sound wave's energy gain over 20 periods in `steps` equal steps, relative to its energy (its
// kinetic energy at the start, where rho is uniform).
double fixedStepGain(const std::string& integrator, long steps) {
  const Scene sc = parseScene(latticeScene(integrator, 0.0, 0.25), "lattice");
  Particles<2> p = latticeParticles<2>(sc);
  for (std::size_t i = 0; i < p.size(); ++i)
    p.v[i][0] = 0.01 * kC0 * std::sin(2 * pi * p.r[i][0] / kL);  // Mach 0.01
  Simulation<2> sim(sc, std::move(p));
  const EnergyBudget<2> budget(sc, sim.particles());
  auto energy = [&](const Particles<2>& s) {
    const auto e = budget.parts(s);
    return e.kinetic + e.internal;
  };
  const double e0 = energy(sim.particles()), dt = 20 * kL / kC0 / steps;
  for (long k = 0; k < steps; ++k) {
    const auto failure = sim.advance(dt);
    EXPECT_FALSE(failure) << failure->message;
    if (failure) return 0;
    EXPECT_EQ(sim.lastDt(), dt) << "the CFL limit cut the step";
  }
  return energy(sim.particles()) / e0 - 1;
}

// Issue 36: velocity Verlet's one evaluation a step against Heun's two, on the standing sound wave
// of the square, each in the same equal steps (dt 2/1000 and 2/700 s, within the acoustic CFL 0.25
// limit of 3.1e-3 s). The wave's omega is SPH's, not c0 k (the kernel smooths the pressure
// gradient), so it is read from Heun's gain: z = omega dt solves heunGain(z, steps) = the gain. At
// that z the linear theory predicts velocity Verlet's gain, about 2.1 to 2.3 times Heun's.
// Asserted: the measured gain within 3 % of that prediction (measured 0.1 % and 0.5 %), and the
// wave's omega the same at both steps within 1 % (it is the SPH operator's, not the step's;
// measured 0.918 c0 k both, 0.03 % apart).
TEST(VelocityVerlet, GainsTwiceHeunsEnergyAStepInUndampedSoundWaves) {
  Results r;
  const double c0k = 2 * pi * kC0 / kL, T = 20 * kL / kC0;
  std::vector<double> omegas;
  for (long steps : {1000L, 700L}) {
    const double heun = fixedStepGain("predictor_corrector", steps);
    const double verlet = fixedStepGain("velocity_verlet", steps);
    // (1 + z^4/4)^steps = 1 + heun
    const double z = std::pow(4 * (std::pow(1 + heun, 1.0 / steps) - 1), 0.25);
    const double predicted = velocityVerletGain(z, steps);
    omegas.push_back(z / (T / steps) / c0k);
    std::printf(
        "%ld steps: energy gain Heun %.4e, so omega = %.4f c0 k; velocity Verlet %.4e, "
        "predicted %.4e (ratio to Heun's %.4f)\n",
        steps, heun, omegas.back(), verlet, predicted, verlet / heun);
    EXPECT_TRUE(r.check("sound wave, 20 periods in " + std::to_string(steps) +
                            " steps: |velocity Verlet's energy gain / linear theory - 1|",
                        std::abs(verlet / predicted - 1), "<", 0.03,
                        "two-step Adams-Bashforth's amplification at Heun's omega dt "
                        "(VelocityVerlet.hpp); measured 0.1 and 0.5 %"));
  }
  EXPECT_TRUE(r.check("sound wave: |omega at dt 2/700 s / omega at dt 2/1000 s - 1|",
                      std::abs(omegas[1] / omegas[0] - 1), "<", 0.01,
                      "one SPH operator, one omega"));
}

}  // namespace
}  // namespace sph::verification
