// Issue 2, parts 7-9: what `sph run` writes. Failure detection (exit 3, failure_cause, the series
// kept, a last good snapshot), the run file against its XDMF sidecar (reports/SCHEMA.md), and a
// 3-D hydrostatic box that must stay at rest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "ProgramHelpers.hpp"
#include "Results.hpp"

namespace {

using namespace sph::core_tests;

struct RunOutcome {
  std::string file;  // the .h5
  ProgramResult result;
};

RunOutcome runScene(const std::string& scene, const std::string& name) {
  const std::string out = freshOutputDirectory();
  RunOutcome r;
  r.result = runSph("run '" + scenePath(scene) + "' --out '" + out + "' --threads 1 --quiet");
  r.file = out + "/" + name + ".h5";
  return r;
}

// The last snapshot group, /snapshots/<NNNNN> with the largest number.
std::string lastSnapshot(const std::string& file) {
  auto names = groupMembers(file, "/snapshots");
  if (names.empty()) return "";
  std::sort(names.begin(), names.end());
  return "/snapshots/" + names.back();
}

// Exit 3, failure_cause, status, the series written up to the failure (all columns of one length,
// at least the initial row), and a final snapshot marked last_good = 1 holding the state of the
// last recorded step.
void expectFailure(const std::string& scene, const std::string& name, const std::string& cause) {
  const RunOutcome r = runScene(scene, name);
  EXPECT_EQ(r.result.exitCode, 3) << r.result.output;
  EXPECT_NE(r.result.output.find("numerical failure (" + cause + ")"), std::string::npos)
      << r.result.output;
  EXPECT_EQ(stringAttribute(r.file, "/", "failure_cause"), cause);
  EXPECT_EQ(stringAttribute(r.file, "/", "status"), "unstable");
  const auto failure = stringAttribute(r.file, "/", "failure");
  ASSERT_TRUE(failure.has_value());
  EXPECT_NE(failure->find("step"), std::string::npos) << *failure;
  // A time-step collapse is a property of the whole state and names no particle.
  if (cause != "dt_collapse") EXPECT_NE(failure->find("particle"), std::string::npos) << *failure;

  const auto time = datasetShape(r.file, "/series/time");
  ASSERT_TRUE(time.has_value()) << "no /series/time";
  ASSERT_EQ(time->size(), 1u);
  EXPECT_GE((*time)[0], 1u);
  for (const auto& column : groupMembers(r.file, "/series"))
    EXPECT_EQ(datasetShape(r.file, "/series/" + column), *time) << column;

  const std::string last = lastSnapshot(r.file);
  ASSERT_FALSE(last.empty());
  EXPECT_NE(last, "/snapshots/00000") << "only the initial snapshot was written";
  EXPECT_EQ(integerAttribute(r.file, last, "last_good"), 1);
  const auto steps = readDoubles(r.file, "/series/step");
  ASSERT_FALSE(steps.empty());
  EXPECT_EQ(integerAttribute(r.file, last, "step"), static_cast<std::int64_t>(steps.back()));
  for (double rho : readDoubles(r.file, last + "/density")) EXPECT_TRUE(std::isfinite(rho));
}

TEST(FailureDetection, DensityBand) {
  expectFailure("fail_density_band.toml", "fail_density_band", "density_band");
}

TEST(FailureDetection, WallPenetration) {
  expectFailure("fail_wall_impact.toml", "fail_wall_impact", "wall_penetration");
}

TEST(FailureDetection, TimeStepCollapse) {
  expectFailure("fail_dt_collapse.toml", "fail_dt_collapse", "dt_collapse");
}

// A tank at rest without artificial viscosity, stepped at 2.4 times the acoustic limit,
// gains energy from nowhere while its density stays in the (opened) band.
TEST(FailureDetection, EnergyGrowth) {
  expectFailure("fail_energy_growth.toml", "fail_energy_growth", "energy_growth");
}

// A scene with initial = "packed" (issue 6) keeps the packing history in /packing/block_<k>: a
// record per iteration from the start (iteration 0), and says when the packing stopped on
// max_iterations rather than on its kinetic-energy criterion (here 40 iterations, criterion 1e-30).
TEST(RunFile, KeepsThePackingHistory) {
  const RunOutcome r = runScene("packed_tank.toml", "packed_tank");
  ASSERT_EQ(r.result.exitCode, 0) << r.result.output;
  EXPECT_NE(r.result.output.find("warning: the packing of fluid block 0 stopped at max_iterations"),
            std::string::npos)
      << r.result.output;
  const std::string g = "/packing/block_0";
  EXPECT_EQ(integerAttribute(r.file, g, "converged"), 0);
  EXPECT_EQ(integerAttribute(r.file, g, "iterations"), 40);
  const auto it = readDoubles(r.file, g + "/iteration");
  const auto grad = readDoubles(r.file, g + "/max_grad_gamma");
  ASSERT_EQ(it.size(), 41u);
  ASSERT_EQ(readDoubles(r.file, g + "/kinetic").size(), 41u);
  EXPECT_EQ(it.front(), 0.0);
  EXPECT_EQ(it.back(), 40.0);
  // The packing moves particles down the gradient of Gamma (eq. 2.16): it falls from the lattice.
  EXPECT_LT(grad.back(), grad.front());
}

// An output directory that cannot be made (here: the path is an existing file) stops the run with
// exit 4 (Run.hpp: exitOutputError) and a message naming the path, and the file is left as it was.
TEST(OutputError, OutputPathIsAFile) {
  const std::string out = freshOutputDirectory() + "/not_a_directory";
  writeText(out, "written before the run\n");
  const ProgramResult r =
      runSph("run '" + scenePath("small_tank.toml") + "' --out '" + out + "' --threads 1 --quiet");
  EXPECT_EQ(r.exitCode, 4) << r.output;
  EXPECT_NE(r.output.find(out), std::string::npos) << r.output;
  EXPECT_EQ(readText(out), "written before the run\n");
}

// Every DataItem of the XDMF sidecar names "<file>:<dataset>" and its Dimensions; each must exist
// in the HDF5 file with exactly that shape, or ParaView shows garbage.
TEST(RunFile, XdmfMatchesHdf5) {
  const RunOutcome r = runScene("small_tank.toml", "small_tank");
  ASSERT_EQ(r.result.exitCode, 0) << r.result.output;
  EXPECT_EQ(stringAttribute(r.file, "/", "format"), "sph-run-1");
  EXPECT_EQ(stringAttribute(r.file, "/", "status"), "stable");
  EXPECT_EQ(stringAttribute(r.file, "/", "failure_cause"), "");
  EXPECT_EQ(integerAttribute(r.file, "/", "threads"), 1);
  EXPECT_EQ(integerAttribute(r.file, "/", "dimension"), 2);

  const std::string xdmfPath = r.file.substr(0, r.file.size() - 3) + ".xdmf";
  const std::string xdmf = readText(xdmfPath);
  ASSERT_FALSE(xdmf.empty()) << xdmfPath;
  const std::regex item(R"re(<DataItem Dimensions="([0-9 ]+)"[^>]*>([^<:]+):([^<]+)</DataItem>)re");
  int items = 0;
  std::set<std::string> grids;
  for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), item); it != std::sregex_iterator();
       ++it, ++items) {
    const std::string dims = (*it)[1], file = (*it)[2], dataset = (*it)[3];
    EXPECT_EQ(file, "small_tank.h5");
    std::vector<std::uint64_t> expected;
    std::istringstream in(dims);
    for (std::uint64_t d; in >> d;) expected.push_back(d);
    const auto shape = datasetShape(r.file, dataset);
    ASSERT_TRUE(shape.has_value()) << dataset << " is named in the XDMF but not in the HDF5";
    EXPECT_EQ(*shape, expected) << dataset;
    grids.insert(dataset.substr(0, dataset.rfind('/')));
  }
  // end_time 0.02 s, snapshot_interval 0.01 s: the initial state and two more, each with
  // position, velocity, density, pressure, h, mass, phase.
  EXPECT_EQ(grids.size(), 3u);
  EXPECT_EQ(items, 7 * 3);
  EXPECT_EQ(groupMembers(r.file, "/snapshots").size(), grids.size());
  // Each snapshot's <Time> matches its group's time attribute (the same snapshots, in order).
  const std::regex time(R"re(<Time Value="([^"]+)"/>)re");
  std::vector<double> times;
  for (auto it = std::sregex_iterator(xdmf.begin(), xdmf.end(), time); it != std::sregex_iterator();
       ++it)
    times.push_back(std::stod((*it)[1]));
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[0], 0.0);
  EXPECT_NEAR(times[2], 0.02, 1e-12);
  // The series: equal lengths, the probes present.
  const auto n = datasetShape(r.file, "/series/time");
  ASSERT_TRUE(n.has_value());
  for (const char* c :
       {"dt", "step", "dt_limiter", "kinetic_energy", "max_speed", "rho_min", "rho_max",
        "volume_error", "volume_error_water", "probe_front", "probe_p_bottom"})
    EXPECT_EQ(datasetShape(r.file, std::string("/series/") + c), *n) << c;
}

