#pragma once
// The pair loop: the machinery that evaluates a set of terms (sph/terms/) over every pair of an
// interaction set. Included by ForceEvaluation.cpp only, which builds it for the menu.
#include <omp.h>
#if defined(__AVX__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <stdexcept>
#include <thread>

#include "sph/CacheLines.hpp"
#include "sph/ForceEvaluation.hpp"
#include "sph/Parallel.hpp"
#include "sph/terms/PairValues.hpp"

namespace sph {

// How the loop is laid out (issue 7):
// * The interaction set is copied, cell-sorted, into arrays by field (x, h: pass 1) and records
//   by entry (pass 2), with the per-particle factors of the pair sums precomputed (p/rho^2,
//   1/rho, m/rho). The arrays end in `lanes` far-away, massless entries, so that a vector may
//   read past the end.
// * Each pair once (Newton's third law): eq. 11-13 give j the same pair values as i, up to the
//   masses and the sign of grad W, so the pair's square root, division and kernel are shared.
//   Particle i takes the pairs with the entries j after it in the sorted order: in 2-D, with
//   cells of half the reach, the rest of its own row of five cells and the two rows of five above
//   (CellList::forEachForwardRow<2>), about 22 candidates for 10 neighbours. A halo entry takes
//   its pairs with fluid entries only.
// * Pass 1 tests a block of `lanes` consecutive candidates at a time (one vector of doubles, GCC
//   vector extensions) and appends the neighbours (inside the row, 0 < r_ij < support h_ij) to a
//   per-thread list, as 16 j (the byte offset of j's 16-byte record; see pass 2). Pass 2 evaluates
//   the terms on that list, `lanes` neighbours at a time, padded with a far-away massless entry:
//   i's rates add in registers (lane l into lane l, the lanes summed in a fixed order at the end),
//   j's share goes straight to j's rate record. Pass 2 has no branch: the approaching-pair test of
//   eq. 10 is a select.
// * Threads without atomics in the pair loop, and the same bits for any thread count: the sorted
//   entries are cut into bands of two layers of cells (along the cell list's slowest axis). A
//   pair's j lies in i's band or the next, so the even bands run at once, and each odd band once
//   the even bands beside it are done (one flag a band); within a band entries go in sorted
//   order. Every rate is thus summed in an order fixed by the cell list alone. Each thread takes a
//   contiguous run of bands of about equal work (counted in the last evaluation), copies the
//   entries it reads (its bands' and the next band's) into arrays of its own, and writes out its
//   bands' entries: little moves between cores, and only the rates are shared.
// * At most one square root and one division per pair: 1/r, 1/h_ij, 1/(r^2 + eta^2) and
//   1/(rho_i + rho_j) come from the reciprocal of their product (pairReciprocals); with AVX-512
//   neither, but Newton steps from hardware estimates (pairInverses).
// * All arrays live in the workspace and only grow: no allocation per step.
namespace pair_loop {
constexpr int lanes = 4;  // one AVX2 register of doubles (two SSE2 registers on x86-64-v2)
using Vd = double __attribute__((vector_size(lanes * sizeof(double))));
using Vi = std::int64_t __attribute__((vector_size(lanes * sizeof(std::int64_t))));
inline Vd load(const double* p) {  // lanes consecutive doubles, unaligned
  Vd v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}
inline Vd load2(const double* a, const double* b) {  // {a[0], a[1], b[0], b[1]}
#if defined(__AVX__)
  return reinterpret_cast<Vd>(_mm256_loadu2_m128d(b, a));
#else
  return Vd{a[0], a[1], b[0], b[1]};
#endif
}
inline Vd broadcast(double x) {
  return Vd{} + x;
}
// Bit l set where lane l of the mask is set (all ones).
inline unsigned laneBits(Vi mask) {
#if defined(__AVX__)
  return static_cast<unsigned>(_mm256_movemask_pd(reinterpret_cast<__m256d>(mask)));
#else
  unsigned bits = 0;
  for (int l = 0; l < lanes; ++l) bits |= static_cast<unsigned>(mask[l] & 1) << l;
  return bits;
#endif
}
// For each 4-bit lane mask, the set lanes in order (then zeros): compressOffsets[0b1010] =
// {1, 3, 0, 0}. Appending j + these to a list and advancing by the mask's popcount keeps the
// lanes inside.
using Vi32 = int __attribute__((vector_size(lanes * sizeof(int))));
constexpr Vi32 compressOffsets[16] = {{0, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}, {0, 1, 0, 0},
                                      {2, 0, 0, 0}, {0, 2, 0, 0}, {1, 2, 0, 0}, {0, 1, 2, 0},
                                      {3, 0, 0, 0}, {0, 3, 0, 0}, {1, 3, 0, 0}, {0, 1, 3, 0},
                                      {2, 3, 0, 0}, {0, 2, 3, 0}, {1, 2, 3, 0}, {0, 1, 2, 3}};
inline Vd sqrt(Vd x) {
  Vd r;
  for (int l = 0; l < lanes; ++l) r[l] = __builtin_sqrt(x[l]);  // one vsqrtpd (-fno-math-errno)
  return r;
}
// Rows a, b, c, d (four fields of four particles) to columns (one field of the four particles).
inline void transpose(Vd& a, Vd& b, Vd& c, Vd& d) {
  const Vd t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6),
           t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const Vd t2 = __builtin_shufflevector(c, d, 0, 4, 2, 6),
           t3 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
  a = __builtin_shufflevector(t0, t2, 0, 1, 4, 5), b = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  c = __builtin_shufflevector(t0, t2, 2, 3, 6, 7), d = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}
inline double sum(Vd x) {  // the lanes, in a fixed order
  double s = 0.0;
  for (int l = 0; l < lanes; ++l) s += x[l];
  return s;
}

// Which bands one evaluation has finished: band b's flag holds the number of the evaluation that
// last finished it, so that nothing is reset between evaluations.
class BandSignals {
 public:
  // Before any thread of a new evaluation signals or waits: before its parallel region, or by one
  // thread before a barrier in it.
  void start(int bands) {
    ++evaluation_;
    if (static_cast<int>(flags_.size()) < bands) flags_.resize(bands, 0);
  }
  void done(int b) {  // release: the band's stores before the flag
    std::atomic_ref<std::uint64_t>(flags_[b]).store(evaluation_, std::memory_order_release);
    // The flag's store before the look at the sleepers (and a sleeper's count before its look at
    // the flag, in wait): one of the two sees the other.
    std::atomic_thread_fence(std::memory_order_seq_cst);
    if (std::atomic_ref<std::uint32_t>(sleepers_).load(std::memory_order_relaxed) != 0) {
      std::atomic_ref<std::uint32_t> wakes(wakes_);
      wakes.fetch_add(1, std::memory_order_release);  // a sleeper that sees it sees the flag
      wakes.notify_all();
    }
  }
  // The band waited for is the first its thread runs (the order below), so a wait is short
  // unless that thread lost its core to other work: then this one sleeps instead of holding a
  // core the other may be waiting for. spinPauses pauses: 13 us in the 2-vCPU VM (26 ns a
  // pause), half of OpenMP's spin (sph/WaitPolicy.hpp).
  void wait(int b) {
    std::atomic_ref<std::uint64_t> flag(flags_[b]);
    auto isDone = [&] { return flag.load(std::memory_order_acquire) == evaluation_; };
    for (int spins = 0; spins < spinPauses; ++spins) {
      if (isDone()) return;
      pause();
    }
    std::atomic_ref<std::uint32_t> sleepers(sleepers_), wakes(wakes_);
    sleepers.fetch_add(1, std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_seq_cst);
    for (;;) {
      const std::uint32_t seen = wakes.load(std::memory_order_acquire);
      if (isDone()) break;
      wakes.wait(seen, std::memory_order_acquire);  // until a done() after `seen`
    }
    sleepers.fetch_sub(1, std::memory_order_relaxed);
  }

