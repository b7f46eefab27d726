#include "sph/Run.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "sph/Checkpoint.hpp"
#include "sph/Diagnostics.hpp"
#include "sph/DomainDecomposition.hpp"
#include "sph/EnergyBudget.hpp"
#include "sph/InitialParticles.hpp"
#include "sph/Interrupt.hpp"
#include "sph/RemainingTime.hpp"
#include "sph/RunFile.hpp"
#include "sph/Simulation.hpp"
#include "sph/ThreadTuner.hpp"

namespace sph {

namespace {

// Particles move less than a cell (h) in 10 steps (the acoustic CFL step is a fraction of h / c0,
// and the flow is slower than c0): the stored order stays close to the cell order.
constexpr int cellOrderSteps = 10;

// The particles in the order of the start (ids), whatever order the simulation keeps them in.
template <int D>
SnapshotFields fieldsOf(const Particles<D>& s, const std::vector<int>& ids) {
  SnapshotFields f;
  const std::size_t n = s.size();
  f.position.assign(3 * n, 0.0), f.velocity.assign(3 * n, 0.0);
  f.density.resize(n), f.pressure.resize(n), f.h.resize(n), f.mass.resize(n), f.phase.resize(n);
  // By ascending id: slot i holds id i until particles leave (then the ids say whose it is).
  const int top = ids.empty() ? -1 : *std::max_element(ids.begin(), ids.end());
  std::vector<int> slot(static_cast<std::size_t>(top + 1), -1);
  for (std::size_t k = 0; k < n; ++k) slot[ids[k]] = 1;
  const bool departed = static_cast<std::size_t>(top + 1) != n;
  for (int id = 0, next = 0; id <= top; ++id)
    if (slot[id] >= 0) slot[id] = next++;
  if (departed) {
    f.id.resize(n);
    for (std::size_t k = 0; k < n; ++k) f.id[slot[ids[k]]] = ids[k];
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = slot[ids[k]];
    for (int a = 0; a < D; ++a)
      f.position[3 * i + a] = s.r[k][a], f.velocity[3 * i + a] = s.v[k][a];
    f.density[i] = s.rho[k], f.pressure[i] = s.p[k], f.h[i] = s.h[k], f.mass[i] = s.m[k];
    f.phase[i] = s.phase[k];
  }
  return f;
}

const char* signalName(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal";
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ",") + s;
  return out;
}

// The time series of a run: fixed columns, one per phase, one per probe (reports/SCHEMA.md).
class Series {
 public:
  explicit Series(const Scene& scene) {
    for (const char* n : {"time", "dt", "step", "dt_limiter", "kinetic_energy", "max_speed",
                          "rho_min", "rho_max", "volume_error"})
      columns.push_back({n, {}, {}, {}});
    for (const auto& ph : scene.phases) columns.push_back({"volume_error_" + ph.name, {}, {}, {}});
    for (const auto& p : scene.probes) {
      SeriesColumn c{
          "probe_" + p.name,
          {},
          {{"type", p.type}, {"units", p.type.find("pressure") != std::string::npos ? "Pa" : "m"}},
          {}};
      if (!p.reference.empty()) c.text.push_back({"reference", p.reference});
      if (p.scaleLength > 0) c.numbers.push_back({"scale_length", p.scaleLength});
      if (p.scaleHeight > 0) c.numbers.push_back({"scale_height", p.scaleHeight});
      columns.push_back(c);
    }
    countsDepartures = scene.leaving == Scene::Leaving::removed;
    if (countsDepartures) columns.push_back({"departed_particles", {}, {}, {}});
    maxVariation.assign(scene.phases.size() + 1, 0.0);
  }
  // `departed`: the volume of each phase that has left the run (Simulation::departedVolume),
  // counted in the volume errors as if still there: they measure the fluid's compression.
  void record(double t, double dt, long step, int limiter, const Diagnostics& d,
              const std::vector<double>& departed, std::size_t departures) {
    if (volume0.empty()) volume0 = d.phaseVolume, total0 = d.volume;
    double gone = 0;
    for (const double v : departed) gone += v;
    std::vector<double> row{t,
                            dt,
                            double(step),
                            double(limiter),
                            d.kineticEnergy,
                            d.maxSpeed,
                            d.rhoMin,
                            d.rhoMax,
                            (d.volume + gone) / total0 - 1.0};
    for (std::size_t k = 0; k < d.phaseVolume.size(); ++k)
      row.push_back(volume0[k] > 0 ? (d.phaseVolume[k] + departed[k]) / volume0[k] - 1.0 : 0.0);
    row.insert(row.end(), d.probes.begin(), d.probes.end());
    if (countsDepartures) row.push_back(double(departures));
    for (std::size_t k = 0; k < columns.size(); ++k) columns[k].values.push_back(row[k]);
    maxVariation[0] = std::max(maxVariation[0], std::abs(row[8]));
    for (std::size_t k = 0; k < d.phaseVolume.size(); ++k)
      maxVariation[k + 1] = std::max(maxVariation[k + 1], std::abs(row[9 + k]));
  }
  std::vector<SeriesColumn> columns;
  std::vector<double> volume0, maxVariation;  // [0]: all fluid, [1 + k]: phase k
  double total0 = 0;
  bool countsDepartures = false;  // the column departed_particles (leaving = "remove")
};

// /departures: each particle that left the run through an open face, as its last step left it.
template <class Departure>
void writeDepartures(RunFile& file, const std::vector<Departure>& departures) {
  std::vector<double> id, step, time, mass, density, phase, r[3], v[3];
  for (const Departure& d : departures) {
    id.push_back(d.id), step.push_back(double(d.step)), time.push_back(d.time);
    mass.push_back(d.m), density.push_back(d.rho), phase.push_back(d.phase);
    for (int a = 0; a < 3; ++a) {
      r[a].push_back(a < d.r.size() ? d.r[a] : 0.0);
      v[a].push_back(a < d.v.size() ? d.v[a] : 0.0);
    }
  }
  const std::string g = "/departures";
  file.array(g, "id", id), file.array(g, "step", step), file.array(g, "time", time);
  const char* axis[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) file.array(g, axis[a], r[a]);
  for (int a = 0; a < 3; ++a) file.array(g, std::string("u") + axis[a], v[a]);
  file.array(g, "mass", mass), file.array(g, "density", density), file.array(g, "phase", phase);
}

// /packing/block_<k>: the packing history of a block with initial = "packed" (issue 6), and a
// warning when it stopped on max_iterations instead of the kinetic-energy criterion.
void writePacking(RunFile& file, const Scene& scene, const PackedBlock& b) {
  const std::string g = "/packing/block_" + std::to_string(b.block);
  std::vector<double> it, kinetic, mean, grad;
  for (const auto& r : b.history) {
    it.push_back(r.iteration), kinetic.push_back(r.kinetic);
    mean.push_back(r.kineticMean), grad.push_back(r.maxGradGamma);
  }
  file.array(g, "iteration", it), file.array(g, "kinetic", kinetic);
  file.array(g, "kinetic_mean", mean), file.array(g, "max_grad_gamma", grad);
  const FluidBlock& f = scene.fluids[b.block];
  file.attribute("converged", std::int64_t(b.converged), g);
  file.attribute("iterations", std::int64_t(b.history.empty() ? 0 : b.history.back().iteration), g);
  file.attribute("stop_kinetic_energy", f.packingStop, g);
  file.attribute("noise", f.packingNoise, g);
  if (!b.converged && !b.history.empty())
    std::cerr << scene.file << ": warning: the packing of fluid block " << b.block
              << " stopped at max_iterations = " << f.packingMaxIterations
              << " with T/(N beta) = " << b.history.back().kineticMean
              << ", above stop_kinetic_energy = " << f.packingStop << "\n";
}

// The state of a checkpoint and the simulation continued from it (Simulation::resume). The
// rates of a state whose next step did not fail, evaluated again, must be the checkpoint's to the
// bit: else the build or the lists differ from the run's.
template <int D>
CheckpointState<D> resumeFrom(const std::string& path, const Scene& scene,
                              std::optional<Simulation<D>>& sim,
                              std::shared_ptr<DomainDecomposition<D>> domain) {
  CheckpointState<D> c = readCheckpoint<D>(path, scene);
  checkCheckpointRecord(path);
  sim.emplace(scene, c.particles);
  sim->particles().p = c.particles.p;
  sim->keepCellOrder(cellOrderSteps);
  // Its particles are stored in one process's order: their keys (any process count wrote it).
  if (domain) sim->distribute(domain);
  bool same = false;
  try {
    same = sim->resume(c.simulation, c.rates, !c.afterFailure);
  } catch (const std::invalid_argument& e) {
    throw CheckpointError(path + ": " + e.what());
  }
  if (!same)
    throw CheckpointError(
        path + ": the rates of its state, evaluated again, are not the ones it holds: " +
        (c.commit != provenance().commit
             ? "it was written by another build (git_commit " + c.commit + ", this one " +
                   provenance().commit + ") whose arithmetic differs"
             : std::string("it is damaged")));
  if (c.commit != provenance().commit)
    std::cerr << path << ": warning: written by the build of git_commit " << c.commit
              << ", this one is " << provenance().commit
              << ": the continued run may differ from an uninterrupted one in the last bits\n";
  return c;
}

// What ran: the build, the machine, the scene and its model (reports/SCHEMA.md).
template <int D>
void writeHeader(RunFile& file, const Scene& scene, const Simulation<D>& sim, int processes) {
  const Provenance p = provenance();
  file.attribute("sph_version", p.version), file.attribute("git_commit", p.commit);
  file.attribute("compiler", p.compiler), file.attribute("cxx_flags", p.flags);
  file.attribute("build_type", p.buildType), file.attribute("machine", p.machine);
  file.attribute("date", p.date);
  file.attribute("threads", std::int64_t(omp_get_max_threads()));  // of each process
  file.attribute("processes", std::int64_t(processes));
  file.attribute("scene_name", scene.name), file.attribute("scene_file", scene.file);
  file.attribute("dimension", std::int64_t(D));
  double g = 0;
  for (double c : scene.bodyAcceleration) g += c * c;
  file.attribute("gravity", std::sqrt(g));
  file.attribute("rho0", scene.phases[0].rho0);
  file.attribute("kernel", std::string(name(scene.kernel)));
  file.attribute("integrator", std::string(name(scene.integrator)));
  file.attribute("terms", join(sim.termNames()));
  file.attribute("boundary_model", std::string(sim.boundary().name()));
  file.attribute("status", std::string("running"));
  file.text("/scene", scene.text);
}

// Over several processes (DomainDecomposition.hpp), the whole domain's particles in one
// process's order and the set one process would hold, on process 0, for the record, the
// snapshots and the energy budget: what they sum, they sum in one process's order.
template <int D>
struct WholeDomain {
  const DomainDecomposition<D>* domain = nullptr;  // null: one process
  Particles<D> particles;
  std::vector<int> ids;
  InteractionSet<D> set;
  long at = -1;  // the step gathered

