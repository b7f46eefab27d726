#pragma once
// The model's terms: those every scene evaluates, the optional ones a scene switches on, and
// the slots where a scene picks at most one of several forms of a term. The pair loop is built
// for every subset of the optional terms times every choice in each slot (ForceEvaluation.cpp
// makes the menu from these lists), so a new term is its header and a place in a list here; a
// form added to a slot grows the menu by one subset's worth, a new optional term doubles it.
#include <type_traits>

#include "sph/terms/ArtificialViscosity.hpp"
#include "sph/terms/BodyForce.hpp"
#include "sph/terms/ConcentrationGradient.hpp"
#include "sph/terms/ContinuityEquation.hpp"
#include "sph/terms/DensityDiffusionAntuono.hpp"
#include "sph/terms/DensityDiffusionFourtakas.hpp"
#include "sph/terms/DensityDiffusionFourtakasPhases.hpp"
#include "sph/terms/DensityDiffusionMolteniColagrossi.hpp"
#include "sph/terms/MorrisViscosity.hpp"
#include "sph/terms/PressureGradient.hpp"
#include "sph/terms/TermSet.hpp"
#include "sph/terms/VariableSmoothingLength.hpp"

namespace sph::terms {

template <class... Ts>
struct TermList {
  static constexpr int size = sizeof...(Ts);
};

using RequiredTerms = TermList<ContinuityEquation, PressureGradient, BodyForce>;
// Bit k of a menu index's optional part switches on the k-th (TermSwitches follows this order).
using OptionalTerms = TermList<ArtificialViscosity, MorrisViscosity, VariableSmoothingLength>;
// The density diffusion slot: none (0) or the form at 1, 2, ... (TermSwitches::DensityDiffusion).
using DensityDiffusionForms = TermList<DensityDiffusionMolteniColagrossi, DensityDiffusionFourtakas,
                                       DensityDiffusionFourtakasPhases, DensityDiffusionAntuono>;
inline constexpr unsigned optionalSubsets = 1u << OptionalTerms::size;
inline constexpr unsigned ratesEntries = optionalSubsets * (1 + DensityDiffusionForms::size);
// Particle shifting's pair sums (ConcentrationGradient) join one optional subset only, with each
// diffusion form: every optional term on, the paper's model (Lobovsky & Kren: artificial
// viscosity, Morris viscosity, variable h), which is the model of every scene and test that
// shifts (the dam break's, the tanks at rest). Other sets take particle shifting's own gather
// (ParticleShifting.hpp). An optional term would double the menu: with the sums for every subset
// (48 entries) the 1-D menu file took 137 s of compile CPU against 61 s without them; with these
// three entries the 1-, 2- and 3-D files take 81, 84 and 105 s against 61, 62 and 78 s (-O3, one
// core each, loaded machine).
inline constexpr unsigned shiftingSubset = optionalSubsets - 1;
using ShiftingTerms = TermList<ConcentrationGradient>;

namespace detail {
// The optional terms whose bits are set in Mask, appended to Chosen.
template <unsigned Mask, class Chosen, class Rest>
struct Pick;
template <unsigned Mask, class... C>
struct Pick<Mask, TermList<C...>, TermList<>> {
  using type = TermList<C...>;
};
template <unsigned Mask, class... C, class T, class... R>
struct Pick<Mask, TermList<C...>, TermList<T, R...>> {
  using type = typename Pick<(Mask >> 1),
                             std::conditional_t<(Mask & 1) != 0, TermList<C..., T>, TermList<C...>>,
                             TermList<R...>>::type;
};
// A slot's form `Form` (0: none, k: the k-th of Forms) appended to Chosen.
template <unsigned Form, class Chosen, class Forms>
struct Choose;
template <class... C, class Forms>
struct Choose<0, TermList<C...>, Forms> {
  using type = TermList<C...>;
};
template <unsigned Form, class... C, class F, class... R>
requires(Form > 0) struct Choose<Form, TermList<C...>, TermList<F, R...>> {
  using type = std::conditional_t<Form == 1, TermList<C..., F>,
                                  typename Choose<Form - 1, TermList<C...>, TermList<R...>>::type>;
};
template <class List>
struct SetOf;
template <class... C>
struct SetOf<TermList<C...>> {
  using type = TermSet<C...>;
};
template <class List, class More>
struct Append;
template <class... C, class... M>
struct Append<TermList<C...>, TermList<M...>> {
  using type = TermList<C..., M...>;
};
template <unsigned Index>
struct Entry {
  static constexpr bool sums = Index >= ratesEntries;
  static constexpr unsigned rates =
      sums ? shiftingSubset + optionalSubsets * (Index - ratesEntries) : Index;
  using optional = typename Pick<rates % optionalSubsets, RequiredTerms, OptionalTerms>::type;
  using withSums =
      std::conditional_t<sums, typename Append<optional, ShiftingTerms>::type, optional>;
  using type = typename SetOf<
      typename Choose<rates / optionalSubsets, withSums, DensityDiffusionForms>::type>::type;
};
}  // namespace detail

// The term set of menu entry `Index` = optional subset + optionalSubsets x diffusion form: the
// required terms, then the optional ones the subset switches on, then the slot's form; from
// ratesEntries on, ratesEntries + diffusion form: the shifting subset's with the pair sums.
template <unsigned Index>
using MenuEntry = typename detail::Entry<Index>::type;
inline constexpr unsigned menuSize = ratesEntries + 1 + DensityDiffusionForms::size;

}  // namespace sph::terms
