#pragma once
// Smoothing kernels W(r, h) with compact support 2h, normalised so that the integral over R^D is
// one (Lobovsky & Kren eq. 4). Each kernel is a small type with static members so that the pair
// loop inlines it; the scene picks one by name (KernelKind).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sph {

// h^n for a small compile-time n >= 1, without std::pow's cost in the pair loop. T is double or
// the pair loop's vector of doubles.
template <int n, class T>
constexpr T ipow(T h) {
  static_assert(n >= 1);
  if constexpr (n == 1)
    return h;
  else
    return h * ipow<n - 1>(h);
}

enum class KernelKind { quadratic, cubic_spline, wendland_c2 };

std::string_view name(KernelKind);

// Lobovsky & Kren eq. (5): W = N_D / h^D (3/16 q^2 - 3/4 q + 3/4), 0 <= q = r/h <= 2.
// N_1 = 1, N_2 = 2/pi, N_3 = 5/(4 pi). Its slope at q = 0 is -3/4 N_D / h^(D+1), not zero.
struct QuadraticKernel {
  static constexpr double support = 2.0;
  static constexpr KernelKind kind = KernelKind::quadratic;
  template <int D>
  static constexpr double norm() {
    if constexpr (D == 1) return 1.0;
    if constexpr (D == 2) return 2.0 / std::numbers::pi;
    return 5.0 / (4.0 * std::numbers::pi);
  }
  template <int D>
  static double W(double r, double h) {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    return norm<D>() / ipow<D>(h) * (0.1875 * q * q - 0.75 * q + 0.75);
  }
  template <int D>
  static double dWdr(double r, double h) {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    return norm<D>() / ipow<D + 1>(h) * (0.375 * q - 0.75);
  }
  // W's shape: W = N_D / h^D shape(q), for the pair loop (0 <= q <= 2; branch-free).
  template <int D, class T>
  static T shape(T q) {
    return (0.1875 * q - 0.75) * q + 0.75;
  }
  // (1/r) dW/dr for the pair loop, from r, 1/r and 1/h, which the loop computes once per pair
  // for all its terms. Valid for 0 < r < 2h only (the
  // loop masks the other pairs out) and branch-free so that the loop vectorises.
  // (0.375 q - 0.75) / r = 0.375 / h - 0.75 / r. Here and in the other kernels N_D is folded
  // into the constants: a multiply fewer a pair.
  template <int D, class T>
  static T gradOverR(T /*r*/, T rInv, T hInv) {
    constexpr double a = 0.375 * norm<D>(), b = 0.75 * norm<D>();
    return ipow<D + 1>(hInv) * (a * hInv - b * rInv);
  }
};

// Monaghan & Lattanzio (1985) cubic B-spline, support 2h.
struct CubicSplineKernel {
  static constexpr double support = 2.0;
  static constexpr KernelKind kind = KernelKind::cubic_spline;
  template <int D>
  static constexpr double norm() {
    if constexpr (D == 1) return 2.0 / 3.0;
    if constexpr (D == 2) return 10.0 / (7.0 * std::numbers::pi);
    return 1.0 / std::numbers::pi;
  }
  template <int D>
  static double W(double r, double h) {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double f =
        q < 1.0 ? 1.0 - 1.5 * q * q + 0.75 * q * q * q : 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return norm<D>() / ipow<D>(h) * f;
  }
  template <int D>
  static double dWdr(double r, double h) {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double df = q < 1.0 ? -3.0 * q + 2.25 * q * q : -0.75 * (2.0 - q) * (2.0 - q);
    return norm<D>() / ipow<D + 1>(h) * df;
  }
  // W's shape (see QuadraticKernel::shape): both branches computed and one selected.
  template <int D, class T>
  static T shape(T q) {
    const T s = 2.0 - q;
    const T inner = 1.0 + q * q * (0.75 * q - 1.5), outer = 0.25 * (s * s * s);
    return q < 1.0 ? inner : outer;
  }
  // (1/r) dW/dr for 0 < r < 2h (see QuadraticKernel::gradOverR); for q < 1, df/q = -3 + 2.25 q;
  // for q >= 1, df/q = -0.75 s^2 / q with 1/q = h/r, so (1/r) dW/dr = N/h^(D+1) (-0.75 s^2) / r.
  // Both branches are computed and one selected (a vector select when T is a vector).
  template <int D, class T>
  static T gradOverR(T r, T rInv, T hInv) {
    constexpr double a = -3.0 * norm<D>(), b = 2.25 * norm<D>(), c = -0.75 * norm<D>();
    const T q = r * hInv, s = 2.0 - q;
    const T inner = ipow<D + 2>(hInv) * (a + b * q);
    const T outer = ipow<D + 1>(hInv) * (c * s * s) * rInv;
    return q < 1.0 ? inner : outer;
  }
};

