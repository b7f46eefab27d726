// A build without MPI: every run is one process.
#include "sph/DomainDecomposition.hpp"

namespace sph {

template <int D>
std::shared_ptr<DomainDecomposition<D>> slabDecomposition(const Scene&) {
  return nullptr;
}
template std::shared_ptr<DomainDecomposition<1>> slabDecomposition<1>(const Scene&);
template std::shared_ptr<DomainDecomposition<2>> slabDecomposition<2>(const Scene&);
template std::shared_ptr<DomainDecomposition<3>> slabDecomposition<3>(const Scene&);

}  // namespace sph
