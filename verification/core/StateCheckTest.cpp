// Issue 2 and 7: every new state is checked (Simulation::check), first by a test without branches
// that every good particle passes, then, for a particle that fails it, by the detailed test that
// names the fault. Each fault here is planted in one particle of a small water column; the step
// must stop on it, name it and name that particle, on one thread and on two (the 2-thread tank
// is above parallelFrom(), so the check's loop runs in parallel).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "sph/Parallel.hpp"
#include "sph/Simulation.hpp"

namespace {

// A water column of `columns` x 20 particles in a box with free-slip walls and an open top.
sph::Scene column(int columns) {
  const double width = 0.01 * columns;
  const std::string w = std::to_string(width);
  return sph::parseScene(R"(
name = "state_check"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [)" + w + R"(, 0.4]
x_lower = "free_slip"
x_upper = "free_slip"
y_lower = "free_slip"
y_upper = "open"
ghost_pressure = "hydrostatic"
[[phase]]
name = "water"
rho0 = 1000.0
c0 = 20.0
mu = 1.0e-3
[[fluid]]
shape = "rectangle"
lower = [0.0, 0.0]
upper = [)" + w + R"(, 0.2]
initial_pressure = "hydrostatic"
[physics]
gravity = [0.0, -9.81]
artificial_viscosity = 1.0
morris_viscosity = true
variable_h = true
[numerics]
kernel = "quadratic"
dx = 0.01
h_over_dx = 1.33
end_time = 1.0
)",
                         "state_check");
}

using Fault = std::function<void(sph::Particles<2>&, int)>;

// Plants `fault` in particle `victim` and takes a step: it must fail with `cause`, at step 1,
// naming the victim and `what`.
void expectCaught(int columns, int threads, const Fault& fault, sph::FailureCause cause,
                  const std::string& what) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  sph::Simulation<2> sim(column(columns));
  const int victim = static_cast<int>(sim.particles().size()) * 2 / 3;
  fault(sim.particles(), victim);
  const auto failure = sim.advance();
  omp_set_num_threads(saved);
  ASSERT_TRUE(failure) << what;
  EXPECT_EQ(failure->cause, cause) << failure->message;
  EXPECT_EQ(failure->step, 1);
  EXPECT_EQ(failure->particle, victim) << failure->message;
  EXPECT_NE(failure->message.find("particle " + std::to_string(victim)), std::string::npos)
      << failure->message;
  EXPECT_NE(failure->message.find(what), std::string::npos) << failure->message;
}

void expectEveryFaultCaught(int columns, int threads) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Far outside the band [0.8, 1.2] rho0: one step cannot bring it back.
  expectCaught(
      columns, threads, [](auto& p, int i) { p.rho[i] = 1500.0; }, sph::FailureCause::density_band,
      "outside the band");
  expectCaught(
      columns, threads, [](auto& p, int i) { p.rho[i] = 500.0; }, sph::FailureCause::density_band,
      "outside the band");
  expectCaught(
      columns, threads, [&](auto& p, int i) { p.h[i] = nan; }, sph::FailureCause::nan,
      "smoothing length");
  // Above the open top, and through a wall by more than the dx/2 a reflection puts back.
  expectCaught(
      columns, threads, [](auto& p, int i) { p.r[i][1] = 0.45; }, sph::FailureCause::escaped_domain,
      "left the domain");
  expectCaught(
      columns, threads, [](auto& p, int i) { p.r[i][0] = -0.03; },
      sph::FailureCause::wall_penetration, "crossed the wall");
  expectCaught(
      columns, threads, [](auto& p, int i) { p.r[i][1] = -0.03; },
      sph::FailureCause::wall_penetration, "crossed the wall");
}

TEST(StateCheck, GoodStatesPass) {
  sph::Simulation<2> sim(column(10));
  for (int step = 0; step < 20; ++step) {
    const auto failure = sim.advance();
    ASSERT_FALSE(failure) << failure->message;
  }
}

TEST(StateCheck, EveryFaultIsCaughtAndNamedOnOneThread) {
  expectEveryFaultCaught(10, 1);
}

TEST(StateCheck, EveryFaultIsCaughtAndNamedOnTwoThreads) {
  const int columns = static_cast<int>(sph::parallelFrom()) / 20 + 10;
  expectEveryFaultCaught(columns, 2);
}

}  // namespace
