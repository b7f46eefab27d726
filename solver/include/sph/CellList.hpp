#pragma once
// Cell-linked list (Hockney & Eastwood): points binned into cubic cells of side `cellSize` over
// their bounding box and counting-sorted by cell, so that all neighbours of a point within
// cellSize lie in the 3^D cells around it. O(N) to build and to query.
//
// Cells are numbered along the points' axes in order, fastest first, except that an axis at least
// twice as long as the last comes last (slowest): the layers along it, which a parallel pair loop
// hands out in bands, are then many (a dam break's flow is several times wider than deep). Below,
// axis 0 is the fastest numbering axis. The three cells ix-1, ix, ix+1 of one row along it are
// consecutive and their points form one contiguous range of the sorted order: a point's neighbours
// lie in 3^(D-1) such ranges (forEachAdjacentRow), which a pair loop can sweep without per-cell
// bookkeeping. With cells of half the reach, the neighbours lie within two cells
// (forEachAdjacentRow<2>: 5^(D-1) rows of 5 cells), a tighter box around the reach's sphere:
// in 2-D 25/4 against 9 times the squared reach, so fewer candidates to test.
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sph/CacheLines.hpp"
#include "sph/Parallel.hpp"
#include "sph/Vector.hpp"

namespace sph {

template <int D>
class CellList {
 public:
  template <class Allocator>
  void build(const std::vector<Vec<D>, Allocator>& x, double cellSize) {
    build(
        x.size(), [&](std::size_t i, int a) { return x[i][a]; }, cellSize);
  }

  // The same, for points given by an accessor pos(i, axis); the arrays are reused between builds
  // (no allocation once they have grown to the largest n seen).
  // `cellsPerPoint` bounds the grid's size (cells are doubled until it holds). The threads bin
  // the points as shareOf(n, leading, ...) splits them (Parallel.hpp; leading = n: evenly), and
  // sort those of whole layers (below): thread t those of layers cut(layers, nt, t) ..
  // cut(layers, nt, t + 1) - 1, where cut(layers, nt, 0) = 0, cut(layers, nt, nt) = layers, and
  // cut ascends in t (EvenLayers by default). A pair loop that hands the layers to its threads
  // so gets the sorted order of its layers written by the thread that reads it. The order does
  // not depend on the cut or the thread count.
  struct EvenLayers {
    int operator()(int layers, int nt, int t) const {
      return static_cast<int>(std::int64_t{layers} * t / nt);
    }
  };
  template <class Pos, class Cut = EvenLayers>
  void build(std::size_t n, Pos&& pos, double cellSize, int cellsPerPoint = 4,
             std::size_t leading = ~std::size_t{0}, Cut&& cut = {}) {
    Box box;
    box.include(n, pos, leading);
    build(n, pos, box, cellSize, cellsPerPoint, leading, cut);
  }
  // The points' bounding box, for a caller that finds it in a pass of its own over the points.
  struct Box {
    double lo[D], hi[D];
    Box() {
      for (int a = 0; a < D; ++a) lo[a] = 1e300, hi[a] = -1e300;
    }
    template <class Pos>
    void include(std::size_t n, Pos&& pos, std::size_t leading) {  // in shares, as build() splits
      const std::int64_t count = static_cast<std::int64_t>(n);
      const std::int64_t lead = static_cast<std::int64_t>(std::min(leading, n));
      double low[D], high[D];
      for (int a = 0; a < D; ++a) low[a] = lo[a], high[a] = hi[a];
#pragma omp parallel if (count >= parallelFrom()) reduction(min : low[:D]) reduction(max : high[:D])
      walk(shareOf(count, lead, omp_get_thread_num(), omp_get_num_threads()), [&](std::int64_t i) {
        for (int a = 0; a < D; ++a)
          low[a] = std::min(low[a], pos(i, a)), high[a] = std::max(high[a], pos(i, a));
      });
      for (int a = 0; a < D; ++a) lo[a] = low[a], hi[a] = high[a];
    }
  };
  // The grid of points spread over several processes (sph/DomainDecomposition.hpp): the cells
  // that all of them (`points`, in `box`) would get, of which each process builds the window
  // of whole cells around its own, its first layer a multiple of `layerAlign` (the bands a
  // pair loop pairs layers in stay the same). The window's cells come in the same order as the
  // whole grid's, so a point's neighbours come in the same order as there.
  struct Frame {
    Box box;
    std::size_t points = 0;
    int layerAlign = 1;
  };
  template <class Pos, class Cut = EvenLayers>
  void build(std::size_t n, Pos&& pos, const Box& box, double cellSize, int cellsPerPoint,
             std::size_t leading, Cut&& cut, const Frame* frame = nullptr) {
    checkBox(n, box);
    const bool parallel = static_cast<std::int64_t>(n) >= parallelFrom();
    const int threads = parallel ? std::min(omp_get_max_threads(), maxTeam) : 1;
    reserve(n, cellsPerPoint, threads, frame ? frame->points : 0);
#pragma omp parallel num_threads(threads) if (parallel)
    buildInTeam(n, pos, box, cellSize, cellsPerPoint, leading, cut, frame);
  }

