// Issue 6: the elliptical drop (Monaghan 1994; Colagrossi et al. 2012, section 3.4) at R/dx = 40
// and 80, Cartesian and packed starts. Tolerances: checkDropErrors in EllipticalDropCommon.hpp.
#include "EllipticalDropCommon.hpp"

namespace sph::verification {
namespace {

void atResolution(double ROverDx) {
  Results r;
  const DropRun cartesian = dropRun("Cartesian", ROverDx, r);
  const DropRun packed = dropRun("packed", ROverDx, r);
  checkDropErrors(r, ROverDx, cartesian.maxError, packed.maxError);
}

TEST(EllipticalDropNightly, CartesianAndPackedStartsROverDx40) {
  atResolution(40.0);
}
TEST(EllipticalDropNightly, CartesianAndPackedStartsROverDx80) {
  atResolution(80.0);
}

}  // namespace
}  // namespace sph::verification
