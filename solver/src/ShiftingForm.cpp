// The scene-level names and defaults of particle shifting (sph/ParticleShifting.hpp), apart from
// the pass itself so that the scene reader links without the cell list and OpenMP (fuzz/).
#include <stdexcept>
#include <string>

#include "sph/ParticleShifting.hpp"

namespace sph {

std::string_view name(ShiftingForm f) {
  switch (f) {
    case ShiftingForm::none:
      return "none";
    case ShiftingForm::lind:
      return "lind";
    case ShiftingForm::delta_plus:
      return "delta_plus";
  }
  // No default: -Wswitch names an enumerator missing above; any other value is a bug.
  throw std::logic_error("name(ShiftingForm): unknown value " +
                         std::to_string(static_cast<int>(f)));
}

double defaultShiftingCoefficient(ShiftingForm f) {
  return f == ShiftingForm::delta_plus ? 4.0 : 2.0;
}

double defaultSurfaceThreshold(int dimension) {
  return dimension == 1 ? 0.75 : dimension == 2 ? 1.5 : 2.75;
}

}  // namespace sph
