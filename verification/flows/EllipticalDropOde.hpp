#pragma once
// The semi-axes of Monaghan's (1994, J. Comput. Phys. 110, 399) elliptical drop:
//   da/dt = A a,  db/dt = -A b,  dA/dt = A^2 (b^2 - a^2)/(a^2 + b^2),  a = b = R, A = A0 at t = 0
// (incompressible and inviscid; a b = R^2 for all t), solved with GSL's rk8pd. The project's one
// solution of this ODE: the GoogleTest cases (EllipticalDrop.hpp) call it, and the stability
// sweep (validation/stability/sweep.py) reads it from the tool elliptical_drop_ode
// (EllipticalDropOdeTool.cpp).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace sph::verification {

struct DropAxes {
  double a = 0.0, b = 0.0, A = 0.0;
};

// The ODE at each of `times` (ascending, >= 0); A0 != 0 (a sign of A0 compresses along x).
inline std::vector<DropAxes> dropOde(double A0, double R, const std::vector<double>& times) {
  auto rhs = [](double, const double y[], double f[], void*) -> int {
    const double a2 = y[0] * y[0], b2 = y[1] * y[1];
    f[0] = y[2] * y[0];
    f[1] = -y[2] * y[1];
    f[2] = y[2] * y[2] * (b2 - a2) / (a2 + b2);
    return GSL_SUCCESS;
  };
  gsl_odeiv2_system sys = {rhs, nullptr, 3, nullptr};
  // Tolerances 1e-13 relative: far below any SPH error measured here (1e-3 and up).
  gsl_odeiv2_driver* d =
      gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 / std::abs(A0), 1e-13, 1e-13);
  double y[3] = {R, R, A0}, t = 0.0;
  std::vector<DropAxes> out;
  for (double ti : times) {
    if (ti > t && gsl_odeiv2_driver_apply(d, &t, ti, y) != GSL_SUCCESS) {
      gsl_odeiv2_driver_free(d);
      throw std::runtime_error("GSL ODE solver failed on the elliptical drop");
    }
    out.push_back({y[0], y[1], y[2]});
  }
  gsl_odeiv2_driver_free(d);
  return out;
}

}  // namespace sph::verification
