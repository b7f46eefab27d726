// The particle count and memory of a scene (RunBudget.hpp); the steps and output are in
// RunDuration.cpp.
#include "sph/RunBudget.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

namespace sph {

namespace {

// The volume of the D-ball of radius r.
double ballVolume(int D, double r) {
  if (D == 1) return 2.0 * r;
  if (D == 2) return std::numbers::pi * r * r;
  return 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

// The number in a /proc or /sys file's first token (0 where it cannot be read or is "max").
double readNumber(const std::string& path) {
  std::ifstream in(path);
  std::string token;
  if (!(in >> token) || token == "max") return 0.0;
  try {
    return std::stod(token);
  } catch (const std::exception&) {
    return 0.0;
  }
}

// What the process's cgroup still allows (v2, then v1), or 0 where it sets no limit.
double cgroupRoom() {
  const double v2 = readNumber("/sys/fs/cgroup/memory.max");
  if (v2 > 0) return std::max(0.0, v2 - readNumber("/sys/fs/cgroup/memory.current"));
  const double v1 = readNumber("/sys/fs/cgroup/memory/memory.limit_in_bytes");
  if (v1 > 0 && v1 < 1e18)  // v1 writes a huge number for "no limit"
    return std::max(0.0, v1 - readNumber("/sys/fs/cgroup/memory/memory.usage_in_bytes"));
  return 0.0;
}

// The process's virtual size now (VmSize in /proc/self/status), bytes.
double virtualSize() {
  std::ifstream in("/proc/self/status");
  for (std::string key; in >> key;) {
    if (key == "VmSize:") {
      double kib = 0.0;
      in >> kib;
      return 1024.0 * kib;
    }
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0.0;
}

std::string gib(double bytes) {
  std::ostringstream m;
  m.precision(3);
  m << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return m.str();
}

}  // namespace

double bytesPerParticle(const Scene& s) {
  const double listed = (1.0 + s.neighbourSkin) * 2.0 * s.hOverDx;  // in units of dx
  const double neighbours = ballVolume(s.dimension, listed);
  const double base = s.dimension == 3 ? 800.0 : 620.0;
  return 1.25 * (base + 4.5 * neighbours);
}

double availableMemory(std::string* source) {
  double kib = 0.0;
  std::ifstream in("/proc/meminfo");
  for (std::string key; in >> key;) {
    double value = 0.0;
    in >> value;
    if (key == "MemAvailable:") kib = value;
    in.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  double bytes = 1024.0 * kib;
  if (source) *source = "MemAvailable in /proc/meminfo";
  const double room = cgroupRoom();
  if (room > 0 && (bytes == 0 || room < bytes)) {
    bytes = room;
    if (source) *source = "the memory the process's cgroup leaves";
  }
  // ulimit -v: allocations beyond it fail whatever the machine has.
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const double left = std::max(0.0, double(as.rlim_cur) - virtualSize());
    if (bytes == 0 || left < bytes) {
      bytes = left;
      if (source) *source = "the address space ulimit -v leaves";
    }
  }
  return bytes;
}

double estimateParticles(const Scene& s) {
  double total = 0.0;
  for (const FluidBlock& b : s.fluids) {
    if (b.shape == FluidBlock::Shape::circle) {
      total += ballVolume(s.dimension, b.radius) / std::pow(s.dx, s.dimension);
      continue;
    }
    double n = 1.0;  // round(width / dx) nodes along each axis (InitialParticles.hpp)
    for (int a = 0; a < s.dimension; ++a) n *= std::floor((b.upper[a] - b.lower[a]) / s.dx + 0.5);
    total += n;
  }
  return total;
}

RunEstimate checkMemory(const Scene& s, const RunLimits& limits) {
  RunEstimate e;
  e.particles = estimateParticles(s);
  e.bytesPerParticle = bytesPerParticle(s);
  e.memory = 64.0 * 1024 * 1024 + e.particles * e.bytesPerParticle;  // + the program itself
  e.available = limits.maxMemory > 0 ? limits.maxMemory : availableMemory(&e.availableSource);
  if (limits.maxMemory > 0) e.availableSource = "--max-memory";
  std::ostringstream m;
  m.precision(3);
  m << s.file << ": key 'numerics.dx': at dx = " << s.dx << " m the fluid blocks hold about "
    << e.particles << " particles";
  // The solver indexes particles (and the ghosts with them) with int.
  if (!(e.particles <= 0.5 * std::numeric_limits<int>::max())) {
    m << ", more than the solver can index (" << 0.5 * std::numeric_limits<int>::max()
      << ", half of the largest int, leaving room for the ghosts)";
    throw SceneError(m.str());
  }
  if (e.available > 0 && !(e.memory <= e.available)) {
    m << ", which need about " << gib(e.memory) << " (" << e.bytesPerParticle << " B a particle at "
      << "h/dx = " << s.hOverDx << " in " << s.dimension
      << "-D, an upper estimate: RunBudget.hpp), "
      << "more than the " << gib(e.available) << " available (" << e.availableSource
      << "; sph check/run --max-memory sets another limit)";
    throw SceneError(m.str());
  }
  return e;
}

}  // namespace sph
