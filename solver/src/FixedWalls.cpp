#include "sph/FixedWalls.hpp"

#include <algorithm>
#include <cmath>

namespace sph {

FixedWalls::FixedWalls(std::vector<Vec<2>> position, double V0, double h, KernelKind kernel,
                       const Phase& phase, const Vec<2>& g)
    : x_(std::move(position)), V0_(V0), h_(h), kernel_(kernel), phase_(phase), g_(g) {}

void FixedWalls::append(InteractionSet<2>& set) const {
  const int nFluid = static_cast<int>(set.nFluid);
  const int nWall = static_cast<int>(x_.size());
  const double reach = 2.0 * h_;  // lambda h, lambda = 2 for every kernel here
  // Fluid entries into cells of side `reach`: a wall particle's neighbours lie in the cells
  // around its own.
  cells_.build(
      nFluid, [&](std::size_t f, int a) { return set.x[f][a]; }, reach);
  const auto& order = cells_.order();

  p_.resize(nWall), rho_.resize(nWall);
#pragma omp parallel for schedule(static)
  for (int w = 0; w < nWall; ++w) {
    const Vec<2>& xw = x_[w];
    double sumW = 0, sumPW = 0;
    Vec<2> sumRhoRW = Vec<2>::Zero();
    if (const std::int64_t c = cells_.cellOf(xw); c >= 0)
      cells_.forEachAdjacentRange(c, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) {
          const int f = order[k];
          const Vec<2> r_wf = xw - set.x[f];
          const double r = r_wf.norm();
          if (r >= reach) continue;
          const double W_wf = kernelValue<2>(kernel_, r, h_);
          sumW += W_wf, sumPW += set.p[f] * W_wf, sumRhoRW += set.rho[f] * W_wf * r_wf;
        }
      });
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