  // Throws std::invalid_argument where the box has no number along an axis (no point has one
  // there: a NaN), unless there are no points.
  static void checkBox(std::size_t n, const Box& box) {
    for (int a = 0; a < D && n > 0; ++a)
      if (!(box.lo[a] <= box.hi[a]))
        throw std::invalid_argument("CellList: the points' box is empty along axis " +
                                    std::to_string(a));
  }

  // The same inside a parallel region of the caller's (a pass of its own before or after the
  // build then needs no region of its own: issue 7). reserve() first, outside the region, for the
  // team's size (at most maxTeam); then every thread of the team calls buildInTeam with the same
  // arguments (a box that passes checkBox). Returns the calling thread's part of the sorted order
  // (the points of its layers, which it placed). On return the grid (cells(), layers(), ...) and
  // that part may be read; the other threads' parts after the team's next barrier.
  static constexpr int maxTeam = 64;
  // (With a Frame, `framePoints` its points: the window holds at most the whole grid's cells.)
  void reserve(std::size_t n, int cellsPerPoint, int threads, std::size_t framePoints = 0) {
    order_.resize(n), sortedCell_.resize(n);
    // As many cells as the grid may have (below), unset: only the cells of the grid in use are
    // ever stored to, so that the bound costs no memory beyond them.
    const std::size_t bound =
        static_cast<std::size_t>(cellsPerPoint) * std::max(n, framePoints) + 64 + 1;
    if (start_.size() < bound) start_.resize(bound);
    if (static_cast<int>(buckets_.size()) < threads * threads) buckets_.resize(threads * threads);
    blockSum_.resize(static_cast<std::size_t>(threads) * 16);
  }
  // (`gridPoints`, where more than n: the points the grid is sized for, as if that many.)
  template <class Pos, class Cut = EvenLayers>
  Share buildInTeam(std::size_t n, Pos&& pos, const Box& box, double cellSize, int cellsPerPoint,
                    std::size_t leading, Cut&& cut, const Frame* frame = nullptr,
                    std::size_t gridPoints = 0) {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    const std::int64_t count = static_cast<std::int64_t>(n);
    const std::int64_t lead = static_cast<std::int64_t>(std::min(leading, n));
    // Every thread finds the grid (the same); the first stores it for the queries.
    const Grid g = frame ? windowOf(gridFor(frame->points, frame->box, cellSize, cellsPerPoint), n,
                                    box, frame->layerAlign)
                         : gridFor(std::max(n, gridPoints), box, cellSize, cellsPerPoint);
    std::int64_t perLayer = 1;
    for (int a = 0; a + 1 < D; ++a) perLayer *= g.dims[a];
    const std::int64_t total = g.total;
    // A counting sort by cell, stable (points of a cell in increasing index). Each thread bins its
    // share of the points into one bucket for each thread (the one whose layers hold the point's
    // cell), then counts and places the points of the buckets for it: thread 0's, then thread
    // 1's, ..., each in increasing index, so the order is the serial one whatever the thread
    // count and the cut. A thread so writes the sorted order of its own layers only. (Each thread
    // placed its own share before: the last thread, which bins the halo of an interaction set,
    // wrote into the other's layers at every wall, and each thread summed and numbered the
    // other's counts of its cells. The block of makeBlock (perf/Workload.hpp), two threads, best
    // of 4 alternated runs of each: 1e3 points 6.53 -> 6.14 us, 1e4 38.8 -> 36.6, 1e5 352 -> 320,
    // 1e6 3,771 -> 3,393 us; one thread 7.81 -> 8.14, 60.0 -> 63.6, 637 -> 622, 6,937 -> 6,739
    // us. The whole force evaluation at 1e3 with lists built, two threads on cores that do not
    // share a cache, 99.7-101 -> 90.4-93.0 us.)
    // start_[c + 1] counts cell c's points, then holds its next place, and so ends as the start
    // of cell c + 1.
    const auto [begin, end] = shareOf(count, lead, t, nt);
    std::array<std::int64_t, maxTeam + 1> firstCell{};  // thread u's: firstCell[u] .. [u + 1]
    const int layers = g.dims[D - 1];
    for (int u = 1; u < nt; ++u)  // (ascending whatever `cut` returns)
      firstCell[u] =
          std::max(firstCell[u - 1], std::clamp(cut(layers, nt, u), 0, layers) * perLayer);
    firstCell[nt] = total;
    std::uint64_t* into[maxTeam];  // where the next point for thread u's bucket goes
    for (int u = 0; u < nt; ++u) {
      Bucket& bucket = buckets_[t * nt + u];
      if (static_cast<std::int64_t>(bucket.points.size()) < end - begin)
        bucket.points.resize(end - begin);
      into[u] = bucket.points.data();
    }
    // Bin: point i of cell c as c 2^32 + i into the bucket of the thread whose cells hold c,
    // and counted at once if they are this thread's own (the others' after the barrier).
    const std::int64_t c0 = firstCell[t], c1 = firstCell[t + 1];
    int* next = start_.data() + 1;  // next[c]: cell c's count, then its next place
    std::fill(next + c0, next + c1, 0);
    if (t == 0) start_[0] = 0, grid_ = g;
    int to = t;
    std::uint64_t* out = into[to];  // into[to], in a register while `to` stays
    for (std::int64_t i = begin; i < end; ++i) {
      std::int64_t idx = 0, stride = 1;
      for (int a = 0; a < D; ++a) {
        idx += g.bin(pos(i, g.axis[a]), a) * stride;
        stride *= g.dims[a];
      }
      if (idx < firstCell[to] || idx >= firstCell[to + 1]) {  // the points come near one another
        into[to] = out;
        while (idx >= firstCell[to + 1]) ++to;
        while (idx < firstCell[to]) --to;
        out = into[to];
      }
      *out++ = static_cast<std::uint64_t>(idx) << 32 | static_cast<std::uint64_t>(i);
      if (to == t) ++next[idx];
    }
    into[to] = out;
    for (int u = 0; u < nt; ++u)
      buckets_[t * nt + u].filled = into[u] - buckets_[t * nt + u].points.data();
    // Cell c's points start after all points of cells < c: after the own cells' before it and
    // the points of the threads before (the grid has about as many cells as points, so a serial
    // sum over it would not scale: 1e6 points on two threads, the build 2.84-3.00 ms with one
    // serial sum, 2.68-2.87 ms so).
    int running = 0;
    if (nt > 1) {
#pragma omp barrier
      for (int u = 0; u < nt; ++u) {
        if (u == t) continue;
        const Bucket& bucket = buckets_[u * nt + t];
        for (std::int64_t k = 0; k < bucket.filled; ++k) ++next[bucket.points[k] >> 32];
      }
      int sum = 0;
      for (std::int64_t c = c0; c < c1; ++c) sum += next[c];
      blockSum_[16 * t] = sum;  // a cache line a thread
#pragma omp barrier
      for (int u = 0; u < t; ++u) running += blockSum_[16 * u];
    }
    const int placedBegin = running;
    for (std::int64_t c = c0; c < c1; ++c) {
      const int here = next[c];
      next[c] = running, running += here;
    }
    // Place. Points in cell order (as Simulation::keepCellOrder stores them) come in runs of
    // one cell: the next place kept in a register along a run.
    std::int64_t run = -1;
    int place = 0;
    for (int u = 0; u < nt; ++u) {
      const Bucket& bucket = buckets_[u * nt + t];
      for (std::int64_t k = 0; k < bucket.filled; ++k) {
        const std::uint64_t point = bucket.points[k];
        const std::int64_t c = static_cast<std::int64_t>(point >> 32);
        if (c != run) {
          if (run >= 0) next[run] = place;
          run = c, place = next[c];
        }
        order_[place] = static_cast<int>(point & 0xffffffffu);
        sortedCell_[place] = c;
        ++place;
      }
    }
    if (run >= 0) next[run] = place;
    return {placedBegin, running};
  }