// `sph run` times its steps on all threads and on one now and then and runs the faster
// (ThreadTuner); the run file says how many steps ran on all. The small tank (about 120 steps)
// gets through the first trial (25 steps on all threads, then 25 on one) and so runs on both, and
// ends where the same run on fixed threads ends, to the bit.
TEST(RunFile, SaysHowManyStepsRanOnAllThreads) {
  const std::string tuned = freshOutputDirectory() + "/tuned", fixed = tuned + "/../fixed";
  const std::string scene = "'" + scenePath("small_tank.toml") + "' --threads 2 --quiet";
  ASSERT_EQ(runSph("run " + scene + " --out '" + tuned + "'").exitCode, 0);
  ASSERT_EQ(runSph("run " + scene + " --fixed-threads --out '" + fixed + "'").exitCode, 0);
  const std::string a = tuned + "/small_tank.h5", b = fixed + "/small_tank.h5";
  const auto steps = integerAttribute(a, "/metrics", "steps");
  ASSERT_TRUE(steps.has_value());
  ASSERT_GE(*steps, 51) << "too short a run for a trial on both counts";
  const auto onAllTuned = doubleAttribute(a, "/metrics", "steps_on_all_threads");
  const auto onAllFixed = doubleAttribute(b, "/metrics", "steps_on_all_threads");
  ASSERT_TRUE(onAllTuned.has_value() && onAllFixed.has_value());
  EXPECT_GT(*onAllTuned, 0.0);
  EXPECT_LT(*onAllTuned, 1.0);
  EXPECT_EQ(*onAllFixed, 1.0);
  const std::string last = lastSnapshot(a);
  ASSERT_EQ(last, lastSnapshot(b));
  for (const char* field : {"/position", "/velocity", "/density", "/pressure"})
    EXPECT_EQ(readDoubles(a, last + field), readDoubles(b, last + field)) << field;
}