 private:
  static constexpr int spinPauses = 512;
  static void pause() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }
  LineVector<std::uint64_t> flags_;
  std::uint64_t evaluation_ = 0;
  alignas(64) std::uint32_t sleepers_ = 0;  // threads in wait's sleep
  std::uint32_t wakes_ = 0;                 // done() calls that found a sleeper
};
}  // namespace pair_loop
using namespace pair_loop;

template <int D>
struct ForceEvaluation<D>::Workspace {
  CellList<D> cells;
  // With `framed`, the grid of the whole domain's entries (ForceEvaluation::frameGrid): its
  // box, count and h_max instead of this set's.
  bool framed = false;
  typename CellList<D>::Frame frame;
  double frameHMax = 0.0;
  // The rates' record of each sorted entry (rateWidth doubles: d rho/dt, the dh/dt sum, dv/dt by
  // axis), which every thread adds to; on cache lines; each entry's zeroed as it is placed or
  // copied in.
  UnsetLineVector<double> rateStore;
  double* rate = nullptr;
  struct alignas(64) Scratch {  // one thread's: a particle's neighbours
    LineVector<int> neighbours;
    LineVector<unsigned char> copied;  // of the thread's bands in the pair loop, and the next
    // The thread's cell-sorted copies of the entries it reads, at their sorted positions k: those
    // of its bands and of the band after them (set only there). x[a][k], v[a][k] for axis a (v,
    // rho, p/rho^2, m by field in 3-D only), receives[k] all ones for a fluid entry, zero for
    // the halo. For D <= 2, the same per entry as one 64-byte record {x, y, v_x, v_y, h, rho,
    // p/rho^2, m} (y = v_y = 0 in 1-D): pass 2 loads four neighbours' records as eight vectors
    // and transposes them, instead of gathering each field. For every D, a 16-byte record {mu,
    // 1/rho}, or {mu, 1/rho, rho0, 0} of 32 bytes where a term reads the rest density. Each thread
    // has a copy of its own of the next band (the first of the next thread's), which it reads too:
    // when the other thread copied it in, each store went to a line that this thread's core had
    // read, and when the two cores share no cache each such store waited for the other core
    // (makeBlock, two threads, rdtsc: that band's copy-in at 1e4 37-41 us against 7.6-7.9 when the
    // cores share a cache; with the copy 2.1-3.3 us, and the wait for it at the barrier 32-37 ->
    // 0.4-1.4 us; at 1e3 9.8-10.7 -> 0.6-1.4 us). The rates stay one array, zeroed by each entry's
    // own thread (by the thread that placed it, at a build). Unset arrays: a thread's copy costs
    // memory for its part only (plus whole 2 MiB pages at its ends: 596-607 -> 632-639 B a particle
    // at 1e6).
    std::array<UnsetLineVector<double>, D> x, v;
    UnsetLineVector<double> h, rho, pOverRho2, m;
    UnsetLineVector<std::int64_t> receives;
    UnsetLineVector<double> recordStore, extraStore;
    double *record = nullptr, *extra = nullptr;
  };
  std::vector<Scratch> scratch;
  // The neighbour lists of the last build (NeighbourLists): band b's particles' lists one after
  // the other in bandLists[b], each padded to whole vectors; sorted entry k's starts at
  // listBegin[k] and holds listCount[k] neighbours. `listed` entries were in that set.
  std::vector<LineVector<int>> bandLists;
  LineVector<int> listBegin, listCount;
  std::size_t listed = 0;
  // The work of each band of two cell layers, in this evaluation (bandWork, written by the band's
  // thread) and in the last (bandCost), by which the threads' shares are cut: the candidates
  // pass 1 tests, 5 per neighbour pass 2 takes and 22 per particle (its rows, its sums). Fitted
  // to the bands' times on one thread, lists built and kept: the dam break at dx 0.01 after 500
  // and 5,000 steps, and makeBlock (perf/Workload.hpp) at 1e3 and 1e4 particles, 0.5-1.1 ns a
  // candidate, 4.7-5.9 ns a neighbour, 10-41 ns a particle. The bands' times differ from the
  // counts (scaled) by 2.1-6.4 % rms; from the candidates plus 3 per neighbour alone, as before,
  // by 2.9-10 % (the last band of the block at 1e3, the free surface's, by 35 %). Counted, not
  // timed: the cut is the same in every run.
  LineVector<std::int64_t> bandCost, bandWork;
  BandSignals evenDone;        // the even bands this evaluation has finished
  double hMax = 0.0;           // the largest h at the last build
  struct alignas(64) Extent {  // one thread's part of a build's box and h_max
    typename CellList<D>::Box box;
    double hMax;
  };
  LineVector<Extent> extents;
  // Antuono et al.'s density diffusion: the pass's sums and every entry's renormalised density
  // gradient (ForceEvaluation::densityGradients), which the copy-in reads.
  Derivatives<D> gradientSums;
  LineVector<Vec<D>> densityGradient;
};

