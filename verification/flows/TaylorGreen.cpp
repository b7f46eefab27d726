// Issue 3 (nightly): the Taylor-Green vortex at Re = U L / nu = 100 in the unit periodic box,
//   u = U sin(2 pi x) cos(2 pi y),  v = -U cos(2 pi x) sin(2 pi y),
//   p = p0 - rho0 U^2 / 4 (cos(4 pi x) + cos(4 pi y)),
// a solution of the Navier-Stokes equations whose speed decays as exp(-2 nu k^2 t), k = 2 pi:
// max|v| = U exp(-8 pi^2 t / Re) for U = L = 1 (Taylor & Green 1937). Weakly compressible SPH
// needs a background pressure p0 against the tensile instability (the lattice of a pure vortex
// with p < 0 clumps; Adami et al. 2013 use p0 = rho0 c0^2); here p0 = 1 = 2x the vortex's
// pressure amplitude keeps p > 0. c0 = 10 U (Mach 0.1), 50^2 particles, h/dx = 1.33.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "FlowCases.hpp"
#include "Results.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InitialParticles.hpp"

namespace sph::verification {
namespace {

constexpr double kRe = 100.0, kP0 = 1.0;

struct Decay {
  double rate;        // fitted decay rate of max|v| over the run [1/s]
  double trackedTo;   // first time max|v| differs from the exact decay by more than 5 %
  double errorAtEnd;  // |max|v| / exact - 1| at the end
};

// `physics` and `numerics`: extra lines of those tables.
Decay taylorGreen(const std::string& kernel, int n, double T, const std::string& physics = "",
                  const std::string& numerics = "") {
  std::ostringstream s;
  s.precision(17);
  s << "name = \"taylor_green\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
    << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"periodic\"\ny_upper = "
       "\"periodic\"\n"
    << "[[phase]]\nname = \"fluid\"\nrho0 = 1.0\nc0 = 10.0\nmu = " << 1.0 / kRe << "\np0 = " << kP0
    << "\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n[physics]\nmorris_viscosity = true\n"
    << physics << "[numerics]\nkernel = \"" << kernel << "\"\ndx = " << 1.0 / n
    << "\nend_time = " << T << "\n"
    << numerics;
  const Scene sc = parseScene(s.str(), "taylor_green");
  Particles<2> p = latticeParticles<2>(sc);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = 2 * pi * p.r[i][0], y = 2 * pi * p.r[i][1];
    p.v[i] = Vec<2>(std::sin(x) * std::cos(y), -std::cos(x) * std::sin(y));
    const double pr = kP0 - 0.25 * (std::cos(2 * x) + std::cos(2 * y));
    p.rho[i] = TaitEquationOfState::density(pr, sc.phases[0]);
    p.m[i] = p.rho[i] * sc.dx * sc.dx;
  }
  Simulation<2> sim(sc, std::move(p));
  const double rate = 8 * pi * pi / kRe;
  Decay d{0, T, 0};
  double st = 0, sl = 0, stt = 0, stl = 0;
  int count = 0;
  bool tracking = true;
  for (int k = 1; k <= 40; ++k) {
    const double t = T * k / 40;
    std::string why;
    if (!runTo(sim, t, &why)) {
      ADD_FAILURE() << why;
      return d;
    }
    double vmax = 0;
    for (const auto& v : sim.particles().v) vmax = std::max(vmax, v.norm());
    const double err = std::abs(vmax / std::exp(-rate * t) - 1);
    if (tracking && err > 0.05) d.trackedTo = t, tracking = false;
    d.errorAtEnd = err;
    const double l = std::log(vmax);
    st += t, sl += l, stt += t * t, stl += t * l, ++count;
  }
  d.rate = -(count * stl - st * sl) / (count * stt - st * st);
  return d;
}

TEST(TaylorGreen, DecayRatePerKernel) {
  Results r;
  const double T = 1.0, exact = 8 * pi * pi / kRe;
  for (const std::string kernel : {"quadratic", "cubic_spline", "wendland_c2"}) {
    const Decay d = taylorGreen(kernel, 50, T);
    std::printf(
        "%s: decay rate %.4f (exact %.4f, %+.2f %%), within 5 %% until t = %.2f, end error %.3f\n",
        kernel.c_str(), d.rate, exact, 100 * (d.rate / exact - 1), d.trackedTo, d.errorAtEnd);
    r.figure("Taylor-Green (Re 100, 50^2) time max|v| tracks exp(-8 pi^2 t/Re) within 5 % [s], " +
                 kernel,
             d.trackedTo, "how long each kernel tracks the decay");
    r.figure("Taylor-Green fitted decay rate / (8 pi^2 / Re), " + kernel, d.rate / exact,
             "theory 1");
    // Finding: the SPH vortex decays too fast. The initial rate on the perfect lattice is right
    // (-0.788 against -0.790 /s at 50^2), but as the strain field disorders the particles the
    // Morris operator (a second derivative) loses consistency (Quinlan et al. 2006; compare
    // Operators.PerturbedLatticeLosesConvergence) and the rate grows. Measured at 50^2 over
    // t <= 1: fitted rates +76 % (quadratic), +139 % (cubic spline), +169 % (Wendland C2);
    // max|v| at t = 1 is 0.56, 0.38, 0.31 of the exact value; all track within 5 % only to
    // t = 0.12-0.15. The error falls with resolution and h/dx (quadratic, t = 1: 0.25 of exact
    // at 25^2, 0.64 at 100^2; 0.90 with h/dx = 2). Theory (a consistent scheme) is 0 error; the
    // bound only guards against a regression beyond what was measured.
    EXPECT_TRUE(r.check("Taylor-Green |max|v| / exact - 1| at t = 1, " + kernel, d.errorAtEnd,
                        "<=", 0.8,
                        "theory 0; measured 0.44-0.69 (disorder, see comment): regression bound"));
  }
}

// Issue 31: the disorder that makes the vortex decay too fast is what particle shifting removes.
// With the delta-plus shift (Sun et al. 2017; ParticleShifting.hpp) at h/dx 2 the fitted rate is
// the viscous one: measured at 50^2 over t <= 1, quadratic +3.12 %, Wendland C2 -0.06 %, and the
// named model (Wendland C2, Fourtakas diffusion delta 0.1, delta-plus) +1.05 %, each tracking
// exp(-8 pi^2 t / Re) within 5 % to t = 1 (end errors 0.024, 0.014, 0.014). Lind's shift (D
// proportional to the particle's own speed, zero at the vortex's stagnation points) left the
// Wendland vortex at +29.7 %, and Wendland at h/dx 2 without shifting at +47.3 %. A delta-plus
// shift once in 5 steps (shifting_every = 5: 5 dt a shift, c0 / U = 10 here) gave +2.86 % where
// one a step gave +0.05 % (2026-12-05). The bar is the issue's: the rate within 5 % of
// 8 pi^2 / Re at 50^2 or finer.
TEST(TaylorGreen, DeltaPlusShiftingDecaysAtTheViscousRate) {
  Results r;
  const double T = 1.0, exact = 8 * pi * pi / kRe;
  const std::string shift = "shifting = \"delta_plus\"\n", hOverDx2 = "h_over_dx = 2.0\n";
  const std::string diffusion = "density_diffusion = 0.1\ndensity_diffusion_form = \"fourtakas\"\n";
  struct Model {
    std::string name, kernel, physics;
  };
  for (const Model& m : {Model{"quadratic, delta-plus", "quadratic", shift},
                         Model{"wendland_c2, delta-plus", "wendland_c2", shift},
                         Model{"named model", "wendland_c2", shift + diffusion},
                         Model{"wendland_c2, delta-plus every 5 steps", "wendland_c2",
                               shift + "shifting_every = 5\n"}}) {
    const Decay d = taylorGreen(m.kernel, 50, T, m.physics, hOverDx2);
    std::printf("%s (h/dx 2): decay rate %.4f (exact %.4f, %+.2f %%), within 5 %% until t = %.2f\n",
                m.name.c_str(), d.rate, exact, 100 * (d.rate / exact - 1), d.trackedTo);
    r.figure("Taylor-Green (Re 100, 50^2, h/dx 2) fitted decay rate / (8 pi^2 / Re), " + m.name,
             d.rate / exact, "theory 1");
    EXPECT_TRUE(
        r.check("Taylor-Green (Re 100, 50^2, h/dx 2) |decay rate / (8 pi^2 / Re) - 1|, " + m.name,
                std::abs(d.rate / exact - 1), "<=", 0.05,
                "issue 31's bar; measured 0.0005-0.031 (comment)"));
  }
}

}  // namespace
}  // namespace sph::verification
