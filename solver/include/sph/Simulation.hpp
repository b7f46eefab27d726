#pragma once
// The time loop of one scene: ghosts and neighbours, the enabled terms, the body force, and the
// time integrator's step (integrators/) with the Morris et al. (1997) time-step limits.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "sph/DomainDecomposition.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/ParticleShifting.hpp"
#include "sph/Particles.hpp"
#include "sph/Scene.hpp"
#include "sph/boundaries/Boundary.hpp"

namespace sph {

enum class FailureCause {
  nan,
  density_band,
  escaped_domain,
  wall_penetration,
  dt_collapse,
  energy_growth  // EnergyBudget.hpp
};
std::string_view name(FailureCause);

struct Failure {
  FailureCause cause;
  long step;
  double time;
  int particle;
  std::string message;  // names step, time, particle and quantity
};
// A failure as text and back, to send it from one process to the others.
std::string encode(const Failure&);
Failure decodeFailure(const std::string&);

enum class TimeStepLimit { acoustic = 0, viscous = 1, acceleration = 2 };

template <int D>
class Simulation {
 public:
  explicit Simulation(const Scene& scene);
  Simulation(const Scene& scene, Particles<D> initial);

  // Extra rates added after the SPH terms, e.g. the sources of a manufactured solution.
  using Source = std::function<void(double t, const Particles<D>&, Derivatives<D>&)>;
  void setSource(Source s) { source_ = std::move(s); }
  // The boundary model that builds the interaction set (boundaries/Boundary.hpp): the scene's
  // ([walls], [[obstacle]]) by default; e.g. the packing tanks' fixed wall particles.
  void setBoundary(std::unique_ptr<Boundary<D>> b) { boundary_ = std::move(b); }
  const Boundary<D>& boundary() const { return *boundary_; }
  // A further check of every new state (e.g. wall penetration against a curved wall), run after
  // the built-in ones; a failure stops the step as those do. Over several processes every
  // process calls it at the same steps, with its own particles, after the built-in checks have
  // passed on all of them; it must then give the same answer on every process.
  using Check = std::function<std::optional<Failure>(const Particles<D>&, double t, long step)>;
  void setCheck(Check c) { check_ = std::move(c); }
  // A further correction of every new state before the checks (e.g. putting back a particle that
  // crossed a curved wall by a little), run after the box walls' own reflection.
  using Reflection = std::function<void(Particles<D>&)>;
  void setReflection(Reflection r) { reflection_ = std::move(r); }

  // Every `steps` accepted steps (0, the default: never) the particles are stored again in the
  // cell order of the last force evaluation, so that the pair loop's copy reads them nearly in
  // sequence and a thread's particles stay together (issue 7). particles() then changes order
  // between steps; ids() gives each stored particle's index at the start, by which failures
  // name a particle.
  void keepCellOrder(int steps) { cellOrderEvery_ = steps; }
  // Neighbour lists with a skin of `fraction` of the support (2 h_max), kept while the particles
  // have not moved enough to need new ones (Verlet 1967; ForceEvaluation.hpp); 0 builds them at
  // every evaluation. The scene's numerics.neighbour_skin sets it.
  void keepNeighbourLists(double fraction) { skinFraction_ = fraction, listedAt_.clear(); }
  const std::vector<int>& ids() const { return id_; }

  // Over several processes (DomainDecomposition.hpp): from here on this simulation holds the
  // particles of its process's slab (particles(), ids() and keys() are those), and each step is
  // the one a single process would take, to the bit. Before the first step; not with a source
  // or particle shifting.
  void distribute(std::shared_ptr<DomainDecomposition<D>> d);
  const DomainDecomposition<D>* decomposition() const { return domain_.get(); }
  // Each particle's place in a single process's storage (DomainDecomposition.hpp).
  const std::vector<std::int64_t>& keys() const { return key_; }
  // The interaction set one process would hold at the current state, built from `all`, the
  // whole domain's particles in key order (DomainDecomposition::gather): its entries within the
  // support of any point are those of one process's set, in the same order.
  void wholeSet(const Particles<D>& all, InteractionSet<D>& set) const;

  // Evaluates the rates of the current state (and the halo the probes read), if not done yet.
  void prepare();

  // One step of the scene's integrator (numerics.integrator: integrators/). On failure the state
  // stays the last good one.
  std::optional<Failure> advance(double dtMax = 1e300) { return (this->*advance_)(dtMax); }

  // The rates of the given state at time t: every term, the body force and the source.
  void rates(const Particles<D>& state, double t, Derivatives<D>& out);

