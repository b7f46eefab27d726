#pragma once
// The scene readers' view of one TOML table (Scene.cpp, packing/PackingScene.cpp): it knows its
// dotted path, reports every error against the file, the line:column where the TOML has one, and
// the key (SceneError), and rejects unknown (misspelt) keys with the nearest known key as a
// suggestion. A reader that declares its table's keys (allow) has the unknown ones rejected before
// it reads any, so `end_tme` is named as unknown, not `end_time` as missing. Internal to the
// solver library.
#include <toml++/toml.h>

#include <Eigen/Dense>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "SceneNames.hpp"
#include "sph/Scene.hpp"  // SceneError

namespace sph {

class SceneTable {
 public:
  SceneTable(const toml::table& t, std::string path, const std::string& file)
      : t_(t), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    const toml::node* n = t_.get(key);
    throw SceneError(where(n ? &n->source() : nullptr) + ": key '" + full(key) + "': " + what);
  }
  std::string full(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) {
    use(key);
    return t_.contains(key);
  }
  // Declares every key the table may hold and rejects any other now, before a reader asks for a
  // value that a misspelt key was meant to give. Reading an undeclared key later is a bug of the
  // reader (std::logic_error).
  void allow(const std::vector<std::string>& keys) {
    allowed_.insert(keys.begin(), keys.end());
    for (const auto& [k, v] : t_)
      if (!allowed_.count(std::string(k.str()))) unknown(k, allowed_);
  }

