#pragma once
// Runs a checked scene to its end time and writes its run file. Exit codes of the `sph` program.
#include <string>

#include "sph/RunBudget.hpp"
#include "sph/Scene.hpp"

namespace sph {

// exitOutOfMemory: an allocation failed (std::bad_alloc) although the scene passed the memory
// estimate (RunBudget.hpp): other processes took memory, or the estimate was short.
// exitOutputError: the run file or the output directory cannot be written (a full disk, a path that
// is a file); the message names the path. exitInterrupted + the signal (130 SIGINT, 143 SIGTERM,
// the shell's convention): the run was stopped by one (Interrupt.hpp) and its run file, status
// interrupted, holds the run so far.
enum ExitCode {
  exitDone = 0,
  exitBadInput = 2,
  exitNumericalFailure = 3,
  exitOutputError = 4,
  exitOutOfMemory = 5,
  exitInterrupted = 128
};

struct RunOptions {
  std::string outDir = ".";
  int threads = 0;            // 0: OpenMP's default
  bool fixedThreads = false;  // every step on `threads`; else the faster of them and one
                              // (ThreadTuner)
  bool progress = false;      // a progress line on stderr (only on a terminal)
  bool quiet = false;
  RunLimits limits;  // checked before anything is made (its outDir is set from outDir)
  // A checkpoint (Checkpoint.hpp) to continue, of the scene given to runScene (from
  // checkpointScene); empty: a run from the start.
  std::string restart;
  // > 0: the run stops after the first step at or past this simulated time [s] (the step is not
  // shortened to it, so that a restart continues the uninterrupted run's steps), writes a
  // checkpoint and ends with status interrupted (interrupted_by "stop_at") and exitDone.
  double stopAt = 0.0;
  // > 0: a checkpoint also after the first step that ends this many wall-clock minutes after the
  // last one (or the start), besides the scene's output.checkpoint_interval.
  double checkpointMinutes = 0.0;
};

// Throws SceneError where the scene passes the limits (checkMemory, checkDuration). Returns
// exitDone, or exitNumericalFailure when the run stopped on a failure (the run file then
// keeps the series so far and the last good state as its final snapshot), or exitInterrupted + the
// signal when catchInterrupts() is in force and SIGINT or SIGTERM came.
int runScene(const Scene& scene, const RunOptions& options);

// Build and machine facts written into every run file.
struct Provenance {
  std::string version, commit, compiler, flags, buildType, machine, date;
};
Provenance provenance();

}  // namespace sph
