#include "sph/ParticleShifting.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sph/CellList.hpp"
#include "sph/Parallel.hpp"

namespace sph {

template <int D>
struct ParticleShifting<D>::Cells {
  CellList<D> list;
};

template <int D>
ParticleShifting<D>::ParticleShifting(KernelKind kernel, const ShiftingParameters& p, double dx)
    : kernel_(kernel), p_(p), dx_(dx), cells_(std::make_unique<Cells>()) {
  if (p_.form == ShiftingForm::none)
    throw std::invalid_argument("ParticleShifting: no shifting form chosen");
  if (!(dx > 0) || !(p_.coefficient > 0))
    throw std::invalid_argument("ParticleShifting: dx and the coefficient must be positive");
  if (p_.surfaceThreshold <= 0) p_.surfaceThreshold = defaultSurfaceThreshold(D);
}

template <int D>
ParticleShifting<D>::~ParticleShifting() = default;

template <int D>
void ParticleShifting<D>::start(const InteractionSet<D>& set, LineVector<Vec<D>>& shift) {
  const std::size_t nf = set.nFluid;
  shift.assign(nf, Vec<D>::Zero());
  gradC_.assign(nf, Vec<D>::Zero()), g_.assign(nf, Vec<D>::Zero()), divR_.assign(nf, 0.0);
  surface_.assign(nf, 0), near_.assign(nf, 0);
}

template <int D>
void ParticleShifting<D>::operator()(const InteractionSet<D>& set, double dt,
                                     const Derivatives<D>& sums, const ForceEvaluation<D>& forces,
                                     LineVector<Vec<D>>& shift) {
  using Term = terms::ConcentrationGradient;
  constexpr int width = Term::sums<D>;
  const std::size_t nf = set.nFluid;
  if (sums.sumsWidth != width || sums.sums.size() != width * nf)
    throw std::logic_error("ParticleShifting: the evaluation has no concentration gradient");
  // Every field is written below.
  shift.resize(nf), gradC_.resize(nf), g_.resize(nf), divR_.resize(nf), surface_.resize(nf);
  near_.assign(nf, 0);
  if (nf == 0) return;
  const double* s = sums.sums.data();
  const double threshold = p_.surfaceThreshold;
  Vec<D>*gradC = gradC_.data(), *g = g_.data();
  double* divR = divR_.data();
  char* surface = surface_.data();
  forEachInShares(static_cast<std::int64_t>(nf), [=](std::int64_t i) {
    const double* si = s + width * i;
    for (int a = 0; a < D; ++a)
      gradC[i][a] = si[Term::gradCAt + a], g[i][a] = si[Term::normalAt<D> + a];
    divR[i] = si[Term::divRAt<D>];
    surface[i] = divR[i] < threshold;
  });
  if (p_.freeSurface) {
    near_ = surface_;
    forces.markWithinSupport(set, surface_.data(), near_.data());
  }
  shiftsFrom(set, dt, shift);
}

template <int D>
void ParticleShifting<D>::operator()(const InteractionSet<D>& set, double dt,
                                     LineVector<Vec<D>>& shift) {
  const std::int64_t nf = static_cast<std::int64_t>(set.nFluid);
  const std::size_t haloEnd = set.haloEnd();
  start(set, shift);
  if (nf == 0) return;
  double hMax = 0.0;
  for (const double h : set.h) hMax = std::max(hMax, h);
  volume_.resize(set.size());
  for (std::size_t j = 0; j < set.size(); ++j) volume_[j] = set.m[j] / set.rho[j];
  CellList<D>& cells = cells_->list;
  const auto& order = cells.order();
  const double R = ShiftingParameters::anticlumpingR, dx = dx_;
  // A pass costs some 300 ns a particle (the dam break at dx 0.01, one thread), against the few ns
  // of the loops parallelFrom() is for: from 512 particles it outweighs a parallel region's wake
  // (20 us with idle threads asleep, Parallel.hpp) seven times.
  const bool parallel = nf >= 512;

  withKernel(kernel_, [&](auto kernel) {
    using K = decltype(kernel);
    // Cells of half the reach: a particle's neighbours lie in the 5^(D-1) rows of 5 cells
    // around it (CellList::forEachAdjacentRow<2>), a tighter box around the support than 3^D
    // cells of the whole reach.
    cells.build(set.x, 0.5 * K::support * hMax);
    const std::int64_t ncells = cells.cells();
    // Calls f(j, r_ij, r^2, h_ij) for each entry j inside the support of fluid entry i (cell c).
    auto neighbours = [&](std::int64_t c, int i, auto&& f) {
      const Vec<D> xi = set.x[i];
      const double hi = set.h[i];
      cells.template forEachAdjacentRow<2>(c, [&](int begin, int end) {
        for (int kk = begin; kk < end; ++kk) {
          const int j = order[kk];
          const Vec<D> r = xi - set.x[j];
          const double r2 = r.squaredNorm(), hij = 0.5 * (hi + set.h[j]);
          const double reach = K::support * hij;
          // r2 > 0: a distinct particle at r = 0 adds nothing (as in the pair loop).
          if (j != i && r2 > 0.0 && r2 < reach * reach) f(j, r, r2, hij);
        }
      });
    };
    // The sums of grad C, g and div r (header), the threads taking equal runs of the sorted
    // entries (not of the cells: a free-surface flow fills a part of its box).
    const std::int64_t entries = static_cast<std::int64_t>(set.size());
#pragma omp parallel for schedule(static) if (parallel)
    for (std::int64_t k = 0; k < entries; ++k) {
      const int i = order[k];
      const std::int64_t c = cells.sortedCell(static_cast<int>(k));
      if (i >= nf) continue;
      Vec<D> gradC = Vec<D>::Zero(), g = Vec<D>::Zero();
      double divR = 0.0;
      neighbours(c, i, [&](int j, const Vec<D>& r, double r2, double hij) {
        const double dist = std::sqrt(r2), hInv = 1.0 / hij;
        // grad_i W_ij = F r_ij (the pair loop's form: no division beyond 1/r and 1/h_ij)
        const double F = K::template gradOverR<D>(dist, 1.0 / dist, hInv);
        const double V = volume_[j];
        // W_ij / W(dx) at h_ij = the kernel's shape at q over its shape at dx / h_ij
        const double w = K::template W<D>(dist * hInv, 1.0) / K::template W<D>(dx * hInv, 1.0);
        const double w2 = w * w;
        g += (V * F) * r;
        gradC += (V * F * (1.0 + R * (w2 * w2))) * r;
        divR -= V * F * r2;
      });
      gradC_[i] = gradC, g_[i] = g, divR_[i] = divR;
      surface_[i] = divR < p_.surfaceThreshold;
    }
    if (!p_.freeSurface) return;
    // Near the surface: inside the support of a surface particle (the support is symmetric in i
    // and j), marked from the surface particles, which are few; a fluid entry's own, an image's
    // or ghost's for its source (wall particles are never on the surface).
    near_ = surface_;
    for (std::int64_t c = 0; c < ncells; ++c)
      for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
        const int i = order[k];
        if (i >= nf || !surface_[i]) continue;
        neighbours(c, i, [&](int j, const Vec<D>&, double, double) {
          const std::size_t u = static_cast<std::size_t>(j);
          if (u < static_cast<std::size_t>(nf))
            near_[j] = 1;
          else if (u < haloEnd)
            near_[set.source[j]] = 1;
        });
      }
  });
  shiftsFrom(set, dt, shift);
}

template <int D>
void ParticleShifting<D>::shiftsFrom(const InteractionSet<D>& set, double dt,
                                     LineVector<Vec<D>>& shift) {
  const std::int64_t nf = static_cast<std::int64_t>(set.nFluid);
  double uMax = 0.0;
  if (p_.form == ShiftingForm::delta_plus)
    for (std::int64_t i = 0; i < nf; ++i) uMax = std::max(uMax, set.v[i].norm());
  const double A = p_.coefficient;
  forEachInShares(nf, [&](std::int64_t i) {
    const double U = p_.form == ShiftingForm::delta_plus ? uMax : set.v[i].norm();
    Vec<D> dr = -(A * set.h[i] * U * dt) * gradC_[i];
    if (p_.freeSurface && near_[i]) {
      const double gNorm = g_[i].norm();
      if (gNorm > 0) {
        const Vec<D> n = -g_[i] / gNorm;
        dr -= dr.dot(n) * n;
      } else {
        dr.setZero();
      }
    }
    shift[i] = dr;
  });
}

template class ParticleShifting<1>;
template class ParticleShifting<2>;
template class ParticleShifting<3>;

}  // namespace sph
