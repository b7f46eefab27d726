// Issue 32, parts 6 and 7: a scene that would need more memory than the machine has, or would
// run for ever, is refused by `sph check` and `sph run` before anything is made (RunBudget.hpp),
// with exit 2 and the key and the numbers. dx = 5e-324 segfaulted in the cell list, dx = 1e-31
// hung (lround overflowed), dx = 1e-9 ended in exit 4 'std::bad_alloc' (an output error);
// mu = 1e300, p0 = 1e300, cfl_acoustic = 1e-300, end_time = 1e30 or a snapshot every 1e-300 s
// ran for ever.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;
namespace fs = std::filesystem;

// Part 6: the particle count and memory.
TEST(RunBudget, SubnormalDxIsRefused) {
  expectRejected("dx = 0.01", "dx = 5e-324", "numerics.dx", "particles, more than the solver");
  const std::string path = editedScene("dx = 0.01", "dx = 5e-324");
  const std::string out = (fs::path(path).parent_path() / "out").string();
  const ProgramResult r = runSph("run '" + path + "' --out '" + out + "' --threads 1 --quiet");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_FALSE(fs::exists(out)) << "a refused scene wrote " << out;
}

// lround overflowed here and the lattice loop never ended: bounded by a wait of 30 s.
TEST(RunBudget, TinyDxIsRefusedAtOnce) {
  const std::string path = editedScene("dx = 0.01", "dx = 1e-31");
  const std::string log = (fs::path(path).parent_path() / "log.txt").string();
  const int pid = startSph(
      {"run", path, "--out", fs::path(path).parent_path() / "out", "--threads", "1", "--quiet"},
      log);
  EXPECT_EQ(waitForSph(pid, 30), 2) << readText(log);
  EXPECT_NE(readText(log).find("key 'numerics.dx'"), std::string::npos) << readText(log);
}

TEST(RunBudget, DxBeyondTheMemoryIsRefused) {
  const std::string out = expectRejected("dx = 0.01", "dx = 1e-9", "numerics.dx",
                                         "the fluid blocks hold about 1e+16 particles");
  EXPECT_NE(out.find("more than the solver can index"), std::string::npos) << out;
}

// 10^4 particles: some 73 MiB by the estimate (64 MiB for the program, 926 B a particle).
TEST(RunBudget, MaxMemory) {
  const std::string path = editedScene("dx = 0.01", "dx = 0.001");
  const ProgramResult refused = runSph("check '" + path + "' --max-memory 32M");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  for (const char* part : {"key 'numerics.dx'", "about 1e+04 particles", "926 B a particle",
                           "more than the 0.0312 GiB available (--max-memory"})
    EXPECT_NE(refused.output.find(part), std::string::npos) << part << "\n" << refused.output;
  const ProgramResult accepted = runSph("check '" + path + "' --max-memory 1G");
  EXPECT_EQ(accepted.exitCode, 0) << accepted.output;
  EXPECT_NE(accepted.output.find("estimated: 1e+04 particles"), std::string::npos)
      << accepted.output;
}

// ulimit -v is a limit of the machine too.
TEST(RunBudget, AddressSpaceLimitIsRefused) {
  const std::string path = editedScene("dx = 0.01", "dx = 0.00005");  // 4e6 particles, 3.5 GiB
  const ProgramResult r = runSph("check '" + path + "'", "ulimit -v 300000;");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("the address space ulimit -v leaves"), std::string::npos) << r.output;
}

// An allocation that fails all the same (here: --max-memory above ulimit -v, so the estimate
// passes) is exit 5 with its own message, not an output error. The lattice start is built outside
// any OpenMP region, where the std::bad_alloc reaches main.
TEST(RunBudget, OutOfMemoryHasItsOwnExitCode) {
  const std::string path = editedScene("dx = 0.01", "dx = 0.00005");
  const std::string out = (fs::path(path).parent_path() / "out").string();
  const ProgramResult r =
      runSph("run '" + path + "' --out '" + out + "' --threads 1 --quiet --max-memory 100G",
             "ulimit -v 300000;");
  EXPECT_EQ(r.exitCode, 5) << r.output;
  EXPECT_NE(r.output.find("error: out of memory"), std::string::npos) << r.output;
}

// Part 7: how long a run would take, from its first time step.
TEST(RunBudget, EndlessEndTime) {
  // Without snapshots, so that the steps (not the snapshots) are what is too many.
  const std::string path = editedScene({{"end_time = 0.02", "end_time = 1e30"},
                                        {"snapshot_interval = 0.01", "snapshot_interval = 0"}});
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  for (const char* part : {"key 'numerics.end_time'", "steps, more than 1e+09",
                           "the acoustic limit 'numerics.cfl_acoustic'"})
    EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
}

