// Issue 7: the thread count must not change a bit of a run. Above sph::parallelFrom() particles
// the whole step runs in parallel (cell list, interaction set, force loop, time step, predictor,
// corrector, wall reflections, checks); each part combines its threads' shares in a fixed order.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <functional>
#include <random>

#include "sph/CellList.hpp"
#include "sph/Parallel.hpp"
#include "sph/Simulation.hpp"

namespace {

template <class T, class Allocator>
bool sameBits(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// The counting sort: stable by cell (points of a cell in increasing index) with any thread count.
TEST(ParallelCellList, OrderIsTheSerialOne) {
  const int n = 5 * static_cast<int>(sph::parallelFrom());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<sph::Vec<2>> x(n);
  for (auto& p : x) p = {u(rng), u(rng)};
  const int saved = omp_get_max_threads();
  sph::CellList<2> one, two;
  omp_set_num_threads(1);
  one.build(x, 0.01);
  omp_set_num_threads(2);
  two.build(x, 0.01);
  omp_set_num_threads(saved);
  EXPECT_TRUE(sameBits(one.order(), two.order()));
  for (int k = 1; k < n; ++k) {
    const auto c0 = two.sortedCell(k - 1), c1 = two.sortedCell(k);
    ASSERT_TRUE(c0 < c1 || (c0 == c1 && two.order()[k - 1] < two.order()[k])) << k;
  }
}

// The threads sort the points of the layers a cut gives them (a pair loop's bands): no cut changes
// the order or the cells' starts, also one that gives a thread no layer or does not ascend.
TEST(ParallelCellList, OrderDoesNotDependOnTheCut) {
  const int n = 5 * static_cast<int>(sph::parallelFrom());
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<sph::Vec<2>> x(n);
  for (auto& p : x) p = {u(rng), 0.3 * u(rng)};  // x the slowest axis: layers along x
  auto pos = [&](std::size_t i, int a) { return x[i][a]; };
  const int saved = omp_get_max_threads();
  sph::CellList<2> one;
  omp_set_num_threads(1);
  one.build(x.size(), pos, 0.01, 4, n - 100);  // the last 100 points as a halo
  omp_set_num_threads(2);
  const std::vector<std::function<int(int, int, int)>> cuts = {
      [](int layers, int, int) { return layers; },                        // all to thread 0
      [](int, int, int) { return 0; },                                    // all to thread 1
      [](int, int, int) { return 3; },                                    // near the start
      [](int layers, int nt, int t) { return layers - layers * t / nt; }  // descending
  };
  for (const auto& cut : cuts) {
    sph::CellList<2> two;
    two.build(x.size(), pos, 0.01, 4, n - 100, cut);
    EXPECT_TRUE(sameBits(one.order(), two.order()));
    ASSERT_EQ(one.cells(), two.cells());
    for (std::int64_t c = 0; c < one.cells(); ++c) {
      ASSERT_EQ(one.cellBegin(c), two.cellBegin(c)) << c;
      ASSERT_EQ(one.cellEnd(c), two.cellEnd(c)) << c;
    }
  }
  omp_set_num_threads(saved);
}

// A dam break of 100 x 100 particles (above parallelFrom() for either wait policy).
sph::Scene damBreak() {
  return sph::parseScene(R"(
name = "parallel_dam_break"
dimension = 2
[domain]
lower = [0.0, 0.0]
upper = [0.2, 0.2]
x_lower = "free_slip"
x_upper = "free_slip"
y_lower = "no_slip"
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
upper = [0.1, 0.1]
initial_pressure = "hydrostatic"
[physics]
gravity = [0.0, -9.81]
artificial_viscosity = 1.0
morris_viscosity = true
variable_h = true
[numerics]
kernel = "quadratic"
dx = 0.001
h_over_dx = 1.33
end_time = 1.0
)",
                         "parallel_dam_break");
}

// 20 steps of the dam break on `threads` threads, stored in cell order every `cellOrderEvery`
// steps (0: never), with neighbour lists of a skin of `skin` of the support (the scenes' default
// 0.1; 0: built at every evaluation).
sph::Simulation<2> twentySteps(int threads, int cellOrderEvery, double skin = 0.1) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  sph::Simulation<2> sim(damBreak());
  sim.keepCellOrder(cellOrderEvery);
  sim.keepNeighbourLists(skin);
  for (int step = 0; step < 20; ++step) {
    const auto failure = sim.advance();
    EXPECT_FALSE(failure) << failure->message;
  }
  omp_set_num_threads(saved);
  return sim;
}

void expectSameBits(const sph::Simulation<2>& one, const sph::Simulation<2>& two) {
  EXPECT_EQ(one.time(), two.time());
  EXPECT_EQ(one.ids(), two.ids());
  EXPECT_TRUE(sameBits(one.particles().r, two.particles().r));
  EXPECT_TRUE(sameBits(one.particles().v, two.particles().v));
  EXPECT_TRUE(sameBits(one.particles().rho, two.particles().rho));
  EXPECT_TRUE(sameBits(one.particles().h, two.particles().h));
  EXPECT_TRUE(sameBits(one.particles().p, two.particles().p));
}

