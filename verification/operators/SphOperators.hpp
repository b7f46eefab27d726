#pragma once
// SPH operators evaluated by brute force over a periodic lattice of the unit square, for the
// manufactured-solution tests of issue 3. They are written out here, independently of the
// solver's pair loop, so that the tests can compare the two (solver forms in SolverForms.cpp).
//   interpolation (Lobovsky & Kren eq. 1):   <f>_i      = sum_j V_j f_j W_ij
//   gradient (eq. 2):                        <grad f>_i = sum_j V_j f_j grad_i W_ij
//   difference form (continuity, eq. 11):    sum_j V_j (f_j - f_i) grad_i W_ij
//   symmetric form (momentum, eq. 12):       sum_j V_j (f_i + f_j) grad_i W_ij
//   Gamma_i = sum_j V_j W_ij, grad Gamma_i = sum_j V_j grad_i W_ij  (Colagrossi et al., packing)
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "sph/Kernels.hpp"
#include "sph/Vector.hpp"

namespace sph::verification {

using V2 = Vec<2>;

// n x n particles at cell centres of the unit square, each displaced by a uniform random vector
// of at most `perturbation` dx per component (0: the perfect lattice).
struct PeriodicLattice {
  int n;
  double dx;
  std::vector<V2> x;
  PeriodicLattice(int n_, double perturbation = 0.0, unsigned seed = 1) : n(n_), dx(1.0 / n_) {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(-perturbation, perturbation);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) x.push_back(V2((i + 0.5 + u(gen)) * dx, (j + 0.5 + u(gen)) * dx));
  }
};

struct OperatorValues {
  std::vector<double> interpolation, gamma;
  std::vector<V2> gradient, difference, symmetric, gradGamma;
};

// The operators of f on the lattice with kernel `kind` and smoothing length h (V_j = dx^2).
inline OperatorValues applyOperators(const PeriodicLattice& L, KernelKind kind, double h,
                                     const std::function<double(const V2&)>& f) {
  const int n = L.n;
  const double V = L.dx * L.dx;
  const int reach = static_cast<int>(std::ceil(2.0 * h / L.dx)) + 2;  // covers perturbed lattices
  std::vector<double> fv(L.x.size());
  for (std::size_t k = 0; k < L.x.size(); ++k) fv[k] = f(L.x[k]);
  OperatorValues o;
  o.interpolation.assign(L.x.size(), 0.0), o.gamma.assign(L.x.size(), 0.0);
  o.gradient.assign(L.x.size(), V2::Zero()), o.difference = o.gradient, o.symmetric = o.gradient;
  o.gradGamma = o.gradient;
  for (int jy = 0; jy < n; ++jy)
    for (int jx = 0; jx < n; ++jx) {
      const int i = jy * n + jx;
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dxi = -reach; dxi <= reach; ++dxi) {
          const int j = ((jy + dy + n) % n) * n + (jx + dxi + n) % n;
          V2 rij = L.x[i] - L.x[j];
          for (int a = 0; a < 2; ++a) rij[a] -= std::round(rij[a]);  // nearest periodic image
          const double r = rij.norm();
          if (r >= 2.0 * h) continue;
          const double W = kernelValue<2>(kind, r, h);
          const V2 gradW = r > 0 ? V2(rij * (kernelSlope<2>(kind, r, h) / r)) : V2::Zero();
          o.interpolation[i] += V * fv[j] * W;
          o.gamma[i] += V * W;
          o.gradient[i] += V * fv[j] * gradW;
          o.difference[i] += V * (fv[j] - fv[i]) * gradW;
          o.symmetric[i] += V * (fv[i] + fv[j]) * gradW;
          o.gradGamma[i] += V * gradW;
        }
    }
  return o;
}

// The manufactured field of the operator tests and its gradient: one wavelength per axis.
inline double field(const V2& x) {
  return std::sin(2 * std::numbers::pi * x[0]) * std::cos(2 * std::numbers::pi * x[1]);
}
inline V2 fieldGradient(const V2& x) {
  const double k = 2 * std::numbers::pi;
  return V2(k * std::cos(k * x[0]) * std::cos(k * x[1]),
            -k * std::sin(k * x[0]) * std::sin(k * x[1]));
}

// Max-norm error over particles, relative to the max of the exact values.
inline double relativeMaxError(const std::vector<double>& got, const std::vector<double>& exact) {
  double e = 0, s = 0;
  for (std::size_t k = 0; k < got.size(); ++k)
    e = std::max(e, std::abs(got[k] - exact[k])), s = std::max(s, std::abs(exact[k]));
  return e / s;
}
inline double relativeMaxError(const std::vector<V2>& got, const std::vector<V2>& exact) {
  double e = 0, s = 0;
  for (std::size_t k = 0; k < got.size(); ++k)
    e = std::max(e, (got[k] - exact[k]).norm()), s = std::max(s, exact[k].norm());
  return e / s;
}

}  // namespace sph::verification
