#pragma once
// A manufactured solution of the whole discretisation (continuity eq. 11, momentum eq. 12 with
// the Tait EOS eq. 8 and Morris viscosity eq. 9) on the periodic unit square (D = 2) or cube
// (D = 3), k = 2 pi, with C = prod_b cos(k x_b):
//   u_a = a(t) sin(k x_a) prod_{b != a} cos(k x_b),    a(t) = U cos(omega t)
//   rho = rho0 (1 + b(t) C),                           b(t) = eps cos(omega t)
// (in 2-D: u = a sin kx cos ky, w = a cos kx sin ky). The flow is compressible (div v = D a k C),
// so the continuity equation is tested. Sources, added through Simulation::setSource at each
// particle's position and time:
//   S_rho = d rho/dt + v . grad rho + rho div v
//   S_v   = dv/dt + (v . grad) v + p'(rho) grad rho / rho - (mu / rho) lap v,
// p'(rho) = c0^2 (rho/rho0)^(gamma-1), lap u_a = -D k^2 u_a. The Morris term approximates
// (1/rho) div(mu grad v) (Morris et al. 1997 eq. 8), which for constant mu is (mu/rho) lap v; that
// is what it is compared with. The particles move with their SPH velocity (a Lagrangian scheme);
// the exact density and velocity are evaluated at each particle's current position and time, so
// the error measures the solution along the computed trajectories.
// S_rho is a source of mass: a particle of volume V gains V S_rho a unit time (giveMass). With
// fixed masses the volumes m/rho would part from the space the particles fill (by the integral of
// div v, about 10 % at t = 1/4 in 2-D), an O(1) error of every kernel sum at any resolution.
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include "sph/InitialParticles.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace sph::verification {

template <int D = 2>
struct Manufactured {
  static constexpr double rho0 = 1.0, c0 = 1.0, gamma = 7.0, nu = 0.01;
  static constexpr double U = 0.05, eps = 0.01, omega = 2 * std::numbers::pi;
  static constexpr double k = 2 * std::numbers::pi;

  static double a(double t) { return U * std::cos(omega * t); }
  static double da(double t) { return -U * omega * std::sin(omega * t); }
  static double b(double t) { return eps * std::cos(omega * t); }
  static double db(double t) { return -eps * omega * std::sin(omega * t); }

  // The fields and their derivatives at x and t.
  struct Point {
    double rho, rhot;
    Vec<D> v, vt, gradRho;
    double gradV[D][D];  // d u_a / d x_b
    double divV;
  };
  static Point at(const Vec<D>& x, double t) {
    std::array<double, D> s, c;
    double C = 1.0;
    for (int q = 0; q < D; ++q) s[q] = std::sin(k * x[q]), c[q] = std::cos(k * x[q]), C *= c[q];
    // prod_{q != a, b} cos(k x_q)
    auto others = [&](int a, int b) {
      double P = 1.0;
      for (int q = 0; q < D; ++q)
        if (q != a && q != b) P *= c[q];
      return P;
    };
    Point p;
    const double A = a(t), B = b(t);
    p.rho = rho0 * (1 + B * C), p.rhot = rho0 * db(t) * C, p.divV = D * A * k * C;
    for (int q = 0; q < D; ++q) {
      p.v[q] = A * s[q] * others(q, q), p.vt[q] = da(t) * s[q] * others(q, q);
      p.gradRho[q] = -rho0 * B * k * s[q] * others(q, q);
      for (int r = 0; r < D; ++r)
        p.gradV[q][r] = q == r ? A * k * C : -A * k * s[q] * s[r] * others(q, r);
    }
    return p;
  }

  static double density(const Vec<D>& x, double t) { return at(x, t).rho; }
  static Vec<D> velocity(const Vec<D>& x, double t) { return at(x, t).v; }

  // S_rho at a point, and at x and t.
  static double massSource(const Point& p) { return p.rhot + p.v.dot(p.gradRho) + p.rho * p.divV; }
  static double massSource(const Vec<D>& x, double t) { return massSource(at(x, t)); }

