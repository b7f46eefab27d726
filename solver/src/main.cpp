// The `sph` program: run or check a scene file.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <new>
#include <stdexcept>

#include "sph/Checkpoint.hpp"
#include "sph/DomainDecomposition.hpp"
#include "sph/Interrupt.hpp"
#include "sph/LatticeUnderPressure.hpp"
#include "sph/Run.hpp"
#include "sph/Scene.hpp"
#include "sph/WaitPolicy.hpp"
#include "sph/packing/PackingScene.hpp"
#include "sph/packing/TankRun.hpp"

namespace {

// Bad input (SceneError, invalid_argument: named by file and key) exits 2, an allocation that
// failed 5; anything else that stops a run is the output failing to be written (HDF5, the file
// system) and exits 4. Only here is std::bad_alloc caught: one thrown inside an OpenMP region
// ends the program (std::terminate), which is why RunBudget refuses such scenes at the start.
int reportError(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e)) {
    std::cerr << "error: out of memory (" << e.what()
              << "): the scene passed the memory estimate, but an allocation failed (other "
                 "processes took the memory, or the estimate was short: sph run --max-memory "
                 "sets a lower limit for it)\n";
    return sph::exitOutOfMemory;
  }
  std::cerr << "error: " << e.what() << "\n";
  const bool badInput = dynamic_cast<const sph::SceneError*>(&e) != nullptr ||
                        dynamic_cast<const std::invalid_argument*>(&e) != nullptr;
  return badInput ? sph::exitBadInput : sph::exitOutputError;
}

