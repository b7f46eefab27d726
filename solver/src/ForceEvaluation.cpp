#if defined(__GNUC__) && !defined(__clang__)
// The pair loop's vector helpers (PairLoop.hpp) and the kernels' instantiations for vectors
// (Kernels.hpp; only the pair loop's files make them) pass no vector across a boundary compiled
// elsewhere: the note GCC gives on the ABI of 32-byte vectors in an x86-64-v2 build does not
// concern them. Before the includes, since GCC checks it where the headers define them.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
#include "sph/ForceEvaluation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "PairLoopMenu.hpp"

namespace sph {

namespace {

template <unsigned... Mask>
std::vector<std::string> namesOf(unsigned index, std::integer_sequence<unsigned, Mask...>) {
  std::vector<std::string> names;
  ((Mask == index ? void(names = terms::MenuEntry<Mask>::names()) : void()), ...);
  return names;
}

template <unsigned... Mask>
terms::Flops flopsOf(unsigned index, std::integer_sequence<unsigned, Mask...>) {
  terms::Flops flops;
  ((Mask == index ? void(flops = terms::MenuEntry<Mask>::flops) : void()), ...);
  return flops;
}

// Bit k: the k-th optional term of terms::OptionalTerms.
unsigned optionalBits(TermSwitches t) {
  return unsigned(t.artificialViscosity) | unsigned(t.morrisViscosity) << 1 |
         unsigned(t.variableH) << 2;
}

}  // namespace

terms::Flops pairFlops(TermSwitches t) {
  return flopsOf(menuIndex(t), std::make_integer_sequence<unsigned, terms::menuSize>{});
}

unsigned menuIndex(TermSwitches t) {
  const unsigned optional = optionalBits(t);
  const auto form = static_cast<unsigned>(t.densityDiffusion);
  if (form > terms::DensityDiffusionForms::size)
    throw std::invalid_argument("menuIndex: density diffusion form " + std::to_string(form) +
                                " is not one of the menu's");
  if (!t.concentrationGradient) return optional + terms::optionalSubsets * form;
  if (optional != terms::shiftingSubset)
    throw std::invalid_argument(
        "menuIndex: the concentration gradient is on the menu with every optional term only");
  return terms::ratesEntries + form;
}

bool onMenu(TermSwitches t) {
  return !t.concentrationGradient || optionalBits(t) == terms::shiftingSubset;
}

template <int D>
ForceEvaluation<D>::ForceEvaluation(KernelKind kernel, TermSwitches terms, double beta)
    : ForceEvaluation(kernel, terms, terms::TermParameters{.beta = beta}) {}

template <int D>
ForceEvaluation<D>::ForceEvaluation(KernelKind kernel, TermSwitches terms,
                                    const terms::TermParameters& parameters)
    : kernel_(kernel),
      terms_(terms),
      parameters_(parameters),
      work_(std::make_shared<Workspace>()) {
  static_assert(terms::optionalSubsets == 8 && terms::DensityDiffusionForms::size == 4,
                "menuIndex covers every optional term and every form");
  TermSwitches rates = terms;
  rates.concentrationGradient = false;
  loop_ = pair_loop::menuLoop<D>(kernel, menuIndex(rates));
  ownSumsLoop_ = pair_loop::menuLoop<D>(kernel, menuIndex(terms));  // throws off the menu
  if (terms.densityDiffusion == DensityDiffusion::antuono)
    gradientLoop_ = pair_loop::densityGradientLoop<D>(kernel);
}

template <int D>
void ForceEvaluation<D>::operator()(const InteractionSet<D>& set, Derivatives<D>& out,
                                    const Vec<D>& g, NeighbourLists lists, bool ownSums) {
  if (gradientLoop_) densityGradients(set, lists);
  (ownSums ? ownSumsLoop_ : loop_)(parameters_, set, g, lists, *work_, out);
}

// Every entry's renormalised density gradient, into the workspace, where the pair loop's copy of
// the entries reads it: the fluid's from its pair sums, a halo entry's its source's (a periodic
// image's is its source's; a hydrostatic mirror ghost's density continues its source's field
// across the wall, terms/DensityDiffusionAntuono.hpp). A wall particle (Adami et al. 2012) stands
// for no fluid particle: its pressure is the fluid's extrapolated along the gradient rho g of a
// fluid at rest against a wall at rest (eq. 27, FixedWalls), so its density's gradient is that
// one's, rho g / c^2 with c^2 = dp/drho of eq. (8), and nil where eq. (27) gave the floor p0
// (there rho = rho0 exactly). The pass builds the neighbour lists where the rates' pass would,
// which then reuses them: lists asked for without a skin get one of a millionth of the support,
// so that they are kept for that one reuse (the pairs beyond the support are masked out in both
// passes, NeighbourLists).
template <int D>
void ForceEvaluation<D>::densityGradients(const InteractionSet<D>& set, NeighbourLists& lists) {
  if (!set.ownedParticle.empty())
    throw std::invalid_argument(
        "ForceEvaluation: Antuono et al.'s density diffusion needs every fluid entry's "
        "neighbours, and a set of one process of several has copies of other processes' "
        "entries without them");
  Workspace& w = *work_;
  if (!lists.reuse && !(lists.skin > 0)) {
    double hMax = 0.0;
    for (std::size_t k = 0; k < set.size(); ++k) hMax = std::max(hMax, set.h[k]);
    lists.skin = 1e-6 * hMax;
  }
  gradientLoop_(parameters_, set, Vec<D>::Zero(), lists, w, w.gradientSums);
  for (std::size_t k = set.nFluid; k < set.size(); ++k)
    if (set.source[k] >= static_cast<int>(set.nFluid))
      throw std::logic_error("ForceEvaluation: halo entry " + std::to_string(k) +
                             " stands for entry " + std::to_string(set.source[k]) +
                             ", which is not a fluid particle");
  w.densityGradient.resize(set.size());
  const terms::TermParameters& eos = parameters_;
  Vec<D> g;
  for (int a = 0; a < D; ++a) g[a] = eos.g[a];
  auto wallGradient = [&](std::size_t k) -> Vec<D> {
    const double rho = set.rho[k];
    if (rho == set.rho0[k]) return Vec<D>::Zero();
    const double c2 = eos.bulkModulus * eos.gammaInteger / eos.rho0 *
                      std::pow(rho / eos.rho0, eos.gammaInteger - 1);
    return rho / c2 * g;
  };
  const double* sums = w.gradientSums.sums.data();
  const int width = w.gradientSums.sumsWidth;
  const std::int64_t nFluid = static_cast<std::int64_t>(set.nFluid);
  const std::int64_t n = static_cast<std::int64_t>(set.size());
  Vec<D>* G = w.densityGradient.data();
  const int* source = set.source.data();
#pragma omp parallel
  {
#pragma omp for schedule(static)
    for (std::int64_t i = 0; i < nFluid; ++i)
      G[i] = terms::RenormalisedDensityGradient::gradient<D>(sums + width * i);
#pragma omp for schedule(static)
    for (std::int64_t k = nFluid; k < n; ++k)
      G[k] = source[k] >= 0 ? G[source[k]] : wallGradient(static_cast<std::size_t>(k));
  }
  if (lists.skin > 0) lists.reuse = true;
}

template <int D>
void ForceEvaluation<D>::markWithinSupport(const InteractionSet<D>& set, const char* marked,
                                           char* near) const {
  // The cells are half the reach (support h_max + skin) of the last build: every entry within
  // the support of i lies in the 5^(D-1) rows of 5 cells around i's cell (as for the pair loop's
  // kept lists, the motion since the build is within the skin: NeighbourLists).
  const auto& cells = work_->cells;
  const auto& order = cells.order();
  const std::size_t nf = set.nFluid, haloEnd = set.haloEnd();
  const double support = withKernel(kernel_, [](auto k) { return decltype(k)::support; });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int i = order[k];
    if (static_cast<std::size_t>(i) >= nf || !marked[i]) continue;
    const Vec<D> xi = set.x[i];
    const double hi = set.h[i];
    cells.template forEachAdjacentRow<2>(cells.sortedCell(static_cast<int>(k)), [&](int b, int e) {
      for (int kk = b; kk < e; ++kk) {
        const std::size_t j = static_cast<std::size_t>(order[kk]);
        const double reach = 0.5 * support * (hi + set.h[j]);
        const double r2 = (xi - set.x[j]).squaredNorm();
        // r2 > 0: a distinct particle at r = 0 adds nothing (as in the pair loop).
        if (j == static_cast<std::size_t>(i) || !(r2 > 0.0) || !(r2 < reach * reach)) continue;
        if (j < nf)
          near[j] = 1;
        else if (j < haloEnd)
          near[set.source[j]] = 1;
      }
    });
  }
}