  double number(const std::string& key, std::optional<double> fallback = std::nullopt) {
    use(key);
    const toml::node* n = t_.get(key);
    if (!n) {
      if (fallback) return *fallback;
      fail(key, "missing value (a number)");
    }
    if (auto v = n->value<double>()) {
      if (!std::isfinite(*v)) fail(key, "must be a finite number, got " + fmt(*v));
      return *v;
    }
    fail(key, std::string("wrong type: expected a number, got ") + typeName(*n));
  }
  // A whole number (a TOML integer, or a float without a fractional part).
  long integer(const std::string& key, std::optional<long> fallback = std::nullopt) {
    const double v = number(key, fallback ? std::optional<double>(*fallback) : std::nullopt);
    if (v != std::floor(v) || std::abs(v) > 1e9) fail(key, "must be a whole number, got " + fmt(v));
    return static_cast<long>(v);
  }
  double positive(const std::string& key, std::optional<double> fallback = std::nullopt) {
    const double v = number(key, fallback);
    if (!(v > 0.0)) fail(key, "must be positive, got " + fmt(v));
    return v;
  }
  double nonNegative(const std::string& key, std::optional<double> fallback = std::nullopt) {
    const double v = number(key, fallback);
    if (v < 0.0) fail(key, "must not be negative, got " + fmt(v));
    return v;
  }
  std::string string(const std::string& key, std::optional<std::string> fallback = std::nullopt) {
    use(key);
    const toml::node* n = t_.get(key);
    if (!n) {
      if (fallback) return *fallback;
      fail(key, "missing value (a string)");
    }
    if (auto v = n->value<std::string>()) return *v;
    fail(key, std::string("wrong type: expected a string, got ") + typeName(*n));
  }
  // A scene's name, a phase's or a probe's: a plain name (SceneNames.hpp).
  std::string name(const std::string& key) {
    const std::string v = string(key);
    const std::string problem = nameProblem(v);
    if (!problem.empty())
      fail(key, "'" + v + "' is not a valid name: " + problem +
                    " (names become file and HDF5 names; allowed: [A-Za-z0-9_.-], not starting "
                    "with '.')");
    return v;
  }
  // Only the TOML booleans: toml++ would read an integer as one (1 as true), which SCENES.md
  // does not allow, so `morris_viscosity = 1` is refused rather than guessed.
  bool boolean(const std::string& key, bool fallback) {
    use(key);
    const toml::node* n = t_.get(key);
    if (!n) return fallback;
    if (const auto* b = n->as_boolean()) return b->get();
    fail(key, std::string("wrong type: must be true or false, got ") + typeName(*n));
  }
  std::vector<double> vector(const std::string& key, int size,
                             std::optional<std::vector<double>> fallback = std::nullopt) {
    use(key);
    const toml::node* n = t_.get(key);
    if (!n) {
      if (fallback) return *fallback;
      fail(key, "missing value (an array of " + std::to_string(size) + " numbers)");
    }
    const toml::array* a = n->as_array();
    if (!a) fail(key, std::string("wrong type: expected an array of numbers, got ") + typeName(*n));
    if (static_cast<int>(a->size()) != size)
      fail(key, "expected " + std::to_string(size) + " numbers (one per dimension), got " +
                    std::to_string(a->size()));
    std::vector<double> out;
    for (const auto& e : *a) {
      auto v = e.value<double>();
      const std::string entry = "entry " + std::to_string(out.size());
      if (!v) fail(key, "wrong type: " + entry + " is " + typeName(e) + ", expected a number");
      if (!std::isfinite(*v)) fail(key, entry + " must be a finite number, got " + fmt(*v));
      out.push_back(*v);
    }
    return out;
  }
  // A size x size matrix written as an array of rows, returned row-major.
  std::vector<double> matrix(const std::string& key, int size) {
    use(key);
    const toml::node* n = t_.get(key);
    if (!n) fail(key, "missing value (an array of " + std::to_string(size) + " rows)");
    const toml::array* a = n->as_array();
    const std::string shape = std::to_string(size) + " x " + std::to_string(size);
    if (!a || static_cast<int>(a->size()) != size)
      fail(key, "expected a " + shape + " matrix written as " + std::to_string(size) +
                    " rows, e.g. [[1.0, 0.0], [0.0, -1.0]]");
    std::vector<double> out;
    for (std::size_t r = 0; r < a->size(); ++r) {
      const toml::array* row = (*a)[r].as_array();
      if (!row || static_cast<int>(row->size()) != size)
        fail(key, "row " + std::to_string(r) + " must be an array of " + std::to_string(size) +
                      " numbers (a " + shape + " matrix)");
      for (const auto& e : *row) {
        auto v = e.value<double>();
        const std::string entry =
            "entry [" + std::to_string(r) + "][" + std::to_string(out.size() % size) + "]";
        if (!v) fail(key, "wrong type: " + entry + " is " + typeName(e) + ", expected a number");
        if (!std::isfinite(*v)) fail(key, entry + " must be a finite number, got " + fmt(*v));
        out.push_back(*v);
      }
    }
    return out;
  }
  SceneTable sub(const std::string& key) {
    use(key);
    const toml::node* n = t_.get(key);
    if (!n) return SceneTable(empty(), full(key), file_);
    if (!n->is_table()) fail(key, std::string("wrong type: expected a table, got ") + typeName(*n));
    return SceneTable(*n->as_table(), full(key), file_);
  }
  std::vector<SceneTable> array(const std::string& key) {
    use(key);
    std::vector<SceneTable> out;
    const toml::node* n = t_.get(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
      fail(key, "wrong type: expected an array of tables ([[" + full(key) + "]])");
    for (std::size_t i = 0; i < a->size(); ++i)
      out.emplace_back(*(*a)[i].as_table(), full(key) + "[" + std::to_string(i) + "]", file_);
    return out;
  }
  // A 2-D point [x, y] (the packing scenes' geometry).
  Eigen::Vector2d point(const std::string& key,
                        std::optional<Eigen::Vector2d> fallback = std::nullopt) {
    if (fallback && !t_.contains(key)) {
      use(key);
      return *fallback;
    }
    const std::vector<double> v = vector(key, 2);
    return {v[0], v[1]};
  }
  // Call after reading a table: any key never asked for is unknown.
  void rejectUnknown() const {
    for (const auto& [k, v] : t_)
      if (!used_.count(std::string(k.str()))) unknown(k, allowed_.empty() ? used_ : allowed_);
  }

  static std::string fmt(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }

 private:
  void use(const std::string& key) {
    if (!allowed_.empty() && !allowed_.count(key))
      throw std::logic_error("scene reader: key '" + full(key) + "' is read but not declared");
    used_.insert(key);
  }
  // "file:line:column" where the TOML gives a place, else "file".
  std::string where(const toml::source_region* at) const {
    if (!at || at->begin.line == 0) return file_;
    return file_ + ":" + std::to_string(at->begin.line) + ":" + std::to_string(at->begin.column);
  }
  [[noreturn]] void unknown(const toml::key& k, const std::set<std::string>& known) const {
    const std::string typed(k.str());
    std::string guess;
    std::size_t best = ~std::size_t{0};
    for (const auto& c : known)
      if (nearMiss(typed, c) && editDistance(typed, c) < best)
        guess = c, best = editDistance(typed, c);
    throw SceneError(where(&k.source()) + ": key '" + full(typed) + "': unknown key" +
                     (guess.empty() ? "" : " (did you mean '" + full(guess) + "'?)"));
  }
  static const toml::table& empty() {
    static const toml::table e;
    return e;
  }
  static const char* typeName(const toml::node& n) {
    switch (n.type()) {
      case toml::node_type::string:
        return "a string";
      case toml::node_type::integer:
        return "an integer";
      case toml::node_type::floating_point:
        return "a number";
      case toml::node_type::boolean:
        return "a boolean";
      case toml::node_type::array:
        return "an array";
      case toml::node_type::table:
        return "a table";
      case toml::node_type::date:
      case toml::node_type::time:
      case toml::node_type::date_time:
        return "a date or time";
      case toml::node_type::none:
        return "nothing";
    }
    return "a value of an unknown TOML type";  // toml++ added a type: named, not mistaken
  }
  const toml::table& t_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> used_, allowed_;
};

}  // namespace sph