  const Scene& scene() const { return scene_; }
  const Particles<D>& particles() const { return y_; }
  Particles<D>& particles() { return y_; }
  // After an edit of particles() between steps: the next step evaluates their rates anew instead
  // of taking those the last step left.
  void particlesEdited() { ratesValid_ = false; }
  // The set of the last evaluation (of a trial state with velocity Verlet).
  const InteractionSet<D>& interactionSet() const { return set_; }
  // The set of the current state: the last evaluation's, or (where that was of a trial state,
  // VelocityVerlet.hpp) one built from the state into `scratch`. One process.
  const InteractionSet<D>& stateSet(InteractionSet<D>& scratch) const;
  double time() const { return t_; }
  long step() const { return step_; }
  double lastDt() const { return dt_; }
  TimeStepLimit lastLimit() const { return limit_; }
  long forceEvaluations() const { return evaluations_; }
  long reusedNeighbourLists() const { return reusedLists_; }  // evaluations that kept them
  // Particles that ended a step less than dx/2 beyond a wall (or inside an obstacle) and were
  // reflected back (position
  // mirrored, normal velocity reversed). The mirror ghosts of the paper give a finite, not a
  // growing, repulsion as a particle nears its own ghost, so a thin free-surface layer on a wall
  // (the dam-break toe) can creep through it; deeper crossings are wall_penetration failures.
  long wallReflections() const { return reflections_; }
  // The deepest such crossing so far [m] (at most dx/2), for the wall tests of issue 3.
  double maxReflectionDepth() const { return reflectionDepth_; }
  const ForceEvaluation<D>& forces() const { return forces_; }
  // The scene's particle shifting (none: null) and the shifts of the last step that shifted (one
  // step in shifting.every), by particle.
  const ParticleShifting<D>* shifting() const { return shifting_.get(); }
  const LineVector<Vec<D>>& lastShift() const { return shift_; }
  std::vector<std::string> termNames() const;

  // A particle taken out of the run at the end of the step in which it crossed an open face
  // (Scene::Leaving::removed), as that step left it.
  struct Departure {
    int id;
    long step;
    double time;
    Vec<D> r, v;
    double m, rho;
    int phase;
    // As a row of numbers (a checkpoint's table, a message between processes): id, step, time,
    // r, v, m, rho, phase.
    static constexpr int width = 2 * D + 6;
    void appendTo(std::vector<double>& rows) const;
    static Departure ofRow(const double* row);
  };
  // Every departure so far, by step and then in one process's storage order (over several
  // processes: on process 0; the others hold none).
  const std::vector<Departure>& departures() const { return departures_; }
  // The departed particles' volume m/rho of each phase (summed in departures() order).
  std::vector<double> departedVolume() const;

  // What a checkpoint keeps of the time loop besides the particles (in their stored order) and
  // ids(): with these the next step reads what it would have read (Checkpoint.hpp).
  struct Resumable {
    std::vector<int> ids;
    double time = 0, lastDt = 0, dtFloor = 0, reflectionDepth = 0, skin = 0;
    TimeStepLimit limit = TimeStepLimit::acoustic;
    long step = 0, evaluations = 0, reflections = 0, reusedLists = 0;
    // The positions and h at the neighbour lists' build (empty: no lists kept).
    LineVector<Vec<D>> listedAt;
    LineVector<double> listedH;
    std::vector<Departure> departures;
  };
  Resumable resumable() const;
  // The whole domain's particles, Resumable and rates in one process's order: over several
  // processes gathered on process 0 (every process calls it; the others get nothing), so that a
  // checkpoint is the one a single process writes.
  struct Whole {
    Particles<D> particles;
    Resumable state;
    Derivatives<D> rates;
  };
  void gatherWhole(Whole& w) const;
  // Continues from a Resumable, on a simulation made from the checkpoint's particles, whose
  // rates were `rates`. Over several processes (after distribute()) r and rates are the whole
  // domain's in one process's order, and each process takes its own particles' part. The neighbour
  // lists are built again from the listed positions and h (the same halo, cells and pairs as then:
  // nothing else sets them). With `verify` the state's rates are evaluated again with them (the
  // step that wrote the state had moved it less than the skin from there, or listed it) and the
  // result says whether they are `rates` to the bit; without (a state whose step then failed, which
  // may have listed its trial state) `rates` are taken. Throws std::invalid_argument where r does
  // not fit this simulation (another particle count).
  bool resume(const Resumable& r, const Derivatives<D>& rates, bool verify);
  const Derivatives<D>& currentRates() const { return f_; }

