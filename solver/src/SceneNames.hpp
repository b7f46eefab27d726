#pragma once
// Two small rules of the scene readers (SceneTable.hpp): which strings may name a scene, a phase
// or a probe, and which known key a misspelt one was most likely meant to be. Internal to the
// solver library.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace sph {

// A scene's name becomes the run file <out>/<name>.h5, a phase's and a probe's the HDF5 names
// /series/volume_error_<name> and /series/probe_<name>. The rule keeps all three plain names:
// [A-Za-z0-9_.-]+, not starting with '.' (no "..", no hidden file, no path), at most 100
// characters (a file name may have 255 bytes; ".h5.partial" and the HDF5 prefixes fit easily).
// Returns what is wrong, or an empty string.
inline std::string nameProblem(std::string_view name) {
  if (name.empty()) return "must not be empty";
  if (name.size() > 100) return "must have at most 100 characters";
  if (name.front() == '.') return "must not start with '.'";
  for (char c : name) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '.' || c == '-';
    if (!ok) return "may hold only letters, digits, '_', '.' and '-'";
  }
  return "";
}

// Optimal string alignment distance (Levenshtein with a swap of two neighbours counting as one
// edit): "end_tme" is 1 from "end_time", "numerix" 2 from "numerics".
inline std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// Whether `typed` is close enough to `known` to be a typo of it: at most two edits, and fewer
// than half of `known`'s characters (so that "mu" is no typo of "p0").
inline bool nearMiss(std::string_view typed, std::string_view known) {
  const std::size_t d = editDistance(typed, known);
  return d > 0 && d <= 2 && 2 * d < known.size();
}

}  // namespace sph
