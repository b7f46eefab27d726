#pragma once
// Positions and velocities in D = 1, 2 or 3 dimensions.
#include <Eigen/Core>

namespace sph {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

}  // namespace sph
