// Issue 2, part 2: neighbour search. The cell list (CellList.hpp) against an O(N^2) search, with a
// variable smoothing length, and periodic images (buildInteractionSet) against the
// minimum-image convention.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sph/CellList.hpp"
#include "sph/EquationOfState.hpp"
#include "sph/InteractionSet.hpp"

namespace {

using Pair = std::pair<int, int>;

// Pair criterion of the force loop: r_ij < 2 h_ij, h_ij = (h_i + h_j) / 2 (Lobovsky & Kren eq. 5,
// support 2h, with the pair's mean smoothing length).
template <int D>
bool within(const sph::Vec<D>& a, const sph::Vec<D>& b, double hi, double hj) {
  const double reach = hi + hj;  // 2 h_ij
  return (a - b).squaredNorm() < reach * reach;
}

// 600 points in the unit box with h varying by a factor 3 (h0/2 .. 3 h0/2); `clustered` sends a
// few of them far away, which forces the cell list onto coarser cells (its O(N) guard).
template <int D>
struct RandomPoints {
  static constexpr int n = 600;
  std::vector<sph::Vec<D>> x = std::vector<sph::Vec<D>>(n);
  std::vector<double> h = std::vector<double>(n);
  double hMax = 0.0;
  RandomPoints(unsigned seed, double h0, bool clustered) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < n; ++i) {
      for (int a = 0; a < D; ++a) x[i][a] = u(rng);
      h[i] = h0 * (0.5 + u(rng));
    }
    if (clustered)
      for (int i = 0; i < 3; ++i) x[i] *= 1e4;
    hMax = *std::max_element(h.begin(), h.end());
  }
};

template <int D>
void cellListAgainstBruteForce(unsigned seed, bool clustered) {
  // About 20 (2-D) and 10 (3-D) neighbours each.
  const RandomPoints<D> p(seed, D == 2 ? 0.03 : 0.08, clustered);
  const int n = p.n;
  const auto &x = p.x, &h = p.h;
  const double hMax = p.hMax;
  sph::CellList<D> cells;
  cells.build(x, 2.0 * hMax);
  const auto& order = cells.order();
  std::multiset<Pair> found;
  for (std::int64_t c = 0; c < cells.cells(); ++c)
    for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
      const int i = order[k];
      cells.forEachAdjacentRange(c, [&](int begin, int end) {
        for (int l = begin; l < end; ++l) {
          const int j = order[l];
          if (j != i && within<D>(x[i], x[j], h[i], h[j])) found.insert({i, j});
        }
      });
    }
  std::multiset<Pair> expected;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (j != i && within<D>(x[i], x[j], h[i], h[j])) expected.insert({i, j});
  ASSERT_GT(expected.size(), static_cast<std::size_t>(5 * n)) << "too few pairs to test anything";
  EXPECT_EQ(found, expected);  // every pair once (a multiset also catches duplicates)
}

TEST(Neighbours, CellListMatchesBruteForce2D) {
  cellListAgainstBruteForce<2>(1, false);
  cellListAgainstBruteForce<2>(2, true);
}

TEST(Neighbours, CellListMatchesBruteForce3D) {
  cellListAgainstBruteForce<3>(3, false);
  cellListAgainstBruteForce<3>(4, true);
}

// The pair-once loop's half shell (ForceEvaluation.cpp): with cells of half the reach, the rest of
// a point's own row of five cells (up to ownRowEnd<2>) and its forward rows (forEachForwardRow<2>)
// must hold every neighbour that follows it in the sorted order, so that each pair is found exactly
// once; and the later point of a pair must lie in the same band of two layers or the next (the
// loop's even and odd bands run at once on that promise).
template <int D>
void forwardRowsAgainstBruteForce(unsigned seed, bool clustered) {
  // About 10-20 neighbours each.
  const RandomPoints<D> p(seed, D == 1 ? 0.01 : D == 2 ? 0.03 : 0.08, clustered);
  const int n = p.n;
  const auto &x = p.x, &h = p.h;
  const double hMax = p.hMax;
  sph::CellList<D> cells;
  cells.build(x, hMax);  // half the reach 2 h_max
  const auto& order = cells.order();
  std::vector<int> layerStart;
  for (int l = 0; l <= cells.layers(); ++l) layerStart.push_back(cells.layerBegin(l));
  auto band = [&](int k) {
    const auto it = std::upper_bound(layerStart.begin(), layerStart.end(), k);
    return static_cast<int>(it - layerStart.begin() - 1) / 2;
  };
  std::multiset<Pair> found;
  for (int k = 0; k < n; ++k) {
    const std::int64_t c = cells.sortedCell(k);
    auto sweep = [&](int begin, int end) {
      for (int l = begin; l < end; ++l) {
        const int i = order[k], j = order[l];
        if (!within<D>(x[i], x[j], h[i], h[j])) continue;
        found.insert({std::min(i, j), std::max(i, j)});
        const int step = band(l) - band(k);
        EXPECT_TRUE(step == 0 || step == 1) << "pair in bands " << band(k) << " and " << band(l);
      }
    };
    sweep(k + 1, cells.template ownRowEnd<2>(c));
    cells.template forEachForwardRow<2>(c, sweep);
  }
  std::multiset<Pair> expected;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (within<D>(x[i], x[j], h[i], h[j])) expected.insert({i, j});
  ASSERT_GT(expected.size(), static_cast<std::size_t>(2 * n)) << "too few pairs to test anything";
  EXPECT_EQ(found, expected);  // every pair once
}

