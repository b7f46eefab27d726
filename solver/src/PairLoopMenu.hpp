#pragma once
// The menu of pair loops, made from the term lists (terms/Menu.hpp): one pair loop for every
// kernel and every subset of the optional terms, indexed by the subset's bits. Each dimension's
// loops are built in a file of their own (PairLoopMenu{1,2,3}D.cpp), so that a build compiles
// them side by side.
#include <array>
#include <utility>

#include "PairLoop.hpp"
#include "sph/terms/Menu.hpp"
#include "sph/terms/RenormalisedDensityGradient.hpp"

namespace sph::pair_loop {

template <int D>
using Loop = void (*)(const terms::TermParameters&, const InteractionSet<D>&, const Vec<D>&,
                      NeighbourLists, typename ForceEvaluation<D>::Workspace&, Derivatives<D>&);

template <class Kernel, unsigned Mask, int D>
void evaluate(const terms::TermParameters& parameters, const InteractionSet<D>& set,
              const Vec<D>& g, NeighbourLists lists, typename ForceEvaluation<D>::Workspace& w,
              Derivatives<D>& out) {
  using Terms = terms::MenuEntry<Mask>;
  pairLoop<Kernel, Terms, D>(Terms(parameters), set, g, lists, w, out);
}

template <int D, class Kernel, unsigned... Mask>
constexpr std::array<Loop<D>, sizeof...(Mask)> menuOf(std::integer_sequence<unsigned, Mask...>) {
  return {&evaluate<Kernel, Mask, D>...};
}

// The loop of `kind` and menu entry `index` (below terms::menuSize).
template <int D>
Loop<D> menuLoop(KernelKind kind, unsigned index);
// The loop of `kind` that sums the renormalised density gradient alone (the pass before the
// rates of Antuono et al.'s density diffusion).
using GradientTerms = terms::TermSet<terms::RenormalisedDensityGradient>;
template <int D>
Loop<D> densityGradientLoop(KernelKind kind);

#ifdef SPH_PAIR_LOOP_MENU_DEFINITION
template <int D>
Loop<D> menuLoop(KernelKind kind, unsigned index) {
  return withKernel(kind, [&](auto k) {
    static constexpr auto menu =
        menuOf<D, decltype(k)>(std::make_integer_sequence<unsigned, terms::menuSize>{});
    return menu.at(index);
  });
}
template <int D>
Loop<D> densityGradientLoop(KernelKind kind) {
  return withKernel(kind, [&](auto k) -> Loop<D> {
    return
        [](const terms::TermParameters& parameters, const InteractionSet<D>& set, const Vec<D>& g,
           NeighbourLists lists, typename ForceEvaluation<D>::Workspace& w, Derivatives<D>& out) {
          pairLoop<decltype(k), GradientTerms, D>(GradientTerms(parameters), set, g, lists, w, out);
        };
  });
}
#else
extern template Loop<1> menuLoop<1>(KernelKind, unsigned);
extern template Loop<2> menuLoop<2>(KernelKind, unsigned);
extern template Loop<3> menuLoop<3>(KernelKind, unsigned);
extern template Loop<1> densityGradientLoop<1>(KernelKind);
extern template Loop<2> densityGradientLoop<2>(KernelKind);
extern template Loop<3> densityGradientLoop<3>(KernelKind);
#endif

}  // namespace sph::pair_loop
