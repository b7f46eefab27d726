#pragma once
// A hydrostatic tank of a packing scene run with the SPH scheme (Colagrossi et al. 2012, sections
// 3.1-3.2): the fluid below the free surface on the Cartesian lattice (latticeInside) or packed
// (eq. 2.16), the fixed wall particles of Adami et al. (2012) (FixedWalls) on the solid layers
// along the walls, the hydrostatic start p = p0 + rho0 g (H_s - y), rho from the inverse Tait EOS,
// m = rho V0, v = 0, and gravity. The scheme: Wendland C2 (the scene's kernel and h/dx),
// continuity (Lobovsky & Kren eq. 11), pressure gradient (eq. 12), a linear viscosity
// nu = alpha h c0 / 8 (below: the time integrator needs it), optionally the quadratic artificial
// viscosity of eq. (10) (default beta = 0: its quadratic form does nothing at the speeds of a
// tank at rest), fixed h, the predictor-corrector and time step of Simulation. 2-D only.
//
// Optional settling (section 3.1.1, after Monaghan 1994): while t < dampingTime the momentum
// equation carries the linear damping dv_i/dt += -zeta v_i, zeta given as zeta H / c0 (the
// paper's 1, 0.1, 0.02); after it the run goes on undamped from the state it reached.
#include <functional>
#include <memory>
#include <optional>

#include "sph/FixedWalls.hpp"
#include "sph/Simulation.hpp"
#include "sph/boundaries/WallParticles.hpp"
#include "sph/packing/PackingScene.hpp"

namespace sph::packing {

struct TankRunOptions {
  bool packed = false;  // start: Cartesian lattice (false) or packed
  double beta = 0.0;    // artificial viscosity, eq. (10); 0: not in the loop
  // Dissipation as a kinematic viscosity nu = alpha h c0 / 8 in the viscous term of eq. (12)
  // (Morris et al. 1997): the 2-D equivalent of Monaghan's linear artificial viscosity alpha
  // (Monaghan 2005, section 4.6); walls at rest enter it as no-slip, which a fluid at rest does
  // not feel. Needed: the predictor-corrector (Heun) amplifies an undamped oscillation by
  // |1 + z + z^2/2| = (1 + (omega dt)^4 / 4)^(1/2) > 1 per step (z = i omega dt), and a tank at
  // rest is nothing but acoustic oscillations. Measured at H/dx = 25 (packed start): with
  // alpha = 0.02 and CFL 0.25 the kinetic energy grows from 2e-8 at t sqrt(g/H) = 40 to 2e-4 at
  // 100; halving the CFL (growth per step / 16) or alpha = 0.1 (damping x 5) removes the
  // growth. 0.1 costs half the steps of the other cure.
  double alpha = 0.1;
  double cflAcoustic = 0.25;  // dt <= cfl h / (c0 + max|v|) (Morris et al. 1997)
  double dampingZeta = 0.0;   // zeta H / c0 of the settling term; 0: none
  double dampingTime = 0.0;   // t sqrt(g/H) until which it acts
  // Reflect a fluid particle that ends a step at most dx/2 beyond the container's wall line back
  // (TankRun::wallReflections); false: only the wall_penetration check.
  bool reflect = true;
  // The reflection's coefficient of restitution e: the excursion beyond the wall line (from the
  // nearest wall point) and the normal velocity are both scaled by -e. 1: the mirror image, as
  // Simulation at its box walls; 0 (default): put back onto the wall line, the normal velocity
  // removed. 0 because the Adami walls' balance for such a particle lies beyond the line, so the
  // contact lasts: measured at H/dx = 25 from the Cartesian start, e = 1 keeps one particle
  // bouncing on the bottom (29 reflections per unit of t sqrt(g/H) over t = 25-80, at 0.5-2e-3
  // sqrt(gH), the fastest particle most of that time: the mean max|u| over [50, 100] is 7.0e-4
  // against 5.8e-4 with e = 0, where it rests on the line, creeping along it at <= 3.6e-4).
  double restitution = 0.0;
};

// One moment of the run, in the paper's units (Figs. 8, 10, 12).
struct TankSample {
  double t = 0.0;         // t sqrt(g/H)
  double maxSpeed = 0.0;  // max_i |u_i| / sqrt(g H)
  double kinetic = 0.0;   // E_k / (rho0 g H V_tot), E_k = sum_i m_i |u_i|^2 / 2
};

class TankRun {
 public:
  // Builds the start (packing first when options.packed, with the scene's packing parameters) and
  // the simulation. Throws std::invalid_argument when the scene has no free surface.
  TankRun(const PackingScene& scene, const TankRunOptions& options);

  // Steps until t sqrt(g/H) >= tEnd; `observe` sees the state after every step (and the start).
  // Returns the failure that stopped the run, if any: besides Simulation's own checks, a fluid
  // particle that ends a step more than dx/2 outside the container (inside the solid) is
  // wall_penetration.
  std::optional<Failure> runTo(double tEnd,
                               const std::function<void(const TankSample&)>& observe = {});

  TankSample sample() const;
  Simulation<2>& simulation() { return *sim_; }
  const Simulation<2>& simulation() const { return *sim_; }
  const FixedWalls<2>& walls() const { return *walls_; }
  const Region& region() const { return region_; }  // the fluid at the start
  double H() const { return H_; }                   // filling height: surface minus lowest point
  double V0() const { return V0_; }
  int packingIterations() const { return packingIterations_; }  // 0 for the lattice start
  // Fluid particles that ended a step beyond the container's wall line by at most dx/2 and were
  // put back (TankRunOptions::restitution; with the default 0 a particle pressed against the wall
  // is put back once a step), and the deepest such crossing [m]. The fixed walls of Adami et al.
  // (2012) hold a particle through the pressure gradient alone, which lets a particle of the
  // Cartesian start settle between the wall line and the first wall layer and from there slip
  // through it (TankRun.cpp); packed starts never reach the wall line (measured).
  long wallReflections() const { return reflections_->count; }
  double maxReflectionDepth() const { return reflections_->deepest; }

 private:
  PackingScene scene_;
  TankRunOptions options_;
  Region region_, container_;
  double H_ = 0.0, V0_ = 0.0, volume_ = 0.0, timeScale_ = 0.0;
  int packingIterations_ = 0;
  std::shared_ptr<FixedWalls<2>> walls_;
  struct Reflections {
    long count = 0;
    double deepest = 0.0;
  };
  std::shared_ptr<Reflections> reflections_ = std::make_shared<Reflections>();
  std::unique_ptr<Simulation<2>> sim_;
};

}  // namespace sph::packing
