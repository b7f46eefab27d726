#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"  // as in ForceEvaluation.cpp
#endif
#define SPH_PAIR_LOOP_MENU_DEFINITION
#include "PairLoopMenu.hpp"

namespace sph::pair_loop {
template Loop<3> menuLoop<3>(KernelKind, unsigned);
template Loop<3> densityGradientLoop<3>(KernelKind);
}  // namespace sph::pair_loop
