#include "sph/FixedWalls.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sph {

FixedWalls::FixedWalls(std::vector<Vec<2>> position, double V0, double h, KernelKind kernel,
                       const Phase& phase, const Vec<2>& g)
    : x_(std::move(position)), V0_(V0), h_(h), kernel_(kernel), phase_(phase), g_(g) {}

void FixedWalls::append(InteractionSet<2>& set) const {
  const int nFluid = static_cast<int>(set.nFluid);
  const int nWall = static_cast<int>(x_.size());
  const double reach = 2.0 * h_;  // lambda h, lambda = 2 for every kernel here
  // Fluid entries into cells of side `reach`: a wall particle's neighbours lie in its 3 x 3 block.
  Vec<2> lo = Vec<2>::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (int f = 0; f < nFluid; ++f) lo = lo.cwiseMin(set.x[f]), hi = hi.cwiseMax(set.x[f]);
  const int nx = nFluid ? static_cast<int>((hi.x() - lo.x()) / reach) + 1 : 1;
  const int ny = nFluid ? static_cast<int>((hi.y() - lo.y()) / reach) + 1 : 1;
  auto cellOf = [&](const Vec<2>& r, int& cx, int& cy) {
    cx = static_cast<int>(std::floor((r.x() - lo.x()) / reach));
    cy = static_cast<int>(std::floor((r.y() - lo.y()) / reach));
  };
  cellStart_.assign(static_cast<std::size_t>(nx) * ny + 1, 0);
  cellEntries_.resize(nFluid);
  for (int f = 0; f < nFluid; ++f) {
    int cx, cy;
    cellOf(set.x[f], cx, cy);
    ++cellStart_[cy * nx + cx + 1];
  }
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (int f = 0; f < nFluid; ++f) {
    int cx, cy;
    cellOf(set.x[f], cx, cy);
    cellEntries_[fill[cy * nx + cx]++] = f;
  }

  p_.resize(nWall), rho_.resize(nWall);
#pragma omp parallel for schedule(static)
  for (int w = 0; w < nWall; ++w) {
    const Vec<2>& xw = x_[w];
    int cx, cy;
    cellOf(xw, cx, cy);
    double sumW = 0, sumPW = 0;
    Vec<2> sumRhoRW = Vec<2>::Zero();
    for (int jy = std::max(cy - 1, 0); jy <= std::min(cy + 1, ny - 1); ++jy)
      for (int jx = std::max(cx - 1, 0); jx <= std::min(cx + 1, nx - 1); ++jx)
        for (int k = cellStart_[jy * nx + jx]; k < cellStart_[jy * nx + jx + 1]; ++k) {
          const int f = cellEntries_[k];
          const Vec<2> r_wf = xw - set.x[f];
          const double r = r_wf.norm();
          if (r >= reach) continue;
          const double W_wf = kernelValue<2>(kernel_, r, h_);
          sumW += W_wf, sumPW += set.p[f] * W_wf, sumRhoRW += set.rho[f] * W_wf * r_wf;
        }
    // Adami et al. (2012) eq. (27) with the wall at rest (a_w = 0); eq. (28) for the density.
    // Not below p0: see the header.
    const double p = sumW > 0 ? std::max((sumPW + g_.dot(sumRhoRW)) / sumW, phase_.p0) : phase_.p0;
    p_[w] = p;
    rho_[w] = TaitEquationOfState::density(p, phase_);
  }
  for (int w = 0; w < nWall; ++w) {
    set.x.push_back(x_[w]), set.v.push_back(Vec<2>::Zero());
    set.rho.push_back(rho_[w]), set.p.push_back(p_[w]), set.m.push_back(rho_[w] * V0_);
    set.h.push_back(h_), set.mu.push_back(phase_.mu), set.source.push_back(-1);
  }
}

}  // namespace sph
