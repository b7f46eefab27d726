#pragma once
// Velocity Verlet (kick-drift-kick; Swope et al. 1982, Leimkuhler & Reich 2004 section 2.3) with
// one force evaluation a step: the rates of the new state are those of its prediction, whose
// positions are the new state's. With f = (dv/dt, d rho/dt, dh/dt) of y = (r, v, rho, h),
//   r' = r + dt v + dt^2/2 dv/dt            (= r + dt v_1/2, v_1/2 = v + dt/2 dv/dt),
//   y* = (r', v + dt dv/dt, rho + dt drho/dt, h + dt dh/dt),   f* = f(y*) at t + dt,
//   v' = v + dt/2 (dv/dt + dv/dt*),  rho' = rho + dt/2 (drho/dt + drho/dt*),  h' likewise,
//   f(y') := f*.
// y* is y' with v, rho and h predicted by Euler, as the SPH forces of GADGET-2 take predicted
// velocities at the drifted positions (Springel 2005, MNRAS 364 1105, section 4) and as the
// velocity Verlet of dissipative particle dynamics does (Groot & Warren 1997, J. Chem. Phys. 107
// 4423, eq. 23 with lambda = 1). What it is:
//  * For forces of the positions alone, f* = f(y') exactly, and (r, v) take the velocity Verlet
//    map: symplectic and time-reversible, one evaluation a step.
//  * Otherwise f(y') - f* is of dt/2 (f* - f) in v, rho and h: O(dt^2), so the step stays
//    second order (ManufacturedSolution.VelocityVerletIsSecondOrderInTime).
//  * For the (rho, v) pair of a sound wave (a linear oscillator, z = omega dt), the map taking
//    (rho, v, drho/dt, dv/dt) to the next is that of the two-step Adams-Bashforth rule; its
//    amplification grows as 1 + z^4/4, Heun's as 1 + z^4/8: twice the energy gain a step of the
//    predictor-corrector (VelocityVerlet.GainsTwiceHeunsEnergyAStepInUndampedSoundWaves), at half
//    the cost. At equal cost (dt halved) it gains a quarter of Heun's over a time.
// The rates it carries from step to step are not those of the state it holds: a checkpoint keeps
// them, and a continued run takes them as they are (Simulation::resume).
#include <string_view>

#include "sph/integrators/StateUpdate.hpp"

namespace sph::integrators {

struct VelocityVerlet {
  static constexpr std::string_view name = "velocity_verlet";
  static constexpr int evaluationsPerStep = 1;

  // false: the final stage failed a check (the step says which); the state stays y.
  template <class Step>
  static bool advance(Step& step, double dt) {
    const double half = 0.5 * dt;
    {
      const auto y = step.state();
      const auto f = step.rates();
      const auto s = step.trial();  // y*
      step.move(
          [=](std::int64_t i) __attribute__((always_inline)) {
            s.r[i] = y.r[i] + dt * (y.v[i] + half * f.dvdt[i]);
            s.v[i] = y.v[i] + dt * f.dvdt[i];
            s.rho[i] = y.rho[i] + dt * f.drhodt[i];
            s.h[i] = y.h[i] + dt * f.dhdt[i];
            s.m[i] = y.m[i], s.phase[i] = y.phase[i];
          },
          trialStage);
    }
    step.evaluate(dt);  // f(y*) at t + dt: the rates the next step starts from
    // (taken after it: over several processes it may have sent particles elsewhere, y and f too)
    const auto y = step.state();
    const auto f = step.rates();
    const auto s = step.trial();  // y'
    const auto fs = step.trialRates();
    return step.move(
        [=](std::int64_t i) __attribute__((always_inline)) {
          s.v[i] = y.v[i] + half * (f.dvdt[i] + fs.dvdt[i]);
          s.rho[i] = y.rho[i] + half * (f.drhodt[i] + fs.drhodt[i]);
          s.h[i] = y.h[i] + half * (f.dhdt[i] + fs.dhdt[i]);
        },
        finalStage);
  }
};

}  // namespace sph::integrators