// "1 phase", "2 phases".
std::string counted(std::size_t n, const std::string& noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// --max-memory and --max-steps, for `run` and `check`.
void addLimits(CLI::App* command, sph::RunLimits& limits, std::uint64_t& maxMemory) {
  command
      ->add_option("--max-memory", maxMemory,
                   "refuse a scene estimated to need more memory than this, e.g. 8G (default: "
                   "the memory available now)")
      ->transform(CLI::AsSizeValue(false));
  command
      ->add_option("--max-steps", limits.maxSteps,
                   "refuse a scene estimated to need more time steps than this")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

}  // namespace

int main(int argc, char** argv) {
  sph::chooseWaitPolicy(argv);  // first: it may execute the program again (WaitPolicy.hpp)
  CLI::App app{"sph: weakly compressible SPH (Lobovsky & Kren) with a V&V harness"};
  app.set_version_flag("--version",
                       std::string("sph ") + SPH_VERSION + " (" + SPH_GIT_COMMIT + ")");
  app.require_subcommand(1);
  std::string scenePath;
  sph::RunOptions options;
  options.progress = true;

  auto* run = app.add_subcommand("run", "run a scene to its end time and write <out>/<name>.h5");
  run->add_option("scene", scenePath, "scene file (TOML); not with --restart");
  run->add_option("--out", options.outDir,
                  "output directory (with --restart: default the checkpoint's directory)")
      ->capture_default_str();
  run->add_option("--restart", options.restart,
                  "continue the run of a checkpoint (<out>/<name>.checkpoint.h5) to its end time, "
                  "bit for bit as if it had not stopped; the scene is the checkpoint's");
  run->add_option("--stop-at", options.stopAt,
                  "stop after the first step at or past this simulated time [s], writing a "
                  "checkpoint (the run file's status is then interrupted)")
      ->check(CLI::PositiveNumber);
  run->add_option("--checkpoint-every", options.checkpointMinutes,
                  "also write a checkpoint after the first step this many wall-clock minutes "
                  "after the last one (besides the scene's output.checkpoint_interval)")
      ->check(CLI::PositiveNumber);
  run->add_option("--threads", options.threads, "OpenMP threads (default: all)")
      ->check(CLI::NonNegativeNumber);
  run->add_flag("--quiet", options.quiet, "print nothing but errors");
  run->add_flag("--fixed-threads", options.fixedThreads,
                "run every step on --threads threads (default: time them against one thread now "
                "and then and run the faster; results are the same either way)");

  std::uint64_t maxMemory = 0;
  addLimits(run, options.limits, maxMemory);

  auto* check = app.add_subcommand(
      "check", "read and validate a scene file and estimate its cost, run nothing");
  check->add_option("scene", scenePath, "scene file (TOML)")->required();
  check->add_option("--out", options.outDir, "where the run would write (its free space)")
      ->capture_default_str();
  addLimits(check, options.limits, maxMemory);

  // Colagrossi et al. (2012) particle packing: its own scene format (validation/packing/README.md).
  sph::packing::PackOptions packOptions;
  auto* pack =
      app.add_subcommand("pack", "pack the particles of a packing scene, write <out>/<name>.h5");
  pack->add_option("scene", scenePath, "packing scene file (TOML)")->required();
  pack->add_option("--out", packOptions.outDir, "output directory")->capture_default_str();
  pack->add_option("--threads", packOptions.threads, "OpenMP threads (default: all)")
      ->check(CLI::NonNegativeNumber);
  pack->add_flag("--quiet", packOptions.quiet, "print nothing but errors");

  // The hydrostatic tank of a packing scene run with fixed walls (Colagrossi et al. 2012, sections
  // 3.1-3.2; solver/include/sph/packing/TankRun.hpp); the history goes to standard output as CSV.
  sph::packing::TankRunOptions tank;
  double tankEnd = 100.0, tankEvery = 0.25, tankHOverDx = 0.0;
  int tankThreads = 0;
  auto* tankCmd = app.add_subcommand(
      "tank", "run a packing scene's tank at rest, print t sqrt(g/H), max|u|/sqrt(gH), E_k as CSV");
  tankCmd->add_option("scene", scenePath, "packing scene file (TOML)")->required();
  tankCmd->add_flag("--packed", tank.packed, "start from the packed particles (else the lattice)");
  tankCmd->add_option("--end", tankEnd, "end time t sqrt(g/H)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  tankCmd->add_option("--every", tankEvery, "output interval in t sqrt(g/H)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  tankCmd->add_option("--h-over-dx", tankHOverDx, "H / dx (default: the scene's dx)")
      ->check(CLI::PositiveNumber);
  tankCmd->add_option("--alpha", tank.alpha, "viscosity nu = alpha h c0 / 8")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  tankCmd->add_option("--beta", tank.beta, "artificial viscosity beta, eq. (10)")
      ->check(CLI::NonNegativeNumber);
  tankCmd->add_option("--cfl", tank.cflAcoustic, "acoustic CFL number")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  tankCmd->add_option("--damping", tank.dampingZeta, "settling damping zeta H / c0 (section 3.1.1)")
      ->check(CLI::NonNegativeNumber);
  tankCmd->add_option("--damping-time", tank.dampingTime, "damping until t sqrt(g/H)")
      ->check(CLI::NonNegativeNumber);
  tankCmd->add_option("--threads", tankThreads, "OpenMP threads (default: all)")
      ->check(CLI::NonNegativeNumber);
  tankCmd
      ->add_option("--restitution", tank.restitution,
                   "restitution of the wall reflections (0: onto the wall line; 1: mirror)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  bool tankNoReflect = false;
  tankCmd->add_flag("--no-reflect", tankNoReflect,
                    "do not reflect particles that end a step < dx/2 beyond a wall line");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : sph::exitBadInput;
  }
  if (pack->parsed()) {
    try {
      return sph::packing::packScene(sph::packing::readPackingScene(scenePath), packOptions);
    } catch (const std::exception& e) {
      return reportError(e);
    }
  }
  if (tankCmd->parsed()) {
    try {
      if (tankThreads > 0) omp_set_num_threads(tankThreads);
      sph::packing::PackingScene ps = sph::packing::readPackingScene(scenePath);
      if (tankHOverDx > 0) ps.dx = ps.lengthScale / tankHOverDx;
      tank.reflect = !tankNoReflect;
      sph::packing::TankRun run(ps, tank);
      // The last two columns: the wall reflections so far (TankRun::wallReflections) and the
      // deepest of them in units of dx.
      std::printf(
          "t_sqrt_g_over_H,max_u_over_sqrt_gH,Ek_over_rho0_g_H_V,wall_reflections,"
          "max_reflection_depth_over_dx\n");
      double next = 0.0;
      const auto failure = run.runTo(tankEnd, [&](const sph::packing::TankSample& x) {
        if (x.t + 1e-12 < next) return;
        std::printf("%.6g,%.6e,%.6e,%ld,%.4f\n", x.t, x.maxSpeed, x.kinetic, run.wallReflections(),
                    run.maxReflectionDepth() / ps.dx);
        next += tankEvery;
      });
      std::cerr << "wall reflections: " << run.wallReflections()
                << ", deepest: " << run.maxReflectionDepth() / ps.dx << " dx\n";
      if (failure) {
        std::cerr << "error: " << sph::name(failure->cause) << ": " << failure->message << "\n";
        return sph::exitNumericalFailure;
      }
      return sph::exitDone;
    } catch (const std::exception& e) {
      return reportError(e);
    }
  }
  options.limits.maxMemory = static_cast<double>(maxMemory);
  const bool restart = run->parsed() && !options.restart.empty();
  if (run->parsed() && restart == !scenePath.empty()) {
    std::cerr << "error: sph run takes a scene file or --restart CHECKPOINT, "
              << (restart ? "not both" : "and got neither") << "\n";
    return sph::exitBadInput;
  }
  sph::Scene scene;
  try {
    if (restart) {
      scene = sph::checkpointScene(options.restart);
      if (run->count("--out") == 0)
        options.outDir = std::filesystem::absolute(options.restart).parent_path().string();
    } else {
      scene = sph::readScene(scenePath);
    }
  } catch (const sph::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return sph::exitBadInput;
  } catch (const sph::CheckpointError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return sph::exitBadInput;
  }
  for (const auto& w : scene.warnings) std::cerr << w << "\n";
  if (check->parsed()) {
    try {
      options.limits.outDir = options.outDir;
      sph::RunEstimate e = sph::checkMemory(scene, options.limits);
      sph::checkDuration(scene, options.limits, e);
      std::cout << scenePath << ": ok (scene '" << scene.name << "', " << scene.dimension << "-D, "
                << counted(scene.fluids.size(), "fluid block") << ", "
                << counted(scene.phases.size(), "phase") << ")\n"
                << std::setprecision(3) << "  estimated: " << e.particles << " particles, "
                << e.memory / 1048576.0 << " MiB of memory (" << e.available / 1048576.0
                << " MiB available), " << e.steps << " steps (first dt " << e.firstDt << " s, "
                << e.limiter << " limit), " << e.snapshots << " snapshots, "
                << e.outputBytes / 1048576.0 << " MiB of output\n"
                << "  work: " << e.entries
                << " entries in the interaction set at the start (fluid, ghosts, wall particles); "
                << "a force evaluation " << e.evaluationSeconds << " s here now, so about "
                << e.runSeconds << " s of force evaluations (" << e.evaluationsPerStep
                << " a step)\n";
      if (const std::string note = sph::latticeUnderPressureNote(scene); !note.empty())
        std::cout << "  " << note << "\n";
      return sph::exitDone;
    } catch (const std::exception& e) {
      return reportError(e);
    }
  }
  try {
    // Launched as several processes (mpirun -n N): each runs its slab of the domain, process 0
    // writes the run file (sph/DomainDecomposition.hpp).
    sph::Processes processes;
    sph::catchInterrupts();
    return sph::runScene(scene, options);
  } catch (const std::exception& e) {
    return reportError(e);
  }
}
