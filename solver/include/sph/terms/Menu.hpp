#pragma once
// The model's terms: those every scene evaluates, and the optional ones a scene switches on.
// The pair loop is built for every subset of the optional terms (ForceEvaluation.cpp makes the
// menu from these lists), so a new term is its header and a place in a list here.
#include <type_traits>

#include "sph/terms/ArtificialViscosity.hpp"
#include "sph/terms/BodyForce.hpp"
#include "sph/terms/ContinuityEquation.hpp"
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
// Bit k of a menu index switches on the k-th (TermSwitches follows this order).
using OptionalTerms = TermList<ArtificialViscosity, MorrisViscosity, VariableSmoothingLength,
                               DensityDiffusionMolteniColagrossi>;

namespace detail {
template <unsigned Mask, class Chosen, class Rest>
struct Pick;
template <unsigned Mask, class... C>
struct Pick<Mask, TermList<C...>, TermList<>> {
  using type = TermSet<C...>;
};
template <unsigned Mask, class... C, class T, class... R>
struct Pick<Mask, TermList<C...>, TermList<T, R...>> {
  using type = typename Pick<(Mask >> 1),
                             std::conditional_t<(Mask & 1) != 0, TermList<C..., T>, TermList<C...>>,
                             TermList<R...>>::type;
};
template <unsigned Mask, class Required>
struct WithRequired;
template <unsigned Mask, class... C>
struct WithRequired<Mask, TermList<C...>> {
  using type = typename Pick<Mask, TermList<C...>, OptionalTerms>::type;
};
}  // namespace detail

// The term set of menu entry `Mask`: the required terms, then the optional ones it switches on.
template <unsigned Mask>
using MenuEntry = typename detail::WithRequired<Mask, RequiredTerms>::type;
inline constexpr unsigned menuSize = 1u << OptionalTerms::size;

}  // namespace sph::terms