TEST(RunBudget, EndlessEndTimeWithSnapshots) {
  expectRejected("end_time = 0.02", "end_time = 1e30", "output.snapshot_interval",
                 "to 'numerics.end_time' = 1e+30 s makes about 1e+32 snapshots, more than 1e+04");
}

// Issue 32, checkpoints: each copies the run file so far, so a checkpoint at every step of a long
// run would rewrite it thousands of times over.
TEST(RunBudget, TinyCheckpointInterval) {
  expectRejected("series_every = 5", "series_every = 5\ncheckpoint_interval = 1e-9",
                 "output.checkpoint_interval",
                 "to 'numerics.end_time' = 0.02 s makes about 2e+07 checkpoints, more than 1e+04");
}

TEST(RunBudget, TinyAcousticCfl) {
  expectRejected("h_over_dx = 1.33", "h_over_dx = 1.33\ncfl_acoustic = 1e-300",
                 "numerics.cfl_acoustic", "h / (c0 + |v|) = 1e-300 x 0.0133 m");
}

TEST(RunBudget, HugeViscosity) {
  expectRejected("mu = 1.0e-3", "mu = 1e300", "phase[0].mu", "the viscous limit");
}

TEST(RunBudget, HugeBackgroundPressure) {
  expectRejected("mu = 1.0e-3", "mu = 1.0e-3\np0 = 1e300", "phase[0].p0",
                 "a non-finite acceleration");
}

TEST(RunBudget, SnapshotEveryStep) {
  expectRejected("snapshot_interval = 0.01", "snapshot_interval = 1e-300",
                 "output.snapshot_interval", "makes about 2e+298 snapshots");
}

// The small tank takes some 120 steps.
TEST(RunBudget, MaxSteps) {
  const ProgramResult r = runSph("check '" + scenePath("small_tank.toml") + "' --max-steps 100");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("steps, more than 100 (sph check/run --max-steps)"), std::string::npos)
      << r.output;
  EXPECT_EQ(runSph("check '" + scenePath("small_tank.toml") + "' --max-steps 1000").exitCode, 0);
}

// The work counts what a particle costs: the SPHERIC case's wall particles within reach of the
// water (the fuzz driver counted fluid particles times steps, so a 3-D run on wall particles that
// took minutes passed its cap and was called a hang), and its integrator's evaluations a step.
TEST(RunBudget, WorkCountsWallParticlesAndEvaluations) {
  const std::string scene =
      std::string(SPH_SOURCE_DIR) + "/validation/scenes/spheric_dam_break_dx0.08.toml";
  const ProgramResult r = runSph("check '" + scene + "'");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  double particles = 0, entries = 0, evaluation = 0, seconds = 0, steps = 0, perStep = 0;
  const auto at = r.output.find("estimated: "), work = r.output.find("work: ");
  ASSERT_NE(at, std::string::npos) << r.output;
  ASSERT_NE(work, std::string::npos) << r.output;
  ASSERT_EQ(std::sscanf(r.output.c_str() + at, "estimated: %lf particles", &particles), 1);
  const auto stepsAt = r.output.find(" steps (first dt", at);
  ASSERT_NE(stepsAt, std::string::npos) << r.output;
  steps = std::stod(r.output.substr(r.output.rfind(' ', stepsAt - 1) + 1));
  ASSERT_EQ(std::sscanf(r.output.c_str() + work,
                        "work: %lf entries in the interaction set at the start (fluid, ghosts, "
                        "wall particles); a force evaluation %lf s here now, so about %lf s of "
                        "force evaluations (%lf a step)",
                        &entries, &evaluation, &seconds, &perStep),
            4)
      << r.output;
  // 1,360 fluid particles at dx 0.08 and the wall particles within reach of them (4,220).
  EXPECT_GT(entries, 2 * particles) << r.output;
  EXPECT_EQ(perStep, 2) << "the paper's predictor-corrector";
  EXPECT_GT(evaluation, 0);
  // (each printed to 3 digits)
  EXPECT_NEAR(seconds, steps * perStep * evaluation, 0.02 * seconds) << r.output;
}

TEST(RunBudget, HOverDxOutsideItsRange) {
  expectRejected("h_over_dx = 1.33", "h_over_dx = 1e-6", "numerics.h_over_dx",
                 "must lie in [1, 4], got 1e-06");
  expectRejected("h_over_dx = 1.33", "h_over_dx = 4.5", "numerics.h_over_dx", "must lie in [1, 4]");
  for (const char* edge : {"h_over_dx = 1.0", "h_over_dx = 4.0"}) {
    const ProgramResult r = runSph("check '" + editedScene("h_over_dx = 1.33", edge) + "'");
    EXPECT_EQ(r.exitCode, 0) << edge << "\n" << r.output;
  }
}

}  // namespace
