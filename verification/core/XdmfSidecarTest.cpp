// The run file's XDMF sidecar grows by appending each snapshot in place (XdmfSidecar.hpp): the
// appended file is the one written whole, byte for byte; an append onto a file that is not a
// sidecar is refused; and an append cut short by a full disk leaves the sidecar as it was.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "XdmfSidecar.hpp"
#include "sph/RunFile.hpp"

namespace {

namespace fs = std::filesystem;
using sph::XdmfSnapshot;

std::string readAll(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path freshDirectory() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / ("sph_" + std::string(info->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

const std::vector<XdmfSnapshot> snapshots = {
    {"/snapshots/00000", 0.0, 3}, {"/snapshots/00001", 0.25, 3}, {"/snapshots/00002", 0.5, 4}};

TEST(XdmfSidecar, AppendedIsTheSidecarWrittenWhole) {
  const fs::path dir = freshDirectory();
  const std::string h5 = (dir / "run.h5.partial").string();
  sph::writeXdmf((dir / "appended.xdmf").string(), h5, {snapshots[0]});
  sph::appendXdmf((dir / "appended.xdmf").string(), h5, snapshots[1]);
  sph::appendXdmf((dir / "appended.xdmf").string(), h5, snapshots[2]);
  sph::writeXdmf((dir / "whole.xdmf").string(), h5, snapshots);
  EXPECT_EQ(readAll(dir / "appended.xdmf"), readAll(dir / "whole.xdmf"));
}

TEST(XdmfSidecar, AppendToAFileThatIsNotOneIsRefused) {
  const fs::path dir = freshDirectory();
  const fs::path other = dir / "notes.xdmf";
  std::ofstream(other) << "not a sidecar\n";
  EXPECT_THROW(sph::appendXdmf(other.string(), "run.h5", snapshots[1]), sph::OutputError);
  EXPECT_EQ(readAll(other), "not a sidecar\n");
  EXPECT_THROW(sph::appendXdmf((dir / "missing.xdmf").string(), "run.h5", snapshots[1]),
               sph::OutputError);
}

// RLIMIT_FSIZE stands for the full disk (as OutputFailureTest.cpp does for the program): the
// snapshot of 10^5 particles (about 0.6 MB of connectivity) does not fit in 100 more bytes.
TEST(XdmfSidecar, AppendCutShortLeavesTheSidecarWhole) {
  const fs::path dir = freshDirectory();
  const fs::path xdmf = dir / "run.xdmf";
  sph::writeXdmf(xdmf.string(), "run.h5", {snapshots[0]});
  const std::string before = readAll(xdmf);
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  rlimit limited = saved;
  limited.rlim_cur = static_cast<rlim_t>(before.size() + 100);
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limited), 0);
  bool threw = false;
  try {
    sph::appendXdmf(xdmf.string(), "run.h5", {"/snapshots/00001", 0.25, 100000});
  } catch (const sph::OutputError& e) {
    threw = true;
    EXPECT_NE(std::string(e.what()).find(xdmf.string()), std::string::npos) << e.what();
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous);
  EXPECT_TRUE(threw);
  EXPECT_EQ(readAll(xdmf), before);
}

}  // namespace
