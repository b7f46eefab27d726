// elliptical_drop_ode A0 R t [t ...]: Monaghan's elliptical-drop ODE (EllipticalDropOde.hpp) for
// an initial velocity gradient A0 [1/s] and radius R [m], as CSV: a header "t,a,b,A", then one
// line per time t [s] (ascending, >= 0), 17 significant digits. For validation/stability/sweep.py,
// so that the ODE has one solution in the project, the one the GoogleTest cases check.
// Exit status 0, or 2 with a message on bad arguments.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "EllipticalDropOde.hpp"

namespace {

double number(const char* text, const char* what) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || text[used] != '\0' || !std::isfinite(v))
    throw std::invalid_argument(std::string(what) + " \"" + text + "\" is not a finite number");
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s A0 R t [t ...]   (A0 in 1/s, R in m, times in s)\n", argv[0]);
    return 2;
  }
  try {
    const double A0 = number(argv[1], "A0"), R = number(argv[2], "R");
    if (A0 == 0.0) throw std::invalid_argument("A0 must not be 0 (the drop then stays a circle)");
    if (!(R > 0.0)) throw std::invalid_argument("R must be positive");
    std::vector<double> times;
    for (int k = 3; k < argc; ++k) {
      times.push_back(number(argv[k], "t"));
      if (times.back() < 0.0 || (times.size() > 1 && times.back() < times[times.size() - 2]))
        throw std::invalid_argument("times must be ascending and >= 0");
    }
    const std::vector<sph::verification::DropAxes> s = sph::verification::dropOde(A0, R, times);
    std::printf("t,a,b,A\n");
    for (std::size_t k = 0; k < times.size(); ++k)
      std::printf("%.17g,%.17g,%.17g,%.17g\n", times[k], s[k].a, s[k].b, s[k].A);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "elliptical_drop_ode: %s\n", e.what());
    return 2;
  }
  return 0;
}