  // order()[k] is the point at position k of the cell-sorted sequence.
  const LineVector<int>& order() const {
    return order_;
  }
  // The cell of the point at sorted position k.
  std::int64_t sortedCell(int k) const {
    return sortedCell_[k];
  }
  // The same cell's index in the whole grid of a Frame (without one, the grid's own).
  std::int64_t frameCell(int k) const {
    std::int64_t rest = sortedCell_[k], idx = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      idx += (rest % grid_.dims[a] + grid_.offset[a]) * stride;
      rest /= grid_.dims[a], stride *= grid_.frameDims[a];
    }
    return idx;
  }
  std::int64_t cells() const {
    return grid_.total;
  }
  int cellBegin(std::int64_t c) const {
    return start_[c];
  }
  int cellEnd(std::int64_t c) const {
    return start_[c + 1];
  }
  // The cell side actually used (cellSize, doubled as often as the O(N) guard needed).
  double cellSize() const {
    return grid_.size;
  }

  // The cell for a query point x that need not be one of the built points: -1 when x lies more
  // than one cell beyond the grid (no point within cellSize() of it); otherwise x's cell clamped
  // to the grid, whose adjacent cells (forEachAdjacentRange) hold every point within cellSize().
  std::int64_t cellOf(const Vec<D>& x) const {
    std::int64_t idx = 0, stride = 1;
    for (int a = 0; a < D; ++a) {
      const double k =
          std::floor((x[grid_.axis[a]] - grid_.lo[a]) * grid_.inverse) - grid_.offset[a];
      if (k < -1.0 || k > grid_.dims[a]) return -1;
      idx += std::clamp(static_cast<int>(k), 0, grid_.dims[a] - 1) * stride;
      stride *= grid_.dims[a];
    }
    return idx;
  }

