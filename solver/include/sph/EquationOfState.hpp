#pragma once
// Tait equation of state, Lobovsky & Kren eq. (8):
//   p = p0 + K ((rho/rho0)^gamma - 1),  K = rho0 c0^2 / gamma,  gamma = 7.
#include <cmath>
#include <string>

namespace sph {

struct Phase {
  std::string name;
  double rho0 = 1000.0;  // reference density [kg/m^3]
  double c0 = 10.0;      // reference speed of sound [m/s]
  double mu = 0.0;       // dynamic viscosity [Pa s]
  double p0 = 0.0;       // background pressure [Pa]
  double gamma = 7.0;

  double bulkModulus() const { return rho0 * c0 * c0 / gamma; }
};

struct TaitEquationOfState {
  static double pressure(double rho, const Phase& ph) {
    const double x = rho / ph.rho0;
    // gamma = 7 (every scene) by four multiplications, x^7 = (x^2)^2 x^2 x, within a few ulp of
    // std::pow and several times cheaper; it runs for every particle at every force evaluation.
    const double x2 = x * x;
    const double xGamma = ph.gamma == 7.0 ? x2 * x2 * x2 * x : std::pow(x, ph.gamma);
    return ph.p0 + ph.bulkModulus() * (xGamma - 1.0);
  }
  // The inverse, used to start a fluid at hydrostatic pressure.
  static double density(double p, const Phase& ph) {
    return ph.rho0 * std::pow((p - ph.p0) / ph.bulkModulus() + 1.0, 1.0 / ph.gamma);
  }
};

}  // namespace sph
