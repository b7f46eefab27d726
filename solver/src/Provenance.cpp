#include <unistd.h>

#include <chrono>
#include <ctime>
#include <fstream>

#include "sph/Run.hpp"

namespace sph {

Provenance provenance() {
  Provenance p;
  p.version = SPH_VERSION;
  p.commit = SPH_GIT_COMMIT;
  p.compiler = std::string("g++ ") + __VERSION__;
  p.flags = SPH_CXX_FLAGS;
  p.buildType = SPH_BUILD_TYPE;
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  std::string cpu;
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  p.machine = std::string(host) + ", " + cpu + ", " + std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) +
              " cores";
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  p.date = date;
  return p;
}

}  // namespace sph
