#include "sph/packing/LatticeStability.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sph::packing {

namespace {

// d^2W/dr^2 in 2-D, from the kernels' definitions in Kernels.hpp with q = r/h, W = N/h^2 f(q):
// quadratic (Lobovsky & Kren eq. 5) f = 3/16 q^2 - 3/4 q + 3/4, f'' = 3/8;
// cubic spline f = 1 - 3/2 q^2 + 3/4 q^3 (q < 1), (2 - q)^3/4 (q < 2): f'' = -3 + 9/2 q, 3/2 (2 -
// q); Wendland C2 f = (1 - q/2)^4 (2q + 1), f' = -5 q (1 - q/2)^3, f'' = (1 - q/2)^2 (10 q - 5).
double secondDerivative(KernelKind kind, double r, double h) {
  const double q = r / h, h4 = h * h * h * h;
  if (q >= 2.0) return 0.0;
  switch (kind) {
    case KernelKind::quadratic:
      return 2.0 / std::numbers::pi / h4 * 0.375;
    case KernelKind::cubic_spline:
      return 10.0 / (7.0 * std::numbers::pi) / h4 * (q < 1.0 ? -3.0 + 4.5 * q : 1.5 * (2.0 - q));
    case KernelKind::wendland_c2: {
      const double s = 1.0 - 0.5 * q;
      return 7.0 / (4.0 * std::numbers::pi) / h4 * s * s * (10.0 * q - 5.0);
    }
  }
  // No default: -Wswitch names an enumerator missing above, and any other value is a bug
  // (an error here), never the last case.
  throw std::logic_error("secondDerivative(KernelKind): unknown value " +
                         std::to_string(static_cast<int>(kind)));
}

}  // namespace

LinearStability linearStability(const PeriodicLattice& lattice, KernelKind kernel, double h,
                                double V0, double beta) {
  const auto& x = lattice.position;
  const int n = static_cast<int>(x.size());
  const Vec2 L = lattice.box.hi - lattice.box.lo;
  const double support = 2.0 * h;
  const int mx = static_cast<int>(std::ceil(support / L.x())),
            my = static_cast<int>(std::ceil(support / L.y()));
  // V = sum over pairs (i < j, all images) of phi(r), phi = beta V0 W: the 1/2 of eq. (B.34)
  // cancels the double count. Pair block k = phi'' e e^T + phi'/r (I - e e^T); K_ii += k,
  // K_ij -= k (for an image of i itself, the pair term cancels in K_ii and adds nothing).
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int sx = -mx; sx <= mx; ++sx)
        for (int sy = -my; sy <= my; ++sy) {
          if (i == j && sx == 0 && sy == 0) continue;
          const Vec2 r_ij = x[i] - x[j] - Vec2(sx * L.x(), sy * L.y());
          const double r = r_ij.norm();
          if (r >= support) continue;
          const Vec2 e = r_ij / r;
          const double d1 = beta * V0 * kernelSlope<2>(kernel, r, h),
                       d2 = beta * V0 * secondDerivative(kernel, r, h);
          const Eigen::Matrix2d k =
              d2 * e * e.transpose() + d1 / r * (Eigen::Matrix2d::Identity() - e * e.transpose());
          K.block<2, 2>(2 * i, 2 * i) += k;
          K.block<2, 2>(2 * i, 2 * j) -= k;
        }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, Eigen::EigenvaluesOnly);
  Eigen::VectorXd ev = solver.eigenvalues();  // ascending
  // The two rigid translations give exact zeros; drop the two eigenvalues nearest zero.
  std::vector<double> v(ev.data(), ev.data() + ev.size());
  for (int drop = 0; drop < 2; ++drop) {
    auto it = std::min_element(v.begin(), v.end(),
                               [](double a, double b) { return std::abs(a) < std::abs(b); });
    v.erase(it);
  }
  LinearStability s;
  s.lambdaMin = *std::min_element(v.begin(), v.end());
  s.lambdaMax = *std::max_element(v.begin(), v.end());
  s.sigma = std::sqrt(std::max(0.0, -s.lambdaMin));
  return s;
}

}  // namespace sph::packing
