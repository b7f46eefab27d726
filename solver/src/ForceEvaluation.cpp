#include "sph/ForceEvaluation.hpp"

#include <omp.h>

#include <algorithm>
#include <array>

namespace sph {

// How the loop is laid out (issue 7):
// * The interaction set is copied, cell-sorted, into one array per scalar field (structure of
//   arrays), with the per-particle factors of the pair sums precomputed (p/rho^2, 1/rho, m/rho).
// * For each fluid particle the candidates in its 3^(D-1) cell rows (CellList::forEachAdjacentRow)
//   are swept in order; those within reach are packed (index and r_ij) into a per-thread buffer,
//   and a second loop over the packed pairs evaluates the terms. That loop has no branch (the
//   approaching-pair test of eq. 10 is a select) and is vectorised with `omp simd`, whose lane
//   split is fixed at compile time: each particle's rates are its own neighbours' sum in a fixed
//   order, whatever the thread count, and no thread writes another particle's rates (no atomics).
// * All arrays live in the workspace and only grow: no allocation per step.
template <int D>
struct ForceEvaluation<D>::Workspace {
  CellList<D> cells;
  // Cell-sorted copies: x[a][k], v[a][k] for axis a, sorted position k.
  std::array<std::vector<double>, D> x, v;
  std::vector<double> h, rho, rhoInv, pOverRho2, m, mOverRho, mu;
  std::vector<int> fluid;     // sorted positions of the fluid entries (those that receive rates)
  struct alignas(64) Pairs {  // one thread's packed neighbours of its current particle
    std::vector<int> j;
    std::array<std::vector<double>, D> r;
    std::vector<double> r2;
    void reserve(std::size_t n) {
      if (j.size() >= n) return;
      j.resize(n), r2.resize(n);
      for (auto& c : r) c.resize(n);
    }
  };
  std::vector<Pairs> pairs;
};

namespace {

template <class Kernel, bool ArtificialViscosity, bool MorrisViscosity, bool VariableH, int D>
void pairLoop(const InteractionSet<D>& set, double beta, typename ForceEvaluation<D>::Workspace& w,
              Derivatives<D>& out) {
  const std::size_t n = set.size();
  double hMax = 0.0;
  for (double hk : set.h) hMax = std::max(hMax, hk);
  w.cells.build(
      n, [&](std::size_t i, int a) { return set.x[i][a]; }, Kernel::support * hMax);
  const auto& order = w.cells.order();
  for (int a = 0; a < D; ++a) w.x[a].resize(n), w.v[a].resize(n);
  w.h.resize(n), w.rho.resize(n), w.pOverRho2.resize(n), w.m.resize(n);
  if constexpr (MorrisViscosity) w.mu.resize(n), w.rhoInv.resize(n);
  if constexpr (VariableH) w.mOverRho.resize(n);
  const int nFluid = static_cast<int>(set.nFluid);
  w.fluid.clear();
  for (std::size_t k = 0; k < n; ++k)
    if (order[k] < nFluid) w.fluid.push_back(static_cast<int>(k));
  out.resize(set.nFluid);

  const int nThreads = omp_get_max_threads();
  if (static_cast<int>(w.pairs.size()) < nThreads) w.pairs.resize(nThreads);
  const std::int64_t nSorted = static_cast<std::int64_t>(n);
  const std::int64_t nWork = static_cast<std::int64_t>(w.fluid.size());

#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (std::int64_t k = 0; k < nSorted; ++k) {
      const int s = order[k];
      for (int a = 0; a < D; ++a) w.x[a][k] = set.x[s][a], w.v[a][k] = set.v[s][a];
      const double rho = set.rho[s];
      w.rho[k] = rho, w.m[k] = set.m[s], w.h[k] = set.h[s];
      w.pOverRho2[k] = set.p[s] / (rho * rho);
      if constexpr (MorrisViscosity) w.mu[k] = set.mu[s], w.rhoInv[k] = 1.0 / rho;
      if constexpr (VariableH) w.mOverRho[k] = set.m[s] / rho;
    }
    auto& buf = w.pairs[omp_get_thread_num()];
    const double* xs[D];
    const double* vs[D];
    for (int a = 0; a < D; ++a) xs[a] = w.x[a].data(), vs[a] = w.v[a].data();
    const double *hs = w.h.data(), *rhos = w.rho.data(), *prs = w.pOverRho2.data(),
                 *ms = w.m.data(), *mus = w.mu.data(), *rhoInvs = w.rhoInv.data(),
                 *mOverRhos = w.mOverRho.data();
    constexpr double reachFactor2 = 0.25 * Kernel::support * Kernel::support;

#pragma omp for schedule(dynamic, 64)
    for (std::int64_t f = 0; f < nWork; ++f) {
      const int i = w.fluid[f];
      std::array<double, D> xi, vi;
      for (int a = 0; a < D; ++a) xi[a] = xs[a][i], vi[a] = vs[a][i];
      const double hi = hs[i], rhoi = rhos[i], pri = prs[i];

      // Pass 1: pack the neighbours (0 < r_ij < support h_ij, h_ij = (h_i + h_j)/2) in sorted
      // order.
      int count = 0;
      w.cells.forEachAdjacentRow(w.cells.sortedCell(i), [&](int begin, int end) {
        buf.reserve(static_cast<std::size_t>(count + end - begin));
        int* bj = buf.j.data();
        double* br2 = buf.r2.data();
        double* br[D];
        for (int a = 0; a < D; ++a) br[a] = buf.r[a].data();
        for (int j = begin; j < end; ++j) {
          double r2 = 0.0;
          std::array<double, D> rij;
          for (int a = 0; a < D; ++a) rij[a] = xi[a] - xs[a][j], r2 += rij[a] * rij[a];
          const double hSum = hi + hs[j];
          bj[count] = j, br2[count] = r2;
          for (int a = 0; a < D; ++a) br[a][count] = rij[a];
          // r2 > 0 drops the particle itself; a distinct particle at r = 0 adds nothing to any
          // term.
          count += (r2 < reachFactor2 * hSum * hSum) & (r2 > 0.0);
        }
      });

      // Pass 2: the terms, over the packed pairs.
      const int* bj = buf.j.data();
      const double* br2 = buf.r2.data();
      const double* br[D];
      for (int a = 0; a < D; ++a) br[a] = buf.r[a].data();
      double drho = 0.0, dh = 0.0, dv0 = 0.0, dv1 = 0.0, dv2 = 0.0;
      const double mui = MorrisViscosity ? mus[i] : 0.0;
      const double rhoInvi = MorrisViscosity ? rhoInvs[i] : 0.0;
#pragma omp simd reduction(+ : drho, dh, dv0, dv1, dv2)
      for (int k = 0; k < count; ++k) {
        const int j = bj[k];
        const double r2 = br2[k];
        const double hSum = hi + hs[j];
        const double hInv = 2.0 / hSum;                            // 1 / h_ij
        const double F = Kernel::template gradOverR<D>(r2, hInv);  // grad_i W_ij = F r_ij
        std::array<double, D> vij;
        double vr = 0.0;  // v_ij . r_ij
        for (int a = 0; a < D; ++a) vij[a] = vi[a] - vs[a][j], vr += vij[a] * br[a][k];
        const double mj = ms[j];
        const double vDotGradW = vr * F;
        drho += mj * vDotGradW;                                   // eq. (11)
        if constexpr (VariableH) dh += mOverRhos[j] * vDotGradW;  // eq. (13)
        double pressureTerm = pri + prs[j];                       // eq. (12)
        // Anti-crossing eta^2 = 0.01 h_ij^2 (DESIGN.md 1), h_ij^2 = hSum^2 / 4.
        const double rEta2Inv = 1.0 / (r2 + 0.0025 * hSum * hSum);
        if constexpr (ArtificialViscosity) {  // eq. (10), approaching pairs only (a select)
          const double muij = vr * rEta2Inv;
          const double pi = 0.5 * beta * hSum * hSum / (rhoi + rhos[j]) * muij * muij;
          pressureTerm += vr < 0.0 ? pi : 0.0;
        }
        const double cr = -mj * pressureTerm * F;  // coefficient of r_ij
        double cv = 0.0;                           // coefficient of v_ij
        if constexpr (MorrisViscosity)             // eq. (9); r_ij . grad_i W_ij = F r^2
          cv = mj * (mui + mus[j]) * (rhoInvi * rhoInvs[j]) * (F * r2) * rEta2Inv;
        dv0 += cr * br[0][k] + cv * vij[0];
        if constexpr (D > 1) dv1 += cr * br[1][k] + cv * vij[1];
        if constexpr (D > 2) dv2 += cr * br[2][k] + cv * vij[2];
      }
      const int dst = order[i];
      out.drhodt[dst] = drho;
      out.dvdt[dst][0] = dv0;
      if constexpr (D > 1) out.dvdt[dst][1] = dv1;
      if constexpr (D > 2) out.dvdt[dst][2] = dv2;
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
