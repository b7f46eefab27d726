// The XDMF sidecar's topology, as ParaView's default reader for .xdmf needs it (Xdmf3ReaderS,
// ParaView 5.11): it makes cells only from an explicit connectivity item, and without cells the
// particles draw nothing. Each grid must give a Polyvertex topology whose inline connectivity
// lists the grid's n particles, 0 .. n-1, n being the rows of its snapshot's position dataset.
// The nightly test paraview.DamBreakOpensWithDefaultReader opens a run with ParaView itself.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>

#include "ProgramHelpers.hpp"

namespace {

using namespace sph::core_tests;

// Checks every grid of the sidecar `xdmf` against the run file `h5`; returns the grids seen.
int expectVertexCells(const std::string& xdmf, const std::string& h5) {
  const std::string text = readText(xdmf);
  const std::regex grid(
      R"re(<Grid Name="[0-9]+" GridType="Uniform">\s*<Time Value="[^"]+"/>\s*)re"
      R"re(<Topology TopologyType="Polyvertex" NumberOfElements="([0-9]+)" NodesPerElement="1">\s*)re"
      R"re(<DataItem Dimensions="([0-9]+)" NumberType="Int" Precision="8" Format="XML">([0-9 ]*))re"
      R"re(</DataItem>\s*</Topology>\s*<Geometry GeometryType="XYZ">\s*)re"
      R"re(<DataItem Dimensions="([0-9]+) 3"[^>]*>[^:<]+:([^<]+)</DataItem>)re");
  int grids = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), grid); it != std::sregex_iterator();
       ++it, ++grids) {
    const std::uint64_t elements = std::stoull((*it)[1]), listed = std::stoull((*it)[2]),
                        points = std::stoull((*it)[4]);
    const std::string position = (*it)[5];
    const auto shape = datasetShape(h5, position);
    EXPECT_TRUE(shape.has_value()) << position << " is named in " << xdmf << " but not in " << h5;
    if (shape) EXPECT_EQ((*shape)[0], elements) << position;
    EXPECT_EQ(listed, elements) << position;
    EXPECT_EQ(points, elements) << position;
    std::istringstream in((*it)[3].str());
    std::uint64_t expected = 0;
    for (std::uint64_t k; in >> k; ++expected)
      if (k != expected) {
        ADD_FAILURE() << position << ": connectivity entry " << expected << " is " << k;
        break;
      }
    EXPECT_EQ(expected, elements) << position << ": connectivity length";
  }
  // Every uniform grid matched the pattern above, none was passed over.
  std::ptrdiff_t uniform = 0;
  for (std::size_t at = 0; (at = text.find("GridType=\"Uniform\"", at)) != std::string::npos; ++at)
    ++uniform;
  EXPECT_EQ(grids, uniform) << xdmf;
  return grids;
}

// `sph run`: the small tank's three snapshots (end_time 0.02 s, snapshot_interval 0.01 s).
TEST(XdmfTopology, RunGivesEachParticleAVertexCell) {
  const std::string out = freshOutputDirectory();
  const ProgramResult r =
      runSph("run '" + scenePath("small_tank.toml") + "' --out '" + out + "' --threads 1 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(expectVertexCells(out + "/small_tank.xdmf", out + "/small_tank.h5"), 3);
  EXPECT_EQ(groupMembers(out + "/small_tank.h5", "/snapshots").size(), 3u);
}

// `sph pack` writes its sidecar the same way: the trapezoidal tank, packed to T/beta < 1e-2
// instead of the validation's 1e-8 (850 iterations, 1.4 s: the packing's result does not matter
// here, its output does).
TEST(XdmfTopology, PackGivesEachParticleAVertexCell) {
  const std::string out = freshOutputDirectory();
  std::string scene =
      readText(std::string(SPH_SOURCE_DIR) + "/validation/packing/trapezoidal_tank.toml");
  const std::string from = "stop_kinetic_energy = 1e-8";
  const auto at = scene.find(from);
  ASSERT_NE(at, std::string::npos) << "trapezoidal_tank.toml no longer says " << from;
  scene.replace(at, from.size(), "stop_kinetic_energy = 1e-2");
  writeText(out + "/trapezoidal_tank.toml", scene);
  const ProgramResult r =
      runSph("pack '" + out + "/trapezoidal_tank.toml' --out '" + out + "' --threads 1 --quiet");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string h5 = out + "/trapezoidal_tank.h5";
  const int grids = expectVertexCells(out + "/trapezoidal_tank.xdmf", h5);
  EXPECT_GE(grids, 2);  // the lattice and the packed state at least
  EXPECT_EQ(groupMembers(h5, "/snapshots").size(), static_cast<std::size_t>(grids));
}

}  // namespace
