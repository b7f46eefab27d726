#include "Results.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sph::verification {

namespace {
std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}
std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}
std::string array(const std::vector<double>& v) {
  std::string out = "[";
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + number(v[i]);
  return out + "]";
}
}  // namespace

double observedOrder(const std::vector<double>& x, const std::vector<double>& e) {
  const std::size_t n = x.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double lx = std::log(x[i]), ly = std::log(e[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

Results::Results() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  test_ = info ? std::string(info->test_suite_name()) + "." + info->name() : "unknown";
}

Results::~Results() {
  namespace fs = std::filesystem;
  std::string name = test_;
  for (char& c : name)
    if (c == '/') c = '_';
  fs::create_directories(SPH_RESULTS_DIR);
  std::ofstream out(fs::path(SPH_RESULTS_DIR) / (name + ".json"));
  out << "{\n  \"test\": " << quote(test_) << ",\n  \"checks\": [";
  for (std::size_t i = 0; i < checks_.size(); ++i) out << (i ? ",\n    " : "\n    ") << checks_[i];
  out << "\n  ],\n  \"convergence\": [";
  for (std::size_t i = 0; i < convergence_.size(); ++i)
    out << (i ? ",\n    " : "\n    ") << convergence_[i];
  out << "\n  ],\n  \"figures\": [";
  for (std::size_t i = 0; i < figures_.size(); ++i)
    out << (i ? ",\n    " : "\n    ") << figures_[i];
  out << "\n  ]";
  if (!histories_.empty()) {
    out << ",\n  \"histories\": [";
    for (std::size_t i = 0; i < histories_.size(); ++i)
      out << (i ? ",\n    " : "\n    ") << histories_[i];
    out << "\n  ]";
  }
  out << "\n}\n";
}

bool Results::check(const std::string& name, double measured, const std::string& comparison,
                    double threshold, const std::string& source) {
  bool pass = false;
  if (comparison == "<")
    pass = measured < threshold;
  else if (comparison == "<=")
    pass = measured <= threshold;
  else if (comparison == ">")
    pass = measured > threshold;
  else if (comparison == ">=")
    pass = measured >= threshold;
  checks_.push_back("{\"name\": " + quote(name) + ", \"measured\": " + number(measured) +
                    ", \"threshold\": " + number(threshold) +
                    ", \"comparison\": " + quote(comparison) + ", \"source\": " + quote(source) +
                    ", \"pass\": " + (pass ? "true" : "false") + "}");
  return pass;
}

void Results::figure(const std::string& name, double measured, const std::string& source) {
  figures_.push_back("{\"name\": " + quote(name) + ", \"measured\": " + number(measured) +
                     ", \"source\": " + quote(source) + "}");
}

void Results::history(const std::string& name, const std::string& xLabel,
                      const std::vector<double>& x, const std::string& yLabel,
                      const std::vector<double>& y, const std::string& source) {
  histories_.push_back("{\"name\": " + quote(name) + ", \"x_label\": " + quote(xLabel) +
                       ", \"x\": " + array(x) + ", \"y_label\": " + quote(yLabel) +
                       ", \"y\": " + array(y) + ", \"source\": " + quote(source) + "}");
}

double Results::convergence(const std::string& name, const std::string& xLabel,
                            const std::vector<double>& x, const std::vector<double>& error,
                            double theoryOrder, const std::string& source) {
  const double order = observedOrder(x, error);
  convergence_.push_back(
      "{\"name\": " + quote(name) + ", \"x_label\": " + quote(xLabel) + ", \"x\": " + array(x) +
      ", \"error\": " + array(error) + ", \"observed_order\": " + number(order) +
      ", \"theory_order\": " + number(theoryOrder) + ", \"source\": " + quote(source) + "}");
  return order;
}

}  // namespace sph::verification