TEST(ParallelStep, ThreadCountDoesNotChangeBits) {
  const sph::Simulation<2> one = twentySteps(1, 0), two = twentySteps(2, 0);
  ASSERT_GE(static_cast<std::int64_t>(one.particles().size()), sph::parallelFrom());
  expectSameBits(one, two);
}

// `sph run` may change the thread count between steps (ThreadTuner): the 20 steps with 2, 1, 1, 2,
// 2, 2, 1, ... threads, stored in cell order every 5 steps, are bitwise those on one thread.
TEST(ParallelStep, ThreadCountChangedBetweenStepsDoesNotChangeBits) {
  const int saved = omp_get_max_threads();
  sph::Simulation<2> mixed(damBreak());
  mixed.keepCellOrder(5);
  for (int step = 0; step < 20; ++step) {
    omp_set_num_threads(step % 3 == 1 || step % 7 == 2 ? 1 : 2);
    const auto failure = mixed.advance();
    EXPECT_FALSE(failure) << failure->message;
  }
  omp_set_num_threads(saved);
  expectSameBits(twentySteps(1, 5), mixed);
}

// Storing the particles in cell order (as `sph run` does) moves them in memory, not in the flow:
// each particle, found by its id, ends where it ends without reordering, but for round-off (the
// cell list lists a cell's points by storage index, so sums within a cell change order). And the
// order is the cell list's, which no thread count changes.
TEST(ParallelStep, CellOrderMovesParticlesOnlyInMemory) {
  const sph::Simulation<2> plain = twentySteps(1, 0), one = twentySteps(1, 5),
                           two = twentySteps(2, 5);
  expectSameBits(one, two);
  const auto& ids = one.ids();
  const std::size_t n = ids.size();
  ASSERT_EQ(n, plain.particles().size());
  std::vector<int> seen(n, 0);
  std::size_t moved = 0;
  double drMax = 0.0, drhoMax = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const int i = ids[k];
    ASSERT_TRUE(i >= 0 && static_cast<std::size_t>(i) < n && seen[i]++ == 0) << k;
    moved += static_cast<std::size_t>(i) != k;
    drMax = std::max(drMax, (one.particles().r[k] - plain.particles().r[i]).norm());
    drhoMax = std::max(drhoMax, std::abs(one.particles().rho[k] - plain.particles().rho[i]));
  }
  EXPECT_GT(moved, n / 4);  // the lattice order (x fastest) is not the cell order: 4,950 moved
  // Round-off at most: 20 steps of sums of ~20 terms. Measured 0: a stable sort keeps the order
  // within a cell, and in 20 steps hardly a particle changes cell.
  EXPECT_LT(drMax, 1e-12) << "max |dr| [m], dx = 1e-3 m";
  EXPECT_LT(drhoMax, 1e-9) << "max |d rho| [kg/m^3], rho0 = 1000";
  std::printf("[ measured ] max |dr| = %.3g m, max |d rho| = %.3g kg/m^3, %zu of %zu moved\n",
              drMax, drhoMax, moved, n);
}

// Neighbour lists kept between evaluations (Simulation::keepNeighbourLists) change which pairs
// are listed, not which pairs act (those inside the support): the run is the one with lists built
// at every evaluation but for round-off (a pair's terms are summed in the order of the lists'
// build, not of the evaluation's cell list), with the bounds of the test above. Most evaluations
// must keep their lists: in 20 steps at c0 = 20 m/s a particle moves about 0.02 h an evaluation.
TEST(ParallelStep, KeptNeighbourListsChangeOnlyRoundOff) {
  const sph::Simulation<2> built = twentySteps(1, 0, 0.0), kept = twentySteps(2, 0, 0.1);
  EXPECT_EQ(built.reusedNeighbourLists(), 0);
  EXPECT_GT(kept.reusedNeighbourLists(), kept.forceEvaluations() / 2);
  double drMax = 0.0, drhoMax = 0.0;
  for (std::size_t i = 0; i < built.particles().size(); ++i) {
    drMax = std::max(drMax, (built.particles().r[i] - kept.particles().r[i]).norm());
    drhoMax = std::max(drhoMax, std::abs(built.particles().rho[i] - kept.particles().rho[i]));
  }
  EXPECT_LT(drMax, 1e-12) << "max |dr| [m], dx = 1e-3 m";
  EXPECT_LT(drhoMax, 1e-9) << "max |d rho| [kg/m^3], rho0 = 1000";
  std::printf(
      "[ measured ] %ld of %ld evaluations kept their lists; max |dr| = %.3g m, max |d rho| "
      "= %.3g kg/m^3\n",
      kept.reusedNeighbourLists(), kept.forceEvaluations(), drMax, drhoMax);
}

}  // namespace
