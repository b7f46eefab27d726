// The progress line's ETA (RemainingTime, issue 37) on made-up runs whose remaining wall time is
// known: after the first 5 % of a run it must be within a factor 1.5 of the real remaining time
// (the bar), whatever the first steps cost, with noisy steps, a time step that shrinks,
// and a machine that slows down part-way.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "sph/RemainingTime.hpp"

namespace {

// A run to simulated time `end` in steps of dt(t), step k taking cost(k) wall seconds; returns the
// worst ratio of the estimate to the real remaining wall time over every step from `from` (a
// fraction of `end`) on, as max(estimate / real, real / estimate), while more than a second is
// left (the line shows whole seconds).
struct MadeUpRun {
  double end;
  std::function<double(double)> dt;
  std::function<double(long)> cost;
};

double worstRatio(const MadeUpRun& run, double from) {
  std::vector<double> t{0.0}, wall{0.0};
  while (t.back() < run.end) {
    const long k = long(t.size()) - 1;
    t.push_back(std::min(run.end, t.back() + run.dt(t.back())));
    wall.push_back(wall.back() + run.cost(k));
  }
  sph::RemainingTime remaining(run.end);
  remaining.observe(wall[0], t[0], 0);
  double worst = 1.0;
  for (long k = 1; k + 1 < long(t.size()); ++k) {
    remaining.observe(wall[k], t[k], k);
    const double estimate = remaining.seconds(), real = wall.back() - wall[k];
    if (t[k] < from * run.end || real < 1.0) continue;
    EXPECT_TRUE(std::isfinite(estimate)) << k;
    worst = std::max({worst, estimate / real, real / estimate});
  }
  std::printf("  worst ratio from %g of the run on: %.3f\n", from, worst);
  return worst;
}

// Steps 0-30 % slower at random, and one in 100 ten times slower (another process's slice).
std::function<double(long)> noisy(double cost, unsigned seed) {
  auto random = std::make_shared<std::mt19937_64>(seed);
  return [=](long) {
    const double u = double((*random)() >> 11) * 0x1p-53;
    return cost * (1 + 0.3 * u) * ((*random)() % 100 == 0 ? 10.0 : 1.0);
  };
}

TEST(RemainingTime, NothingBeforeTheFirstSample) {
  sph::RemainingTime remaining(1.0);
  EXPECT_TRUE(std::isnan(remaining.seconds()));
  remaining.observe(0.0, 0.0, 0);
  remaining.observe(0.001, 1e-4, 1);  // shorter than a sample's interval
  EXPECT_FALSE(remaining.known());
  remaining.observe(0.1, 0.01, 100);
  EXPECT_NEAR(remaining.seconds(), 9.9, 1e-9);  // 9,900 steps left at 1,000 steps/s
}

TEST(RemainingTime, ASteadyRun) {
  // 20,000 steps of 1e-4 s at 1 ms each: exact from the first sample on, but for the steps since
  // the last sample (up to 20 ms) and the rounding of t.
  const MadeUpRun run{2.0, [](double) { return 1e-4; }, [](long) { return 1e-3; }};
  EXPECT_LT(worstRatio(run, 0.001), 1.01);
}

TEST(RemainingTime, NoisyStepsWithinTheBar) {
  // Wall time per step noisy, as on a shared machine: the bar is 1.5; 1.2 holds here.
  for (unsigned seed : {1u, 2u, 3u}) {
    const MadeUpRun run{2.0, [](double) { return 1e-4; }, noisy(1e-3, seed)};
    EXPECT_LT(worstRatio(run, 0.05), 1.2) << seed;
  }
}

TEST(RemainingTime, SlowFirstStepsDoNotCount) {
  // The first 30 steps 30 times slower (pages touched for the first time, the thread tuner's
  // first trial): 0.9 s of a 20.9 s run. The average since the start would say 1.9 times the
  // real remaining time at 5 % (1.9 s in, 19 s left).
  const MadeUpRun run{2.0, [](double) { return 1e-4; },
                      [](long k) { return k < 30 ? 3e-2 : 1e-3; }};
  EXPECT_LT(worstRatio(run, 0.05), 1.5);
}

TEST(RemainingTime, AShrinkingTimeStepIsFollowed) {
  // dt falls linearly in t to half its start at the end (the flow speeds up): more steps remain
  // than the remaining time over dt now. The remaining time over dt now is 1.37 times too low at
  // 5 %, 1.31 at 25 %; the trend, carried only as far as it was seen, takes a little off that
  // (1.36, 1.25 measured).
  const double end = 2.0, dt0 = 1e-4;
  const MadeUpRun run{end, [=](double t) { return dt0 * (1 - 0.5 * t / end); },
                      [](long) { return 1e-3; }};
  EXPECT_LT(worstRatio(run, 0.05), 1.5);
  EXPECT_LT(worstRatio(run, 0.25), 1.3);
}

TEST(RemainingTime, AMachineThatSlowsDownIsFollowed) {
  // At step 8,000 of 20,000 another process takes the core: steps twice as long. No estimate
  // could know before; within the bar again from a horizon (3 s) after the change: step 9,500,
  // t = 0.95 s of 2 s.
  const MadeUpRun run{2.0, [](double) { return 1e-4; },
                      [](long k) { return k < 8000 ? 1e-3 : 2e-3; }};
  EXPECT_LT(worstRatio(run, 0.95 / 2.0), 1.5);
}

}  // namespace
