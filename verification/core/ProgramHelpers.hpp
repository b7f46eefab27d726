#pragma once
// Running the `sph` program from a test and reading the run file it writes (HDF5 C API).
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sph::core_tests {

struct ProgramResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs `sph <arguments>` (SPH_EXE) through the shell and returns its exit code and output;
// `shellPrefix` runs first in the same shell (e.g. "ulimit -v 300000;").
ProgramResult runSph(const std::string& arguments, const std::string& shellPrefix = "");

// perf/compare_runs.py A B: exit 0 and "N datasets bit-identical" where every dataset, the
// physics attributes and the /metrics counters are equal to the bit.
ProgramResult compareRuns(const std::string& a, const std::string& b);

// Starts `sph <arguments>` (no shell) as a child process, its output appended to `log`; returns
// its process id.
int startSph(const std::vector<std::string>& arguments, const std::string& log);
// Waits up to `seconds` for a child started by startSph. Returns its exit status, 128 + the signal
// if one ended it, or -1 if it was still running (it is then killed).
int waitForSph(int pid, double seconds);
// Waits up to `seconds` for `path` to exist.
bool waitForFile(const std::string& path, double seconds);

// A fresh, empty directory for the running test: CORE_OUT/<Suite>.<Test>.
std::string freshOutputDirectory();

std::string scenePath(const std::string& name);  // CORE_SCENES/<name>
std::string readText(const std::string& path);
void writeText(const std::string& path, const std::string& text);

// A scene of CORE_SCENES (small_tank.toml by default) with each `from` (which must occur) replaced
// by its `to`, written to the running test's fresh output directory; returns the path.
std::string editedScene(const std::vector<std::pair<std::string, std::string>>& edits,
                        const std::string& base = "small_tank.toml");
std::string editedScene(const std::string& from, const std::string& to);

// `sph check` of the small tank with one edit must exit 2 (Run.hpp: exitBadInput) with a message
// naming the file, 'key' and the problem (STYLE.md section 6). Returns the output.
std::string expectRejected(const std::string& from, const std::string& to, const std::string& key,
                           const std::string& problem);

// HDF5 reading; each returns nullopt where the object does not exist.
std::optional<std::string> stringAttribute(const std::string& file, const std::string& object,
                                           const std::string& name);
std::optional<std::int64_t> integerAttribute(const std::string& file, const std::string& object,
                                             const std::string& name);
std::optional<double> doubleAttribute(const std::string& file, const std::string& object,
                                      const std::string& name);
std::optional<std::vector<std::uint64_t>> datasetShape(const std::string& file,
                                                       const std::string& dataset);
std::vector<double> readDoubles(const std::string& file, const std::string& dataset);
std::vector<std::string> groupMembers(const std::string& file, const std::string& group);

}  // namespace sph::core_tests
