#pragma once
// Scenes built in code for the whole-discretisation tests of issue 3, and the analytical
// solutions they are compared with.
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace sph::verification {

constexpr double pi = std::numbers::pi;

// Morris, Fox & Zhu (1997), section 4.1 and DESIGN.md section 3: plates at y = 0 and y = L.
struct ChannelFlow {
  static constexpr double L = 1e-3, nu = 1e-6, rho0 = 1000.0;
  static constexpr double F = 2e-4;     // Poiseuille body force per unit mass [m/s^2]
  static constexpr double V0 = 2.5e-5;  // Couette top-plate speed [m/s]
  static constexpr double vMax = F * L * L / (8 * nu);  // Poiseuille centre-line speed = V0

  // Start-up Poiseuille flow (reference_data/README.md; Morris et al. 1997 eq. 20).
  static double poiseuille(double y, double t, int terms = 200) {
    double v = F * y * (L - y) / (2 * nu);
    for (int n = 0; n < terms; ++n) {
      const double k = 2 * n + 1;
      v -= 4 * F * L * L / (nu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / L) *
           std::exp(-k * k * pi * pi * nu * t / (L * L));
    }
    return v;
  }
  // Start-up Couette flow with the upper plate at V0 (Morris et al. 1997 eq. 21).
  static double couette(double y, double t, int terms = 200) {
    double v = V0 * y / L;
    for (int n = 1; n <= terms; ++n)
      v += 2 * V0 / (n * pi) * (n % 2 ? -1.0 : 1.0) * std::sin(n * pi * y / L) *
           std::exp(-n * n * pi * pi * nu * t / (L * L));
    return v;
  }

  // Periodic in x over 8 dx (wider than the kernel's reach 2h = 2.66 dx, so one periodic image
  // of each particle suffices), no-slip ghost walls at y = 0 and L. c0 = 10 v_max (Morris et
  // al. used a sound speed giving a Mach number of 0.1 at most; DESIGN.md section 1).
  static std::string scene(bool couetteFlow, int cellsAcross, double endTime,
                           const std::string& kernel = "quadratic", double hOverDx = 1.33,
                           double machInverse = 10) {
    const double dx = L / cellsAcross, width = 8 * dx;
    std::ostringstream s;
    s.precision(17);
    s << "name = \"" << (couetteFlow ? "couette" : "poiseuille") << "\"\ndimension = 2\n"
      << "[domain]\nlower = [0.0, 0.0]\nupper = [" << width << ", " << L << "]\n"
      << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"no_slip\"\n"
      << "y_upper = \"no_slip\"\n";
    if (couetteFlow) s << "[domain.wall_velocity]\ny_upper = [" << V0 << ", 0.0]\n";
    s << "[[phase]]\nname = \"water\"\nrho0 = " << rho0 << "\nc0 = " << machInverse * vMax
      << "\nmu = " << nu * rho0 << "\n"
      << "[[fluid]]\nlower = [0.0, 0.0]\nupper = [" << width << ", " << L << "]\n"
      << "[physics]\nbody_force = [" << (couetteFlow ? 0.0 : F) << ", 0.0]\n"
      << "morris_viscosity = true\n"
      << "[numerics]\nkernel = \"" << kernel << "\"\ndx = " << dx << "\nh_over_dx = " << hOverDx
      << "\nend_time = " << endTime << "\n";
    return s.str();
  }
};

// Runs `sim` to time `t` exactly (the last step shortened), failing the test on a numerical
// failure. Returns false on failure.
template <int D>
bool runTo(Simulation<D>& sim, double t, std::string* why = nullptr) {
  while (sim.time() < t * (1 - 1e-12)) {
    if (auto f = sim.advance(t - sim.time())) {
      if (why) *why = f->message;
      return false;
    }
  }
  return true;
}

}  // namespace sph::verification
