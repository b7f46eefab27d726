#pragma once
// What a time integrator works with: the fields of a state and of its rates, as pointers that a
// per-particle update captures by value (through a reference each would be loaded again after
// every store), and the stages of a step. An integrator is a type with
//   name                the run file's word for it,
//   evaluationsPerStep  force evaluations a step takes (the accepted state's included; 1: the
//                       trial state's rates are taken as the accepted state's, not evaluated),
//   advance(step, dt)   one step: updates of the trial state y* from y and the rates, through
//                       step.move(update, trialStage or finalStage), and evaluations of y*, through
//                       step.evaluate().
// The step (Simulation) does the rest of each stage after the update, in the same pass over the
// particles: the periodic wrap and the neighbour lists' motion at every stage; at the final
// stage also the Tait pressure of the new density, the walls' reflection and the checks. It
// accepts y* as the new state and evaluates its rates after a final stage that passed.
#include <cstdint>
#include <type_traits>

#include "sph/Vector.hpp"

namespace sph::integrators {

enum class Stage { trial, final };
template <Stage S>
using StageTag = std::integral_constant<Stage, S>;
inline constexpr StageTag<Stage::trial> trialStage{};
inline constexpr StageTag<Stage::final> finalStage{};

// A state's evolved fields (Writable: the trial state's) and the fields carried along.
template <int D, bool Writable>
struct StateFields {
  template <class T>
  using Field = std::conditional_t<Writable, T, const T>*;
  Field<Vec<D>> r, v;
  Field<double> rho, h, m;
  Field<int> phase;
};
template <int D>
struct RateFields {
  const Vec<D>* dvdt;
  const double *drhodt, *dhdt;
};

}  // namespace sph::integrators
