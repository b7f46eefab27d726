#pragma once
// The XDMF 3 sidecar of a run file (RunFile.cpp): a temporal collection of polyvertex grids, each
// particle a vertex cell, pointing into the HDF5 file, which ParaView opens as a time series
// (layout: reports/SCHEMA.md). Internal to the solver library.
#include <cstddef>
#include <string>
#include <vector>

namespace sph {

struct XdmfSnapshot {
  std::string group;  // /snapshots/<NNNNN>
  double time;
  std::size_t n;  // particles
};

// Writes `xdmf` naming the HDF5 file `h5` (by its file name: the two lie side by side), through
// a temporary file renamed into place, so that a reader never sees half of it. Throws OutputError
// naming the path where it cannot be written whole; the earlier `xdmf` then stays as it was.
void writeXdmf(const std::string& xdmf, const std::string& h5,
               const std::vector<XdmfSnapshot>& snapshots);

// Adds one snapshot to the sidecar `xdmf` that writeXdmf wrote, in place over its closing lines,
// so that a run's sidecar costs its size once and not at every snapshot (rewritten whole, a run of
// S snapshots wrote S^2/2 grids). A write that fails leaves the sidecar whole as it was and throws
// OutputError naming the path.
void appendXdmf(const std::string& xdmf, const std::string& h5, const XdmfSnapshot& snapshot);

}  // namespace sph
