#pragma once
// Cell-linked list (Hockney & Eastwood): points binned into cubic cells of side `cellSize` over
// their bounding box and counting-sorted by cell, so that all neighbours of a point within
// cellSize lie in the 3^D cells around it. O(N) to build and to query.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sph/Vector.hpp"

namespace sph {

template <int D>
class CellList {
 public:
  void build(const std::vector<Vec<D>>& x, double cellSize) {
    const std::size_t n = x.size();
    lo_ = Vec<D>::Constant(0.0);
    Vec<D> hi = Vec<D>::Constant(0.0);
    if (n > 0) {
      lo_ = x[0], hi = x[0];
      for (const auto& p : x) lo_ = lo_.cwiseMin(p), hi = hi.cwiseMax(p);
    }
    // Keep the grid O(N) even when a few points are far apart: coarser cells stay correct.
    size_ = cellSize;
    for (;;) {
      std::int64_t total = 1;
      for (int a = 0; a < D; ++a) {
        dims_[a] = static_cast<int>(std::floor((hi[a] - lo_[a]) / size_)) + 1;
        total *= dims_[a];
      }
      if (total <= static_cast<std::int64_t>(4 * n + 64)) break;
      size_ *= 2.0;
    }
    std::int64_t total = 1;
    for (int a = 0; a < D; ++a) total *= dims_[a];
    start_.assign(total + 1, 0);
    cellOf_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      cellOf_[i] = cellIndex(x[i]);
      ++start_[cellOf_[i] + 1];
    }
    for (std::int64_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
    order_.resize(n);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order_[fill[cellOf_[i]]++] = static_cast<int>(i);
  }

  // order()[k] is the point at position k of the cell-sorted sequence.
  const std::vector<int>& order() const { return order_; }
  std::int64_t cells() const { return static_cast<std::int64_t>(start_.size()) - 1; }
  int cellBegin(std::int64_t c) const { return start_[c]; }
  int cellEnd(std::int64_t c) const { return start_[c + 1]; }

  // Calls f(begin, end) for the sorted range of each cell around cell `c` (itself included).
  template <class F>
  void forEachAdjacentRange(std::int64_t c, F&& f) const {
    std::array<int, D> ic;
    std::int64_t rest = c;
    for (int a = 0; a < D; ++a) ic[a] = static_cast<int>(rest % dims_[a]), rest /= dims_[a];
    std::array<int, D> off;
    off.fill(-1);
    for (;;) {
      std::int64_t idx = 0, stride = 1;
      bool inside = true;
      for (int a = 0; a < D; ++a) {
        const int k = ic[a] + off[a];
        if (k < 0 || k >= dims_[a]) inside = false;
        idx += k * stride;
        stride *= dims_[a];
      }
      if (inside && start_[idx] != start_[idx + 1]) f(start_[idx], start_[idx + 1]);
      int a = 0;
      while (a < D && ++off[a] > 1) off[a++] = -1;
      if (a == D) break;
    }
  }

 private:
  std::int64_t cellIndex(const Vec<D>& p) const {
    std::int64_t idx = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      int k = static_cast<int>((p[a] - lo_[a]) / size_);
      k = std::clamp(k, 0, dims_[a] - 1);
      idx += k * stride;
      stride *= dims_[a];
    }
    return idx;
  }

  Vec<D> lo_;
  double size_ = 1.0;
  std::array<int, D> dims_{};
  std::vector<int> start_, order_;
  std::vector<std::int64_t> cellOf_;
};

}  // namespace sph