namespace pair_loop {

// 1/a, 1/b, 1/c, 1/d from one division: with P = a b c d, 1/a = (b c d) / P and so on. Each is
// within a few ulp of the direct quotient; the terms' sum is compared with the O(N^2) reference
// loop to 1e-12 (verification/core/ForceEvaluationTest.cpp). All four are positive and of
// moderate size in any SI scene (P ~ 1e-5 at dx = 0.01 m), far from overflow and underflow.
struct Reciprocals {
  Vd a, b, c, d;
};
inline Reciprocals pairReciprocals(Vd a, Vd b, Vd c, Vd d) {
  const Vd ab = a * b, cd = c * d;
  const Vd inv = 1.0 / (ab * cd);
  const Vd abInv = inv * cd, cdInv = inv * ab;
  return {abInv * b, abInv * a, cdInv * d, cdInv * c};
}

// A pair's r = |r_ij|, 1/r and the reciprocals of a, b, c (all positive). With AVX-512 (the
// pair loop's x86-64-v4 build) 1/sqrt(r^2) and 1/(a b c) start from the 14-bit estimates of
// vrsqrt14pd and vrcp14pd, and two Newton steps each square the relative error (2^-14, 2^-28,
// below 2^-53; a few ulp of rounding remain): multiply-adds, which the core runs two at a time,
// instead of the square root and the division, which share one divider that is not pipelined
// (7 % off the whole force evaluation, 1e4 particles, 1 thread: 110 -> 102 ns a particle, best
// of 1,500 calls). Otherwise one square root and one division (pairReciprocals).
struct PairInverses {
  Vd r, rInv, a, b, c;
};
inline PairInverses pairInverses(Vd r2, Vd a, Vd b, Vd c) {
#if defined(__AVX512VL__)
  const Vd half = 0.5 * r2;
  Vd y = reinterpret_cast<Vd>(_mm256_rsqrt14_pd(reinterpret_cast<__m256d>(r2)));
  y = y * (1.5 - half * (y * y));  // Newton for 1/sqrt(x): y (3 - x y^2) / 2
  y = y * (1.5 - half * (y * y));
  const Vd ab = a * b, p = ab * c;
  Vd q = reinterpret_cast<Vd>(_mm256_rcp14_pd(reinterpret_cast<__m256d>(p)));
  q = q + q * (1.0 - p * q);  // Newton for 1/x: y (2 - x y)
  q = q + q * (1.0 - p * q);
  const Vd abInv = q * c;
  return {r2 * y, y, abInv * b, abInv * a, q * ab};
#else
  const Vd r = sqrt(r2);
  const auto inv = pairReciprocals(a, b, c, r);
  return {r, inv.d, inv.a, inv.b, inv.c};
#endif
}

// The pair loop's threads take the bands, of two layers of cells each, in runs of about equal
// cost: a band goes to the thread in whose share of the cost its middle falls. Returns thread u's
// first band (nBands for u = nt); thread u takes firstBand(u) .. firstBand(u + 1) - 1.
constexpr int bandLayers = 2;
template <class Cost>
int firstBand(int u, int nt, int nBands, const Cost& cost) {
  double all = 0.0, before = 0.0;
  for (int b = 0; b < nBands; ++b) all += cost(b);
  for (int b = 0; b < nBands; ++b) {
    const double mid = before + 0.5 * cost(b);
    before += cost(b);
    const int owner = all > 0 ? std::min(nt - 1, static_cast<int>(nt * mid / all)) : 0;
    if (owner >= u) return b;
  }
  return nBands;
}

// Grows `store` to hold n doubles (not set) and returns its data, on a cache line. The capacity
// grows by half again at least: with particle shifting, the two evaluations of a step ask for
// rate records of 16 and 4 doubles in turn, and a vector grown from its smaller size to just the
// larger one reallocated (fresh pages, first touched in the zeroing) whenever the set had grown
// by an entry (page faults and the zeroing 4-5 % of the dam break with shifting, one thread).
inline double* grown(UnsetLineVector<double>& store, std::size_t n) {
  if (n > store.capacity()) store.reserve(n + n / 2);
  store.resize(n);
  return store.data();
}

// The terms of `Terms` (a terms::TermSet) over every pair of `set`, the body acceleration g
// added at the end: out's rates of the fluid.
template <class Kernel, class Terms, int D>
void pairLoop(const Terms terms, const InteractionSet<D>& set, const Vec<D>& g,
              NeighbourLists lists, typename ForceEvaluation<D>::Workspace& w,
              Derivatives<D>& out) {
  using Extent = typename ForceEvaluation<D>::Workspace::Extent;
  const std::size_t n = set.size();
  const std::int64_t nSorted = static_cast<std::int64_t>(n);
  if (nSorted + lanes >= std::int64_t{1} << 27)  // 16 j must fit the neighbour lists' int
    throw std::length_error("ForceEvaluation: more than 2^27 interaction entries");
  const bool reuse = lists.reuse, skinned = lists.skin > 0;
  if (reuse && (w.listed != n || !skinned))
    throw std::logic_error(
        "ForceEvaluation: no neighbour lists with a skin for a set of this size");
  // Cells of half the largest reach, support h_max + skin (h_ij <= h_max): neighbours within two
  // cells. The grid may have 4 cells per point per halving, as many as the full-size cells would.
  // Reused lists keep the last build's cells and sorted order, and its h_max for the padding (any
  // h gives a far-away, massless entry the same zero terms; a scan of all entries split by count
  // would have one thread read the h of the other's fluid at every evaluation). A build runs in
  // the pair loop's parallel region: h_max and the box, the cell list, then the pairs, with
  // barriers between them instead of a region each (two regions fewer).
  constexpr int cellsPerPoint = 4 << D;
  const int team = std::min(omp_get_max_threads(), CellList<D>::maxTeam);
  if (!reuse) {
    w.cells.reserve(n, cellsPerPoint, team, w.framed ? w.frame.points : n + set.leftOut.count);
    w.listBegin.resize(n), w.listCount.resize(n), w.listed = lists.skin > 0 ? n : 0;
    w.extents.resize(team);
  }
  const auto& order = w.cells.order();
  const std::size_t nPadded = n + lanes;
  // A rate record: d rho/dt, the dh/dt sum, dv/dt by axis (four doubles in 1-D and 2-D, with
  // v_y = 0 in 1-D; five in 3-D), then the term set's own sums (TermSet::ownSums), if any; its
  // width a power of two, so that 16 j times it over 16 is an addressing mode's scale. A set
  // whose terms write no rate (the density gradient's pass: only sums of their own, and no
  // pressure bracket, so that the pair force is zero) has the own sums alone.
  constexpr auto writes = Terms::writes;
  constexpr bool writesRates =
      writes.density || writes.smoothingLength || writes.bracket || writes.viscous;
  constexpr int ratesUsed = writesRates ? (D <= 2 ? 4 : 5) : 0;
  constexpr int own = Terms::template ownSums<D>, rateUsed = ratesUsed + own;
  // The fields a particle's record holds follow from what the terms read (terms::Reads): the
  // extra record {mu, 1/rho} only where a term reads either or the rest density (then {mu,
  // 1/rho, rho0, 0}) or the density gradient (then {mu, 1/rho, its D axes}, padded to 4 or 8),
  // and in 3-D each of rho, p/rho^2 and m only where read. (The 2-D record of 8 keeps every
  // field: its loads are two whole transposes whatever they hold.)
  constexpr terms::Reads reads = Terms::reads;
  static_assert(!(reads.restDensity && reads.densityGradient),
                "the extra record holds the rest density or the density gradient");
  constexpr bool extraRecord =
      reads.viscosity || reads.densityInverse || reads.restDensity || reads.densityGradient;
  constexpr int recordSize = 8,
                extraSize = reads.densityGradient ? (D <= 2 ? 4 : 8)
                            : reads.restDensity   ? 4
                                                  : 2,
                rateWidth = rateUsed <= 4   ? 4
                            : rateUsed <= 8 ? 8
                                            : 16;
  constexpr int ownAt = ratesUsed;  // where the own sums start in a rate record
  static_assert(rateUsed <= rateWidth);
  if (reads.restDensity && set.rho0.size() < n)
    throw std::logic_error("pair loop: a term reads the rest density, and the set has none");
  if (reads.densityGradient && w.densityGradient.size() < n)
    throw std::logic_error("pair loop: a term reads the density gradient, and the set has none");
  w.rate = grown(w.rateStore, rateWidth * nPadded);
  if (static_cast<int>(w.scratch.size()) < omp_get_max_threads())
    w.scratch.resize(omp_get_max_threads());
  for (auto& view : w.scratch) {
    // Pass 1 reads whole vectors: a row's last one reads up to lanes - 1 entries past the row,
    // which may lie in a band this thread never copies in. Their lanes are masked out, but x and
    // h start as numbers where never written (memory not yet stored to may hold a NaN, whose
    // comparison raises the invalid exception: the FPE-trapped tests trap it).
    for (int a = 0; a < D; ++a) view.x[a].resize(nPadded, 0.0);
    view.h.resize(nPadded, 0.0), view.receives.resize(nPadded);
    if constexpr (D > 2) {  // in 1-D and 2-D these fields are read from the records only
      for (int a = 0; a < D; ++a) view.v[a].resize(nPadded);
      view.rho.resize(nPadded), view.pOverRho2.resize(nPadded), view.m.resize(nPadded);
    }
    if constexpr (D <= 2) view.recordStore.resize(recordSize * nPadded);
    view.extraStore.resize(extraSize * nPadded);
    view.record = view.recordStore.data(), view.extra = view.extraStore.data();
  }
  const int nFluid = static_cast<int>(set.nFluid);
  out.resize(set.owned());
  out.sumsWidth = own, out.sums.resize(own * set.owned());
  const int* ownedParticle = set.ownedParticle.empty() ? nullptr : set.ownedParticle.data();
  // Bands of two layers of cells: a point's forward neighbours lie in its own band and the next,
  // so the even bands can run at the same time, then the odd ones. Set up before the region when
  // the lists are reused, else by thread 0 after the cell list.
  constexpr int reach = bandLayers;
  int nBands = 0;
  bool known = false;
  auto& evenDone = w.evenDone;
  auto setUpBands = [&] {
    nBands = (w.cells.layers() + reach - 1) / reach;
    if (!reuse && static_cast<int>(w.bandLists.size()) < nBands) w.bandLists.resize(nBands);
    known = static_cast<int>(w.bandCost.size()) == nBands;
    w.bandWork.assign(nBands, 0);
    evenDone.start(nBands);
  };
  if (reuse) setUpBands();
  auto bandBegin = [&](int b) { return w.cells.layerBegin(reach * b); };
  // A band's cost: its work in the last evaluation where the bands were as many, else its entries
  // (the particles move by a fraction of a cell a step, so a band's work changes little).
  auto cost = [&](int b) {
    return double(known ? w.bandCost[b] : bandBegin(b + 1) - bandBegin(b));
  };
  bool emptyBox = false;  // a build's box with no number along an axis (CellList::checkBox)
  typename CellList<D>::Box builtBox;

  // A build's h_max, box and cell list, by each thread of the region; returns h_max.
  auto buildCells = [&](int t, int nt) {
    // h_max and the entries' box. The fluid split as the interaction set's build splits it, so
    // that each thread reads the fluid entries it wrote; the halo (whose runs the build gives
    // to the threads that wrote their sources) to the last thread.
    typename CellList<D>::Box box;
    {
      Extent mine{box, 0.0};
      walk(shareOf(nSorted, static_cast<std::int64_t>(set.nFluid), t, nt), [&](std::int64_t k) {
        mine.hMax = std::max(mine.hMax, set.h[k]);
        for (int a = 0; a < D; ++a)
          mine.box.lo[a] = std::min(mine.box.lo[a], set.x[k][a]),
          mine.box.hi[a] = std::max(mine.box.hi[a], set.x[k][a]);
      });
      w.extents[t] = mine;
    }
#pragma omp barrier
    double hMax = w.framed ? w.frameHMax : 0.0;
    for (int u = 0; u < nt; ++u) {
      const Extent& e = w.extents[u];
      hMax = std::max(hMax, e.hMax);
      for (int a = 0; a < D; ++a)
        box.lo[a] = std::min(box.lo[a], e.box.lo[a]), box.hi[a] = std::max(box.hi[a], e.box.hi[a]);
    }
    if (set.leftOut.count > 0) {  // the cells as if the wall particles left out were in
      hMax = std::max(hMax, set.leftOut.h);
      for (int a = 0; a < D; ++a)
        box.lo[a] = std::min(box.lo[a], set.leftOut.lo[a]),
        box.hi[a] = std::max(box.hi[a], set.leftOut.hi[a]);
    }
    // No number along an axis (a NaN in every entry): the build goes on with that axis in one
    // layer, so that every barrier is met, and the error is thrown after the region.
    bool bad = false;
    for (int a = 0; a < D; ++a) bad |= n > 0 && !(box.lo[a] <= box.hi[a]);
    if (t == 0) w.hMax = hMax, emptyBox = bad, builtBox = box;
    for (int a = 0; a < D && bad; ++a)
      if (!(box.lo[a] <= box.hi[a])) box.lo[a] = box.hi[a] = 0.0;
    // Each thread sorts the entries of the layers its bands will hold (as cut by the last
    // evaluation's work where the bands stay as many; else evenly by layers), so that it reads
    // its part of the sorted order from its own cache; and zeroes their rates.
    auto cut = [&](int layers, int threads, int u) {
      const int bands = (layers + bandLayers - 1) / bandLayers;
      if (static_cast<int>(w.bandCost.size()) != bands)
        return typename CellList<D>::EvenLayers{}(layers, threads, u);
      return std::min(layers, bandLayers * firstBand(u, threads, bands,
                                                     [&](int b) { return double(w.bandCost[b]); }));
    };
    const Share placed = w.cells.buildInTeam(
        n, [&](std::size_t i, int a) { return set.x[i][a]; }, box,
        0.5 * (Kernel::support * hMax + lists.skin), cellsPerPoint, set.nFluid, cut,
        w.framed ? &w.frame : nullptr, n + set.leftOut.count);
    std::fill(w.rate + rateWidth * placed.begin, w.rate + rateWidth * placed.end, 0.0);
    if (t == 0) setUpBands();
    return hMax;
  };

#pragma omp parallel num_threads(team)
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    const double hMax = reuse ? w.hMax : buildCells(t, nt);
    {
      auto& view = w.scratch[t];
      for (std::size_t k = n; k < nPadded; ++k) {  // far away and massless: never a neighbour
        for (int a = 0; a < D; ++a) view.x[a][k] = 1e100;
        view.h[k] = hMax, view.receives[k] = 0;
        double* e = view.extra + extraSize * k;
        e[0] = 0.0, e[1] = 1.0;
        for (int f = 2; f < extraSize; ++f) e[f] = 0.0;
        if constexpr (D <= 2) {
          double* r = view.record + recordSize * k;
          r[0] = r[1] = 1e100, r[2] = r[3] = 0.0, r[4] = hMax, r[5] = 1.0, r[6] = r[7] = 0.0;
        } else {
          for (int a = 0; a < D; ++a) view.v[a][k] = 0.0;
          view.rho[k] = 1.0, view.pOverRho2[k] = 0.0, view.m[k] = 0.0;
        }
      }
    }
    if (!reuse) {  // the cell list, the bands and the zeroed rates, whoever wrote them
#pragma omp barrier
    }
    // Thread t's share: a contiguous run of bands, cut where their cost divides evenly (a band
    // goes to the thread in whose share its middle falls). A thread copies in, and writes out,
    // the entries of its bands: those it reads and writes most, so that they rarely move between
    // cores. Which thread runs a band does not change any sum (see above). A band's entries are
    // copied in just before the first band that reads them (itself or the band below) runs, so
    // that they are still in the cache then; the thread's first band before the pairs. (All at
    // once before the pairs, they came back from memory
    // once a share outgrew the caches: 1e6 particles, lists built, medians of alternated runs,
    // 1 thread 123.7 -> 114.4 ns a particle, 2 threads 63.5 -> 57.5 ns; 1e5 1 thread 125.4 ->
    // 114.7 ns; 1e3-1e4 unchanged; perf/README.md.)
    const int first = firstBand(t, nt, nBands, cost), last = firstBand(t + 1, nt, nBands, cost) - 1;
    const int mineBegin = first <= last ? bandBegin(first) : 0;
    const int mineEnd = first <= last ? bandBegin(last + 1) : 0;
    const Share mine{mineBegin, mineEnd};  // walked so that the prefetcher stays inside (walk())
    auto& view = w.scratch[t];
    // Copies entry k into the thread's view, and zeroes its rates if `rates` (the thread's own
    // entries; the next band's owner zeroes those of its entries).
    const auto copyEntry = [&](double* rates) {
      // Through pointers copied into the loop: a store through one of them might change the
      // vectors' own data pointers as far as the compiler knows, so that it loads them again.
      const int* sorted = order.data();
      const Vec<D>* sx = set.x.data();
      const Vec<D>* sv = set.v.data();
      const double *sRho = set.rho.data(), *sM = set.m.data(), *sH = set.h.data(),
                   *sP = set.p.data(), *sMu = set.mu.data(), *sRho0 = set.rho0.data();
      const Vec<D>* sGradRho = w.densityGradient.data();
      std::array<double*, D> wx, wv;
      for (int a = 0; a < D; ++a) wx[a] = view.x[a].data(), wv[a] = view.v[a].data();
      double *wh = view.h.data(), *wRho = view.rho.data(), *wM = view.m.data(),
             *wPr = view.pOverRho2.data();
      std::int64_t* wReceives = view.receives.data();
      double *records = view.record, *extras = view.extra;
      const bool fields = D > 2 || !reuse;
      return [=](std::int64_t k) {
        const int s = sorted[k];
        // Pass 1 reads x and h by field; the rest is read from the records in 1-D and 2-D (v,
        // rho, p/rho^2, m by field only in 3-D), and with reused lists, which skip pass 1,
        // everything.
        const terms::Side<double> f =
            terms::sideOf(sM[s], sRho[s], sP[s], sMu[s], reads.restDensity ? sRho0[s] : 0.0);
        const double rho = f.rho, rhoInv = f.rhoInv, m = f.m, h = sH[s], pr = f.pOverRho2;
        if (fields) {
          for (int a = 0; a < D; ++a) wx[a][k] = sx[s][a];
          wh[k] = h, wReceives[k] = s < nFluid ? -1 : 0;
        }
        if constexpr (extraRecord) {
          double* e = extras + extraSize * k;
          e[0] = f.mu, e[1] = rhoInv;
          if constexpr (reads.restDensity) e[2] = f.rho0, e[3] = 0.0;
          if constexpr (reads.densityGradient)
            for (int a = 0; a < extraSize - 2; ++a) e[2 + a] = a < D ? sGradRho[s][a] : 0.0;
        }
        if (rates) {
          double* rate = rates + rateWidth * k;
          for (int f = 0; f < rateWidth; ++f) rate[f] = 0.0;
        }
        if constexpr (D <= 2) {
          double* r = records + recordSize * k;
          r[0] = sx[s][0], r[1] = D > 1 ? sx[s][D - 1] : 0.0;
          r[2] = sv[s][0], r[3] = D > 1 ? sv[s][D - 1] : 0.0;
          r[4] = h, r[5] = rho, r[6] = pr, r[7] = m;
        } else {
          for (int a = 0; a < D; ++a) wv[a][k] = sv[s][a];
          if constexpr (reads.density) wRho[k] = rho;
          if constexpr (reads.mass) wM[k] = m;
          if constexpr (reads.pressure) wPr[k] = pr;
        }
      };
    };
    // (A build zeroed the rates as it placed the entries.)
    const auto copyOwn = copyEntry(reuse ? w.rate : nullptr), copyNext = copyEntry(nullptr);
    auto& copied = view.copied;  // which of the thread's bands, and the next, are copied in
    copied.assign(std::max(0, last - first + 2), 0);
    auto copyIn = [&](int b) {  // band b's entries, if b is the thread's or the next and not yet
      if (first > last || b < first || b > last + 1 || b >= nBands || copied[b - first]) return;
      copied[b - first] = 1;
      const Share entries{bandBegin(b), bandBegin(b + 1)};
      if (b <= last)
        walk(entries, copyOwn);
      else
        walk(entries, copyNext);
    };
    copyIn(first);
    const double* xs[3] = {};  // three components whatever D, for the pair loop's r_ij, v_ij
    const double* vs[3] = {};
    for (int a = 0; a < D; ++a) xs[a] = view.x[a].data(), vs[a] = view.v[a].data();
    const double *hs = view.h.data(), *rhos = view.rho.data(), *prs = view.pOverRho2.data(),
                 *ms = view.m.data();
    const std::int64_t* receives = view.receives.data();
    double *const record = view.record, *const extra = view.extra;
    constexpr double reachFactor2 = 0.25 * Kernel::support * Kernel::support;
    // (support h_ij + skin)^2 - (support h_ij)^2 = skinSupport 2 h_ij + skin2: with skin = 0
    // the very test of the pairs inside the support.
    const double skinSupport = Kernel::support * lists.skin, skin2 = lists.skin * lists.skin;
    const Vi iota = {0, 1, 2, 3};
    static_assert(lanes == 4);
    // A copy of the thread's own: through a reference, every store to a rate record could change
    // a term's parameters as far as the compiler knows, and it would load them again for each
    // vector of pairs.
    const Terms pairTerms = terms;
    // a . b over the first D components (the third, zero in 2-D, is not added: x + 0 is an
    // instruction, since x might be -0).
    auto dot = [](Vd ax, Vd ay, Vd az, Vd bx, Vd by, Vd bz) {
      if constexpr (D == 1) return ax * bx;
      if constexpr (D == 2) return ax * bx + ay * by;
      return ax * bx + ay * by + az * bz;
    };
    auto& scratch = w.scratch[omp_get_thread_num()];

    // Each pair (i, j > i in sorted order, at least one of them fluid) once: i's rates add the
    // pair's terms in registers, j's record gets the opposite share at once (eq. 11-13 are
    // symmetric in i, j up to the masses and the sign of grad W).
    // Returns the band's work (Workspace::bandWork).
    // Skinned: the lists carry a skin (kept or reused; pairs beyond the support masked), a
    // compile-time choice so that the lists built at every evaluation pay nothing for it.
    auto band = [&]<bool Skinned>(int bandIndex) {
      const std::int64_t begin = bandBegin(bandIndex), end = bandBegin(bandIndex + 1);
      // Lists built without a skin are never reused: each particle's goes to the thread's scratch
      // and is overwritten by the next (a list kept in memory made pass 2 about 6 % slower).
      LineVector<int>& list = Skinned ? w.bandLists[bandIndex] : scratch.neighbours;
      std::size_t used = 0;  // the entries of `list` taken by the band's particles so far
      // The forward rows of cell `rowsOf` (at most the (2 reach + 1)^(D-1) rows around it), and
      // the candidates in them. An array on the stack, not a vector: a vector's push_back is
      // not inlined into a region that also holds the build (one thread, 1e4 particles, 107-117
      // ns a particle with the vector, 97-100 ns with the array).
      constexpr int rowsAround = D == 1   ? 1
                                 : D == 2 ? 2 * reach + 1
                                          : (2 * reach + 1) * (2 * reach + 1);
      std::array<std::array<int, 2>, rowsAround> rows;
      int nRows = 0;
      std::int64_t rowsOf = -1;
      std::int64_t inRows = 0;
      std::int64_t work = 0;
      for (std::int64_t i = begin; i < end; ++i) {
        Vd xi[3], vi[3];
        double rhoi, pri, mi;
        double hi;
        if constexpr (D <= 2) {
          const double* r = record + recordSize * i;
          xi[0] = broadcast(r[0]), xi[1] = broadcast(r[1]), xi[2] = Vd{};
          vi[0] = broadcast(r[2]), vi[1] = broadcast(r[3]), vi[2] = Vd{};
          hi = r[4], rhoi = r[5], pri = r[6], mi = r[7];
        } else {
          for (int a = 0; a < 3; ++a) xi[a] = broadcast(xs[a][i]), vi[a] = broadcast(vs[a][i]);
          hi = hs[i];
          rhoi = reads.density ? rhos[i] : 0.0, pri = reads.pressure ? prs[i] : 0.0;
          mi = reads.mass ? ms[i] : 0.0;
        }
        const double* ei = extra + extraSize * i;
        const double mui = extraRecord ? ei[0] : 0.0, rhoInvi = extraRecord ? ei[1] : 0.0;
        const double rho0i = reads.restDensity ? ei[2] : 0.0;
        double gradRhoi[3] = {};
        if constexpr (reads.densityGradient)
          for (int a = 0; a < D; ++a) gradRhoi[a] = ei[2 + a];
        Vd accRho{}, accH{}, accX{}, accY{}, accZ{};  // d rho/dt, dh/dt sum, dv/dt per axis
        Vd accOwn[own > 0 ? own : 1] = {};            // the own sums

        int* nb;
        int count = 0;
        if (Skinned && reuse) {
          nb = list.data() + w.listBegin[i], count = w.listCount[i];
        } else {
          const std::int64_t c = w.cells.sortedCell(static_cast<int>(i));
          const int ownEnd = w.cells.template ownRowEnd<reach>(c);
          if (c != rowsOf) {
            nRows = 0;
            inRows = 0;
            w.cells.template forEachForwardRow<reach>(c, [&](int b, int e) {
              rows[nRows++] = {b, e}, inRows += e - b;
            });
            rowsOf = c;
          }
          const std::size_t candidates = ownEnd - i - 1 + inRows;
          if (list.size() < used + candidates + 2 * lanes)
            list.resize(2 * (used + candidates + 2 * lanes));
          nb = list.data() + used;
          const Vi anyFluid = Vi{} + receives[i];

          // Pass 1: the forward neighbours (0 < r_ij < support h_ij + skin, one of the two
          // fluid), in sorted order: the own row first, then the shared rows.
          auto test = [&](std::int64_t rowBegin, std::int64_t rowEnd) {
            for (std::int64_t j = rowBegin; j < rowEnd; j += lanes) {
              const Vd rx = xi[0] - load(xs[0] + j);
              const Vd ry = D > 1 ? xi[1] - load(xs[1] + j) : Vd{};
              const Vd rz = D > 2 ? xi[2] - load(xs[2] + j) : Vd{};
              const Vd r2 = rx * rx + ry * ry + rz * rz;
              const Vd hSum = hi + load(hs + j);  // 2 h_ij
              Vi fluidJ;
              __builtin_memcpy(&fluidJ, receives + j, sizeof fluidJ);
              // r2 > 0: a distinct particle at r = 0 adds nothing to any term.
              const Vi in =
                  (j + iota < rowEnd) & (r2 > 0.0) &
                  (r2 < (Skinned ? reachFactor2 * hSum * hSum + (skinSupport * hSum + skin2)
                                 : reachFactor2 * hSum * hSum)) &
                  (anyFluid | fluidJ);
              const unsigned bits = laneBits(in);  // append the lanes inside, in order
              const Vi32 packed = static_cast<int>(j) + compressOffsets[bits];
              const Vi32 scaled = packed << 4;  // 16 j (pass 2)
              __builtin_memcpy(nb + count, &scaled, sizeof scaled);
              count += __builtin_popcount(bits);
            }
          };
          test(i + 1, ownEnd);
          for (int r = 0; r < nRows; ++r) test(rows[r][0], rows[r][1]);
          work += (ownEnd - i - 1) + inRows;
          // Pad the last vector with the far-away, massless entry n: it adds zero to i.
          const Vi32 padding = Vi32{} + static_cast<int>(16 * nSorted);
          __builtin_memcpy(nb + count, &padding, sizeof padding);
          if constexpr (Skinned) {
            w.listBegin[i] = static_cast<int>(used), w.listCount[i] = count;
            used += (count + lanes - 1) / lanes * lanes;
          }
        }
        work += 5 * count + 22;

        // Pass 2: the terms, one vector of neighbours at a time.
        for (int k = 0; k < count; k += lanes) {
          // The list holds 16 j for neighbour j (the byte offset of a 16-byte record), so that
          // each of j's records is at base + 1, 2 or 4 times that: an addressing mode, not a
          // sign extension and a shift a neighbour and array (174 -> 149 instructions a vector,
          // 1.5 % off the force evaluation at 1e4).
          const int* jj = nb + k;
          auto at = [&](double* base, std::size_t scale, int l) {
            return reinterpret_cast<double*>(reinterpret_cast<char*>(base) +
                                             scale * static_cast<std::uint32_t>(jj[l]));
          };
          auto gather = [&](const double* p) {
            return Vd{p[jj[0] >> 4], p[jj[1] >> 4], p[jj[2] >> 4], p[jj[3] >> 4]};
          };
          Vd xj[3], vj[3], hj, rhoj, prj, mj;  // the four neighbours' fields
          if constexpr (D <= 2) {
            static_assert(recordSize * sizeof(double) == 4 * 16);
            const double* r[4] = {at(record, 4, 0), at(record, 4, 1), at(record, 4, 2),
                                  at(record, 4, 3)};
            xj[0] = load(r[0]), xj[1] = load(r[1]), vj[0] = load(r[2]), vj[1] = load(r[3]);
            transpose(xj[0], xj[1], vj[0], vj[1]);
            hj = load(r[0] + 4), rhoj = load(r[1] + 4), prj = load(r[2] + 4), mj = load(r[3] + 4);
            transpose(hj, rhoj, prj, mj);
            xj[2] = vj[2] = Vd{};
          } else {
            for (int a = 0; a < 3; ++a) xj[a] = gather(xs[a]), vj[a] = gather(vs[a]);
            hj = gather(hs);
            rhoj = prj = mj = Vd{};
            if constexpr (reads.density) rhoj = gather(rhos);
            if constexpr (reads.pressure) prj = gather(prs);
            if constexpr (reads.mass) mj = gather(ms);
          }
          Vd muj{}, rhoInvj{}, rho0j{}, gradRhoj[3] = {};
          if constexpr (extraRecord) {
            constexpr std::size_t scale = extraSize * sizeof(double) / 16;  // 1, 2 or 4
            static_assert(scale * 16 == extraSize * sizeof(double) &&
                          (scale == 1 || scale == 2 || scale == 4));
            const Vd t0 = load2(at(extra, scale, 0), at(extra, scale, 2)),
                     t1 = load2(at(extra, scale, 1), at(extra, scale, 3));
            muj = __builtin_shufflevector(t0, t1, 0, 4, 2, 6);
            rhoInvj = __builtin_shufflevector(t0, t1, 1, 5, 3, 7);
            if constexpr (reads.restDensity) {
              const Vd t2 = load2(at(extra, scale, 0) + 2, at(extra, scale, 2) + 2),
                       t3 = load2(at(extra, scale, 1) + 2, at(extra, scale, 3) + 2);
              rho0j = __builtin_shufflevector(t2, t3, 0, 4, 2, 6);
            }
            if constexpr (reads.densityGradient) {
              const Vd t2 = load2(at(extra, scale, 0) + 2, at(extra, scale, 2) + 2),
                       t3 = load2(at(extra, scale, 1) + 2, at(extra, scale, 3) + 2);
              gradRhoj[0] = __builtin_shufflevector(t2, t3, 0, 4, 2, 6);
              gradRhoj[1] = __builtin_shufflevector(t2, t3, 1, 5, 3, 7);
              if constexpr (D > 2) {
                const Vd t4 = load2(at(extra, scale, 0) + 4, at(extra, scale, 2) + 4),
                         t5 = load2(at(extra, scale, 1) + 4, at(extra, scale, 3) + 4);
                gradRhoj[2] = __builtin_shufflevector(t4, t5, 0, 4, 2, 6);
              }
            }
          }
          // r_ij, v_ij by component.
          const Vd rx = xi[0] - xj[0], vx = vi[0] - vj[0];
          const Vd ry = xi[1] - xj[1], vy = vi[1] - vj[1];
          const Vd rz = xi[2] - xj[2], vz = vi[2] - vj[2];
          const Vd r2 = dot(rx, ry, rz, rx, ry, rz), vr = dot(vx, vy, vz, rx, ry, rz);
          const Vd hSum = hi + hj, hSum2 = hSum * hSum;  // 2 h_ij
          // Inside the support (a listed pair may be beyond it, within the skin) and not a padding
          // lane. The others get a harmless r and F = 0: they add zero to i and j.
          const Vi listed = k + iota < count;
          const Vi inside =
              Skinned ? listed & (r2 > 0.0) & (r2 < reachFactor2 * hSum * hSum) : listed;
          const Vd r2c = inside ? r2 : hSum2;
          const Vd rEta2 = r2c + terms::etaSquaredOfHSum2 * hSum2;
          const Vd rhoSum = reads.rhoSumInverse ? rhoi + rhoj : broadcast(1.0);
          const auto inv = pairInverses(r2c, hSum, rEta2, rhoSum);
          const Vd r = inv.r, hInv = 2.0 * inv.a;  // 1 / h_ij
          const Vd gradW = Kernel::template gradOverR<D>(r, inv.rInv, hInv);
          const Vd F = Skinned ? (inside ? gradW : Vd{}) : gradW;  // grad_i W_ij = F r_ij
          const terms::PairValues<double, Vd> pair{
              {mi, rhoi, rhoInvi, pri, mui, rho0i, {gradRhoi[0], gradRhoi[1], gradRhoi[2]}},
              {mj, rhoj, rhoInvj, prj, muj, rho0j, {gradRhoj[0], gradRhoj[1], gradRhoj[2]}},
              rx,
              ry,
              rz,
              vx,
              vy,
              vz,
              r2c,
              r,
              hInv,
              vr,
              hSum,
              hSum2,
              F,
              inv.b,
              inv.c};
          typename Terms::template Shares<D, Vd> si, sj;
          pairTerms.template pair<D, Kernel>(pair, si, sj);
          if constexpr (writes.density) accRho += si.rho;
          if constexpr (writes.smoothingLength) accH += si.h;
          accX += si.v[0];
          if constexpr (D > 1) accY += si.v[1];
          if constexpr (D > 2) accZ += si.v[2];
          for (int o = 0; o < own; ++o) accOwn[o] += si.own[o];
          // j's share, lane by lane into its record (live lanes only: the padding's is dropped).
          Vd jRho = writes.density ? sj.rho : Vd{}, jH = writes.smoothingLength ? sj.h : Vd{};
          Vd jX = sj.v[0], jY = D > 1 ? sj.v[1] : Vd{};
          const int live = std::min(lanes, count - k);
          if constexpr (D <= 2) {
            if constexpr (writesRates) {
              transpose(jRho, jH, jX, jY);  // now one record {rho, h, x, y} per lane
              const Vd lane[4] = {jRho, jH, jX, jY};
              for (int l = 0; l < live; ++l) {
                double* rate = at(w.rate, rateWidth * sizeof(double) / 16, l);
                const Vd updated = load(rate) + lane[l];
                __builtin_memcpy(rate, &updated, sizeof updated);
              }
            }
            // The own sums after them: four at a time as the rates, the rest lane by lane.
            for (int o = 0; o + lanes <= own; o += lanes) {
              Vd a = sj.own[o], b = sj.own[o + 1], c = sj.own[o + 2], d = sj.own[o + 3];
              transpose(a, b, c, d);
              const Vd chunk[4] = {a, b, c, d};
              for (int l = 0; l < live; ++l) {
                double* rate = at(w.rate, rateWidth * sizeof(double) / 16, l) + ownAt + o;
                const Vd updated = load(rate) + chunk[l];
                __builtin_memcpy(rate, &updated, sizeof updated);
              }
            }
            for (int o = own / lanes * lanes; o < own; ++o)
              for (int l = 0; l < live; ++l)
                at(w.rate, rateWidth * sizeof(double) / 16, l)[ownAt + o] += sj.own[o][l];
          } else {
            // {rho, h, x, y} a lane as in 2-D, then z: the same additions, in the same order.
            const Vd jZ = sj.v[2];
            transpose(jRho, jH, jX, jY);
            const Vd lane[4] = {jRho, jH, jX, jY};
            for (int l = 0; l < live; ++l) {
              double* rate = at(w.rate, rateWidth * sizeof(double) / 16, l);
              if constexpr (writesRates) {
                const Vd updated = load(rate) + lane[l];
                __builtin_memcpy(rate, &updated, sizeof updated);
                rate[4] += jZ[l];
              }
              for (int o = 0; o < own; ++o) rate[ownAt + o] += sj.own[o][l];
            }
          }
        }
        double* rate = w.rate + rateWidth * i;
        if constexpr (D <= 2) {  // the lanes summed in a fixed order, four fields at once
          if constexpr (writesRates) {
            transpose(accRho, accH, accX, accY);
            const Vd updated = load(rate) + (((accRho + accH) + accX) + accY);
            __builtin_memcpy(rate, &updated, sizeof updated);
          }
          for (int o = 0; o + lanes <= own; o += lanes) {
            Vd a = accOwn[o], b = accOwn[o + 1], c = accOwn[o + 2], d = accOwn[o + 3];
            transpose(a, b, c, d);
            const Vd chunk = load(rate + ownAt + o) + (((a + b) + c) + d);
            __builtin_memcpy(rate + ownAt + o, &chunk, sizeof chunk);
          }
          for (int o = own / lanes * lanes; o < own; ++o) rate[ownAt + o] += sum(accOwn[o]);
        } else {
          if constexpr (writesRates) {
            rate[0] += sum(accRho), rate[1] += sum(accH), rate[2] += sum(accX);
            rate[3] += sum(accY), rate[4] += sum(accZ);
          }
          for (int o = 0; o < own; ++o) rate[ownAt + o] += sum(accOwn[o]);
        }
      }
      return work;
    };
    // Every even band before the odd bands beside it (an odd band writes to the records of the
    // even band after it, and its own records get the even band's shares before): the order of
    // every sum is as if all even bands ran, then all odd ones. Bands of one parity share no
    // record. Instead of a barrier between the parities, each odd band waits for its two even
    // neighbours only, so that a thread's share is balanced on its whole work, not on each
    // parity's (1e3 particles, 2 threads: 12 of 61 us were one thread waiting at the barriers).
    // The even bands at the share's ends go first: the neighbours' odd bands wait for them. The
    // others go in the order 2, 1, 4, 3, ...: an odd band reads and writes the entries of the
    // even band just run, while they are still in the cache (all even bands, then all odd ones,
    // read every entry from memory twice once a thread's share outgrows the caches: 1e6
    // particles, means of 4 alternated runs, 1 thread 136.1 -> 125.3 ns a particle, 2 threads
    // 70.8 -> 65.8 ns; 1e3-1e4 unchanged).
    auto runBand = [&](int b) {
      copyIn(b), copyIn(b + 1);  // the entries band b reads
      w.bandWork[b] =
          skinned ? band.template operator()<true>(b) : band.template operator()<false>(b);
    };
    const int firstEven = first + first % 2, lastEven = last - last % 2;
    if (reuse) {  // the rates zeroed before any thread adds to them
#pragma omp barrier
    }
    int nextEven = firstEven + 2;  // the thread's next even band not yet run (past the ends)
    if (first <= last && firstEven <= lastEven) {  // (a thread without bands has first > last)
      runBand(firstEven), evenDone.done(firstEven);
      if (lastEven > firstEven) runBand(lastEven), evenDone.done(lastEven);
    }
    for (int b = first + 1 - first % 2; b <= last; b += 2) {
      for (; nextEven < lastEven && nextEven <= b + 1; nextEven += 2)
        runBand(nextEven), evenDone.done(nextEven);
      evenDone.wait(b - 1);
      if (b + 1 < nBands) evenDone.wait(b + 1);
      runBand(b);
    }
    for (; nextEven < lastEven; nextEven += 2) runBand(nextEven), evenDone.done(nextEven);
#pragma omp barrier
    {
      const int* sorted = order.data();
      const double *rates = w.rate, *records = record;
      double *dRho = out.drhodt.data(), *dH = out.dhdt.data(), *sums = out.sums.data();
      Vec<D>* dV = out.dvdt.data();
      const Vec<D> gravity = g;
      walk(mine, [=](std::int64_t k) {
        int dst = sorted[k];
        if (dst >= nFluid || (ownedParticle && (dst = ownedParticle[dst]) < 0)) return;
        const double* rate = rates + rateWidth * k;
        if constexpr (writesRates) {
          terms::ParticleRates<Vec<D>> r{rate[0], rate[1], 0.0, Vec<D>()};
          for (int a = 0; a < D; ++a) r.dvdt[a] = rate[2 + a];
          const double h = D <= 2 ? records[recordSize * k + 4] : hs[k];
          pairTerms.template finish<D>(r, {h, gravity});
          dRho[dst] = r.drhodt, dH[dst] = r.dhdt, dV[dst] = r.dvdt;
        }
        for (int o = 0; o < own; ++o) sums[own * dst + o] = rate[ownAt + o];
      });
    }
  }
  if (emptyBox) CellList<D>::checkBox(n, builtBox);  // throws
  std::swap(w.bandCost, w.bandWork);
}

}  // namespace pair_loop

}  // namespace sph