 private:
  struct Stepper;  // what the integrator sees of a step (Simulation.cpp)
  // advance() with the scene's integrator, chosen once in the constructor: each is its own
  // instance of the step, with no test of the choice inside.
  template <class Integrator>
  std::optional<Failure> advanceWith(double dtMax);
  std::optional<Failure> (Simulation::*advance_)(double) = nullptr;
  // The stable step and what limits it; `particle` is the one with the extreme speed, h or
  // acceleration.
  double timeStep(TimeStepLimit& limit, int& particle) const;
  std::optional<Failure> check(const Particles<D>& s, double t, long step) const;
  // The failure of particle `first` (none if it is past the end), else the custom check's.
  std::optional<Failure> failureFrom(const Particles<D>& s, std::int64_t first, double t,
                                     long step) const;
  std::optional<Failure> checkParticle(const Particles<D>& s, std::size_t i, double t,
                                       long step) const;
  void storeInCellOrder();
  // Takes out the particles beyond an open face (Scene::Leaving::removed) into departures_; the
  // others keep their order. Over several processes every process calls it.
  void removeDeparted();
  // Over several processes, where the owned particles and the halo go in the interaction set's
  // fluid, in key order (placed_, SetFluid): placed anew when the halo's members are chosen
  // anew.
  void placeHalo(bool rescan);
  // The set from `fluid`: the boundary's entries, and the ghosts' densities where they take the
  // hydrostatic pressure.
  void buildSet(const SetFluid<D>& fluid, double reach, HaloMembers members,
                InteractionSet<D>& set) const;
  // The whole domain's cell grid, from every process's part of the set (CellList::Frame).
  void frameGrid(double hMax);
  // The same failure (the first by key) on every process, or none.
  void agree(std::optional<Failure>& failure) const;
  // Whether particles are put back after the step's pass (a custom reflection, an obstacle's):
  // the checks and the lists' motion then wait for it.
  bool reflectsItself() const { return reflection_ || boundary_->hasInnerSolids(); }
  // How far the particles moved, and h grew, since the neighbour lists were built (if `listed`),
  // and the largest h: whether rates() keeps the lists. Gathered in the loop that wrote the state.
  struct Motion {
    double hMax, moved2, grown;
    bool listed;
    const Vec<D>* listedAt;
    const double* listedH;
    void add(const Vec<D>& r, double h, std::int64_t i);
  };
  Motion motionStart(std::int64_t n) const;
  // With `shiftingSums`, out.sums gets particle shifting's pair sums too (ForceEvaluation).
  void rates(const Particles<D>& state, double t, Derivatives<D>& out, const Motion& motion,
             bool shiftingSums = false);

  Scene scene_;
  Boundaries<D> bounds_;
  ForceEvaluation<D> forces_;
  Source source_;
  std::unique_ptr<Boundary<D>> boundary_;
  std::unique_ptr<ParticleShifting<D>> shifting_;
  LineVector<Vec<D>> shift_;   // dr of the step's final stage, from its trial state
  bool shiftingSums_ = false;  // shifting's pair sums in the pair loop (else its own gather)
  // A no-slip face with mirror ghosts: their continuity term is corrected
  // (boundaries/NoSlipContinuity.hpp).
  bool noSlipGhosts_ = false;
  Check check_;
  Reflection reflection_;
  Particles<D> y_, yStar_;
  double skinFraction_ = 0.0, skin_ = 0.0;
  Derivatives<D> f_, fStar_;
  InteractionSet<D> set_;
  std::vector<int> id_, order_, idScratch_;
  std::vector<Departure> departures_;
  int cellOrderEvery_ = 0;
  double t_ = 0.0, dt_ = 0.0, dtFloor_ = 0.0;
  TimeStepLimit limit_ = TimeStepLimit::acoustic;
  long step_ = 0, evaluations_ = 0, reflections_ = 0, reusedLists_ = 0;
  LineVector<Vec<D>> listedAt_;  // the positions and h at the lists' build
  LineVector<double> listedH_;
  double reflectionDepth_ = 0.0;
  bool ratesValid_ = false;
  bool ratesOfState_ = true;  // false: f_ is carried from the step before (VelocityVerlet.hpp)
  std::shared_ptr<DomainDecomposition<D>> domain_;  // null: one process
  std::vector<std::int64_t> key_, haloKey_, cells_;
  Particles<D> halo_;
  std::vector<int> placed_;  // the set's fluid entry k: owned particle i >= 0, or halo -1 - j
};

}  // namespace sph
