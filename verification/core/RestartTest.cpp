// Issue 32, checkpoint and restart: a run stopped part way (--stop-at, SIGTERM, SIGKILL after a
// checkpoint at the scene's cadence) and continued with `sph run --restart` writes a run file
// whose every dataset and counter is bit-identical to the run that did not stop
// (perf/compare_runs.py), and a checkpoint that is missing, damaged or not one is exit 2 with a
// message naming it.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;
namespace fs = std::filesystem;

// The quick tier's dam break (validation/scenes/dam_break_dx0.025.toml, 200 particles) to 0.5 s:
// the collapse and the surge's run along the floor, 2,200 steps, cell order renewed every 10 and
// neighbour lists kept between builds, so that a stop falls between them.
// With `integrator` set, numerics.integrator names it.
std::string shortDamBreak(const std::string& dir, const std::string& integrator = "") {
  std::string text =
      readText(std::string(SPH_SOURCE_DIR) + "/validation/scenes/dam_break_dx0.025.toml");
  const std::string from = "end_time = 1.3";
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  text.replace(
      at, from.size(),
      "end_time = 0.5" + (integrator.empty() ? "" : "\nintegrator = \"" + integrator + "\""));
  const std::string path = dir + "/dam_break_short.toml";
  writeText(path, text);
  return path;
}

void expectSameRun(const std::string& reference, const std::string& restarted) {
  const ProgramResult same = compareRuns(reference, restarted);
  EXPECT_EQ(same.exitCode, 0) << same.output;
  EXPECT_NE(same.output.find("datasets bit-identical"), std::string::npos) << same.output;
}

// Runs `scene` whole, and stopped at 0.25 s on two threads and continued on one; the two run
// files must be the same to the bit.
void expectStopAndContinueBitForBit(const std::string& scene, const std::string& out) {
  const std::string whole = out + "/whole", part = out + "/part";
  const ProgramResult a =
      runSph("run '" + scene + "' --out '" + whole + "' --threads 1 --fixed-threads --quiet");
  ASSERT_EQ(a.exitCode, 0) << a.output;
  // Stopped on two threads, continued on one: the sums do not depend on the thread count.
  const ProgramResult b =
      runSph("run '" + scene + "' --out '" + part + "' --threads 2 --stop-at 0.25 --quiet");
  ASSERT_EQ(b.exitCode, 0) << b.output;
  const std::string checkpoint = part + "/dam_break_dx0.025.checkpoint.h5";
  ASSERT_TRUE(fs::exists(checkpoint));
  EXPECT_EQ(stringAttribute(part + "/dam_break_dx0.025.h5", "/", "interrupted_by"), "stop_at");
  const double stoppedAt = *doubleAttribute(checkpoint, "/", "time");
  EXPECT_GE(stoppedAt, 0.25);
  EXPECT_LT(stoppedAt, 0.26);
  const ProgramResult c = runSph("run --restart '" + checkpoint + "' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  const std::string restarted = part + "/dam_break_dx0.025.h5";
  EXPECT_EQ(stringAttribute(restarted, "/", "status"), "stable");
  EXPECT_EQ(doubleAttribute(restarted, "/", "restart_time"), stoppedAt);
  EXPECT_FALSE(fs::exists(checkpoint)) << "a finished run removes its checkpoint";
  expectSameRun(whole + "/dam_break_dx0.025.h5", restarted);
}

TEST(Restart, DamBreakStoppedHalfwayContinuesBitForBit) {
  const std::string out = freshOutputDirectory();
  expectStopAndContinueBitForBit(shortDamBreak(out), out);
  EXPECT_EQ(stringAttribute(out + "/part/dam_break_dx0.025.h5", "/", "integrator"),
            "predictor_corrector");
}

// The same with position Verlet (issue 31): the checkpoint's scene carries the integrator.
TEST(Restart, PositionVerletDamBreakStoppedHalfwayContinuesBitForBit) {
  const std::string out = freshOutputDirectory();
  expectStopAndContinueBitForBit(shortDamBreak(out, "position_verlet"), out);
  EXPECT_EQ(stringAttribute(out + "/part/dam_break_dx0.025.h5", "/", "integrator"),
            "position_verlet");
}

// The same with velocity Verlet (issue 36), whose rates go from step to step (and into the
// checkpoint) without being those of the state: taken as they are, reordered with the particles.
TEST(Restart, VelocityVerletDamBreakStoppedHalfwayContinuesBitForBit) {
  const std::string out = freshOutputDirectory();
  expectStopAndContinueBitForBit(shortDamBreak(out, "velocity_verlet"), out);
  EXPECT_EQ(stringAttribute(out + "/part/dam_break_dx0.025.h5", "/", "integrator"),
            "velocity_verlet");
}

// The same in 3-D (CORE_SCENES/hydrostatic_box_3d.toml: 512 particles, 290 steps), whose
// checkpoint stores 3-vectors and whose lists hold the ghosts of five walls.
TEST(Restart, Box3dStoppedHalfwayContinuesBitForBit) {
  const std::string out = freshOutputDirectory();
  const std::string scene = scenePath("hydrostatic_box_3d.toml");
  const std::string whole = out + "/whole", part = out + "/part";
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + whole + "' --threads 1 --quiet").exitCode, 0);
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + part + "' --threads 2 --stop-at 0.0277 --quiet")
                .exitCode,
            0);
  const ProgramResult c =
      runSph("run --restart '" + part + "/hydrostatic_box_3d.checkpoint.h5' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  expectSameRun(whole + "/hydrostatic_box_3d.h5", part + "/hydrostatic_box_3d.h5");
}

