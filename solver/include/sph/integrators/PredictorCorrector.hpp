#pragma once
// The predictor-corrector of Lobovsky & Kren (Heun's method), second order in time:
//   y* = y + dt f(y),   y' = y + dt/2 (f(y) + f(y*)),
// for y = (r, v, rho, h) and f = (v, dv/dt, d rho/dt, dh/dt). Two force evaluations a step:
// f(y*), and f(y') for the next step's predictor. The positions' corrector takes v* (the
// trapezoidal rule over the velocities at both ends), so it runs before v is corrected.
#include <string_view>

#include "sph/integrators/StateUpdate.hpp"

namespace sph::integrators {

struct PredictorCorrector {
  static constexpr std::string_view name = "predictor_corrector";
  static constexpr int evaluationsPerStep = 2;

  // false: the final stage failed a check (the step says which); the state stays y.
  template <class Step>
  static bool advance(Step& step, double dt) {
    const auto y = step.state();
    const auto f = step.rates();
    const auto s = step.trial();  // y*
    step.move(
        [=](std::int64_t i) __attribute__((always_inline)) {
          s.r[i] = y.r[i] + dt * y.v[i];
          s.v[i] = y.v[i] + dt * f.dvdt[i];
          s.rho[i] = y.rho[i] + dt * f.drhodt[i];
          s.h[i] = y.h[i] + dt * f.dhdt[i];
          s.m[i] = y.m[i], s.phase[i] = y.phase[i];
        },
        trialStage);
    step.evaluate(dt);  // f(y*) at t + dt
    const auto fs = step.trialRates();
    return step.move(
        [=](std::int64_t i) __attribute__((always_inline)) {
          s.r[i] = y.r[i] + 0.5 * dt * (y.v[i] + s.v[i]);
          s.v[i] = y.v[i] + 0.5 * dt * (f.dvdt[i] + fs.dvdt[i]);
          s.rho[i] = y.rho[i] + 0.5 * dt * (f.drhodt[i] + fs.drhodt[i]);
          s.h[i] = y.h[i] + 0.5 * dt * (f.dhdt[i] + fs.dhdt[i]);
        },
        finalStage);
  }
};

}  // namespace sph::integrators
