#pragma once
// A manufactured solution of the whole discretisation (continuity eq. 11, momentum eq. 12 with
// the Tait EOS eq. 8 and Morris viscosity eq. 9) on the doubly periodic unit square, k = 2 pi:
//   u   = a(t) sin(kx) cos(ky),  w = a(t) cos(kx) sin(ky),          a(t) = U cos(omega t)
//   rho = rho0 (1 + b(t) cos(kx) cos(ky)),                           b(t) = eps cos(omega t)
// The flow is compressible (div v = 2 a k cos kx cos ky), so the continuity equation is tested.
// Sources, added through Simulation::setSource at each particle's position and time:
//   S_rho = d rho/dt + v . grad rho + rho div v
//   S_v   = dv/dt + (v . grad) v + p'(rho) grad rho / rho - (mu / rho) lap v,
// p'(rho) = c0^2 (rho/rho0)^(gamma-1). The Morris term approximates (1/rho) div(mu grad v)
// (Morris et al. 1997 eq. 8), which for constant mu is (mu/rho) lap v; that is what it is
// compared with. The particles move with their SPH velocity (a Lagrangian scheme); the exact
// density and velocity are evaluated at each particle's current position and time, so the error
// measures the solution along the computed trajectories.
// S_rho is a source of mass: a particle of volume V gains V S_rho a unit time (giveMass). With
// fixed masses the volumes m/rho would part from the space the particles fill (by the integral of
// div v, about 10 % at t = 1/4), an O(1) error of every kernel sum at any resolution.
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "sph/InitialParticles.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace sph::verification {

struct Manufactured {
  static constexpr double rho0 = 1.0, c0 = 1.0, gamma = 7.0, nu = 0.01;
  static constexpr double U = 0.05, eps = 0.01, omega = 2 * std::numbers::pi;
  static constexpr double k = 2 * std::numbers::pi;

  static double a(double t) { return U * std::cos(omega * t); }
  static double da(double t) { return -U * omega * std::sin(omega * t); }
  static double b(double t) { return eps * std::cos(omega * t); }
  static double db(double t) { return -eps * omega * std::sin(omega * t); }

  static double density(const Vec<2>& x, double t) {
    return rho0 * (1 + b(t) * std::cos(k * x[0]) * std::cos(k * x[1]));
  }
  static Vec<2> velocity(const Vec<2>& x, double t) {
    const double sx = std::sin(k * x[0]), cx = std::cos(k * x[0]);
    const double sy = std::sin(k * x[1]), cy = std::cos(k * x[1]);
    return Vec<2>(a(t) * sx * cy, a(t) * cx * sy);
  }

  // S_rho at x and t.
  static double massSource(const Vec<2>& x, double t) {
    const double sx = std::sin(k * x[0]), cx = std::cos(k * x[0]);
    const double sy = std::sin(k * x[1]), cy = std::cos(k * x[1]);
    const double A = a(t), B = b(t);
    const double u = A * sx * cy, w = A * cx * sy;
    const double rho = rho0 * (1 + B * cx * cy);
    const double rhot = rho0 * db(t) * cx * cy;
    const double rhox = -rho0 * B * k * sx * cy, rhoy = -rho0 * B * k * cx * sy;
    return rhot + u * rhox + w * rhoy + rho * 2 * A * k * cx * cy;  // div v = 2 A k cx cy
  }