  bool writes() const { return !domain || domain->rank() == 0; }
  // The current state of `sim` (every process calls it; process 0 gets it).
  void gather(const Simulation<D>& sim, bool withSet) {
    if (at == sim.step()) return;
    domain->gather(sim.particles(), sim.ids(), sim.keys(), particles, ids);
    if (withSet && writes()) sim.wholeSet(particles, set);
    at = sim.step();
  }
  // The energy budget's check of a state every process holds its part of: made on process 0,
  // its verdict sent to all.
  std::optional<Failure> check(const EnergyBudget<D>& energy, const Simulation<D>& sim,
                               const Particles<D>& s, double t, long step) {
    Particles<D> all;
    std::vector<int> allIds;
    domain->gather(s, sim.ids(), sim.keys(), all, allIds);
    std::string verdict;
    if (writes())
      if (const auto f = energy.check(all, allIds, t, step)) verdict = encode(*f);
    domain->broadcast(verdict, 0);
    if (verdict.empty()) return std::nullopt;
    return decodeFailure(verdict);
  }
  std::int64_t sum(std::int64_t x) const { return domain ? domain->sumAll(x) : x; }
};

template <int D>
int run(const Scene& scene, const RunOptions& opt) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const bool restarted = !opt.restart.empty();
  std::vector<PackedBlock> packed;
  std::optional<Simulation<D>> storage;
  CheckpointState<D> resumed;
  const auto domain = slabDecomposition<D>(scene);  // null: one process
  if (restarted) {
    resumed = resumeFrom<D>(opt.restart, scene, storage, domain);
  } else {
    storage.emplace(scene, latticeParticles<D>(scene, &packed));
    storage->keepCellOrder(cellOrderSteps);
  }
  Simulation<D>& sim = *storage;
  if (!restarted && sim.particles().size() == 0) {
    std::cerr << scene.file << ": the fluid blocks hold no particles at dx = " << scene.dx << "\n";
    return exitBadInput;
  }
  // The energy budget's start, of all particles (before they are spread over the processes).
  const EnergyBudget<D> energy =
      restarted ? EnergyBudget<D>(scene,
                                  {resumed.progress.energyKinetic, resumed.progress.energyInternal,
                                   resumed.progress.energyPotential},
                                  resumed.progress.energyRoundOff)
                : EnergyBudget<D>(scene, sim.particles());
  WholeDomain<D> whole;
  whole.domain = domain.get();
  if (domain && !restarted) sim.distribute(domain);
  const bool writer = whole.writes();
  bool withSet = false;  // the pressure probes read the interaction set
  for (const auto& pr : scene.probes) withSet |= pr.type == "pressure";
  // Only process 0 writes.
  const std::string checkpoint = checkpointPath(opt.outDir, scene);
  if (writer) std::filesystem::create_directories(opt.outDir);
  std::optional<RunFile> output;
  if (writer) output.emplace((std::filesystem::path(opt.outDir) / (scene.name + ".h5")).string());
  RunFile* const out = writer ? &*output : nullptr;
  if (out) writeHeader(*out, scene, sim, domain ? domain->ranks() : 1);
  // The record segments of this run's checkpoints continue the restart's chain where they go
  // beside it (the checkpoint is continued in place), else start a chain of their own.
  RecordChain chain = newRecordChain();
  if (restarted && out) {
    RunFile& file = *out;
    file.attribute("restarted_from", opt.restart);
    file.attribute("restart_time", sim.time());
    file.attribute("restart_step", std::int64_t(sim.step()));
    RecordChain adopted = adoptCheckpointRecord(opt.restart, file);
    std::error_code ignored;
    if (!adopted.run.empty() && std::filesystem::equivalent(opt.restart, checkpoint, ignored))
      chain = std::move(adopted);
    else
      file.segmented({});
  }
  if (out)
    for (const PackedBlock& b : packed) writePacking(*out, scene, b);

