#pragma once
// The particle packing algorithm of Colagrossi, Bouscasse, Antuono & Marrone (2012), eq. (2.16):
//   du_i/dt = -beta grad Gamma_i - zeta u_i,   dr_i/dt = u_i,
//   Gamma_i = sum_j W_ij V0,  grad Gamma_i = sum_j grad_i W_ij V0  (j over fluid and fixed solid),
//   beta = 2 p0 / rho0,  zeta = alpha sqrt(beta) / V0^(1/D)  (eq. 2.15),
//   dt = CFL V0^(1/D) / sqrt(beta)  (eq. 2.17),
// from rest on a lattice. The fluid particles drift down grad Gamma until the distribution is as
// even as the kernel can see (grad Gamma -> 0, eq. 1.12), the fixed solid particles closing the
// domain along walls and free surface.
//
// Without damping the system is Lagrangian (Appendix B): E = T + V is conserved, with
//   T = sum_i |u_i|^2 / 2  (eq. 2.18, fluid i; "specific": per unit mass),
//   V = beta/2 sum_i sum_j W_ij V0 + beta sum_i sum_j' W_ij V0  (eq. B.34; j fluid, j' solid),
// because -dV/dr_i = -beta grad Gamma_i. With damping dE/dt = -2 zeta T (eq. B.33).
#include <functional>
#include <vector>

#include "sph/EquationOfState.hpp"
#include "sph/Kernels.hpp"
#include "sph/packing/Geometry.hpp"

namespace sph::packing {

struct PackingParameters {
  KernelKind kernel = KernelKind::wendland_c2;
  double hOverDx = 2.0;
  double beta = 1.0;    // 2 p0 / rho0 [m^2/s^2]; the packed positions do not depend on it
  double alpha = 2e-3;  // eq. (2.15); the paper finds 1e-3 .. 5e-3 good
  double cfl = 1.0;     // eq. (2.17)
  int maxIterations = 10000;
  // Stop when T / (N beta), the kinetic energy per fluid particle, falls below this: the paper's
  // T < 1e-8 beta (section 3.1) read per particle, as scenes give it (solver/SCENES.md).
  double stopKineticEnergy = 1e-8;
};

// One iteration's figures, all in units of beta where they carry its dimension.
struct PackingRecord {
  int iteration = 0;
  double kinetic = 0.0;       // T / beta, T of eq. (2.18): the sum over fluid particles
  double kineticMean = 0.0;   // T / (N beta), the same per fluid particle
  double potential = 0.0;     // V / beta, eq. (B.34)
  double maxGradGamma = 0.0;  // max_i |grad Gamma_i| [1/m]
};

// A periodic box [lo, hi) in every axis (Table 1 of the paper studies lattices that fill the
// plane): a particle sees the images of every fluid particle shifted by the box sides, and is
// wrapped back into the box after each drift. The box must be wider than twice the kernel support.
template <int D>
struct PeriodicBox {
  Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Zero();
};

// A straight wall x[axis] = at that the packing sees as the SPH run's mirror ghost wall
// (Boundaries): fluid particles within the kernel support of it see their mirror images (edges and
// corners: the images across every subset of the walls they are near) as fluid, so the packed state
// is at rest under the boundary the run will use.
struct MirrorWall {
  int axis = 0;
  double at = 0.0;
  int fluidSide = 1;  // +1: the fluid is where x[axis] > at; -1: below
};

// Appends to `out` the images of x across every set of `walls` on distinct axes whose wall lines
// x is nearer than `reach` to: one wall's, an edge's two, a corner's three (depth first, in the
// walls' order).
template <int D>
void appendMirrorImages(const Vec<D>& x, const std::vector<MirrorWall>& walls, double reach,
                        std::vector<Vec<D>>& out);

// In D = 2 or 3 dimensions (the paper's eqs. hold in any D; its length scale is V0^(1/D)).
template <int D>
class ParticlePacking {
 public:
  // `fluid` moves, `solid` stays; every particle has volume V0; h = hOverDx dx.
  ParticlePacking(std::vector<Vec<D>> fluid, std::vector<Vec<D>> solid, double V0, double dx,
                  const PackingParameters& parameters);
  // The same on a periodic box (solid may be empty); throws std::invalid_argument when a side is
  // not wider than 2 lambda h.
  ParticlePacking(std::vector<Vec<D>> fluid, std::vector<Vec<D>> solid, double V0, double dx,
                  const PackingParameters& parameters, const PeriodicBox<D>& box);

  // Mirror the fluid across these walls from now on (the energy of Appendix B is then not exact:
  // an image moves with its particle).
  void setMirrorWalls(std::vector<MirrorWall> walls);

  void step();  // one iteration of eq. (2.16)
  // Steps until T/(N beta) < stopKineticEnergy or maxIterations; `observe` sees every record,
  // the start (iteration 0) included. Returns whether it stopped on the kinetic energy.
  bool run(const std::function<void(const PackingRecord&)>& observe = {});

  PackingRecord record() const;
  int iteration() const { return iteration_; }
  double dt() const { return dt_; }
  double zeta() const { return zeta_; }
  double h() const { return h_; }
  double V0() const { return V0_; }
  const PackingParameters& parameters() const { return parameters_; }
  const std::vector<Vec<D>>& positions() const { return x_; }
  const std::vector<Vec<D>>& velocities() const { return u_; }
  void setVelocities(std::vector<Vec<D>> u) { u_ = std::move(u); }
  const std::vector<Vec<D>>& solid() const { return solid_; }
  const std::vector<Vec<D>>& gradGamma() const { return gradGamma_; }  // [1/m]
  const std::vector<double>& gamma() const { return gamma_; }

 private:
  void evaluate();  // Gamma, grad Gamma and V at the current positions
  void wrap();      // periodic box: positions back into [lo, hi)

  PackingParameters parameters_;
  bool periodic_ = false;
  PeriodicBox<D> box_;
  std::vector<MirrorWall> mirrors_;
  std::vector<Vec<D>> x_, u_, solid_, all_;
  std::vector<Vec<D>> gradGamma_;
  std::vector<double> gamma_, potentialTerm_;
  double V0_, h_, dt_, zeta_;
  double potential_ = 0.0;
  int iteration_ = 0;
};

// Section 2: after packing, the hydrostatic pressure p = p0 + rho0 g (surface - height), the
// height the last coordinate, the density from the inverse of the Tait equation of state, and the
// mass m = rho V0.
struct HydrostaticFields {
  std::vector<double> pressure, density, mass;
};
template <int D>
HydrostaticFields hydrostatic(const std::vector<Vec<D>>& x, double V0, const Phase& phase,
                              double gravity, double surface);

}  // namespace sph::packing
