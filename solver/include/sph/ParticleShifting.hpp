#pragma once
// Particle shifting: once a step, each fluid particle is moved by a small dr down the gradient of
// the particle concentration, so that the particles stay near a uniform arrangement (a remedy for
// the clumping and voids a Lagrangian SPH flow develops). A position correction, not a force: the
// velocity and density are carried along unchanged, as DualSPHysics does in its weakly
// compressible form (Lind et al. correct them by a Taylor step in ISPH).
//
// Fickian shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231, 1499, eqs. 21-24 as
// PySPH's shifting module numbers them; the paper itself was not at hand here):
//   dr_i = -D grad C_i,   grad C_i = sum_j V_j (1 + R (W_ij / W(dx))^n) grad_i W_ij,
//   V_j = m_j / rho_j, R = 0.2, n = 4 (Monaghan 2000's anti-clumping factor, which Lind et al.
//   take over), W(dx) the kernel at the initial spacing with h_ij.
// The diffusion coefficient of Skillen, Lind, Stansby & Rogers (2013, Comput. Methods Appl. Mech.
// Engrg. 265, 163, eq. 13), D = A h_i |u_i| dt, A from 1 to 6 (their range; 2 is DualSPHysics'
// default): Lind et al.'s constant D ~ h^2 moves a particle by a fixed amount each step, which at
// a weakly compressible time step (c0 ten times the flow speed) is tens of times the ISPH step's
// shift a unit of time; D proportional to |u| dt moves it by a fraction of its own displacement.
//
// The delta-plus form (Sun, Colagrossi, Marrone, Antuono & Zhang 2017, Comput. Methods Appl. Mech.
// Engrg. 315, 25): the same grad C with D = CFL Ma (2h)^2 = 4 h U_max dt, where
// CFL = c0 dt / h and Ma = U_max / c0; here U_max is the largest |u| of the state (the paper takes
// a reference speed of the flow), and the coefficient 4 may be changed as A is above.
//
// The free surface (Lind et al. 2012): grad C there points into the fluid, and
// dr = -D grad C would push the surface particles out. The surface particles are those with
//   div r_i = -sum_j V_j r_ij . grad_i W_ij  (= D inside the fluid)
// below a threshold: 1.5 in 2-D (Lind et al.), 2.75 in 3-D (the value DualSPHysics' ShiftTFS
// documents for 3-D), 0.75 in 1-D (three quarters of the interior's value, as 1.5 is in 2-D); those
// and the particles that have a surface particle inside their support keep only the part of dr
// tangent to the surface, dr - (dr . n) n, with the normal n = -g_i / |g_i| of the concentration
// gradient without the anti-clumping factor, g_i = sum_j V_j grad_i W_ij (their alpha = 0). A
// particle with g_i = 0 there is not moved.
//
// Both pair sums are taken over the interaction set (fluid, periodic images, mirror ghosts, wall
// particles), which completes the support at walls and across periodic faces: a lattice against a
// mirror wall has grad C = 0 as in the interior. Each particle's sums run over its neighbours in
// the cell list's order, whatever the thread count.
//
// Cost (2-core VM, loaded, one thread): the paper's dam break at dx 0.01 2.5-3.1 s, with Lind
// shifting 7.1-7.6 s; at dx 0.005 to t = 0.6 s 9.5 s, with Fourtakas diffusion and Lind shifting
// 30.4 s: about 400 ns a particle a step, four force evaluations' worth. The pass is scalar and
// visits each pair twice (a gather); in the pair loop (each pair once, four lanes) its sums would
// need room in the rate record beside d rho/dt, dh/dt and dv/dt.
#include <memory>
#include <string_view>
#include <vector>

#include "sph/CacheLines.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"
#include "sph/Vector.hpp"

namespace sph {

// The scene's choice ([physics] shifting, solver/SCENES.md).
enum class ShiftingForm { none, lind, delta_plus };
std::string_view name(ShiftingForm);

struct ShiftingParameters {
  ShiftingForm form = ShiftingForm::none;
  double coefficient = 2.0;  // A of D = A h U dt
  // div r below which a particle is on the free surface; 0: the dimension's default.
  double surfaceThreshold = 0.0;
  bool freeSurface = true;  // the tangential-only treatment near the surface (false: tests)
  static constexpr double anticlumpingR = 0.2;  // Lind et al. 2012 after Monaghan 2000
  static constexpr int anticlumpingN = 4;
};

// A's default of each form: Skillen et al.'s 2 (DualSPHysics' default) and delta-plus's 4.
double defaultShiftingCoefficient(ShiftingForm);
// The dimension's default surface threshold of div r (above).
double defaultSurfaceThreshold(int dimension);

template <int D>
class ParticleShifting {
 public:
  ParticleShifting(KernelKind kernel, const ShiftingParameters& p, double dx);
  ~ParticleShifting();

  // The shifts dr_i of the set's fluid entries i (shift.size() = set.nFluid) for a step dt.
  void operator()(const InteractionSet<D>& set, double dt, LineVector<Vec<D>>& shift);

  // The last call's per-particle sums, for tests: grad C (with the anti-clumping factor), g
  // (without), div r, and whether the particle was on the surface or near it.
  const LineVector<Vec<D>>& gradC() const { return gradC_; }
  const LineVector<Vec<D>>& normalSum() const { return g_; }
  const LineVector<double>& divR() const { return divR_; }
  const std::vector<char>& surface() const { return surface_; }
  const std::vector<char>& nearSurface() const { return near_; }
  const ShiftingParameters& parameters() const { return p_; }

 private:
  struct Cells;
  KernelKind kernel_;
  ShiftingParameters p_;
  double dx_;
  std::unique_ptr<Cells> cells_;
  LineVector<Vec<D>> gradC_, g_;
  LineVector<double> divR_, volume_;  // volume_: m / rho of every entry of the set
  std::vector<char> surface_, near_;
};

}  // namespace sph