  Series series(scene);
  long recorded = -1, snapshotted = -1;  // the steps last recorded and written
  InteractionSet<D> stateSet;            // the probes' set where the last evaluation's is not
  auto record = [&] {
    if (domain) whole.gather(sim, withSet);
    if (writer)
      series.record(sim.time(), sim.lastDt(), sim.step(), int(sim.lastLimit()),
                    domain ? diagnose<D>(scene, whole.particles, whole.set)
                           : diagnose<D>(scene, sim.particles(),
                                         withSet ? sim.stateSet(stateSet) : sim.interactionSet()),
                    sim.departedVolume(), sim.departures().size());
    recorded = sim.step();
  };
  auto snapshot = [&](bool lastGood) {
    if (domain) whole.gather(sim, withSet);
    if (writer) {
      out->appendSeries(series.columns);
      out->snapshot(
          sim.time(), sim.step(),
          domain ? fieldsOf(whole.particles, whole.ids) : fieldsOf(sim.particles(), sim.ids()),
          lastGood);
    }
    snapshotted = sim.step();
  };
  if (!restarted) {
    sim.prepare();
    record();
    snapshot(false);
  } else {
    const RunProgress& r = resumed.progress;
    recorded = r.recorded, snapshotted = r.snapshotted;
    series.volume0 = r.volume0, series.total0 = r.total0, series.maxVariation = r.maxVariation;
  }
  // Every series_every steps, as one of the simulation's checks of a new state: a state that fails
  // it is not taken, so the last good one is the simulation's own.
  if (energy.defined())
    sim.setCheck([&](const Particles<D>& s, double t, long step) -> std::optional<Failure> {
      if (step % scene.seriesEvery != 0) return std::nullopt;
      if (domain) return whole.check(energy, sim, s, t, step);
      return energy.check(s, sim.ids(), t, step);
    });
  double nextSnapshot = scene.snapshotInterval > 0 ? scene.snapshotInterval : scene.endTime;
  double nextCheckpoint = scene.checkpointInterval > 0 ? scene.checkpointInterval : 1e300;
  if (restarted)
    nextSnapshot = resumed.progress.nextSnapshot, nextCheckpoint = resumed.progress.nextCheckpoint;
  // The checkpoint of the state now: after the step's record and snapshot, before the ones a
  // stop adds (the uninterrupted run has neither).
  StepCounters beforeStep;  // the counters before the last step (a failed one counted its own)
  auto writeCheckpointNow = [&](const StepCounters* failedStep) {
    RunProgress r;
    r.nextSnapshot = nextSnapshot, r.nextCheckpoint = nextCheckpoint;
    r.recorded = recorded, r.snapshotted = snapshotted;
    r.volume0 = series.volume0, r.total0 = series.total0, r.maxVariation = series.maxVariation;
    r.energyKinetic = energy.start().kinetic, r.energyInternal = energy.start().internal;
    r.energyPotential = energy.start().potential, r.energyRoundOff = energy.roundOff();
    // Over several processes, the one-process checkpoint from the gathered state.
    typename Simulation<D>::Whole state;
    StepCounters failed;
    if (domain) {
      if (failedStep) {
        failed = *failedStep;
        failed.reflections = whole.sum(failed.reflections);
        domain->maxAll(&failed.reflectionDepth, 1);
        failedStep = &failed;
      }
      sim.gatherWhole(state);
      if (!out) return;
    }
    try {
      if (domain)
        writeCheckpoint<D>(checkpoint, scene, state, r, *out, series.columns, chain, failedStep);
      else
        writeCheckpoint<D>(checkpoint, sim, r, *out, series.columns, chain, failedStep);
    } catch (const OutputError& e) {
      out->outputFailedBeside(e.what());  // the run stops (exit 4) with the file saying why
      throw;
    }
  };
  const bool progress = writer && opt.progress && isatty(STDERR_FILENO);
  auto lastPrint = clock::now(), lastCheckpoint = lastPrint;
  auto since = [&](clock::time_point a, clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  RemainingTime remaining(scene.endTime);
  remaining.observe(since(start, lastPrint), sim.time(), sim.step());
  const int maxThreads = omp_get_max_threads();
  ThreadTuner tuner(maxThreads, opt.fixedThreads);
  std::optional<Failure> failure;
  int interrupted = 0;   // the signal that stopped the run (Interrupt.hpp)
  bool stopped = false;  // at --stop-at
  bool emptied = false;  // every particle has left through an open face
  while (sim.time() < scene.endTime * (1 - 1e-12)) {
    if (opt.stopAt > 0 && sim.time() >= opt.stopAt) {
      stopped = true;
      break;
    }
    interrupted = interruptSignal();
    if (domain) {  // every process stops at the same step
      double v = interrupted;
      domain->maxAll(&v, 1);
      interrupted = static_cast<int>(v);
    }
    if (interrupted) break;
    omp_set_num_threads(tuner.threads());
    const auto stepStart = clock::now();
    beforeStep = {sim.forceEvaluations(), sim.reusedNeighbourLists(), sim.wallReflections(),
                  sim.maxReflectionDepth()};
    failure = sim.advance(std::min(nextSnapshot, scene.endTime) - sim.time());
    const auto stepEnd = clock::now();
    tuner.took(since(stepStart, stepEnd));
    if (failure) break;
    if (scene.leaving == Scene::Leaving::removed &&
        whole.sum(static_cast<std::int64_t>(sim.particles().size())) == 0) {
      emptied = true;  // nothing is left to move
      break;
    }
    remaining.observe(since(start, stepEnd), sim.time(), sim.step());
    const bool atSnapshot = sim.time() >= nextSnapshot * (1 - 1e-12);
    if (atSnapshot || sim.step() % scene.seriesEvery == 0) record();
    if (atSnapshot) {
      snapshot(false);
      nextSnapshot += scene.snapshotInterval > 0 ? scene.snapshotInterval : scene.endTime;
    }
    bool onTime =
        opt.checkpointMinutes > 0 && since(lastCheckpoint, stepEnd) >= 60.0 * opt.checkpointMinutes;
    if (domain && opt.checkpointMinutes > 0) {  // the first process past it decides for all
      double v = onTime ? 1.0 : 0.0;
      domain->maxAll(&v, 1);
      onTime = v > 0;
    }
    if ((sim.time() >= nextCheckpoint * (1 - 1e-12) || onTime) &&
        sim.time() < scene.endTime * (1 - 1e-12)) {
      while (nextCheckpoint <= sim.time() * (1 + 1e-12)) nextCheckpoint += scene.checkpointInterval;
      writeCheckpointNow(nullptr);
      lastCheckpoint = clock::now();
    }
    if (progress && stepEnd - lastPrint > std::chrono::milliseconds(500)) {
      lastPrint = stepEnd;
      const double eta = remaining.seconds();  // tenths below 10 s, where whole seconds mislead
      std::fprintf(stderr, "\r  t = %.4g / %.4g s   step %ld   %.0f steps/s   ETA %.*f s   ",
                   sim.time(), scene.endTime, sim.step(), remaining.stepsPerSecond(),
                   eta < 10 ? 1 : 0, eta);
    }
  }
  if (progress) std::fprintf(stderr, "\n");
  omp_set_num_threads(maxThreads);
  const double onAll = tuner.shareOnAll();
  const double wall = std::chrono::duration<double>(clock::now() - start).count();
  const bool early = failure || interrupted || stopped;
  if (early) writeCheckpointNow(failure ? &beforeStep : nullptr);
  const std::int64_t particles = whole.sum(static_cast<std::int64_t>(sim.particles().size()));
  const std::int64_t reflections = whole.sum(sim.wallReflections());
  if (failure) {
    if (out) {
      out->attribute("status", std::string("unstable"));
      out->attribute("failure_cause", std::string(name(failure->cause)));
      out->attribute("failure", failure->message);
    }
    snapshot(true);
  } else if (interrupted || stopped) {
    // The state of the last step is a good one (checked as every step's): the run file ends with
    // it, so a run stopped on purpose keeps all it computed.
    if (out) {
      out->attribute("status", std::string("interrupted"));
      out->attribute("interrupted_by", std::string(stopped ? "stop_at" : signalName(interrupted)));
      out->attribute("failure_cause", std::string());
      out->attribute("failure", std::string());
    }
    if (recorded != sim.step()) record();
    if (snapshotted != sim.step()) snapshot(false);
    if (out) out->appendSeries(series.columns);
  } else if (out) {
    out->attribute("status", std::string("stable"));
    out->attribute("failure_cause", std::string());
    out->attribute("failure", std::string());
    // (the run ends early, at sim.time(), with nothing left to record or snapshot)
    if (emptied) out->attribute("ended_by", std::string("every particle left the domain"));
    out->appendSeries(series.columns);
  }
  if (!out)
    return failure ? exitNumericalFailure : interrupted ? exitInterrupted + interrupted : exitDone;
  RunFile& file = *out;
  if (scene.leaving == Scene::Leaving::removed) writeDepartures(file, sim.departures());
  const std::string m = "/metrics";
  file.attribute("wall_time_s", wall, m);
  file.attribute("steps", std::int64_t(sim.step()), m);
  file.attribute("particles", particles, m);
  file.attribute("end_time", sim.time(), m);
  file.attribute("force_evaluations", std::int64_t(sim.forceEvaluations()), m);
  file.attribute("kept_neighbour_lists", std::int64_t(sim.reusedNeighbourLists()), m);
  file.attribute("steps_on_all_threads", onAll, m);  // the rest on one (ThreadTuner)
  file.attribute("wall_reflections", reflections, m);
  if (scene.leaving == Scene::Leaving::removed)
    file.attribute("departed_particles", std::int64_t(sim.departures().size()), m);
  file.attribute("particle_evaluations_per_s", double(sim.forceEvaluations()) * particles / wall,
                 m);
  file.attribute("max_volume_variation", series.maxVariation[0], m);
  for (std::size_t k = 0; k < scene.phases.size(); ++k)
    file.attribute("max_volume_variation_" + scene.phases[k].name, series.maxVariation[k + 1], m);
  file.finish();
  // A run that reached its end needs its checkpoint no more: the run file holds it all.
  if (!early) removeCheckpoint(checkpoint);

  if (!opt.quiet) {
    std::printf("%s: %s at t = %.6g s after %ld steps, %lld particles, wall time %.2f s\n",
                scene.name.c_str(),
                failure                  ? "UNSTABLE"
                : interrupted || stopped ? "interrupted"
                                         : "done",
                sim.time(), sim.step(), static_cast<long long>(particles), wall);
    std::printf("  max volume variation %.4f %%", 100 * series.maxVariation[0]);
    for (std::size_t k = 0; k < scene.phases.size(); ++k)
      std::printf("   %s %.4f %%", scene.phases[k].name.c_str(), 100 * series.maxVariation[k + 1]);
    std::printf("\n  wall reflections %lld\n", static_cast<long long>(reflections));
    if (scene.leaving == Scene::Leaving::removed)
      std::printf("  %zu particles left through open faces%s\n", sim.departures().size(),
                  emptied ? " (all: the run ends here)" : "");
    std::printf("  force evaluations %ld, %.0f %% with the neighbour lists kept\n",
                sim.forceEvaluations(),
                100.0 * sim.reusedNeighbourLists() / std::max(1L, sim.forceEvaluations()));
    if (domain) std::printf("  %d processes (MPI)\n", domain->ranks());
    if (maxThreads > 1)
      std::printf("  steps on %d threads %.0f %%, on one %.0f %%%s\n", maxThreads, 100 * onAll,
                  100 * (1 - onAll), opt.fixedThreads ? " (--fixed-threads)" : "");
    std::printf("  run file %s\n", file.path().c_str());
    if (early) std::printf("  checkpoint %s\n", checkpoint.c_str());
  }
  const std::string resume = "; sph run --restart " + checkpoint + " continues it";
  if (failure) {
    std::cerr << scene.file << ": numerical failure (" << name(failure->cause)
              << "): " << failure->message << "; the checkpoint " << checkpoint
              << " holds the last good state\n";
    return exitNumericalFailure;
  }
  if (interrupted) {
    std::cerr << scene.file << ": interrupted by " << signalName(interrupted)
              << " at t = " << sim.time() << " s (of " << scene.endTime << " s) after "
              << sim.step() << " steps; the run file " << file.path()
              << " holds the run so far (status interrupted)" << resume << "\n";
    return exitInterrupted + interrupted;
  }
  if (stopped) {
    if (!opt.quiet)
      std::printf("  stopped at t = %.6g s (--stop-at %.6g s)%s\n", sim.time(), opt.stopAt,
                  resume.c_str());
    return exitDone;
  }
  return exitDone;
}

}  // namespace

int runScene(const Scene& scene, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  // Particle shifting's sums are not split over processes yet (solver/src/mpi/DESIGN-MPI.md).
  if (const int n = launchedProcesses(); n > 1 && scene.shifting.form != ShiftingForm::none)
    throw std::invalid_argument(scene.file +
                                ": a scene with particle shifting runs as one process, "
                                "not as the " +
                                std::to_string(n) + " processes it was launched as (mpirun -n " +
                                std::to_string(n) + ")");
  RunLimits limits = options.limits;
  limits.outDir = options.outDir;
  RunEstimate estimate = checkMemory(scene, limits);
  checkDuration(scene, limits, estimate);
  switch (scene.dimension) {
    case 1:
      return run<1>(scene, options);
    case 2:
      return run<2>(scene, options);
    case 3:
      return run<3>(scene, options);
  }
  // The scene reader admits 1, 2 and 3 only.
  throw std::logic_error("runScene: dimension " + std::to_string(scene.dimension));
}

}  // namespace sph
