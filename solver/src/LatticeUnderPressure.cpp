#include "sph/LatticeUnderPressure.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "sph/InitialParticles.hpp"

namespace sph {

namespace {

// d^2W/dr^2 of the kernels of Kernels.hpp, W = N_D / h^D f(q), q = r / h: quadratic f'' = 3/8;
// cubic spline f'' = -3 + 9/2 q (q < 1), 3/2 (2 - q) (q < 2); Wendland C2 f'' = (1 - q/2)^2
// (10 q - 5).
template <int D>
double curvature(KernelKind kind, double r, double h) {
  const double q = r / h;
  if (q >= 2.0) return 0.0;
  return withKernel(kind, [&](auto k) {
    const double n = decltype(k)::template norm<D>() / ipow<D + 2>(h);
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

// Every lattice vector R != 0 within the support 2 hOverDx (units of dx) with Hess W(R) and
// grad W(R), which the sums over k reuse.
template <int D>
struct Neighbours {
  std::vector<Vec<D>> R, gradW;
  std::vector<Eigen::Matrix<double, D, D>> hessW;
};

template <int D>
Neighbours<D> neighboursOf(KernelKind kind, double hOverDx) {
  using Matrix = Eigen::Matrix<double, D, D>;
  Neighbours<D> out;
  const int n = static_cast<int>(std::ceil(2.0 * hOverDx));
  Eigen::Matrix<int, D, 1> m = Eigen::Matrix<int, D, 1>::Constant(-n);
  while (true) {
    const Vec<D> R = m.template cast<double>();
    const double r = R.norm();
    if (r > 0.0 && r < 2.0 * hOverDx) {
      const Vec<D> e = R / r;
      const Matrix ee = e * e.transpose();
      const double slope = kernelSlope<D>(kind, r, hOverDx), bend = curvature<D>(kind, r, hOverDx);
      out.R.push_back(R), out.gradW.push_back(slope * e);
      out.hessW.push_back(bend * ee + slope / r * (Matrix::Identity() - ee));
    }
    int a = 0;
    while (a < D && m[a] == n) m[a++] = -n;
    if (a == D) return out;
    ++m[a];
  }
}

template <int D>
Eigen::Matrix<double, D, D> stiffnessAt(const Neighbours<D>& nb, const Vec<D>& k) {
  Eigen::Matrix<double, D, D> S = Eigen::Matrix<double, D, D>::Zero();
  for (std::size_t j = 0; j < nb.R.size(); ++j) S += nb.hessW[j] * (1.0 - std::cos(k.dot(nb.R[j])));
  return S;
}

}  // namespace

template <int D>
Eigen::Matrix<double, D, D> latticeStiffness(KernelKind kind, double hOverDx, const Vec<D>& k) {
  return stiffnessAt<D>(neighboursOf<D>(kind, hOverDx), k);
}

template <int D>
LatticeMode<D> leastStiffLatticeMode(KernelKind kind, double hOverDx, int points) {
  using Matrix = Eigen::Matrix<double, D, D>;
  const Neighbours<D> nb = neighboursOf<D>(kind, hOverDx);
  LatticeMode<D> best;
  best.stiffness = 1e300;
  Eigen::Matrix<int, D, 1> m = Eigen::Matrix<int, D, 1>::Zero();
  while (true) {
    const Vec<D> k = m.template cast<double>() * (std::numbers::pi / points);
    if (m.any()) {
      const Matrix S = stiffnessAt<D>(nb, k);
      Vec<D> g = Vec<D>::Zero();
      for (std::size_t j = 0; j < nb.R.size(); ++j) g += nb.gradW[j] * std::sin(k.dot(nb.R[j]));
      // The polarisations normal to g: all of them where g is nil (to round-off).
      Eigen::Matrix<double, D, Eigen::Dynamic> basis;
      if (g.norm() <= 1e-12 * (1.0 + S.norm())) {
        basis = Matrix::Identity();
      } else {
        const Vec<D> u = g.normalized();
        Eigen::JacobiSVD<Matrix> svd(Matrix::Identity() - u * u.transpose(), Eigen::ComputeFullU);
        basis = svd.matrixU().leftCols(D - 1);
      }
      const Eigen::MatrixXd reduced = basis.transpose() * S * basis;
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

double latticeGrowthRate(double stiffness, double pOverRho, double dx) {
  return stiffness < 0.0 && pOverRho > 0.0 ? std::sqrt(-2.0 * pOverRho * stiffness) / dx : 0.0;
}

std::string latticeUnderPressureNote(const Scene& scene) {
  const int D = scene.dimension;
  if (D < 2) return "";
  double g = 0;
  for (double c : scene.bodyAcceleration) g += c * c;
  g = std::sqrt(g);
  // The largest p / rho0 a block starts at on its lattice: its bottom's, hydrostatic or p0.
  double pOverRho = 0.0;
  for (const FluidBlock& b : scene.fluids) {
    if (D == 2 ? packingLeavesLattice<2>(b, scene) : packingLeavesLattice<3>(b, scene)) continue;
    const Phase& ph = scene.phases[b.phase];
    double bottom = 0, top = 0;
    heightRange(scene, b, bottom, top);
    const double p = ph.p0 + (b.hydrostatic ? ph.rho0 * g * (b.surface - bottom) : 0.0);
    pOverRho = std::max(pOverRho, p / ph.rho0);
  }
  if (!(pOverRho > 0.0)) return "";
  // k on a grid of pi/32 in 2-D, pi/8 in 3-D (verification/flows/LatticeUnderPressureTest.cpp).
  const double S = D == 2 ? leastStiffLatticeMode<2>(scene.kernel, scene.hOverDx, 32).stiffness
                          : leastStiffLatticeMode<3>(scene.kernel, scene.hOverDx, 8).stiffness;
  std::ostringstream s;
  s.precision(3);
  s << "lattice: the " << (D == 2 ? "square" : "cubic") << " lattice the fluid starts on "
    << (S < 0.0 ? "gives way" : "holds") << " under pressure with " << name(scene.kernel)
    << " at h/dx " << scene.hOverDx;
  if (S < 0.0) {
    // From round-off (1e-16 of dx) to 1e-3 dx: ln(1e13) = 30 e-foldings.
    const double sigma = latticeGrowthRate(S, pOverRho, scene.dx);
    const double t = 30.0 / sigma;
    s << ": at p / rho0 = " << pOverRho << " m^2/s^2 a mode grows at " << sigma
      << " 1/s, from round-off to 1e-3 dx by t = " << t << " s ("
      << (t < scene.endTime ? "before" : "after") << " the end time " << scene.endTime
      << " s); where the fluid stays still it then moves (verification/README.md, \"the "
         "lattice under pressure\"); a packed start moved off the lattice holds (initial = "
         "\"packed\" with [fluid.packing] noise, SCENES.md)";
  }
  return s.str();
}

template Eigen::Matrix<double, 2, 2> latticeStiffness<2>(KernelKind, double, const Vec<2>&);
template Eigen::Matrix<double, 3, 3> latticeStiffness<3>(KernelKind, double, const Vec<3>&);
template LatticeMode<2> leastStiffLatticeMode<2>(KernelKind, double, int);
template LatticeMode<3> leastStiffLatticeMode<3>(KernelKind, double, int);

}  // namespace sph