// A packed start (CORE_SCENES/packed_tank.toml): the restart takes the particles from the
// checkpoint, packs nothing, and its run file keeps the packing history (/packing/block_0).
TEST(Restart, PackedStartKeepsItsPackingHistory) {
  const std::string out = freshOutputDirectory();
  const std::string scene = scenePath("packed_tank.toml");
  const std::string whole = out + "/whole", part = out + "/part";
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + whole + "' --threads 1 --quiet").exitCode, 0);
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + part + "' --threads 2 --stop-at 0.011 --quiet")
                .exitCode,
            0);
  const ProgramResult c =
      runSph("run --restart '" + part + "/packed_tank.checkpoint.h5' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  EXPECT_EQ(c.output.find("packing"), std::string::npos) << "the restart packed again:\n"
                                                         << c.output;
  EXPECT_FALSE(readDoubles(part + "/packed_tank.h5", "/packing/block_0/kinetic").empty());
  expectSameRun(whole + "/packed_tank.h5", part + "/packed_tank.h5");
}

// A continued run stopped again and continued again is the same run.
TEST(Restart, RestartedRunStoppedAgainContinuesBitForBit) {
  const std::string out = freshOutputDirectory();
  const std::string scene = shortDamBreak(out);
  const std::string whole = out + "/whole", part = out + "/part";
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + whole + "' --threads 2 --quiet").exitCode, 0);
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + part + "' --stop-at 0.1 --quiet").exitCode, 0);
  const std::string checkpoint = part + "/dam_break_dx0.025.checkpoint.h5";
  const ProgramResult again =
      runSph("run --restart '" + checkpoint + "' --stop-at 0.3 --threads 1 --quiet");
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_GE(*doubleAttribute(checkpoint, "/", "time"), 0.3);
  ASSERT_EQ(runSph("run --restart '" + checkpoint + "' --quiet").exitCode, 0);
  expectSameRun(whole + "/dam_break_dx0.025.h5", part + "/dam_break_dx0.025.h5");
}

