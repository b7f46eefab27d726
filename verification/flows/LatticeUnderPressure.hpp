#pragma once
// The linear stability of a particle lattice at rest under a uniform pressure p > 0 in the SPH
// momentum equation (Lobovsky & Kren eq. 12): the square lattice in 2-D, the cubic one in 3-D,
// spacing dx, every particle of mass rho dx^D.
//
// Displace particle i by eps e cos(k . R_i). At uniform p the pressure force is
//   dv_i/dt = -(2 p / rho^2) sum_j m grad_i W_ij,
// the gradient of a potential (2 p m / rho^2) sum_i sum_j W_ij / 2, so to first order in eps
//   d^2 eps / dt^2 = -(2 p / rho) / dx^2 S(k) eps,
//   S(k) = dx^(D+2) sum_(R != 0) Hess W(R) (1 - cos k . R)        (dimensionless, symmetric),
// Hess W(R) = W'' e e^T + (W' / r)(I - e e^T), e = R / r. The density changes to first order by
// rho dx^D g(k) . e eps, g(k) = sum_R grad W(R) sin(k . R) (the continuity equation, eq. 11), and
// the Tait pressure (eq. 8) pushes back on that with c0^2 >> p / rho; so the modes that can give
// way are those that leave the density alone: e normal to g(k) (the limit c0^2 / (p / rho) -> oo;
// exact where g = 0). At the edge of the Brillouin zone
// (every k_a 0 or pi / dx) g vanishes and every polarisation is such a mode. A mode with
// stiffness s = e^T S(k) e < 0 grows as exp(sigma t),
//   sigma = sqrt(-2 (p / rho) s) / dx.
// Neither the artificial viscosity (beta only: quadratic in the velocity, eq. 10), nor a density
// diffusion (the density stays uniform), nor variable h (dh/dt follows the same divergence) acts
// on such a mode to first order; Morris viscosity damps it by nu |k|^2, nil for water.
//
// Dehnen & Aly (2012, MNRAS 425, 1068) analyse lattice modes this way for the pairing
// instability, which they show Wendland kernels avoid; the modes here are those that keep the
// density, and no kernel is free of them at every h/dx (LatticeUnderPressureTest.cpp's map).
#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "sph/Kernels.hpp"
#include "sph/Vector.hpp"

namespace sph::verification::lattice_under_pressure {

// d^2W/dr^2 of the kernels of Kernels.hpp, W = N_D / h^D f(q), q = r / h: quadratic f'' = 3/8;
// cubic spline f'' = -3 + 9/2 q (q < 1), 3/2 (2 - q) (q < 2); Wendland C2 f'' = (1 - q/2)^2
// (10 q - 5).
template <int D>
double curvature(KernelKind kind, double r, double h) {
  const double q = r / h;
  if (q >= 2.0) return 0.0;
  return withKernel(kind, [&](auto k) {
    using K = decltype(k);
    const double n = K::template norm<D>() / ipow<D + 2>(h);
    switch (kind) {
      case KernelKind::quadratic:
        return n * 0.375;
      case KernelKind::cubic_spline:
        return n * (q < 1.0 ? -3.0 + 4.5 * q : 1.5 * (2.0 - q));
      case KernelKind::wendland_c2:
        return n * (1.0 - 0.5 * q) * (1.0 - 0.5 * q) * (10.0 * q - 5.0);
    }
    return 0.0;
  });
}

template <int D>
using Matrix = Eigen::Matrix<double, D, D>;

// S(k) and g(k) (in units of dx^-(D+1)) at the wave vector k (in units of 1 / dx), for the
// kernel at h = hOverDx dx.
template <int D>
struct Response {
  Matrix<D> stiffness = Matrix<D>::Zero();
  Vec<D> coupling = Vec<D>::Zero();
};

template <int D>
Response<D> response(KernelKind kind, double hOverDx, const Vec<D>& k) {
  const double h = hOverDx, reach = 2.0 * h;
  const int n = static_cast<int>(std::ceil(reach));
  Response<D> out;
  Eigen::Matrix<int, D, 1> m = Eigen::Matrix<int, D, 1>::Constant(-n);
  while (true) {
    const Vec<D> R = m.template cast<double>();
    const double r = R.norm();
    if (r > 0.0 && r < reach) {
      const Vec<D> e = R / r;
      const double slope = kernelSlope<D>(kind, r, h), bend = curvature<D>(kind, r, h);
      const Matrix<D> ee = e * e.transpose();
      const Matrix<D> hess = bend * ee + slope / r * (Matrix<D>::Identity() - ee);
      out.stiffness += hess * (1.0 - std::cos(k.dot(R)));
      out.coupling += slope * e * std::sin(k.dot(R));
    }
    int a = 0;  // the next lattice vector of the cube [-n, n]^D
    while (a < D && m[a] == n) m[a++] = -n;
    if (a == D) break;
    ++m[a];
  }
  return out;
}

// The least stiff mode that leaves the density alone, over k on a grid of `points` + 1 values in
// [0, pi] per axis (S and g are even and odd in each k_a: the rest of the zone repeats it).
template <int D>
struct Mode {
  double stiffness = 0.0;  // s = e^T S(k) e: < 0, the lattice gives way
  Vec<D> k = Vec<D>::Zero(), polarisation = Vec<D>::Zero();
};

template <int D>
Mode<D> leastStiffMode(KernelKind kind, double hOverDx, int points) {
  Mode<D> best;
  best.stiffness = 1e300;
  Eigen::Matrix<int, D, 1> m = Eigen::Matrix<int, D, 1>::Zero();
  while (true) {
    const Vec<D> k = m.template cast<double>() * (std::numbers::pi / points);
    if (m.any()) {
      const Response<D> r = response<D>(kind, hOverDx, k);
      // The polarisations normal to g: all of them where g is nil (to round-off).
      Eigen::Matrix<double, D, Eigen::Dynamic> basis;
      const double gNorm = r.coupling.norm();
      if (gNorm <= 1e-12 * (1.0 + r.stiffness.norm())) {
        basis = Matrix<D>::Identity();
      } else {
        const Vec<D> g = r.coupling / gNorm;
        const Matrix<D> normal = Matrix<D>::Identity() - g * g.transpose();
        Eigen::JacobiSVD<Matrix<D>> svd(normal, Eigen::ComputeFullU);
        basis = svd.matrixU().leftCols(D - 1);
      }
      const Eigen::MatrixXd reduced = basis.transpose() * r.stiffness * basis;
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(reduced);
      if (eig.eigenvalues()[0] < best.stiffness) {
        best.stiffness = eig.eigenvalues()[0];
        best.k = k;
        best.polarisation = (basis * eig.eigenvectors().col(0)).normalized();
      }
    }
    int a = 0;
    while (a < D && m[a] == points) m[a++] = 0;
    if (a == D) break;
    ++m[a];
  }
  return best;
}

// sigma of the header's comment [1/s]: 0 for a stiff mode.
inline double growthRate(double stiffness, double pOverRho, double dx) {
  return stiffness < 0.0 ? std::sqrt(-2.0 * pOverRho * stiffness) / dx : 0.0;
}

}  // namespace sph::verification::lattice_under_pressure
