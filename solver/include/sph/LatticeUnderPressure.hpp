#pragma once
// Whether a lattice at rest holds under a uniform pressure p > 0 in the pressure term of Lobovsky &
// Kren eq. (12): the square lattice in 2-D, the cubic one in 3-D, spacing dx, as a scene's fluid
// block starts (verification/README.md, "the lattice under pressure"). Displaced by eps e cos(k.R),
//   d^2 eps / dt^2 = -(2 p / rho) / dx^2 S(k) eps,
//   S(k) = dx^(D+2) sum_(R != 0) Hess W(R) (1 - cos k.R),
// for the modes that leave the density unchanged to first order (e normal to g(k) = sum_R grad W(R)
// sin(k.R); the Tait pressure, eq. 8, resists the others). Where e^T S e < 0 the lattice gives way
// at sigma = sqrt(-2 (p / rho) e^T S e) / dx. The artificial viscosity (eq. 10, quadratic in the
// velocity), a density diffusion and variable h (eq. 13) do not act on such a mode to first order.
#include <string>

#include "sph/Kernels.hpp"
#include "sph/Scene.hpp"
#include "sph/Vector.hpp"

namespace sph {

template <int D>
struct LatticeMode {
  double stiffness = 0.0;  // e^T S(k) e; < 0: the lattice gives way
  Vec<D> k = Vec<D>::Zero(), polarisation = Vec<D>::Zero();  // k in units of 1 / dx
};

// S(k) of the kernel at h = hOverDx dx (k in units of 1 / dx).
template <int D>
Eigen::Matrix<double, D, D> latticeStiffness(KernelKind kind, double hOverDx, const Vec<D>& k);

// The least stiff mode that keeps the density, over k on a grid of `points` + 1 values in [0, pi]
// per axis (S is even in each k_a: the rest of the zone repeats it).
template <int D>
LatticeMode<D> leastStiffLatticeMode(KernelKind kind, double hOverDx, int points);

// sigma above [1/s]: 0 for a stiff mode.
double latticeGrowthRate(double stiffness, double pOverRho, double dx);

// One line for `sph check`: whether the lattice the scene's fluid blocks start on holds at the
// largest pressure they start at, and if not how soon round-off grows to 1e-3 dx; empty where no
// block starts on a lattice under pressure (1-D, packed blocks, p <= 0).
std::string latticeUnderPressureNote(const Scene& scene);

}  // namespace sph