// The small tank with gravity to 2.5 s and a density band of +-0.5 % fails when its collapsing
// column reaches the wall, at step 254 (t = 0.041 s; its hydrostatic start is within 0.25 %): its
// checkpoint holds the last good state, and the restart takes the failing step again and fails
// the same way, with the same run file. (It used to fail on energy growth at step 360, which the
// no-slip floor's ghosts drove: boundaries/NoSlipContinuity.hpp.)
TEST(Restart, FailureCheckpointFailsTheSameWay) {
  const std::string scene =
      editedScene({{"end_time = 0.02", "end_time = 2.5\ndensity_band = [0.995, 1.005]"},
                   {"snapshot_interval = 0.01", "snapshot_interval = 0.02"}});
  const fs::path dir = fs::path(scene).parent_path();
  const std::string out = (dir / "out").string(), h5 = out + "/small_tank.h5";
  const ProgramResult a = runSph("run '" + scene + "' --out '" + out + "' --threads 1 --quiet");
  ASSERT_EQ(a.exitCode, 3) << a.output;
  const std::string checkpoint = out + "/small_tank.checkpoint.h5";
  EXPECT_EQ(integerAttribute(checkpoint, "/", "after_failure"), 1);
  const std::string failed = (dir / "failed.h5").string();
  fs::copy_file(h5, failed);
  const ProgramResult b = runSph("run --restart '" + checkpoint + "' --threads 2 --quiet");
  ASSERT_EQ(b.exitCode, 3) << b.output;
  EXPECT_EQ(stringAttribute(h5, "/", "failure"), stringAttribute(failed, "/", "failure"));
  expectSameRun(failed, h5);
}

// The small tank without gravity (RunOutputTest.cpp's long run: its hydrostatic start relaxes,
// nothing fails) for 2.5 s, some 15,000 steps: 0.3-0.5 s of a quiet machine, several seconds of a
// loaded one. `interval` > 0 sets output.checkpoint_interval; a snapshot every `snapshots` s.
std::string tankScene(double interval, double snapshots = 0.5) {
  return editedScene(
      {{"end_time = 0.02", "end_time = 2.5"},
       {"gravity = [0.0, -9.81]", "gravity = [0.0, 0.0]"},
       {"snapshot_interval = 0.01", "snapshot_interval = " + std::to_string(snapshots) +
                                        "\ncheckpoint_interval = " + std::to_string(interval)}});
}

