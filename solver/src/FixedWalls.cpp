#include "sph/FixedWalls.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sph/Parallel.hpp"

namespace sph {

template <int D>
FixedWalls<D>::FixedWalls(std::vector<Vec<D>> position, double V0, double h, KernelKind kernel,
                          std::vector<Phase> phases, const Vec<D>& g)
    : x_(std::move(position)), V0_(V0), h_(h), kernel_(kernel), phases_(std::move(phases)), g_(g) {
  if (phases_.empty()) throw std::logic_error("FixedWalls: no phase");
  frameTheWalls();
}

template <int D>
FixedWalls<D>::FixedWalls(std::vector<Vec<D>> position, std::vector<WallVelocityRule<D>> velocity,
                          std::vector<double> volume, double h, KernelKind kernel,
                          std::vector<Phase> phases, const Vec<D>& g)
    : x_(std::move(position)),
      velocity_(std::move(velocity)),
      volume_(std::move(volume)),
      h_(h),
      kernel_(kernel),
      phases_(std::move(phases)),
      g_(g) {
  if (phases_.empty()) throw std::logic_error("FixedWalls: no phase");
  if (velocity_.size() != x_.size() || volume_.size() != x_.size())
    throw std::logic_error("FixedWalls: one velocity rule and one volume per wall particle");
  frameTheWalls();
}

template <int D>
void FixedWalls<D>::frameTheWalls() {
  const double reach = 2.0 * h_;
  frame_.points = std::max<std::size_t>(x_.size(), 1);
  for (const Vec<D>& x : x_)
    for (int a = 0; a < D; ++a)
      frame_.box.lo[a] = std::min(frame_.box.lo[a], x[a] - reach),
      frame_.box.hi[a] = std::max(frame_.box.hi[a], x[a] + reach);
  if (x_.empty())
    for (int a = 0; a < D; ++a) frame_.box.lo[a] = 0.0, frame_.box.hi[a] = 0.0;
  lo_ = Vec<D>::Constant(1e300), hi_ = Vec<D>::Constant(-1e300);
  for (const Vec<D>& x : x_) lo_ = lo_.cwiseMin(x), hi_ = hi_.cwiseMax(x);
}

template <int D>
void FixedWalls<D>::choose(InteractionSet<D>& set, double reach) const {
  // A pair (fluid i, wall w) is listed within h_i + h_w plus the skin (support 2 h_ij), which is
  // below reach + h_w whatever h_i (reach = 2 h_max + skin).
  const double near = reach + h_, near2 = near * near;
  const std::size_t nFluid = set.nFluid;
  std::vector<std::int64_t>& members = set.walls;
  members.clear();
  if (nFluid > 0 && std::isfinite(near) && near > 0) {
    fluidCells_.build(
        nFluid, [&](std::size_t f, int a) { return set.x[f][a]; }, near);
    const auto& order = fluidCells_.order();
    // Each cell's box of its fluid, at the cell's first place in the sorted order: a wall
    // particle decides a cell at once where the whole box lies beyond `near` of it, or within.
    // Only where the box says so with a margin far above the rounding of a distance, so that
    // the choice is the particle-by-particle test's.
    const std::int64_t nCells = fluidCells_.cells();
    cellLo_.resize(nFluid), cellHi_.resize(nFluid);
    const bool parallelCells = static_cast<std::int64_t>(nFluid) >= parallelFrom();
#pragma omp parallel for schedule(static) if (parallelCells)
    for (std::int64_t c = 0; c < nCells; ++c) {
      const int begin = fluidCells_.cellBegin(c), end = fluidCells_.cellEnd(c);
      if (begin == end) continue;
      Vec<D> lo = set.x[order[begin]], hi = lo;
      for (int k = begin + 1; k < end; ++k)
        lo = lo.cwiseMin(set.x[order[k]]), hi = hi.cwiseMax(set.x[order[k]]);
      cellLo_[begin] = lo, cellHi_[begin] = hi;
    }
    const double beyond = near2 * (1.0 + 1e-9), within = near2 * (1.0 - 1e-9);
    std::vector<char> in(x_.size(), 0);
    const std::int64_t nWall = static_cast<std::int64_t>(x_.size());
#pragma omp parallel for schedule(static) if (nWall >= parallelFrom())
    for (std::int64_t w = 0; w < nWall; ++w) {
      const std::int64_t c = fluidCells_.cellOf(x_[w]);
      if (c < 0) continue;
      const Vec<D>& xw = x_[w];
      bool any = false;
      fluidCells_.forEachAdjacentRange(c, [&](int begin, int end) {
        if (any) return;
        double nearest2 = 0, farthest2 = 0;  // from x_w to the cell's box
        for (int a = 0; a < D; ++a) {
          const double below = cellLo_[begin][a] - xw[a], above = xw[a] - cellHi_[begin][a];
          const double gap = std::max({0.0, below, above}), span = std::max(-below, -above);
          nearest2 += gap * gap, farthest2 += span * span;
        }
        if (nearest2 > beyond) return;
        if (farthest2 < within) {
          any = true;
          return;
        }
        for (int k = begin; k < end && !any; ++k)
          any = (xw - set.x[order[k]]).squaredNorm() < near2;
      });
      in[w] = any;
    }
    for (std::int64_t w = 0; w < nWall; ++w)
      if (in[w]) members.push_back(w);
  }
  set.leftOut.count = x_.size() - members.size();
  set.leftOut.lo = lo_, set.leftOut.hi = hi_, set.leftOut.h = h_;
}

template <int D>
void FixedWalls<D>::append(InteractionSet<D>& set, double reach, HaloMembers members) const {
  const std::size_t base = set.haloEnd();
  // (a set these walls never chose for is chosen for, whatever `members` says)
  const bool chosenBefore = set.walls.size() + set.leftOut.count == x_.size();
  if (members == HaloMembers::rescan || !chosenBefore) choose(set, reach);
  const std::vector<std::int64_t>& chosen = set.walls;
  const std::int64_t nWall = static_cast<std::int64_t>(chosen.size());
  const bool listed = members == HaloMembers::same && chosenBefore &&
                      set.wallNeighboursAt.size() == chosen.size() + 1;
  set.resize(base + static_cast<std::size_t>(nWall));
  if (listed)
    sumListed(set, base);
  else
    sumAndList(set, base, reach);
}

template <int D>
void FixedWalls<D>::sumAndList(InteractionSet<D>& set, std::size_t base, double reach) const {
  const std::vector<std::int64_t>& chosen = set.walls;
  const std::int64_t nWall = static_cast<std::int64_t>(chosen.size());
  const double support = 2.0 * h_;  // lambda h, lambda = 2 for every kernel
  // The lists reach half the skin beyond the support: the skin is what `reach` holds beyond the
  // fluid's largest support (over several processes the whole domain's h_max, at least this
  // set's: a longer list, the same sums).
  double hMax = 0;
  for (std::size_t f = 0; f < base; ++f) hMax = std::max(hMax, set.h[f]);
  const double skin = std::max(0.0, reach - 2.0 * hMax);
  const double listed = support + 0.5 * skin;
  // Candidates farther than the list's reach by more than rounding are dropped in a vector pass
  // over a row; the survivors are listed, and take the test and the sums exactly as written, in
  // the cells' order.
  const double listed2 = std::isfinite(listed) ? listed * listed * (1.0 + 1e-9) : 1e300;
  // The fluid and its periodic images into cells of side `support`: a wall particle's neighbours
  // lie in the cells around its own.
  // (a fluid entry beyond the frame falls in its edge cell, out of every wall particle's reach)
  cells_.build(
      base, [&](std::size_t f, int a) { return set.x[f][a]; }, frame_.box, support, 4, base,
      typename CellList<D>::EvenLayers{}, &frame_);
  const auto& order = cells_.order();
  // The entries' coordinates in the cells' order, one array an axis, so that a row of cells is
  // one contiguous stretch for the distance test below.
  for (int a = 0; a < D; ++a) sorted_[a].resize(base);
  for (std::size_t k = 0; k < base; ++k)
    for (int a = 0; a < D; ++a) sorted_[a][k] = set.x[order[k]][a];
  std::array<const double*, D> sorted;
  for (int a = 0; a < D; ++a) sorted[a] = sorted_[a].data();
  std::vector<std::size_t>& at = set.wallNeighboursAt;
  at.assign(static_cast<std::size_t>(nWall) + 1, 0);
  const bool parallel = nWall >= parallelFrom();
  std::vector<std::size_t> threadBase(static_cast<std::size_t>(omp_get_max_threads()) + 1, 0);
#pragma omp parallel if (parallel)
  {
    std::vector<double> r2row;
    std::vector<int> inReach;
    std::vector<std::int32_t> mine;  // this thread's lists, its wall particles in order
    std::int64_t first = -1, last = -1;
    // The rows of the cells around the last wall particle's cell: wall particles come along
    // the walls, several to a cell, and the rows are the same for each of them.
    std::vector<std::pair<int, int>> rows;
    std::int64_t rowsOf = -2;
#pragma omp for schedule(static)
    for (std::int64_t q = 0; q < nWall; ++q) {
      if (first < 0) first = q;
      last = q;
      const Vec<D>& xw = x_[chosen[q]];
      // (the rows of forEachAdjacentRow hold forEachAdjacentRange's cells in its order)
      if (const std::int64_t c = cells_.cellOf(xw); c != rowsOf) {
        rows.clear(), rowsOf = c;
        if (c >= 0)
          cells_.forEachAdjacentRow(c, [&](int begin, int end) { rows.emplace_back(begin, end); });
      }
      for (const auto& [begin, end] : rows) {
        const int n = end - begin;
        if (r2row.size() < static_cast<std::size_t>(n)) r2row.resize(n), inReach.resize(n);
        double* r2 = r2row.data();
        for (int j = 0; j < n; ++j) {
          double s = 0;
          for (int a = 0; a < D; ++a) {
            const double d = xw[a] - sorted[a][begin + j];
            s += d * d;
          }
          r2[j] = s;
        }
        // The candidates within reach, in order, without a branch a candidate (most lie
        // outside it: a cube of cells around a sphere).
        int nNear = 0;
        for (int j = 0; j < n; ++j) inReach[nNear] = begin + j, nNear += r2[j] < listed2;
        for (int u = 0; u < nNear; ++u) mine.push_back(order[inReach[u]]);
      }
      at[q + 1] = mine.size();  // within this thread's lists, until they are placed
    }
    const int t = omp_get_thread_num();
    threadBase[t + 1] = mine.size();
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t k = 1; k < threadBase.size(); ++k) threadBase[k] += threadBase[k - 1];
      set.wallNeighbours.resize(threadBase.back());
    }
    if (first >= 0) {
      std::copy(mine.begin(), mine.end(), set.wallNeighbours.begin() + threadBase[t]);
      for (std::int64_t q = first; q <= last; ++q) at[q + 1] += threadBase[t];
    }
  }
  sumListed(set, base);
}

