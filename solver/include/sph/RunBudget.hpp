#pragma once
// What a scene will cost before any of it is made: `sph check` and `sph run` estimate the particle
// count, the memory, the number of steps, snapshots and bytes of output, and refuse a scene that
// exceeds the machine or the limits (SceneError, exit 2, naming the key and the numbers). A dx
// far too small segfaulted in the cell list, threw std::bad_alloc inside an OpenMP region (abort)
// or hung; a first step of 1e-300 s, or a snapshot every step, ran for ever.
#include <string>

#include "sph/Scene.hpp"

namespace sph {

struct RunLimits {
  double maxMemory = 0.0;  // bytes; 0: what the machine has available now (availableMemory)
  double maxSteps = 1e9;   // a year at 30 steps a second, far beyond any run of this solver
  // A guard against an interval typed too small (1e-300 wrote a snapshot every step): 1e4
  // snapshots are 100 a second of a 100 s run. The output's size is checked apart (outDir). The
  // same bound for the checkpoints (output.checkpoint_interval), each of which writes the state.
  double maxSnapshots = 1e4;
  std::string outDir = ".";  // the output's estimated size is compared with its free space
};

struct RunEstimate {
  double particles = 0.0;         // fluid particles
  double bytesPerParticle = 0.0;  // the memory model below
  double memory = 0.0;            // bytes
  double available = 0.0;         // bytes
  std::string availableSource;    // where `available` comes from
  double firstDt = 0.0;           // s, the first step's stable dt (Morris et al. 1997)
  std::string limiter;            // acoustic, viscous or acceleration
  double steps = 0.0, snapshots = 0.0, outputBytes = 0.0;
  // The work: the interaction set's entries at the start (fluid, ghosts and the wall particles
  // within reach of it), the wall time of one force evaluation of the start with its lists kept
  // (on this machine, now, on the threads OpenMP gives), and that times the evaluations of all
  // the steps (the integrator's a step): what the run spends, less its output, list builds, the
  // wall particles its flow reaches later and the load's changes (measured: 0.4-0.75 of a run).
  double entries = 0.0, evaluationSeconds = 0.0, evaluationsPerStep = 0.0, runSeconds = 0.0;
};

// Peak memory of a run, measured (peak RSS of `sph run`, 2026-12-01, this machine): 650-710 B a
// particle in 2-D at h/dx 1.33 (dam break, 0.5-12.5 M particles: 8.07 GB at 12.5 M), 1070-1200 B
// in 3-D (hydrostatic box, 0.26-1 M), and 4 B more for every neighbour listed (those within
// (1 + neighbour_skin) 2h: at h/dx 2 and 4, 864 and 1578 B in 2-D, 2190 and 11200 B in 3-D).
// The model, a + 4.5 B x listed neighbours with a = 620 B (1-D, 2-D) or 800 B (3-D), times 1.25
// for ghosts, allocator slack and the snapshot buffers, lies 25-45 % above every measurement.
double bytesPerParticle(const Scene& scene);

// The machine's memory available now: /proc/meminfo MemAvailable, or less where the process's
// cgroup (v2 memory.max, v1 memory.limit_in_bytes) or its address-space limit (ulimit -v, less
// the virtual size now) leaves less. 0 where none can be read.
double availableMemory(std::string* source = nullptr);

// The fluid particles of the scene's blocks, counted in double arithmetic so that no count can
// overflow (rectangles exactly; circles by their area or volume over dx^D).
double estimateParticles(const Scene& scene);

// The particle count and memory: throws SceneError naming numerics.dx where the count passes the
// solver's int indices or the memory the available (or --max-memory).
RunEstimate checkMemory(const Scene& scene, const RunLimits& limits);

// The first step, from the lattice start's first force evaluation (done here, on a simulation of
// its own that is freed before the run builds its own; a second one is timed): the number of
// steps, snapshots and bytes of output, and the work. Throws SceneError naming the keys where one
// passes its limit. Call checkMemory first.
void checkDuration(const Scene& scene, const RunLimits& limits, RunEstimate& estimate);

}  // namespace sph
