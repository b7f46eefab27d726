// What a launcher tells a process it started, in the environment, before MPI is started.
#include <cstdlib>
#include <string>

#include "sph/DomainDecomposition.hpp"

namespace sph {

namespace {

int fromEnvironment(const char* openMpi, const char* mpich, int otherwise) {
  for (const char* name : {openMpi, mpich})
    if (const char* v = std::getenv(name)) {
      try {
        return std::stoi(v);
      } catch (const std::exception&) {
        return otherwise;
      }
    }
  return otherwise;
}

}  // namespace

int launchedProcesses() {
  return fromEnvironment("OMPI_COMM_WORLD_SIZE", "PMI_SIZE", 1);
}
int launchedRank() {
  return fromEnvironment("OMPI_COMM_WORLD_RANK", "PMI_RANK", 0);
}

}  // namespace sph