template <int D>
void FixedWalls<D>::sumListed(InteractionSet<D>& set, std::size_t base) const {
  const std::vector<std::int64_t>& chosen = set.walls;
  const std::int64_t nWall = static_cast<std::int64_t>(chosen.size());
  const double support = 2.0 * h_, support2 = support * support;
  const std::int32_t* neighbours = set.wallNeighbours.data();
  const std::size_t* at = set.wallNeighboursAt.data();
  const bool moving = !velocity_.empty(), ownVolumes = !volume_.empty();
  const int nPhases = static_cast<int>(phases_.size());
  const int* phaseOf = set.phase.data();
  // The kernel chosen once, outside the loops (kernelValue would switch on it at every pair).
  withKernel(kernel_, [&](auto kernel) {
    using Kernel = decltype(kernel);
#pragma omp parallel if (nWall >= parallelFrom())
    {
      std::vector<double> weightOf(static_cast<std::size_t>(nPhases));  // sum W_wf by phase
#pragma omp for schedule(static)
      for (std::int64_t q = 0; q < nWall; ++q) {
        const std::int64_t w = chosen[q];
        const Vec<D>& xw = x_[w];
        double sumW = 0, sumPW = 0;
        Vec<D> sumRhoRW = Vec<D>::Zero(), sumVW = Vec<D>::Zero();
        if (nPhases > 1) std::fill(weightOf.begin(), weightOf.end(), 0.0);
        for (std::size_t k = at[q]; k < at[q + 1]; ++k) {
          const int f = neighbours[k];
          const Vec<D> r_wf = xw - set.x[f];
          const double r2_wf = r_wf.squaredNorm();
          if (r2_wf >= support2) continue;  // W = 0 from r = 2 h on: no root needed
          const double W_wf = Kernel::template W<D>(std::sqrt(r2_wf), h_);
          sumW += W_wf, sumPW += set.p[f] * W_wf, sumRhoRW += set.rho[f] * W_wf * r_wf;
          if (moving) sumVW += W_wf * set.v[f];
          if (nPhases > 1) weightOf[phaseOf[f]] += W_wf;
        }
        // The phase that weighs most (the header); the first on a tie or with no fluid.
        int phase = 0;
        for (int k = 1; k < nPhases; ++k)
          if (weightOf[k] > weightOf[phase]) phase = k;
        const Phase& ph = phases_[phase];
        // Adami et al. (2012) eq. (27) with the wall at rest (a_w = 0); eq. (28) for the density.
        // Not below p0: see the header.
        const double p = sumW > 0 ? std::max((sumPW + g_.dot(sumRhoRW)) / sumW, ph.p0) : ph.p0;
        // p0 gives rho0 exactly ((p0 - p0) / K + 1 = 1): no root to take.
        const double rho = p == ph.p0 ? ph.rho0 : TaitEquationOfState::density(p, ph);
        Vec<D> v = Vec<D>::Zero();
        if (moving) {
          const WallVelocityRule<D>& rule = velocity_[w];
          if (!rule.atRest) {
            const Vec<D> smoothed = sumW > 0 ? Vec<D>(sumVW / sumW) : Vec<D>::Zero();  // eq. (22)
            for (int a = 0; a < D; ++a)  // eq. (23) along the reversed axes
              v[a] = rule.reversed[a] != 0 ? 2.0 * rule.wallVelocity[a] - smoothed[a] : smoothed[a];
          }
        }
        const std::size_t e = base + static_cast<std::size_t>(q);
        set.x[e] = xw, set.v[e] = v, set.rho[e] = rho, set.p[e] = p,
        set.m[e] = rho * (ownVolumes ? volume_[w] : V0_);
        set.h[e] = h_, set.mu[e] = ph.mu, set.rho0[e] = ph.rho0, set.phase[e] = phase;
        set.source[e] = -1;
      }
    }
  });
}

template class FixedWalls<1>;
template class FixedWalls<2>;
template class FixedWalls<3>;

}  // namespace sph