// Points whose coordinates are all not a number have no box to bin them in: a clear error, not a
// grid of undefined size.
TEST(Neighbours, CellListRefusesPointsWithoutABox) {
  std::vector<sph::Vec<2>> x(10, sph::Vec<2>(std::nan(""), 0.5));
  sph::CellList<2> cells;
  EXPECT_THROW(cells.build(x, 0.1), std::invalid_argument);
  x.assign(10, sph::Vec<2>(0.25, 0.5));  // one point's worth of box: one cell
  cells.build(x, 0.1);
  EXPECT_EQ(cells.cells(), 1);
}

// A cell size of 0 (every point without support), below 0 or not a number: cells as wide as the
// box, where a grid of such cells would have no end, and every point still in one of them.
TEST(Neighbours, CellListTakesACellSizeThatIsNoPositiveNumber) {
  std::vector<sph::Vec<2>> x;
  for (int k = 0; k < 10; ++k) x.push_back(sph::Vec<2>(0.1 * k, 0.5));
  for (double size : {0.0, -1.0, std::nan("")}) {
    sph::CellList<2> cells;
    cells.build(x, size);
    EXPECT_LE(cells.cells(), 4) << "cell size " << size;
    EXPECT_EQ(cells.order().size(), x.size()) << "cell size " << size;
  }
  sph::CellList<2> one;  // all points at one place: a box of no extent
  one.build(std::vector<sph::Vec<2>>(5, sph::Vec<2>(0.25, 0.5)), 0.0);
  EXPECT_EQ(one.cells(), 1);
}

TEST(Neighbours, ForwardRowsHoldEachPairOnce) {
  for (bool clustered : {false, true}) {
    forwardRowsAgainstBruteForce<1>(5, clustered);
    forwardRowsAgainstBruteForce<2>(6, clustered);
    forwardRowsAgainstBruteForce<3>(7, clustered);
  }
}

// Periodic on every axis: the interaction set's fluid entries and their images, searched by
// brute force, must give every pair whose minimum-image distance is below 2 h_ij exactly once
// (as (i, source of j)) and no other pair.
template <int D>
void periodicImages(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 400;
  sph::Boundaries<D> bounds;
  for (int a = 0; a < D; ++a) {
    bounds.lower[a] = -0.3 + 0.1 * a;
    bounds.upper[a] = bounds.lower[a] + 0.5 + 0.1 * a;
    bounds.face[a] = {sph::FaceKind::periodic, sph::FaceKind::periodic};
  }
  sph::Particles<D> fluid;
  fluid.resize(n);
  const double h0 = D == 2 ? 0.02 : 0.06;
  for (int i = 0; i < n; ++i) {
    for (int a = 0; a < D; ++a)
      fluid.r[i][a] = bounds.lower[a] + u(rng) * (bounds.upper[a] - bounds.lower[a]);
    fluid.v[i].setZero();
    fluid.rho[i] = 1000.0, fluid.m[i] = 1.0, fluid.phase[i] = 0;
    fluid.h[i] = h0 * (0.5 + u(rng));
  }
  const double hMax = *std::max_element(fluid.h.begin(), fluid.h.end());
  // The period (>= 0.5) exceeds twice the reach 2 hMax (<= 0.18), so the minimum image is the
  // only image within reach.
  std::vector<sph::Phase> phases{sph::Phase{}};
  sph::InteractionSet<D> set;
  sph::buildInteractionSet<D>(fluid, phases, bounds, 2.0 * hMax, sph::Vec<D>::Zero(), set);
  ASSERT_EQ(set.nFluid, static_cast<std::size_t>(n));
  ASSERT_GT(set.size(), set.nFluid) << "no periodic images were made";

  std::multiset<Pair> found;
  for (int i = 0; i < n; ++i)
    for (std::size_t j = 0; j < set.size(); ++j)
      if (static_cast<int>(j) != i && within<D>(set.x[i], set.x[j], set.h[i], set.h[j]))
        found.insert({i, set.source[j]});
  std::multiset<Pair> expected;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      sph::Vec<D> d = fluid.r[i] - fluid.r[j];
      for (int a = 0; a < D; ++a) {
        const double period = bounds.upper[a] - bounds.lower[a];
        d[a] -= period * std::round(d[a] / period);  // minimum image
      }
      if (within<D>(d, sph::Vec<D>::Zero(), fluid.h[i], fluid.h[j])) expected.insert({i, j});
    }
  ASSERT_GT(expected.size(), static_cast<std::size_t>(5 * n));
  EXPECT_EQ(found, expected);
  // Each image is a copy of its source shifted by whole periods.
  for (std::size_t j = set.nFluid; j < set.size(); ++j) {
    const int s = set.source[j];
    for (int a = 0; a < D; ++a) {
      const double period = bounds.upper[a] - bounds.lower[a];
      const double shift = (set.x[j][a] - fluid.r[s][a]) / period;
      EXPECT_NEAR(shift, std::round(shift), 1e-12);
    }
    EXPECT_EQ(set.rho[j], fluid.rho[s]);
    EXPECT_EQ(set.h[j], fluid.h[s]);
  }
}

TEST(Neighbours, PeriodicImages2D) {
  periodicImages<2>(5);
}
TEST(Neighbours, PeriodicImages3D) {
  periodicImages<3>(6);
}

}  // namespace
