#pragma once
// Position Verlet (drift-kick-drift; Verlet 1967, Leimkuhler & Reich 2004 section 2.3.1), the
// symplectic step of Monaghan (2005, Rep. Prog. Phys. 68 1703, section 6) and of DualSPHysics
// (Crespo et al. 2015, Comput. Phys. Commun. 187 204, section 3.3): with f = (dv/dt, d rho/dt,
// dh/dt) at y = (r, v, rho, h),
//   r* = r + dt/2 v,   v* = v + dt/2 dv/dt,   rho* = rho + dt/2 drho/dt,   h* = h + dt/2 dh/dt,
//   f* = f(y*) at t + dt/2,
//   v' = v + dt dv/dt*,   r' = r* + dt/2 v' = r + dt/2 (v + v'),
//   rho' = rho (2 - e)/(2 + e),  e = -(drho/dt* / rho*) dt        (Monaghan & Rafiee 2013, eq. 17),
//   h'   = h (2 - e_h)/(2 + e_h), e_h = -(dh/dt* / h*) dt.
// For forces of the positions alone the (r, v) map is the symplectic, time-reversible position
// Verlet: r' and v' come from r* and one kick, and reversed (dt -> -dt from y') it returns y.
// v* serves only the terms that read v (viscosities, and continuity: below).
// Density and h are not canonical variables: they follow d ln rho/dt = (drho/dt)/rho and
// d ln h/dt = (dh/dt)/h (eq. 11 and 13: both are -div v times rho or h/D), and the Pade form
// (2 - e)/(2 + e) = exp(-e) + O(e^3) is the midpoint rule of the logarithm: second order, the
// same for +dt and -dt (reversible), and positive for any |e| < 2.
// What it is not: continuity couples rho and v as a second pair, and for that pair (the
// sound waves of a weakly compressible fluid) rho' and v' take rho* and v*, both predicted by
// Euler: the explicit midpoint rule, whose amplification 1 + z + z^2/2 (z = i omega dt) is
// Heun's. No explicit scheme with one pass of the pair loop a stage can do better (a pass gives
// d rho/dt and dv/dt of one state, and a symplectic update of the (rho, v) pair needs them of
// two), so the energy of an undamped sound wave grows here as it does with Heun
// (verification/flows/PositionVerletTest.cpp measures both). Two force evaluations a step: f(y*),
// and f(y') for the next step's first half.
#include <string_view>
#include <type_traits>

#include "sph/integrators/StateUpdate.hpp"

namespace sph::integrators {

struct PositionVerlet {
  static constexpr std::string_view name = "position_verlet";
  static constexpr int evaluationsPerStep = 2;

  // false: the final stage failed a check (the step says which); the state stays y.
  template <class Step>
  static bool advance(Step& step, double dt) {
    const auto y = step.state();
    const auto f = step.rates();
    const auto s = step.trial();  // y*, then y'
    const double half = 0.5 * dt;
    using V = std::remove_cvref_t<decltype(*y.v)>;
    step.move(
        [=](std::int64_t i) __attribute__((always_inline)) {
          s.r[i] = y.r[i] + half * y.v[i];
          s.v[i] = y.v[i] + half * f.dvdt[i];
          s.rho[i] = y.rho[i] + half * f.drhodt[i];
          s.h[i] = y.h[i] + half * f.dhdt[i];
          s.m[i] = y.m[i], s.phase[i] = y.phase[i];
        },
        trialStage);
    step.evaluate(half);  // f(y*) at t + dt/2
    const auto fs = step.trialRates();
    return step.move(
        [=](std::int64_t i) __attribute__((always_inline)) {
          const V v = y.v[i] + dt * fs.dvdt[i];
          // From y.r, not r*: the trial stage's periodic wrap may have moved r* by a period.
          s.r[i] = y.r[i] + half * (y.v[i] + v);
          s.v[i] = v;
          const double e = -dt * fs.drhodt[i] / s.rho[i], eh = -dt * fs.dhdt[i] / s.h[i];
          s.rho[i] = y.rho[i] * (2.0 - e) / (2.0 + e);
          s.h[i] = y.h[i] * (2.0 - eh) / (2.0 + eh);
        },
        finalStage);
  }
};

}  // namespace sph::integrators
