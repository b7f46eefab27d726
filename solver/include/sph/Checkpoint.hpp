#pragma once
// The checkpoint of `sph run` (<out>/<name>.checkpoint.h5; layout: reports/SCHEMA.md): the state
// after an accepted step, from which `sph run --restart` continues the run bit for bit as if it
// had not stopped. It holds the scene text, the particles in their stored (cell) order with their
// ids, the rates of that state, the simulation's clock, counters and dt floor, the positions and
// h at the neighbour lists' build (the lists are built again from them: Simulation::resume), the
// run loop's progress (next snapshot and checkpoint, the series' start values and maxima, the
// energy budget's start) and the list of its record segments: the run file's record so far
// (series, snapshots, packing), so that the continued run file is whole. A segment holds what the
// record gained since the segment before (RunFile::writeRecordSegment), so that a run's
// checkpoints write each snapshot once (a copy of the whole record at each checkpoint wrote C/2
// run files over C checkpoints). Segment k of a run is <out>/<name>.checkpoint.record/<run>/k.h5,
// written once, synced and renamed into place before the checkpoint that lists it, with a random
// token the checkpoint names: a checkpoint adopts only the segments it wrote. The checkpoint is
// written as <path>.partial, synced, then renamed over <path>: a checkpoint cut short leaves the
// previous one, and the segments it lists, as they were.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/ForceEvaluation.hpp"
#include "sph/Particles.hpp"
#include "sph/RunFile.hpp"
#include "sph/Scene.hpp"
#include "sph/Simulation.hpp"

namespace sph {

// A checkpoint that is missing, unreadable or not of this scene (bad input: exit 2, Run.hpp);
// the message names the file and what is wrong.
struct CheckpointError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// What the run loop (Run.cpp) carries from step to step besides the simulation.
struct RunProgress {
  double nextSnapshot = 0, nextCheckpoint = 0;
  long recorded = -1, snapshotted = -1;  // the steps last recorded and written
  std::vector<double> volume0, maxVariation;
  double total0 = 0;
  // EnergyBudget's start: kinetic, internal, potential energy and the round-off allowance.
  double energyKinetic = 0, energyInternal = 0, energyPotential = 0, energyRoundOff = 0;
};

// The simulation's counters before a step (Run.cpp keeps them): a step that fails has counted
// its evaluations and reflections, which the state it leaves (the last good one) has not.
struct StepCounters {
  long evaluations = 0, reusedLists = 0, reflections = 0;
  double reflectionDepth = 0;
};

template <int D>
struct CheckpointState {
  Particles<D> particles;  // in the stored order
  typename Simulation<D>::Resumable simulation;
  Derivatives<D> rates;  // of `particles`, as the step that wrote them left them
  RunProgress progress;
  std::string runFile;        // the run file's name (no directory)
  std::string commit;         // the build that wrote it (git_commit)
  bool afterFailure = false;  // written where the next step failed
};

// <out>/<scene name>.checkpoint.h5
std::string checkpointPath(const std::string& outDir, const Scene& scene);

// A run's chain of record segments: its name (16 random hex digits, new for each run that starts
// a chain) and the token of each segment written so far.
struct RecordChain {
  std::string run;
  std::vector<std::uint64_t> tokens;
};
RecordChain newRecordChain();

// Removes the checkpoint at `path` and the record segments beside it (a run that has finished).
void removeCheckpoint(const std::string& path);

// Writes the checkpoint of `sim` at `path`, with the record of `runFile` as of now (its series
// appended first, so none is left in `series`) as the next segment of `chain`. `failedStep`: the
// counters before the step that failed, where one did. Throws OutputError naming the path on a
// failed write; the previous checkpoint at `path` and its segments are then unchanged.
template <int D>
void writeCheckpoint(const std::string& path, const Simulation<D>& sim, const RunProgress& progress,
                     RunFile& runFile, std::vector<SeriesColumn>& series, RecordChain& chain,
                     const StepCounters* failedStep = nullptr);
// The same of a simulation's state over several processes, gathered (Simulation::gatherWhole).
template <int D>
void writeCheckpoint(const std::string& path, const Scene& scene,
                     const typename Simulation<D>::Whole& state, const RunProgress& progress,
                     RunFile& runFile, std::vector<SeriesColumn>& series, RecordChain& chain,
                     const StepCounters* failedStep = nullptr);

// The scene a checkpoint continues, parsed from its text as the scene file was (its `file` the
// scene file's path then). Throws CheckpointError.
Scene checkpointScene(const std::string& path);

// The state of a checkpoint of `scene` (from checkpointScene). Throws CheckpointError.
template <int D>
CheckpointState<D> readCheckpoint(const std::string& path, const Scene& scene);

// Throws CheckpointError where a record segment the checkpoint lists is missing, cannot be read
// or is not the one it wrote (before the run writes anything).
void checkCheckpointRecord(const std::string& path);

// Copies the checkpoint's record (series, snapshots, packing) into `runFile`, which then continues
// it; returns its chain (no run name for a checkpoint of the first format, which held the record
// itself). Throws CheckpointError where the checkpoint or a segment is missing, cannot be read or
// is not the one it wrote, OutputError where the run file cannot be written.
RecordChain adoptCheckpointRecord(const std::string& path, RunFile& runFile);

}  // namespace sph