  // Calls f(begin, end) for the sorted range of each cell around cell `c` (itself included).
  template <class F>
  void forEachAdjacentRange(std::int64_t c, F&& f) const {
    std::array<int, D> ic;
    std::int64_t rest = c;
    for (int a = 0; a < D; ++a)
      ic[a] = static_cast<int>(rest % grid_.dims[a]), rest /= grid_.dims[a];
    std::array<int, D> off;
    off.fill(-1);
    for (;;) {
      std::int64_t idx = 0, stride = 1;
      bool inside = true;
      for (int a = 0; a < D; ++a) {
        const int k = ic[a] + off[a];
        if (k < 0 || k >= grid_.dims[a]) inside = false;
        idx += k * stride;
        stride *= grid_.dims[a];
      }
      if (inside && start_[idx] != start_[idx + 1]) f(start_[idx], start_[idx + 1]);
      int a = 0;
      while (a < D && ++off[a] > 1) off[a++] = -1;
      if (a == D) break;
    }
  }

  // The forward half of forEachAdjacentRow<Reach>, for a loop that visits each pair once: the
  // rows whose offset along the slowest axis that is not zero is positive (in 2-D the Reach rows
  // above; in 3-D also the rows beside in the layers above). With the points of the own row that
  // come after a point (up to ownRowEnd), they hold every neighbour that follows it in the sorted
  // order and none that precedes it. The rows come in a fixed order.
  template <int Reach = 1, class F>
  void forEachForwardRow(std::int64_t c, F&& f) const {
    if constexpr (D > 1) {
      forEachAdjacentRow<Reach>(c, f, [](const auto& off) {
        for (int a = D - 1; a >= 1; --a)
          if (off[a] != 0) return off[a] > 0;
        return false;
      });
    }
  }
  // The end of the sorted range of the cells ix .. ix+Reach of the own row of cell c.
  template <int Reach = 1>
  int ownRowEnd(std::int64_t c) const {
    const int ix = static_cast<int>(c % grid_.dims[0]);
    return start_[c + std::min(Reach, grid_.dims[0] - 1 - ix) + 1];
  }

