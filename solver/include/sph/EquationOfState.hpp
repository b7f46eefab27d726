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
    return ph.p0 + ph.bulkModulus() * (std::pow(rho / ph.rho0, ph.gamma) - 1.0);
  }
  // The inverse, used to start a fluid at hydrostatic pressure.
  static double density(double p, const Phase& ph) {
    return ph.rho0 * std::pow((p - ph.p0) / ph.bulkModulus() + 1.0, 1.0 / ph.gamma);
  }
};

}  // namespace sph
