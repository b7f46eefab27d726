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
// Every few steps (shifting_every = k): one shift for k steps, with k dt in D. Lind et al. shift
// once an incompressible step, whose length the flow speed sets (advective CFL); a weakly
// compressible step is (c0 + U) / U times shorter (about 10 at Ma 0.1), and both forms move a
// particle by an amount proportional to dt. k steps' shifts taken at once, from the state of
// one of them, differ from k single ones by terms of order (k dt)^2, as long as k dt stays within
// the advective step (k below about c0 / U_max). The pair sums, the marks near the surface and
// the shift are then paid one step in k; the other steps evaluate the rates alone.
//
// Both pair sums are taken over the interaction set (fluid, periodic images, mirror ghosts, wall
// particles), which completes the support at walls and across periodic faces: a lattice against a
// mirror wall has grad C = 0 as in the interior. In a run they are a term of the pair loop
// (terms/ConcentrationGradient.hpp), evaluated with the rates of the step's trial state, where the
// shift is taken: each pair once, summed in an order the cell list fixes, whatever the thread
// count. The particles near the surface are marked through that evaluation's cell list, around the
// surface particles only. This class keeps a scalar gather of the same sums (each pair from both
// sides, over a cell list of its own) as the tests' reference.
//
// Cost (perf record, the dam break at dx 0.005 with Fourtakas diffusion and Lind shifting to
// t = 0.3 s, one thread): the trial evaluation with the sums 46 % of the time, the other, without,
// 28 %; the marks near the surface 2 % and the per-particle rest 1 %. On its own (micro_benchmarks
// BM_Terms/42/0 against /23/0, 2e4 particles, fastest of 15 alternated runs) the loop with the sums
// takes 1.34 times the loop without; taking W(dx) as a constant instead of the division changed
// nothing there (2708 against 2707 us): the cost lies in the rest, the five sums and their adds to
// j's rate record (16 doubles wide with them, 4 without). End to end (perf/remedies_cost.sh, 2
// threads, medians of 5 alternated rounds): the scene costs 1.59 times the paper's with a shift
// every step and 1.20 times with one in 5 steps (shifting_every = 5), against 1.14 times with the
// diffusion alone.

#include <memory>
#include <string_view>
#include <vector>

#include "sph/CacheLines.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"
#include "sph/Vector.hpp"
#include "sph/terms/ConcentrationGradient.hpp"

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
  // Steps from one shift to the next: a shift every `every` steps, for all of them (dt there is
  // `every` times the step's).
  int every = 1;
  // Lind et al. 2012 after Monaghan 2000 (the pair loop's term: terms/ConcentrationGradient.hpp)
  static constexpr double anticlumpingR = terms::ConcentrationGradient::anticlumpingR;
  static constexpr int anticlumpingN = terms::ConcentrationGradient::anticlumpingN;
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

  // The shifts dr_i of the set's fluid entries i (shift.size() = set.nFluid) for a step dt,
  // from the pair sums that `forces` has just evaluated on `set` into `sums` (with the
  // concentration gradient: TermSwitches::concentrationGradient), the particles near the surface
  // marked through its cell list.
  void operator()(const InteractionSet<D>& set, double dt, const Derivatives<D>& sums,
                  const ForceEvaluation<D>& forces, LineVector<Vec<D>>& shift);
  // The same with the pair sums gathered here, each pair from both sides, over a cell list of
  // its own: the scalar reference of the pair loop's sums (tests).
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
  void start(const InteractionSet<D>& set, LineVector<Vec<D>>& shift);
  void shiftsFrom(const InteractionSet<D>& set, double dt, LineVector<Vec<D>>& shift);
  KernelKind kernel_;
  ShiftingParameters p_;
  double dx_;
  std::unique_ptr<Cells> cells_;
  LineVector<Vec<D>> gradC_, g_;
  LineVector<double> divR_, volume_;  // volume_: m / rho of every entry of the set
  std::vector<char> surface_, near_;
};

}  // namespace sph
