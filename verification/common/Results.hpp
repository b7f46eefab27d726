#pragma once
// What a test measured, for the V&V report (reports/SCHEMA.md, "Verification results"). The
// assertions stay in the test; this only records the figures, each with its threshold and source.
#include <string>
#include <vector>

namespace sph::verification {

class Results {
 public:
  // Named after the running GoogleTest test: <results dir>/<Suite>.<Test>.json.
  Results();
  ~Results();  // writes the file

  // Records `measured comparison threshold` and returns whether it holds, for EXPECT_TRUE.
  bool check(const std::string& name, double measured, const std::string& comparison,
             double threshold, const std::string& source);
  // Records a measured figure that has no threshold (a finding reported, not asserted).
  void figure(const std::string& name, double measured, const std::string& source);
  // Records a measured history y(x) (e.g. max|u| over time), reported as a curve, not asserted.
  void history(const std::string& name, const std::string& xLabel, const std::vector<double>& x,
               const std::string& yLabel, const std::vector<double>& y, const std::string& source);
  // Records errors against a resolution (or time step) and returns the least-squares slope of
  // log(error) against log(x) over all points.
  double convergence(const std::string& name, const std::string& xLabel,
                     const std::vector<double>& x, const std::vector<double>& error,
                     double theoryOrder, const std::string& source);

 private:
  std::string test_;
  std::vector<std::string> checks_, convergence_, figures_, histories_;
};

// Least-squares slope of log(e) against log(x).
double observedOrder(const std::vector<double>& x, const std::vector<double>& e);

}  // namespace sph::verification
