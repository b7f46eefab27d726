// A build without MPI: every run is one process.
#include <stdexcept>
#include <string>

#include "sph/DomainDecomposition.hpp"

namespace sph {

template <int D>
std::shared_ptr<DomainDecomposition<D>> slabDecomposition(const Scene&) {
  return nullptr;
}
template std::shared_ptr<DomainDecomposition<1>> slabDecomposition<1>(const Scene&);
template std::shared_ptr<DomainDecomposition<2>> slabDecomposition<2>(const Scene&);
template std::shared_ptr<DomainDecomposition<3>> slabDecomposition<3>(const Scene&);

Processes::Processes() {
  if (const int n = launchedProcesses(); n > 1)
    throw std::invalid_argument("launched as " + std::to_string(n) +
                                " processes, but this sph was built without MPI (configure with "
                                "libopenmpi-dev installed, SPH_MPI ON); run it as one process");
}
Processes::~Processes() = default;

}  // namespace sph
