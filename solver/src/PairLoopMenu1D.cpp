#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"  // as in ForceEvaluation.cpp
#endif
#define SPH_PAIR_LOOP_MENU_DEFINITION
#include "PairLoopMenu.hpp"

namespace sph::pair_loop {
template Loop<1> menuLoop<1>(KernelKind, unsigned);
template Loop<1> densityGradientLoop<1>(KernelKind);
}  // namespace sph::pair_loop