  // Adds S_rho and S_v at every particle.
  static void source(double t, const Particles<D>& s, Derivatives<D>& out) {
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Point p = at(s.r[i], t);
      const double dpdrho = c0 * c0 * std::pow(p.rho / rho0, gamma - 1);
      const double mu = nu * rho0;
      out.drhodt[i] += massSource(p);
      for (int q = 0; q < D; ++q) {
        double advection = 0.0;
        for (int r = 0; r < D; ++r) advection += p.v[r] * p.gradV[q][r];
        out.dvdt[i][q] += p.vt[q] + advection + dpdrho * p.gradRho[q] / p.rho +
                          mu / p.rho * D * k * k * p.v[q];  // lap u_a = -D k^2 u_a
      }
    }
  }

  // dm/dt = m S_rho / rho over dt with positions, density and time held.
  static void giveMass(Particles<D>& p, double t, double dt) {
    for (std::size_t i = 0; i < p.size(); ++i)
      p.m[i] *= std::exp(dt * massSource(p.r[i], t) / p.rho[i]);
  }

  // One step of exactly dt: the mass's half steps around the scene's integrator (Strang
  // splitting, second order as the integrators are).
  static std::optional<Failure> step(Simulation<D>& sim, double dt) {
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

  // `physics`: further [physics] lines (a term beside Morris viscosity).
  static std::string scene(int n, const std::string& kernel, double hOverDx,
                           const std::string& integrator = "predictor_corrector",
                           const std::string& physics = "") {
    const std::string zeros = D == 2 ? "[0.0, 0.0]" : "[0.0, 0.0, 0.0]";
    const std::string ones = D == 2 ? "[1.0, 1.0]" : "[1.0, 1.0, 1.0]";
    std::ostringstream s;
    s.precision(17);
    s << "name = \"mms\"\ndimension = " << D << "\n[domain]\nlower = " << zeros
      << "\nupper = " << ones << "\n";
    for (const char* axis : {"x", "y", "z"}) {
      if (axis[0] == 'z' && D == 2) break;
      s << axis << "_lower = \"periodic\"\n" << axis << "_upper = \"periodic\"\n";
    }
    s << "[[phase]]\nname = \"fluid\"\nrho0 = " << rho0 << "\nc0 = " << c0 << "\nmu = " << nu * rho0
      << "\ngamma = " << gamma << "\n[[fluid]]\nlower = " << zeros << "\nupper = " << ones
      << "\n[physics]\nmorris_viscosity = true\n"
      << physics << "[numerics]\nkernel = \"" << kernel << "\"\ndx = " << 1.0 / n
      << "\nh_over_dx = " << hOverDx << "\nintegrator = \"" << integrator << "\"\nend_time = 1.0\n";
    return s.str();
  }

  // The lattice of `scene` carrying the exact fields at t = 0, with V_j = dx^D (m = rho dx^D).
  static Simulation<D> simulation(int n, const std::string& kernel, double hOverDx,
                                  const std::string& integrator = "predictor_corrector",
                                  const std::string& physics = "") {
    const Scene sc = parseScene(scene(n, kernel, hOverDx, integrator, physics), "mms");
    Particles<D> p = latticeParticles<D>(sc);
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.rho[i] = density(p.r[i], 0.0), p.v[i] = velocity(p.r[i], 0.0);
      p.m[i] = p.rho[i] * std::pow(sc.dx, D);
    }
    Simulation<D> sim(sc, std::move(p));
    sim.setSource(&Manufactured::source);
    return sim;
  }

  struct Error {
    double density, velocity;  // max over particles, relative to rho0 eps and U
  };
  static Error error(const Particles<D>& p, double t) {
    Error e{0, 0};
    for (std::size_t i = 0; i < p.size(); ++i) {
      e.density = std::max(e.density, std::abs(p.rho[i] - density(p.r[i], t)) / (rho0 * eps));
      e.velocity = std::max(e.velocity, (p.v[i] - velocity(p.r[i], t)).norm() / U);
    }
    return e;
  }
};

}  // namespace sph::verification
