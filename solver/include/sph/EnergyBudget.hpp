#pragma once
// The fluid's mechanical energy E = sum m (v^2/2 + e(rho) - g.r), with e the specific internal
// energy of the Tait equation (de/drho = p/rho^2, e(rho0) = 0). The pressure and continuity terms
// (eq. 11, 12) trade v^2/2 for e pair by pair and keep E; the viscosities (eq. 9, 10) take from
// it; mirror walls at rest do no work. So E never exceeds its start by more than round-off and
// the walls' small imbalance. Heun's step, though, amplifies an undamped oscillation a little
// every step (|1 + z + z^2/2| > 1 for z = i omega dt), and without enough damping a run can gain
// energy from nowhere and still stay inside the density band (validation/README.md).
#include <optional>
#include <vector>

#include "sph/Particles.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace sph {

// e(rho) of a phase [J/kg], without cancellation near rho0.
double internalEnergy(double rho, const Phase& ph);

template <int D>
class EnergyBudget {
 public:
  // The start's energy. The budget is undefined, and check() always passes, where energy may
  // enter from outside (a body force along a periodic axis, a moving wall) or where e has no
  // lower bound (a background pressure p0 >= K, the Tait bulk modulus).
  EnergyBudget(const Scene& scene, const Particles<D>& start);
  bool defined() const { return defined_; }

  // energy_growth when E has grown since the start by more than the energy that was there to
  // convert, K0 + U0 + W (kinetic and internal at the start, plus the body force's work since):
  // in a sound run K + U = K0 + U0 + W - (dissipated) <= K0 + U0 + W, so the check fires only
  // when K + U reaches twice that. With a density diffusion term a negative W (the fluid lifted:
  // the term does it without a force's work) counts as none. `ids` name the particles as Failure
  // does.
  std::optional<Failure> check(const Particles<D>& s, const std::vector<int>& ids, double t,
                               long step) const;

  struct Parts {
    // sum m v^2/2; sum m (e - e_min), e_min the phase's e where p = 0 (never negative); -sum m g.r
    double kinetic = 0, internal = 0, potential = 0;
  };
  Parts parts(const Particles<D>& s) const;

  // The budget of a run continued from a checkpoint: the start's parts and the round-off
  // allowance as the run's start gave them (start(), roundOff()).
  EnergyBudget(const Scene& scene, const Parts& start, double roundOff);
  const Parts& start() const { return start_; }
  double roundOff() const { return roundOff_; }

 private:
  void setDefined(const Scene& scene);  // defined_ and lowest_
  const Scene* scene_;
  bool defined_ = true;
  std::vector<double> lowest_;  // e_min of each phase
  Parts start_;
  double roundOff_ = 0;  // of the potential energy's sums
};

}  // namespace sph
