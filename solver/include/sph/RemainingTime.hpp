#pragma once
// The wall time a run has left, for `sph run`'s progress line (issue 37).
//
// The rate of simulated time per wall second is the rate of steps per wall second times the time
// step, and the two change for different reasons: the steps per second with what the machine
// gives the run now (another process, the thread count), the time step with the flow (faster
// flow, shorter steps). So each is estimated on its own, from what the run did over the last
// `horizon` wall seconds, or a quarter of the run so far when that is shorter (exponentially
// weighted: a sample `age` seconds old weighs exp(-age / horizon)), from the first step on (the
// set-up before it, reading the scene and placing the particles, says nothing about the steps'
// rate, and the first steps, with the thread tuner's first trial, little):
// * steps per second: the weighted steps over the weighted wall time;
// * the time step: a weighted straight-line fit of ln(dt) against the simulated time, dt being
//   each sample's mean step (simulated time over steps: a step cut short to land on a snapshot
//   time moves it little). The fit gives dt now, where a mean over the horizon would lag behind
//   a trend, and its slope k carries dt on, dt(t') = dt(t) exp(k (t' - t)), no further ahead than
//   twice as far as the fit's weighted mean lies behind (as far as the samples reach back); dt is
//   held there after, and within [1/4, 4] dt(t). Carried on to the end, the trend seen over the
//   first 5 % put the ETA 1.7 times too high on the dam break (dt falls 4 % as the column starts
//   to move and recovers later) and 1.8 times too low on the drop into a pool (replayed from their
//   run files' dt at a fixed cost a step; as far as seen: within 1.10 from 5 % on, both).
// An average since program start over the simulated time so far (wall / t x (end - t)) counted the
// set-up and the first steps as if the whole run went at their pace.
#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

class RemainingTime {
 public:
  // interval: the shortest stretch of wall time one sample covers [s].
  explicit RemainingTime(double endTime, double horizon = 3.0, double interval = 0.02)
      : end_(endTime), horizon_(horizon), interval_(interval) {}

  // The run's state at wall seconds `wall` (any origin, not decreasing): simulated time t, steps
  // taken so far.
  void observe(double wall, double t, long step) {
    tNow_ = t;
    if (!started_) {
      started_ = true, wallStart_ = wall0_ = wall, t0_ = t, step0_ = step;
      return;
    }
    const double dWall = wall - wall0_;
    const long dSteps = step - step0_;
    if (dWall < interval_ || dSteps <= 0 || !(t > t0_)) return;
    // Early on, a quarter of the run so far: the first steps are forgotten as the run goes on.
    const double horizon = std::min(horizon_, std::max(interval_, 0.25 * (wall - wallStart_)));
    const double decay = std::exp(-dWall / horizon);
    steps_ = steps_ * decay + double(dSteps), seconds_ = seconds_ * decay + dWall;
    const double x = 0.5 * (t + t0_), y = std::log((t - t0_) / double(dSteps));
    w_ = w_ * decay + 1, wx_ = wx_ * decay + x, wy_ = wy_ * decay + y;
    wxx_ = wxx_ * decay + x * x, wxy_ = wxy_ * decay + x * y;
    wall0_ = wall, t0_ = t, step0_ = step;
  }

  bool known() const { return seconds_ > 0; }
  double stepsPerSecond() const { return known() ? steps_ / seconds_ : 0.0; }

  // The wall seconds left until the end time (NaN before the first sample).
  double seconds() const {
    if (!known()) return std::numeric_limits<double>::quiet_NaN();
    const double left = end_ - tNow_;
    if (left <= 0) return 0.0;
    const double xMean = wx_ / w_, yMean = wy_ / w_;
    const double sxx = wxx_ / w_ - xMean * xMean;
    // Two samples or more, spread over simulated time: a slope; else a constant time step.
    const double k = w_ > 1.5 && sxx > 0 ? (wxy_ / w_ - xMean * yMean) / sxx : 0.0;
    const double dtNow = std::exp(yMean + k * (tNow_ - xMean));
    const double ahead = std::min(left, 2 * (tNow_ - xMean));  // as far as the trend is carried
    const double kAhead = std::clamp(k * ahead, -std::log(4.0), std::log(4.0));
    // The steps of dt(t') = dtNow exp(k (t' - t)) over `ahead` (k ahead = kAhead), then of
    // dtNow exp(kAhead) to the end.
    const double trend = std::abs(kAhead) < 1e-9 ? ahead : -std::expm1(-kAhead) / kAhead * ahead;
    const double steps = (trend + (left - ahead) * std::exp(-kAhead)) / dtNow;
    return steps / stepsPerSecond();
  }

 private:
  double end_, horizon_, interval_;
  bool started_ = false;
  double tNow_ = 0;            // at the last observation
  double wallStart_ = 0;       // at the first observation
  double wall0_ = 0, t0_ = 0;  // at the last sample
  long step0_ = 0;
  double steps_ = 0, seconds_ = 0;  // weighted sums of the samples' steps, wall time
  double w_ = 0, wx_ = 0, wy_ = 0, wxx_ = 0, wxy_ = 0;  // the fit's weighted sums: x = t, y = ln dt
};

}  // namespace sph