// A column at rest in a 3-D box, started at the hydrostatic pressure with hydrostatic ghosts
// (scenes/hydrostatic_box_3d.toml, 8^3 particles, 289 steps). The run must end stable and
// the spurious speed stay small against sqrt(g H).
TEST(HydrostaticBox3D, StaysAtRest) {
  const RunOutcome r = runScene("hydrostatic_box_3d.toml", "hydrostatic_box_3d");
  ASSERT_EQ(r.result.exitCode, 0) << r.result.output;
  EXPECT_EQ(stringAttribute(r.file, "/", "status"), "stable");
  const auto speed = readDoubles(r.file, "/series/max_speed");
  ASSERT_GE(speed.size(), 200u);  // a few hundred steps, every one recorded
  const double scale = std::sqrt(9.81 * 0.1);
  const double worst = *std::max_element(speed.begin(), speed.end()) / scale;
  const auto volume = readDoubles(r.file, "/series/volume_error");
  double volumeWorst = 0.0;
  for (double v : volume) volumeWorst = std::max(volumeWorst, std::abs(v));
  sph::verification::Results results;
  // Measured 2.5e-3 (this build, 2026-11): the lattice start is not a relaxed SPH state, so a
  // small spurious current appears at once and stays bounded. 1e-2 gives a factor 4 over the
  // measurement and is 10x below the ~0.1 sqrt(gH) that Colagrossi et al. report for an unpacked
  // lattice at t sqrt(g/H) = 10; an unbalanced wall (mirror ghosts, no hydrostatic correction)
  // or a wrong gravity sign gives O(0.1) at once.
  EXPECT_TRUE(results.check("max|v| / sqrt(gH), 3-D hydrostatic box, t sqrt(g/H) = 0.6", worst,
                            "<=", 1e-2, "measured 2.5e-3; factor 4 margin"));
  // Measured 9.0e-5 (the column's first settling; 7e-7 at the end). 5e-4 is a factor 5 over the
  // measurement and 6x below the 0.3 % Lobovsky & Kren report for the dam break; a density
  // drift (wrong continuity sign, ghosts that leak) shows as percent-level volume change.
  EXPECT_TRUE(results.check("max |V(t)/V(0) - 1|, 3-D hydrostatic box", volumeWorst, "<=", 5e-4,
                            "measured 9.0e-5; factor 5 margin"));
  // `sph run` stores the particles in cell order every 10 steps (issue 7); the snapshots keep the
  // order of the start. At rest each particle must be found where it started: measured 1.4e-6 m
  // at most; a particle written in another's place would be a lattice spacing (0.0125 m) off.
  const auto start = readDoubles(r.file, "/snapshots/00000/position");
  const auto end = readDoubles(r.file, lastSnapshot(r.file) + "/position");
  ASSERT_EQ(start.size(), end.size());
  double moved = 0.0;
  for (std::size_t k = 0; k < start.size(); ++k)
    moved = std::max(moved, std::abs(end[k] - start[k]));
  EXPECT_LT(moved, 1e-4) << "m: a particle of the last snapshot is not where it started";
}

}  // namespace
