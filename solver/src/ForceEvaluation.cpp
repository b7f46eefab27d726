#include "sph/ForceEvaluation.hpp"

#include <algorithm>

namespace sph {

template <int D>
struct ForceEvaluation<D>::Workspace {
  CellList<D> cells;
  // Cell-sorted copies of the interaction set, so that neighbours are read from contiguous memory.
  std::vector<Vec<D>> x, v;
  std::vector<double> rho, pOverRho2, m, h, mu;
};

namespace {

template <class Kernel, bool ArtificialViscosity, bool MorrisViscosity, bool VariableH, int D>
void pairLoop(const InteractionSet<D>& set, double beta,
              typename ForceEvaluation<D>::Workspace& w, Derivatives<D>& out) {
  const std::size_t n = set.size();
  double hMax = 0.0;
  for (double hk : set.h) hMax = std::max(hMax, hk);
  w.cells.build(set.x, Kernel::support * hMax);
  const auto& order = w.cells.order();
  w.x.resize(n), w.v.resize(n), w.rho.resize(n), w.pOverRho2.resize(n), w.m.resize(n), w.h.resize(n);
  if constexpr (MorrisViscosity) w.mu.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const int s = order[k];
    w.x[k] = set.x[s], w.v[k] = set.v[s], w.rho[k] = set.rho[s], w.m[k] = set.m[s], w.h[k] = set.h[s];
    w.pOverRho2[k] = set.p[s] / (set.rho[s] * set.rho[s]);
    if constexpr (MorrisViscosity) w.mu[k] = set.mu[s];
  }
  out.resize(set.nFluid);
  const int nFluid = static_cast<int>(set.nFluid);
  const std::int64_t nCells = w.cells.cells();

#pragma omp parallel for schedule(dynamic, 32)
  for (std::int64_t c = 0; c < nCells; ++c) {
    for (int i = w.cells.cellBegin(c); i < w.cells.cellEnd(c); ++i) {
      if (order[i] >= nFluid) continue;  // halo entries receive no rates
      const Vec<D> xi = w.x[i], vi = w.v[i];
      const double hi = w.h[i], rhoi = w.rho[i], pri = w.pOverRho2[i];
      Vec<D> dv = Vec<D>::Zero();
      double drho = 0.0, dh = 0.0;
      w.cells.forEachAdjacentRange(c, [&](int begin, int end) {
        for (int j = begin; j < end; ++j) {
          const Vec<D> rij = xi - w.x[j];
          const double r2 = rij.squaredNorm();
          const double hij = 0.5 * (hi + w.h[j]);
          const double reach = Kernel::support * hij;
          if (r2 >= reach * reach || j == i) continue;
          const double r = std::sqrt(r2);
          const double dWdr = Kernel::template dWdr<D>(r, hij);
          const Vec<D> gradW = rij * (r > 0.0 ? dWdr / r : 0.0);  // grad_i W_ij
          const Vec<D> vij = vi - w.v[j];
          const double mj = w.m[j];
          const double vDotGradW = vij.dot(gradW);
          drho += mj * vDotGradW;                                           // eq. (11)
          if constexpr (VariableH) dh += mj / w.rho[j] * vDotGradW;        // eq. (13)
          double pressureTerm = pri + w.pOverRho2[j];                       // eq. (12)
          const double eta2 = 0.01 * hij * hij;  // anti-crossing eta^2 = 0.01 h_ij^2 (DESIGN.md 1)
          if constexpr (ArtificialViscosity) {
            const double vr = vij.dot(rij);
            if (vr < 0.0) {  // eq. (10): approaching pairs only
              const double hSum = hi + w.h[j];
              const double muij = vr / (r2 + eta2);
              pressureTerm += 0.5 * beta * hSum * hSum / (rhoi + w.rho[j]) * muij * muij;
            }
          }
          dv -= mj * pressureTerm * gradW;
          if constexpr (MorrisViscosity) {  // eq. (9); r_ij . grad_i W_ij = r dW/dr
            dv += (mj * (w.mu[i] + w.mu[j]) / (rhoi * w.rho[j]) * (r * dWdr) / (r2 + eta2)) * vij;
          }
        }
      });
      const int dst = order[i];
      out.drhodt[dst] = drho;
      out.dvdt[dst] = dv;
      out.dhdt[dst] = VariableH ? hi / D * dh : 0.0;
    }
  }
}

// The menu: every kernel with every combination of the three optional terms.
template <int D, class Kernel>
auto chooseLoop(TermSwitches t) {
  using W = typename ForceEvaluation<D>::Workspace;
  using Fn = void (*)(const InteractionSet<D>&, double, W&, Derivatives<D>&);
  constexpr Fn table[8] = {
      &pairLoop<Kernel, false, false, false, D>, &pairLoop<Kernel, true, false, false, D>,
      &pairLoop<Kernel, false, true, false, D>,  &pairLoop<Kernel, true, true, false, D>,
      &pairLoop<Kernel, false, false, true, D>,  &pairLoop<Kernel, true, false, true, D>,
      &pairLoop<Kernel, false, true, true, D>,   &pairLoop<Kernel, true, true, true, D>};
  return table[int(t.artificialViscosity) + 2 * int(t.morrisViscosity) + 4 * int(t.variableH)];
}

}  // namespace

template <int D>
ForceEvaluation<D>::ForceEvaluation(KernelKind kernel, TermSwitches terms, double beta)
    : kernel_(kernel), terms_(terms), beta_(beta), work_(std::make_shared<Workspace>()) {
  loop_ = withKernel(kernel, [&](auto k) { return chooseLoop<D, decltype(k)>(terms); });
}

template <int D>
void ForceEvaluation<D>::operator()(const InteractionSet<D>& set, Derivatives<D>& out) {
  loop_(set, beta_, *work_, out);
}

template <int D>
std::vector<std::string> ForceEvaluation<D>::termNames() const {
  std::vector<std::string> names{"continuity", "pressure_gradient"};
  if (terms_.artificialViscosity) names.push_back("artificial_viscosity");
  if (terms_.morrisViscosity) names.push_back("morris_viscosity");
  if (terms_.variableH) names.push_back("variable_h");
  return names;
}

template class ForceEvaluation<1>;
template class ForceEvaluation<2>;
template class ForceEvaluation<3>;

}  // namespace sph
