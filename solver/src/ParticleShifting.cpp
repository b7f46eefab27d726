#include "sph/ParticleShifting.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sph/CellList.hpp"

namespace sph {

std::string_view name(ShiftingForm f) {
  switch (f) {
    case ShiftingForm::none:
      return "none";
    case ShiftingForm::lind:
      return "lind";
    case ShiftingForm::delta_plus:
      return "delta_plus";
  }
  // No default: -Wswitch names an enumerator missing above; any other value is a bug.
  throw std::logic_error("name(ShiftingForm): unknown value " +
                         std::to_string(static_cast<int>(f)));
}

double defaultShiftingCoefficient(ShiftingForm f) {
  return f == ShiftingForm::delta_plus ? 4.0 : 2.0;
}

double defaultSurfaceThreshold(int dimension) {
  return dimension == 1 ? 0.75 : dimension == 2 ? 1.5 : 2.75;
}

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
void ParticleShifting<D>::operator()(const InteractionSet<D>& set, double dt,
                                     LineVector<Vec<D>>& shift) {
  const std::int64_t nf = static_cast<std::int64_t>(set.nFluid);
  const std::size_t haloEnd = set.haloEnd();
  shift.assign(nf, Vec<D>::Zero());
  gradC_.assign(nf, Vec<D>::Zero()), g_.assign(nf, Vec<D>::Zero()), divR_.assign(nf, 0.0);
  surface_.assign(nf, 0), near_.assign(nf, 0);
  if (nf == 0) return;
  double hMax = 0.0;
  for (const double h : set.h) hMax = std::max(hMax, h);
  CellList<D>& cells = cells_->list;
  const auto& order = cells.order();
  const double R = ShiftingParameters::anticlumpingR, dx = dx_;
  const bool parallel = nf >= parallelFrom();

  withKernel(kernel_, [&](auto kernel) {
    using K = decltype(kernel);
    cells.build(set.x, K::support * hMax);
    const std::int64_t ncells = cells.cells();
    // Calls f(j, r_ij, r^2, h_ij) for each entry j inside the support of fluid entry i (cell c).
    auto neighbours = [&](std::int64_t c, int i, auto&& f) {
      const Vec<D> xi = set.x[i];
      const double hi = set.h[i];
      cells.forEachAdjacentRange(c, [&](int begin, int end) {
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
    // The sums of grad C, g and div r (header).
#pragma omp parallel for schedule(static) if (parallel)
    for (std::int64_t c = 0; c < ncells; ++c)
      for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
        const int i = order[k];
        if (i >= nf) continue;
        Vec<D> gradC = Vec<D>::Zero(), g = Vec<D>::Zero();
        double divR = 0.0;
        neighbours(c, i, [&](int j, const Vec<D>& r, double r2, double hij) {
          const double dist = std::sqrt(r2);
          const double F = K::template dWdr<D>(dist, hij) / dist;  // grad_i W_ij = F r_ij
          const double V = set.m[j] / set.rho[j];
          const double w = K::template W<D>(dist, hij) / K::template W<D>(dx, hij);
          const double w2 = w * w;
          g += (V * F) * r;
          gradC += (V * F * (1.0 + R * (w2 * w2))) * r;
          divR -= V * F * r2;
        });
        gradC_[i] = gradC, g_[i] = g, divR_[i] = divR;
        surface_[i] = divR < p_.surfaceThreshold;
      }
    if (!p_.freeSurface) return;
      // Near the surface: a surface particle inside the support (an image or ghost stands for
      // its source; wall particles are never on it).
#pragma omp parallel for schedule(static) if (parallel)
    for (std::int64_t c = 0; c < ncells; ++c)
      for (int k = cells.cellBegin(c); k < cells.cellEnd(c); ++k) {
        const int i = order[k];
        if (i >= nf) continue;
        bool near = surface_[i] != 0;
        if (!near)
          neighbours(c, i, [&](int j, const Vec<D>&, double, double) {
            const std::size_t u = static_cast<std::size_t>(j);
            if (u < static_cast<std::size_t>(nf))
              near = near || surface_[j];
            else if (u < haloEnd)
              near = near || surface_[set.source[j]];
          });
        near_[i] = near;
      }
  });

  double uMax = 0.0;
  if (p_.form == ShiftingForm::delta_plus)
    for (std::int64_t i = 0; i < nf; ++i) uMax = std::max(uMax, set.v[i].norm());
  const double A = p_.coefficient;
  for (std::int64_t i = 0; i < nf; ++i) {
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
  }
}

template class ParticleShifting<1>;
template class ParticleShifting<2>;
template class ParticleShifting<3>;

}  // namespace sph
