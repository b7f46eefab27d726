// Issue 32, part 10: a write that fails (a full disk) stops the run with exit 4 and the path, and
// what was written before stays readable. A full disk is stood in for by the file size limit
// (ulimit -f, with SIGXFSZ ignored, as the shell's trap '' XFSZ leaves it for the child), under
// which a write fails with EFBIG as one on a full disk fails with ENOSPC; it needs no root and no
// small file system. Before: unchecked HDF5 writes, the run went on, then exit 0 or a segfault in
// HDF5's cleanup at exit, and a truncated XDMF sidecar.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;
namespace fs = std::filesystem;

// The small tank without gravity (at rest) to 2 s with a snapshot every 0.01 s: 200 snapshots of
// some 9 kB, about 2 MB with the series.
std::string longScene() {
  return editedScene(
      {{"end_time = 0.02", "end_time = 2.0"}, {"gravity = [0.0, -9.81]", "gravity = [0.0, 0.0]"}});
}

// Every DataItem of the XDMF names a dataset of the HDF5 file with its shape, and the XDMF ends
// where an XDMF ends (not cut short).
void expectXdmfMatches(const std::string& xdmfPath, const std::string& h5) {
  const std::string xdmf = readText(xdmfPath);
  ASSERT_GE(xdmf.size(), 8u) << xdmfPath;
  EXPECT_EQ(xdmf.substr(xdmf.size() - 8), "</Xdmf>\n") << xdmfPath;
  const std::regex item(R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*>([^<:]+):([^<]+)</DataItem>)re");
  int items = 0;
  for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), item); it != std::sregex_iterator();
       ++it, ++items) {
    EXPECT_EQ((*it)[2].str(), fs::path(h5).filename().string());
    std::vector<std::uint64_t> expected;
    std::istringstream in((*it)[1].str());
    for (std::uint64_t d; in >> d;) expected.push_back(d);
    EXPECT_EQ(datasetShape(h5, (*it)[3]), expected) << (*it)[3];
  }
  EXPECT_GT(items, 0);
}

// What a failed run leaves: status output_error with the reason, the series columns of one
// length, every snapshot readable and whole.
void expectReadableUpToTheFailure(const std::string& partial, const std::string& reason) {
  EXPECT_EQ(stringAttribute(partial, "/", "status"), "output_error");
  const auto failure = stringAttribute(partial, "/", "failure");
  ASSERT_TRUE(failure.has_value());
  EXPECT_NE(failure->find(reason), std::string::npos) << *failure;
  const auto time = datasetShape(partial, "/series/time");
  ASSERT_TRUE(time.has_value());
  for (const auto& column : groupMembers(partial, "/series"))
    EXPECT_EQ(datasetShape(partial, "/series/" + column), *time) << column;
  const auto snapshots = groupMembers(partial, "/snapshots");
  ASSERT_FALSE(snapshots.empty());
  for (const auto& s : snapshots) {
    const auto rho = readDoubles(partial, "/snapshots/" + s + "/density");
    ASSERT_EQ(rho.size(), 100u) << s;
    for (double r : rho) ASSERT_TRUE(r > 900.0 && r < 1100.0) << s;
  }
}

TEST(OutputFailure, FileSizeLimitStopsTheRunReadable) {
  const std::string scene = longScene();
  const std::string out = (fs::path(scene).parent_path() / "out").string();
  const std::string h5 = out + "/small_tank.h5";
  // A finished run first: the failing rerun must leave it as it was (part 8).
  ASSERT_EQ(
      runSph("run '" + scenePath("small_tank.toml") + "' --out '" + out + "' --quiet").exitCode, 0);
  const std::string before = readText(h5);
  // dash's ulimit -f counts 512-byte blocks: 1 MB, about half the run.
  const ProgramResult r = runSph("run '" + scene + "' --out '" + out + "' --threads 1 --quiet",
                                 "trap '' XFSZ; ulimit -f 2000;");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find(h5 + ".partial: only"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("file size limit"), std::string::npos) << r.output;
  expectReadableUpToTheFailure(h5 + ".partial", "file size limit");
  EXPECT_GE(groupMembers(h5 + ".partial", "/snapshots").size(), 10u);
  expectXdmfMatches(out + "/small_tank.xdmf.partial", h5 + ".partial");
  EXPECT_TRUE(readText(h5) == before) << "the failed rerun changed the earlier run file";
  expectXdmfMatches(out + "/small_tank.xdmf", h5);
}

// No room even for the start: exit 4 and nothing left behind.
TEST(OutputFailure, NoRoomToStart) {
  const std::string scene = longScene();
  const std::string out = (fs::path(scene).parent_path() / "out").string();
  const ProgramResult r = runSph("run '" + scene + "' --out '" + out + "' --threads 1 --quiet",
                                 "trap '' XFSZ; ulimit -f 4;");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("small_tank.h5.partial: only"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the run cannot start"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out + "/small_tank.h5.partial"));
}

// The XDMF sidecar cannot be written (its temporary file's name is taken by a directory that
// holds a file): exit 4 naming it; the HDF5 file, which could be written, says why it stopped.
TEST(OutputFailure, XdmfWriteFails) {
  const std::string scene = longScene();
  const std::string out = (fs::path(scene).parent_path() / "out").string();
  fs::create_directories(out + "/small_tank.xdmf.partial.tmp");
  writeText(out + "/small_tank.xdmf.partial.tmp/taken", "");
  const ProgramResult r = runSph("run '" + scene + "' --out '" + out + "' --threads 1 --quiet");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find("small_tank.xdmf.partial.tmp: cannot write the XDMF sidecar"),
            std::string::npos)
      << r.output;
  expectReadableUpToTheFailure(out + "/small_tank.h5.partial", "cannot write the XDMF sidecar");
  EXPECT_FALSE(fs::exists(out + "/small_tank.xdmf.partial"));
  EXPECT_FALSE(fs::exists(out + "/small_tank.h5"));
}

}  // namespace