  // Layers: the cells with one index along the slowest numbering axis, each a
  // contiguous range of the sorted order. layerBegin(layers()) is the end of the last.
  int layers() const {
    return grid_.dims[D - 1];
  }
  int layerBegin(int layer) const {
    std::int64_t perLayer = 1;
    for (int a = 0; a + 1 < D; ++a) perLayer *= grid_.dims[a];
    return start_[std::min(layer, grid_.dims[D - 1]) * perLayer];
  }

  // Calls f(begin, end) for each of the (2 Reach + 1)^(D-1) rows of cells around cell `c`: the
  // sorted range of the cells ix-Reach .. ix+Reach (clipped to the grid) at each offset -Reach ..
  // Reach of the other axes. The ranges come in a fixed order; for Reach = 1 they together hold
  // the same points as forEachAdjacentRange's.
  template <int Reach = 1, class F>
  void forEachAdjacentRow(std::int64_t c, F&& f) const {
    forEachAdjacentRow<Reach>(c, f, [](const auto&) { return true; });
  }
  // The same for the rows whose offsets (axes 1 .. D-1) `keep(off)` accepts.
  template <int Reach, class F, class Keep>
  void forEachAdjacentRow(std::int64_t c, F&& f, Keep&& keep) const {
    const int ix = static_cast<int>(c % grid_.dims[0]);
    const std::int64_t rowStart = c - ix;  // cell (0, iy, iz)
    const int first = std::max(-Reach, -ix), last = std::min(Reach, grid_.dims[0] - 1 - ix);
    if constexpr (D == 1) {
      f(start_[c + first], start_[c + last + 1]);
    } else {
      std::array<int, D> ic{};
      std::int64_t rest = c / grid_.dims[0];
      for (int a = 1; a < D; ++a)
        ic[a] = static_cast<int>(rest % grid_.dims[a]), rest /= grid_.dims[a];
      std::array<int, D> off;
      off.fill(-Reach);
      for (;;) {
        std::int64_t shift = 0, stride = grid_.dims[0];
        bool inside = true;
        for (int a = 1; a < D; ++a) {
          const int k = ic[a] + off[a];
          if (k < 0 || k >= grid_.dims[a]) inside = false;
          shift += off[a] * stride;
          stride *= grid_.dims[a];
        }
        if (inside && keep(off)) {
          const std::int64_t row = rowStart + shift;
          const int b = start_[row + ix + first], e = start_[row + ix + last + 1];
          if (b != e) f(b, e);
        }
        int a = 1;
        while (a < D && ++off[a] > Reach) off[a++] = -Reach;
        if (a == D) break;
      }
    }
  }

