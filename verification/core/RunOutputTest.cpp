// Issue 32, parts 8 and 9: what `sph run` leaves behind when it does not end on its own. A killed
// rerun into the same --out must leave the earlier run file whole, and SIGINT or SIGTERM must end
// the run with a run file whose status is `interrupted`.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <string>
#include <thread>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;
namespace fs = std::filesystem;

// The small tank without gravity (at rest, so nothing fails) run to 200 s (some 3 minutes at the
// 6600 steps a second measured here): long enough to be stopped part way.
struct LongRun {
  std::string scene, out, h5, log;
};
LongRun longRun() {
  LongRun r;
  r.scene = editedScene({{"end_time = 0.02", "end_time = 200.0"},
                         {"gravity = [0.0, -9.81]", "gravity = [0.0, 0.0]"},
                         {"snapshot_interval = 0.01", "snapshot_interval = 0.5"}});
  const fs::path dir = fs::path(r.scene).parent_path();
  r.out = (dir / "out").string(), r.h5 = r.out + "/small_tank.h5";
  r.log = (dir / "log.txt").string();
  return r;
}

int startLongRun(const LongRun& r) {
  return startSph({"run", r.scene, "--out", r.out, "--threads", "1", "--quiet"}, r.log);
}

TEST(RunFileReplacement, KilledRerunKeepsTheEarlierRunFile) {
  const LongRun r = longRun();
  const ProgramResult first = runSph("run '" + scenePath("small_tank.toml") + "' --out '" + r.out +
                                     "' --threads 1 --quiet");
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const std::string h5 = readText(r.h5), xdmf = readText(r.out + "/small_tank.xdmf");
  ASSERT_FALSE(h5.empty());

  const int pid = startLongRun(r);
  ASSERT_TRUE(waitForFile(r.h5 + ".partial", 60)) << readText(r.log);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGKILL);
  EXPECT_EQ(waitForSph(pid, 60), 128 + SIGKILL);

  EXPECT_TRUE(readText(r.h5) == h5) << "the killed rerun changed the earlier run file";
  EXPECT_TRUE(readText(r.out + "/small_tank.xdmf") == xdmf) << "and its XDMF";
  EXPECT_EQ(stringAttribute(r.h5, "/", "status"), "stable");
  // What the killed run wrote stays beside it, flushed at its snapshots.
  EXPECT_TRUE(fs::exists(r.h5 + ".partial"));
}

// A rerun that finishes replaces the file and leaves no partial files; its XDMF names the final
// file (RunTest.cpp RunFile.XdmfMatchesHdf5 checks the rest of it).
TEST(RunFileReplacement, FinishedRerunReplacesIt) {
  const std::string out = freshOutputDirectory();
  const std::string run =
      "run '" + scenePath("small_tank.toml") + "' --out '" + out + "' --threads 1 --quiet";
  ASSERT_EQ(runSph(run).exitCode, 0);
  ASSERT_EQ(runSph(run).exitCode, 0);
  EXPECT_EQ(stringAttribute(out + "/small_tank.h5", "/", "status"), "stable");
  int files = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    ++files;
    EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
  }
  EXPECT_EQ(files, 2);  // small_tank.h5 and small_tank.xdmf
  const std::string xdmf = readText(out + "/small_tank.xdmf");
  EXPECT_NE(xdmf.find(">small_tank.h5:/snapshots/00000/position<"), std::string::npos) << xdmf;
  EXPECT_EQ(xdmf.find(".partial"), std::string::npos);
}

// Part 9. The signal is taken between steps: the run writes the state of its last step as a final
// snapshot, marks the file interrupted, puts it in place and exits with 128 + the signal.
void expectInterrupted(int signal, const std::string& signalName) {
  const LongRun r = longRun();
  const int pid = startLongRun(r);
  ASSERT_TRUE(waitForFile(r.h5 + ".partial", 60)) << readText(r.log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // some thousands of steps
  kill(pid, signal);
  const int code = waitForSph(pid, 60);
  const std::string log = readText(r.log);
  ASSERT_EQ(code, 128 + signal) << log;
  EXPECT_NE(log.find("interrupted by " + signalName), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(r.h5 + ".partial"));
  EXPECT_EQ(stringAttribute(r.h5, "/", "status"), "interrupted");
  EXPECT_EQ(stringAttribute(r.h5, "/", "interrupted_by"), signalName);
  // Readable to the end: the series columns of one length, the last snapshot at the last
  // recorded step and time, its fields whole.
  const auto time = readDoubles(r.h5, "/series/time");
  const auto steps = readDoubles(r.h5, "/series/step");
  ASSERT_GE(time.size(), 2u);
  for (const auto& column : groupMembers(r.h5, "/series"))
    EXPECT_EQ(datasetShape(r.h5, "/series/" + column)->at(0), time.size()) << column;
  auto snapshots = groupMembers(r.h5, "/snapshots");
  ASSERT_GE(snapshots.size(), 2u);
  const std::string last = "/snapshots/" + snapshots.back();
  EXPECT_EQ(doubleAttribute(r.h5, last, "time"), time.back());
  EXPECT_EQ(integerAttribute(r.h5, last, "step"), static_cast<std::int64_t>(steps.back()));
  EXPECT_GT(time.back(), 0.0);
  EXPECT_EQ(readDoubles(r.h5, last + "/density").size(), 100u);
  EXPECT_EQ(integerAttribute(r.h5, "/metrics", "steps"), static_cast<std::int64_t>(steps.back()));
  const std::string xdmf = readText(r.out + "/small_tank.xdmf");
  EXPECT_NE(xdmf.find(">small_tank.h5:" + last + "/position<"), std::string::npos) << xdmf;
}

TEST(RunInterrupt, Sigterm) {
  expectInterrupted(SIGTERM, "SIGTERM");
}

TEST(RunInterrupt, Sigint) {
  expectInterrupted(SIGINT, "SIGINT");
}

}  // namespace
