#pragma once
// Linear stability of a periodic particle configuration under the undamped packing dynamics
// (Colagrossi et al. 2012, eq. 2.16 with zeta = 0): d^2 r_i/dt^2 = -beta grad Gamma_i = -dV/dr_i
// with V = beta/2 sum_i sum_j W_ij V0 (eq. B.34, fluid only). Near an equilibrium the
// displacements obey d^2 x/dt^2 = -K x with K the Hessian of V, so the configuration is linearly
// stable when K has no negative eigenvalue (its two zero eigenvalues are the rigid translations of
// the periodic box), and an unstable mode grows like exp(sigma t), sigma = sqrt(-lambda_min).
// This is the "theoretical analysis" the paper calls prohibitive and replaces by simulation; for a
// periodic box of a few hundred particles it is one dense eigenvalue problem.
#include "sph/Kernels.hpp"
#include "sph/packing/Lattices.hpp"

namespace sph::packing {

struct LinearStability {
  double lambdaMin = 0.0;  // smallest eigenvalue of K, the translations left out [1/s^2]
  double lambdaMax = 0.0;  // largest [1/s^2]
  double sigma = 0.0;      // growth rate sqrt(max(0, -lambda_min)) [1/s]
};

// K for the given positions in their periodic box, kernel and h, V0 and beta; pairs over all
// periodic images within the support. Exact second derivatives of the kernel (no differencing).
LinearStability linearStability(const PeriodicLattice& lattice, KernelKind kernel, double h,
                                double V0, double beta);

}  // namespace sph::packing