template <int D>
void ForceEvaluation<D>::cellOrder(std::size_t count, std::vector<int>& out,
                                   std::vector<std::int64_t>* cells) const {
  out.clear();
  if (cells) cells->clear();
  const auto& order = work_->cells.order();
  for (std::size_t k = 0; k < order.size(); ++k)
    if (static_cast<std::size_t>(order[k]) < count) {
      out.push_back(order[k]);
      if (cells) cells->push_back(work_->cells.frameCell(static_cast<int>(k)));
    }
}

template <int D>
void ForceEvaluation<D>::frameGrid(const double (&lo)[D], const double (&hi)[D],
                                   std::size_t entries, double hMax) {
  Workspace& w = *work_;
  w.framed = true;
  for (int a = 0; a < D; ++a) w.frame.box.lo[a] = lo[a], w.frame.box.hi[a] = hi[a];
  w.frame.points = entries, w.frame.layerAlign = 2 * pair_loop::bandLayers;
  w.frameHMax = hMax;
}

template <int D>
std::vector<std::string> ForceEvaluation<D>::termNames() const {
  return namesOf(menuIndex(terms_), std::make_integer_sequence<unsigned, terms::menuSize>{});
}

template class ForceEvaluation<1>;
template class ForceEvaluation<2>;
template class ForceEvaluation<3>;

}  // namespace sph