 private:
  // The cells: numbering axis a (0 fastest) is the points' axis axis[a]; lo and dims by numbering
  // axis.
  struct Grid {
    std::array<int, D> axis{};
    Vec<D> lo = Vec<D>::Zero();
    double size = 1.0, inverse = 1.0;
    std::array<int, D> dims{};
    std::int64_t total = 0;
    // A Frame's window: its first cell's index along each numbering axis in the whole grid,
    // and the whole grid's cells along it (without a Frame 0 and dims).
    std::array<int, D> offset{}, frameDims{};
    // The cell of coordinate x along numbering axis a, clamped to the grid (a product, not a
    // division a point and axis; with the run counting above, the build of 1,721 points on one
    // thread went from 10.3 to 9.0 us). In a window, the whole grid's cell less the offset: the
    // same arithmetic, so each point falls in the cell it falls in there.
    int bin(double x, int a) const {
      return std::clamp(static_cast<int>((x - lo[a]) * inverse), 0, frameDims[a] - 1) - offset[a];
    }
  };
  static Grid gridFor(std::size_t n, const Box& box, double cellSize, int cellsPerPoint) {
    Grid g;
    double lo[D], hi[D];  // (checkBox: a number on every axis)
    for (int a = 0; a < D; ++a) lo[a] = n > 0 ? box.lo[a] : 0.0, hi[a] = n > 0 ? box.hi[a] : 0.0;
    // An axis at least twice as long as the last is numbered slowest (the longest such), the
    // others keep their order. (Only a clearly longer axis: on a near-square box the points'
    // usual lattice order, axis 0 fastest, stays the sorted order's.)
    int longest = D - 1;
    for (int a = D - 2; a >= 0; --a)
      if (hi[a] - lo[a] >= 2.0 * (hi[D - 1] - lo[D - 1]) &&
          hi[a] - lo[a] > hi[longest] - lo[longest])
        longest = a;
    for (int a = 0, k = 0; a < D; ++a)
      if (a != longest) g.axis[k++] = a;
    g.axis[D - 1] = longest;
    for (int a = 0; a < D; ++a) g.lo[a] = lo[g.axis[a]];
    // Keep the grid O(N) even when a few points are far apart: coarser cells stay correct. The
    // cells are counted in doubles, so that a box of any extent (a wall 1e300 m away) gives a
    // count, not an integer overflow, and coarser cells until it fits.
    // A cell size that is no positive number (a support of 0: no point has a neighbour) gives
    // cells as wide as the box: doubling it would never end.
    g.size = cellSize;
    if (!(cellSize > 0.0)) {
      g.size = 1.0;
      for (int a = 0; a < D; ++a) g.size = std::max(g.size, hi[a] - lo[a]);
    }
    const double most = static_cast<double>(cellsPerPoint) * static_cast<double>(n) + 64.0;
    for (;;) {
      double total = 1.0;
      for (int a = 0; a < D; ++a) total *= std::floor((hi[g.axis[a]] - g.lo[a]) / g.size) + 1.0;
      if (total <= most) break;
      g.size *= 2.0;
    }
    g.total = 1;
    for (int a = 0; a < D; ++a) {
      g.dims[a] = static_cast<int>(std::floor((hi[g.axis[a]] - g.lo[a]) / g.size)) + 1;
      g.total *= g.dims[a];
    }
    g.inverse = 1.0 / g.size;
    g.frameDims = g.dims;
    return g;
  }
  // The window of `whole` that holds the n points of `box`: from the cell of its low corner
  // (along the slowest axis rounded down to a multiple of `align`) to that of its high one.
  static Grid windowOf(Grid whole, std::size_t n, const Box& box, int align) {
    if (n == 0) return whole;
    Grid g = whole;
    g.total = 1;
    for (int a = 0; a < D; ++a) {
      const int first = whole.bin(box.lo[whole.axis[a]], a);
      const int last = whole.bin(box.hi[whole.axis[a]], a);
      g.offset[a] = a == D - 1 ? first - first % align : first;
      g.dims[a] = last - g.offset[a] + 1;
      g.total *= g.dims[a];
    }
    return g;
  }

  Grid grid_;
  UnsetLineVector<int> start_;  // (reserve)
  LineVector<int> order_, blockSum_;
  LineVector<std::int64_t> sortedCell_;
  struct alignas(64) Bucket {  // one thread's points for one thread's cells (build)
    LineVector<std::uint64_t> points;
    std::int64_t filled = 0;
  };
  std::vector<Bucket> buckets_;
};

}  // namespace sph