  // Adds S_rho and S_v at every particle.
  static void source(double t, const Particles<2>& s, Derivatives<2>& out) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double sx = std::sin(k * s.r[i][0]), cx = std::cos(k * s.r[i][0]);
      const double sy = std::sin(k * s.r[i][1]), cy = std::cos(k * s.r[i][1]);
      const double A = a(t), B = b(t);
      const double u = A * sx * cy, w = A * cx * sy;
      const double ux = A * k * cx * cy, uy = -A * k * sx * sy;
      const double wx = -A * k * sx * sy, wy = A * k * cx * cy;
      const double rho = rho0 * (1 + B * cx * cy);
      const double rhox = -rho0 * B * k * sx * cy, rhoy = -rho0 * B * k * cx * sy;
      const double dpdrho = c0 * c0 * std::pow(rho / rho0, gamma - 1);
      const double mu = nu * rho0;
      out.drhodt[i] += massSource(s.r[i], t);
      out.dvdt[i][0] += da(t) * sx * cy + u * ux + w * uy + dpdrho * rhox / rho +
                        mu / rho * 2 * k * k * u;  // lap u = -2 k^2 u
      out.dvdt[i][1] +=
          da(t) * cx * sy + u * wx + w * wy + dpdrho * rhoy / rho + mu / rho * 2 * k * k * w;
    }
  }

  // dm/dt = m S_rho / rho over dt with positions, density and time held.
  static void giveMass(Particles<2>& p, double t, double dt) {
    for (std::size_t i = 0; i < p.size(); ++i)
      p.m[i] *= std::exp(dt * massSource(p.r[i], t) / p.rho[i]);
  }

  // One step of exactly dt: the mass's half steps around the scene's integrator (Strang
  // splitting, second order as the integrators are).
  static std::optional<Failure> step(Simulation<2>& sim, double dt) {
    giveMass(sim.particles(), sim.time(), dt / 2);
    sim.particlesEdited();
    if (auto f = sim.advance(dt)) return f;
    if (sim.lastDt() != dt) {
      return Failure{FailureCause::dt_collapse, sim.step(), sim.time(), -1,
                     "the CFL limit cut the step below the manufactured run's dt"};
    }
    giveMass(sim.particles(), sim.time(), dt / 2);
    sim.particlesEdited();
    return std::nullopt;
  }

  static std::string scene(int n, const std::string& kernel, double hOverDx,
                           const std::string& integrator = "predictor_corrector") {
    std::ostringstream s;
    s.precision(17);
    s << "name = \"mms\"\ndimension = 2\n[domain]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
      << "x_lower = \"periodic\"\nx_upper = \"periodic\"\ny_lower = \"periodic\"\n"
      << "y_upper = \"periodic\"\n[[phase]]\nname = \"fluid\"\nrho0 = " << rho0 << "\nc0 = " << c0
      << "\nmu = " << nu * rho0 << "\ngamma = " << gamma
      << "\n[[fluid]]\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n[physics]\nmorris_viscosity = true\n"
      << "[numerics]\nkernel = \"" << kernel << "\"\ndx = " << 1.0 / n
      << "\nh_over_dx = " << hOverDx << "\nintegrator = \"" << integrator << "\"\nend_time = 1.0\n";
    return s.str();
  }

  // The lattice of `scene` carrying the exact fields at t = 0, with V_j = dx^2 (m = rho dx^2).
  static Simulation<2> simulation(int n, const std::string& kernel, double hOverDx,
                                  const std::string& integrator = "predictor_corrector") {
    const Scene sc = parseScene(scene(n, kernel, hOverDx, integrator), "mms");
    Particles<2> p = latticeParticles<2>(sc);
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.rho[i] = density(p.r[i], 0.0), p.v[i] = velocity(p.r[i], 0.0);
      p.m[i] = p.rho[i] * sc.dx * sc.dx;
    }
    Simulation<2> sim(sc, std::move(p));
    sim.setSource(&Manufactured::source);
    return sim;
  }

  struct Error {
    double density, velocity;  // max over particles, relative to rho0 eps and U
  };
  static Error error(const Particles<2>& p, double t) {
    Error e{0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
      e.density = std::max(e.density, std::abs(p.rho[i] - density(p.r[i], t)) / (rho0 * eps));
      e.velocity = std::max(e.velocity, (p.v[i] - velocity(p.r[i], t)).norm() / U);
    }
    return e;
  }
};

}  // namespace sph::verification