// Wendland (1995) C2, support 2h (the packing paper's kernel). In 2-D and 3-D
// W = sigma / h^D (1 - q/2)^4 (2q + 1); in 1-D the C2 function is (1 - q/2)^3 (1.5q + 1).
struct WendlandC2Kernel {
  static constexpr double support = 2.0;
  static constexpr KernelKind kind = KernelKind::wendland_c2;
  template <int D>
  static constexpr double norm() {
    if constexpr (D == 1) return 5.0 / 8.0;
    if constexpr (D == 2) return 7.0 / (4.0 * std::numbers::pi);
    return 21.0 / (16.0 * std::numbers::pi);
  }
  template <int D>
  static double W(double r, double h) {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double s = 1.0 - 0.5 * q;
    if constexpr (D == 1) return norm<D>() / h * s * s * s * (1.5 * q + 1.0);
    return norm<D>() / ipow<D>(h) * s * s * s * s * (2.0 * q + 1.0);
  }
  template <int D>
  static double dWdr(double r, double h) {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double s = 1.0 - 0.5 * q;
    if constexpr (D == 1) return norm<D>() / (h * h) * (-3.0 * q * s * s);
    return norm<D>() / ipow<D + 1>(h) * (-5.0 * q * s * s * s);
  }
  // W's shape (see QuadraticKernel::shape).
  template <int D, class T>
  static T shape(T q) {
    const T s = 1.0 - 0.5 * q;
    if constexpr (D == 1) return s * s * s * (1.5 * q + 1.0);
    return (s * s) * (s * s) * (2.0 * q + 1.0);
  }
  // (1/r) dW/dr for 0 < r < 2h (see QuadraticKernel::gradOverR): the factor q cancels against
  // 1/r = 1/(q h), so no division is left.
  template <int D, class T>
  static T gradOverR(T r, T /*rInv*/, T hInv) {
    const T s = 1.0 - 0.5 * r * hInv;
    if constexpr (D == 1) return hInv * hInv * hInv * ((-3.0 * norm<D>()) * s * s);
    return ipow<D + 2>(hInv) * ((-5.0 * norm<D>()) * s * s * s);
  }
};

// Calls f(Kernel{}) with the kernel type that `kind` names.
template <class F>
decltype(auto) withKernel(KernelKind kind, F&& f) {
  switch (kind) {
    case KernelKind::quadratic:
      return f(QuadraticKernel{});
    case KernelKind::cubic_spline:
      return f(CubicSplineKernel{});
    case KernelKind::wendland_c2:
      return f(WendlandC2Kernel{});
  }
  throw std::logic_error("withKernel: KernelKind " + std::to_string(static_cast<int>(kind)) +
                         " is not a kernel this build knows");
}

// Value of `kind`'s kernel, for code outside the pair loop (probes, tests).
template <int D>
double kernelValue(KernelKind kind, double r, double h) {
  return withKernel(kind, [&](auto k) { return decltype(k)::template W<D>(r, h); });
}
template <int D>
double kernelSlope(KernelKind kind, double r, double h) {
  return withKernel(kind, [&](auto k) { return decltype(k)::template dWdr<D>(r, h); });
}

}  // namespace sph