// The uninterrupted run's wall time, from which a signal's delay is taken so that it lands part way
// on a fast machine as on a slow one (a fixed 400 ms outlasted the whole run on CI's machine).
double timedRun(const std::string& scene, const std::string& out) {
  const auto start = std::chrono::steady_clock::now();
  const ProgramResult r = runSph("run '" + scene + "' --out '" + out + "' --threads 1 --quiet");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(Restart, SigtermCheckpointIsRestartable) {
  const std::string scene = tankScene(0.0);
  const fs::path dir = fs::path(scene).parent_path();
  const std::string whole = (dir / "whole").string(), part = (dir / "part").string();
  const double wall = timedRun(scene, whole);
  const std::string log = (dir / "log.txt").string();
  const int pid = startSph({"run", scene, "--out", part, "--threads", "1", "--quiet"}, log);
  ASSERT_TRUE(waitForFile(part + "/small_tank.h5.partial", 60)) << readText(log);
  std::this_thread::sleep_for(std::chrono::duration<double>(0.3 * wall));
  kill(pid, SIGTERM);
  ASSERT_EQ(waitForSph(pid, 60), 128 + SIGTERM) << readText(log);
  const std::string checkpoint = part + "/small_tank.checkpoint.h5";
  EXPECT_NE(readText(log).find("sph run --restart " + checkpoint), std::string::npos)
      << readText(log);
  ASSERT_TRUE(fs::exists(checkpoint));
  EXPECT_FALSE(fs::exists(checkpoint + ".partial"));
  EXPECT_LT(*doubleAttribute(checkpoint, "/", "time"), 2.5);
  const ProgramResult c = runSph("run --restart '" + checkpoint + "' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  expectSameRun(whole + "/small_tank.h5", part + "/small_tank.h5");
}

// Killed with no chance to write anything (SIGKILL), the run leaves the checkpoint of the
// scene's cadence, whole: the restart from it continues the run as if nothing had happened.
TEST(Restart, CheckpointAtTheScenesCadenceSurvivesSigkill) {
  const std::string scene = tankScene(0.05);
  const fs::path dir = fs::path(scene).parent_path();
  const std::string whole = (dir / "whole").string(), part = (dir / "part").string();
  const double wall = timedRun(scene, whole);
  const std::string log = (dir / "log.txt").string();
  const std::string checkpoint = part + "/small_tank.checkpoint.h5";
  const int pid = startSph({"run", scene, "--out", part, "--threads", "1", "--quiet"}, log);
  ASSERT_TRUE(waitForFile(checkpoint, 60)) << readText(log);
  std::this_thread::sleep_for(std::chrono::duration<double>(0.25 * wall));
  kill(pid, SIGKILL);
  ASSERT_EQ(waitForSph(pid, 60), 128 + SIGKILL);
  const double at = *doubleAttribute(checkpoint, "/", "time");
  EXPECT_GT(at, 0.0);
  EXPECT_LT(at, 2.5);
  const ProgramResult c = runSph("run --restart '" + checkpoint + "' --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  expectSameRun(whole + "/small_tank.h5", part + "/small_tank.h5");
}

// The record segments of checkpoint directory `part` (Checkpoint.hpp): the one chain's files in
// order.
std::vector<fs::path> recordSegments(const std::string& part) {
  std::vector<fs::path> chains;
  for (const auto& e : fs::directory_iterator(part + "/small_tank.checkpoint.record"))
    chains.push_back(e.path());
  EXPECT_EQ(chains.size(), 1u) << "one chain of segments";
  std::vector<fs::path> segments;
  for (int k = 0; !chains.empty(); ++k) {
    char name[16];
    std::snprintf(name, sizeof name, "%05d.h5", k);
    if (!fs::exists(chains[0] / name)) break;
    segments.push_back(chains[0] / name);
  }
  return segments;
}

// Each checkpoint writes what the record gained since the one before: over 21 checkpoints the
// segments hold every snapshot once and in order, together about one run file. (A copy of the
// whole record at each checkpoint, as before, held the first snapshot 21 times and some ten run
// files in all.) The restart from them continues the run bit for bit, and the finished run
// removes them.
TEST(Restart, CheckpointSegmentsHoldEachSnapshotOnce) {
  const std::string scene = tankScene(0.1, 0.05);
  const fs::path dir = fs::path(scene).parent_path();
  const std::string whole = (dir / "whole").string(), part = (dir / "part").string();
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + whole + "' --threads 1 --quiet").exitCode, 0);
  EXPECT_FALSE(fs::exists(whole + "/small_tank.checkpoint.record"));
  const ProgramResult stopped =
      runSph("run '" + scene + "' --out '" + part + "' --threads 1 --stop-at 2.0 --quiet");
  ASSERT_EQ(stopped.exitCode, 0) << stopped.output;
  const std::vector<fs::path> segments = recordSegments(part);
  // Checkpoints at 0.1, 0.2, ... up to the stop's (the last near 2.0).
  EXPECT_GE(segments.size(), 20u);
  EXPECT_LE(segments.size(), 21u);
  std::vector<std::string> snapshots;
  double bytes = 0;
  for (const fs::path& segment : segments) {
    bytes += static_cast<double>(fs::file_size(segment));
    for (const std::string& s : groupMembers(segment.string(), "/snapshots"))
      snapshots.push_back(s);
  }
  ASSERT_GE(snapshots.size(), 40u);  // 0, 0.05, ..., about 2.0
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    char name[16];
    std::snprintf(name, sizeof name, "%05zu", k);
    EXPECT_EQ(snapshots[k], name) << "snapshot " << k << " of the segments";
  }
  const double runFile = static_cast<double>(fs::file_size(whole + "/small_tank.h5"));
  EXPECT_LT(bytes, 1.5 * runFile) << "the segments hold " << bytes << " bytes";
  const std::string checkpoint = part + "/small_tank.checkpoint.h5";
  const ProgramResult c = runSph("run --restart '" + checkpoint + "' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  expectSameRun(whole + "/small_tank.h5", part + "/small_tank.h5");
  EXPECT_FALSE(fs::exists(checkpoint));
  EXPECT_FALSE(fs::exists(part + "/small_tank.checkpoint.record"));
}

// A full disk part way: a tmpfs of its own (in a user and mount namespace: unshare -rm, no root
// needed) filled, after the first checkpoint, to 24 kB from full. The run stops with exit 4 at
// the next checkpoint it cannot write; the run file is readable, marked output_error; the
// checkpoint left is the last whole one, and on a disk with room it continues the run bit for
// bit. Checkpoints every 0.1 s and snapshots only at the ends, so that a checkpoint meets the full
// disk before a snapshot's room check does.
TEST(Restart, FullDiskKeepsTheLastCheckpointRestartable) {
  const std::string scene = tankScene(0.1, 2.5);
  const fs::path dir = fs::path(scene).parent_path();
  const std::string whole = (dir / "whole").string(), copy = (dir / "copy").string();
  const std::string mount = (dir / "disk").string(), script = (dir / "full_disk.sh").string();
  ASSERT_EQ(runSph("run '" + scene + "' --out '" + whole + "' --threads 1 --quiet").exitCode, 0);
  fs::create_directories(copy), fs::create_directories(mount);
  writeText(script,
            "mount -t tmpfs -o size=4m tmpfs \"$1\" || exit 90\n"
            "\"$2\" run \"$3\" --out \"$1/out\" --threads 1 --quiet > \"$4/log.txt\" 2>&1 &\n"
            "pid=$!\n"
            "n=0\n"
            "while [ ! -e \"$1/out/small_tank.checkpoint.h5\" ] && [ $n -lt 20000 ]; do\n"
            "  n=$((n + 1)); sleep 0.001\n"
            "done\n"
            "avail=$(df -k --output=avail \"$1\" | tail -n 1)\n"
            "dd if=/dev/zero of=\"$1/filler\" bs=1024 count=$((avail - 24)) 2>/dev/null\n"
            "wait $pid\n"
            "rc=$?\n"
            "rm -f \"$1/filler\"\n"
            "cp -a \"$1/out/.\" \"$4/\"\n"
            "exit $rc\n");
  const std::string command = "unshare -rm sh '" + script + "' '" + mount + "' '" + SPH_EXE +
                              "' '" + scene + "' '" + copy + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[4096];
  while (fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  ASSERT_TRUE(WIFEXITED(status)) << output;
  ASSERT_NE(WEXITSTATUS(status), 90) << "no tmpfs could be mounted (unshare -rm): " << output;
  const std::string log = readText(copy + "/log.txt");
  EXPECT_EQ(WEXITSTATUS(status), 4) << output << log;
  EXPECT_NE(log.find("No space left on device"), std::string::npos) << log;
  const std::string partial = copy + "/small_tank.h5.partial";
  EXPECT_EQ(stringAttribute(partial, "/", "status"), "output_error");
  EXPECT_FALSE(readDoubles(partial, "/snapshots/00000/density").empty());
  const std::string checkpoint = copy + "/small_tank.checkpoint.h5";
  ASSERT_TRUE(fs::exists(checkpoint)) << log;
  EXPECT_FALSE(fs::exists(checkpoint + ".partial"));
  const double at = *doubleAttribute(checkpoint, "/", "time");
  EXPECT_GE(at, 0.1);
  EXPECT_LT(at, 2.5);
  const ProgramResult c = runSph("run --restart '" + checkpoint + "' --threads 1 --quiet");
  ASSERT_EQ(c.exitCode, 0) << c.output;
  expectSameRun(whole + "/small_tank.h5", copy + "/small_tank.h5");
}

// A checkpoint of the small tank stopped at 0.01 s, for the damage below.
std::string tankCheckpoint(const std::string& out) {
  const ProgramResult r = runSph("run '" + scenePath("small_tank.toml") + "' --out '" + out +
                                 "' --threads 1 --stop-at 0.01 --quiet");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return out + "/small_tank.checkpoint.h5";
}

void expectRefused(const std::string& checkpoint, const std::string& says) {
  const ProgramResult r = runSph("run --restart '" + checkpoint + "' --quiet");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(checkpoint), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
}

TEST(Restart, MissingOrDamagedCheckpointIsBadInput) {
  const std::string out = freshOutputDirectory();
  expectRefused(out + "/none.checkpoint.h5", "no such file");
  const std::string text = out + "/text.checkpoint.h5";
  writeText(text, "not a checkpoint\n");
  expectRefused(text, "not an HDF5 file, or damaged");

  const std::string checkpoint = tankCheckpoint(out);
  ASSERT_TRUE(fs::exists(checkpoint));
  // A run file is HDF5 but not a checkpoint.
  expectRefused(out + "/small_tank.h5", "not a checkpoint of sph run");
  // Cut short (a copy of its first half, as a full disk or a killed copy would leave it).
  const std::string bytes = readText(checkpoint);
  const std::string cut = out + "/cut.checkpoint.h5";
  writeText(cut, bytes.substr(0, bytes.size() / 2));
  expectRefused(cut, "damaged");
  // One density changed by one ulp: the rates evaluated again are not the stored ones.
  const std::string edited = out + "/edited.checkpoint.h5";
  fs::copy_file(checkpoint, edited);
  {
    const hid_t f = H5Fopen(edited.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t d = H5Dopen2(f, "/state/density", H5P_DEFAULT);
    ASSERT_GE(d, 0);
    std::vector<double> rho(100);
    ASSERT_GE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rho.data()), 0);
    rho[37] = std::nextafter(rho[37], 2e3);
    ASSERT_GE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rho.data()), 0);
    H5Dclose(d);
    H5Fclose(f);
  }
  expectRefused(edited, "are not the ones it holds: it is damaged");
  // Without its record segments (moved on its own), or with another run's in their place.
  const std::string moved = out + "/moved/small_tank.checkpoint.h5";
  fs::create_directories(out + "/moved");
  fs::copy_file(checkpoint, moved);
  expectRefused(moved, "its record segment");
  const std::string other = out + "/other";
  ASSERT_TRUE(fs::exists(tankCheckpoint(other)));
  const auto run = stringAttribute(checkpoint, "/", "record_run");
  const auto otherRun = stringAttribute(other + "/small_tank.checkpoint.h5", "/", "record_run");
  ASSERT_TRUE(run && otherRun);
  EXPECT_NE(*run, *otherRun);
  fs::create_directories(out + "/moved/small_tank.checkpoint.record/" + *run);
  fs::copy_file(other + "/small_tank.checkpoint.record/" + *otherRun + "/00000.h5",
                out + "/moved/small_tank.checkpoint.record/" + *run + "/00000.h5");
  expectRefused(moved, "is not the one it wrote");
  // A scene and --restart together, or neither.
  const ProgramResult both =
      runSph("run '" + scenePath("small_tank.toml") + "' --restart '" + checkpoint + "' --quiet");
  EXPECT_EQ(both.exitCode, 2) << both.output;
  EXPECT_NE(both.output.find("not both"), std::string::npos) << both.output;
}

}  // namespace
