// The steps, snapshots and output of a scene (RunBudget.hpp), from the first time step of its
// lattice start.
#include <sys/statvfs.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sph/InitialParticles.hpp"
#include "sph/RunBudget.hpp"
#include "sph/Simulation.hpp"
#include "sph/integrators/PositionVerlet.hpp"
#include "sph/integrators/PredictorCorrector.hpp"
#include "sph/integrators/VelocityVerlet.hpp"

namespace sph {

namespace {

// The first step's limits, as Simulation::timeStep computes them (Morris, Fox & Zhu 1997,
// eqs. 34-36, with the flow speed added to the sound speed), from the start's first force
// evaluation. A block with initial = "packed" is taken from its lattice: the packing moves the
// particles by a fraction of dx and changes the first step by as little.
struct FirstStep {
  double h = 0, v = 0, c = 0, nu = 0, a = 0;
  int fastest = -1;  // the particle of the largest |a|
  int phaseC = 0, phaseNu = 0;
  double acoustic = 0, viscous = 0, accel = 0;
  double entries = 0, evaluationSeconds = 0;
};

template <int D>
FirstStep firstStep(const Scene& scene) {
  Scene lattice = scene;
  for (FluidBlock& b : lattice.fluids) b.packed = false;
  Simulation<D> sim(lattice, latticeParticles<D>(lattice));
  Derivatives<D> f;
  sim.rates(sim.particles(), 0.0, f);
  FirstStep s;
  // Again, timed: the neighbour lists of the first are kept (the state has not moved), as at
  // most of a run's evaluations.
  const auto start = std::chrono::steady_clock::now();
  sim.rates(sim.particles(), 0.0, f);
  s.evaluationSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.entries = static_cast<double>(sim.interactionSet().size());
  const Particles<D>& y = sim.particles();
  s.h = *std::min_element(y.h.begin(), y.h.end());
  for (std::size_t i = 0; i < y.size(); ++i) {
    s.v = std::max(s.v, y.v[i].norm());
    const double a = f.dvdt[i].norm();
    if (!std::isfinite(a) || a > s.a) s.a = a, s.fastest = static_cast<int>(i);
    if (!std::isfinite(a)) break;
  }
  for (std::size_t k = 0; k < scene.phases.size(); ++k) {
    const Phase& ph = scene.phases[k];
    if (ph.c0 > s.c) s.c = ph.c0, s.phaseC = static_cast<int>(k);
    if (scene.terms.morrisViscosity && ph.mu / ph.rho0 > s.nu)
      s.nu = ph.mu / ph.rho0, s.phaseNu = static_cast<int>(k);
  }
  s.acoustic = scene.cflAcoustic * s.h / (s.c + s.v);
  s.viscous = s.nu > 0 ? scene.cflViscous * s.h * s.h / s.nu : 1e300;
  s.accel = s.a > 0 ? scene.cflForce * std::sqrt(s.h / s.a) : 1e300;
  return s;
}

int evaluationsPerStep(TimeIntegrator i) {
  switch (i) {
    case TimeIntegrator::predictor_corrector:
      return integrators::PredictorCorrector::evaluationsPerStep;
    case TimeIntegrator::position_verlet:
      return integrators::PositionVerlet::evaluationsPerStep;
    case TimeIntegrator::velocity_verlet:
      return integrators::VelocityVerlet::evaluationsPerStep;
  }
  // No default: -Wswitch names an enumerator missing above; any other value is a bug.
  throw std::logic_error("evaluationsPerStep: unknown time integrator " +
                         std::to_string(static_cast<int>(i)));
}

std::string phaseKey(int k, const char* key) {
  return "'phase[" + std::to_string(k) + "]." + key + "'";
}

// The phases' background pressures, which act as a force at a free surface: "'phase[0].p0' =
// 1e+300 Pa" for each phase with one.
std::string pressures(const Scene& s) {
  std::ostringstream m;
  for (std::size_t k = 0; k < s.phases.size(); ++k)
    if (s.phases[k].p0 != 0.0) m << ", " << phaseKey(k, "p0") << " = " << s.phases[k].p0 << " Pa";
  return m.str();
}

// What sets the first step, with the keys that set it.
std::string explain(const Scene& s, const FirstStep& f, double dt) {
  std::ostringstream m;
  m.precision(3);
  if (dt == s.snapshotInterval) {
    m << "set by 'output.snapshot_interval' = " << dt << " s, shorter than the stable step "
      << std::min({f.acoustic, f.viscous, f.accel}) << " s (a run steps to every snapshot)";
  } else if (dt == f.acoustic) {
    m << "set by the acoustic limit 'numerics.cfl_acoustic' h / (c0 + |v|) = " << s.cflAcoustic
      << " x " << f.h << " m / (" << f.c << " + " << f.v << ") m/s (h: 'numerics.h_over_dx' x "
      << "'numerics.dx'; c0: " << phaseKey(f.phaseC, "c0") << ")";
  } else if (dt == f.viscous) {
    m << "set by the viscous limit 'numerics.cfl_viscous' h^2 / nu = " << s.cflViscous << " x ("
      << f.h << " m)^2 / " << f.nu << " m^2/s (nu: " << phaseKey(f.phaseNu, "mu") << " = "
      << s.phases[f.phaseNu].mu << " Pa s over rho0)";
  } else {
    m << "set by the acceleration limit 'numerics.cfl_force' sqrt(h / |a|) = " << s.cflForce
      << " sqrt(" << f.h << " m / " << f.a << " m/s^2) (|a| of particle " << f.fastest
      << ", from 'physics.gravity' and the pressure forces" << pressures(s) << ")";
  }
  return m.str();
}

// The free bytes where the output will go: its directory, or the nearest one above that exists.
double freeSpace(const std::string& dir) {
  namespace fs = std::filesystem;
  fs::path p = fs::absolute(dir);
  while (!p.empty() && !fs::exists(p) && p != p.parent_path()) p = p.parent_path();
  struct statvfs v {};
  if (statvfs(p.c_str(), &v) != 0) return 0.0;
  return static_cast<double>(v.f_bavail) * static_cast<double>(v.f_frsize);
}

}  // namespace

void checkDuration(const Scene& s, const RunLimits& limits, RunEstimate& e) {
  const FirstStep f = s.dimension == 1   ? firstStep<1>(s)
                      : s.dimension == 2 ? firstStep<2>(s)
                                         : firstStep<3>(s);
  std::ostringstream m;
  m.precision(3);
  if (!std::isfinite(f.a)) {
    // The likely cause: the largest background pressure (a force at a free surface), else g.
    int k = -1;
    for (std::size_t i = 0; i < s.phases.size(); ++i)
      if (s.phases[i].p0 != 0.0 && (k < 0 || std::abs(s.phases[i].p0) > std::abs(s.phases[k].p0)))
        k = static_cast<int>(i);
    m << s.file << ": key " << (k >= 0 ? phaseKey(k, "p0") : std::string("'physics.gravity'"))
      << ": the start's first force evaluation gives particle " << f.fastest
      << " a non-finite acceleration, so no time step can follow (it comes from 'physics.gravity' "
      << "and the pressure forces" << pressures(s) << ")";
    throw SceneError(m.str());
  }
  const double stable = std::min({f.acoustic, f.viscous, f.accel});
  // The run steps to each snapshot time, so a snapshot interval below the stable step sets it.
  const double dt = s.snapshotInterval > 0 ? std::min(stable, s.snapshotInterval) : stable;
  e.firstDt = dt;
  e.limiter = dt == s.snapshotInterval ? "snapshot_interval"
              : dt == f.acoustic       ? "acoustic"
              : dt == f.viscous        ? "viscous"
                                       : "acceleration";
  e.steps = s.endTime / dt;
  e.entries = f.entries, e.evaluationSeconds = f.evaluationSeconds;
  e.evaluationsPerStep = evaluationsPerStep(s.integrator);
  e.runSeconds = e.steps * e.evaluationsPerStep * e.evaluationSeconds;
  // A packed block's packing (Colagrossi et al. 2012) takes up to max_iterations passes of its
  // pair sums over the block, each at most a force evaluation of the start: counted at that
  // bound, so that a packing that cannot end soon (max_iterations = 1e9) shows in the work.
  for (const FluidBlock& b : s.fluids)
    if (b.packed) e.runSeconds += static_cast<double>(b.packingMaxIterations) * e.evaluationSeconds;
  e.snapshots = s.snapshotInterval > 0 ? std::floor(s.endTime / s.snapshotInterval) + 2 : 2;
  const double columns = 9.0 + s.phases.size() + s.probes.size();  // Run.cpp's Series
  const double rows = e.steps / s.seriesEvery + e.snapshots;
  // A snapshot: position and velocity (3 doubles), density, pressure, h, mass, phase (int32);
  // its XDMF entry about 1.6 kB and its inline connectivity "0 1 ... N-1", at most the digits of
  // N and a space a particle (XdmfSidecar.cpp).
  const double indexBytes = std::floor(std::log10(std::max(e.particles, 1.0))) + 2.0;
  e.outputBytes = e.snapshots * (e.particles * (84.0 + indexBytes) + 1600.0) + rows * columns * 8.0;

  m << s.file << ": key ";
  if (!(e.snapshots <= limits.maxSnapshots)) {
    m << "'output.snapshot_interval': a snapshot every " << s.snapshotInterval << " s to "
      << "'numerics.end_time' = " << s.endTime << " s makes about " << e.snapshots
      << " snapshots, more than " << limits.maxSnapshots
      << " (RunBudget.hpp: a guard against an interval typed too small)";
    throw SceneError(m.str());
  }
  // A checkpoint writes the state and the record since the last one (Checkpoint.hpp): its
  // segments hold a second copy of the run file until the run ends.
  const double checkpoints = s.checkpointInterval > 0 ? s.endTime / s.checkpointInterval : 0.0;
  if (!(checkpoints <= limits.maxSnapshots)) {
    m << "'output.checkpoint_interval': a checkpoint every " << s.checkpointInterval << " s to "
      << "'numerics.end_time' = " << s.endTime << " s makes about " << checkpoints
      << " checkpoints, more than " << limits.maxSnapshots
      << " (RunBudget.hpp: a guard against an interval typed too small)";
    throw SceneError(m.str());
  }
  if (!(e.steps <= limits.maxSteps)) {
    m << "'numerics.end_time': the run would take about " << e.steps << " steps, more than "
      << limits.maxSteps << " (sph check/run --max-steps): end_time = " << s.endTime
      << " s over a first time step of " << dt << " s, " << explain(s, f, dt);
    throw SceneError(m.str());
  }
  const double free = freeSpace(limits.outDir);
  const double written = checkpoints > 0 ? 2.0 * e.outputBytes : e.outputBytes;
  if (free > 0 && !(written <= free)) {
    const double series = rows * columns * 8.0;
    m << (series > 0.5 * e.outputBytes ? "'output.series_every'" : "'output.snapshot_interval'")
      << ": the run would write about " << e.outputBytes / 1048576.0 << " MiB (" << e.snapshots
      << " snapshots of " << e.particles << " particles, " << rows << " series rows"
      << (checkpoints > 0 ? "; twice that with the checkpoints' record" : "") << "), more than "
      << "the " << free / 1048576.0 << " MiB free in " << limits.outDir;
    throw SceneError(m.str());
  }
}

}  // namespace sph
