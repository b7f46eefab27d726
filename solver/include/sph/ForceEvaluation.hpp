#pragma once
// One pass of every enabled term over all fluid particles: the rates of change of density,
// velocity and smoothing length. The terms are small types (sph/terms/); the scene's choice of
// kernel and optional terms picks one of the pair loops built for every subset of them
// (terms/Menu.hpp) at construction: a term the scene does not enable is not compiled into the
// loop it runs (no per-pair flag test, no virtual call).
#include <memory>
#include <string>
#include <vector>

#include "sph/CacheLines.hpp"
#include "sph/CellList.hpp"
#include "sph/InteractionSet.hpp"
#include "sph/Kernels.hpp"
#include "sph/terms/PairValues.hpp"

namespace sph {

// The density diffusion slot's forms, in the order of terms::DensityDiffusionForms after none.
enum class DensityDiffusion : unsigned {
  none,
  molteniColagrossi,  // Molteni & Colagrossi (2009)
  fourtakas,          // Fourtakas et al. (2019): the hydrostatic part subtracted
  fourtakasPhases,    // Fourtakas et al.'s within each of several phases
  antuono,            // Antuono et al. (2010): the renormalised density gradient subtracted
};
// The optional terms, in the order of terms::OptionalTerms, and the slots' choices.
struct TermSwitches {
  bool artificialViscosity = false;  // Lobovsky & Kren eq. (10)
  bool morrisViscosity = false;      // eq. (9)
  bool variableH = false;            // eq. (13)
  DensityDiffusion densityDiffusion = DensityDiffusion::none;
  // Particle shifting's pair sums (terms/ConcentrationGradient.hpp), in the evaluations that ask
  // for them (ForceEvaluation::operator()).
  bool concentrationGradient = false;
};
// The menu entry of a choice of optional terms (bit k: the k-th); std::invalid_argument for a
// choice off the menu.
unsigned menuIndex(TermSwitches);
// Whether the menu has a loop for the choice (the concentration gradient joins one set of the
// optional terms only: terms/Menu.hpp).
bool onMenu(TermSwitches);
// The operations a pair of that entry's terms takes (quadratic kernel; terms::Flops).
terms::Flops pairFlops(TermSwitches);

template <int D>
struct Derivatives {
  LineVector<Vec<D>> dvdt;
  LineVector<double> drhodt, dhdt;
  // The sums of its own that a term of the evaluated set has (terms/PairValues.hpp: sums<D>), by
  // particle: sumsWidth a particle, in the term's order; none where no term has such sums.
  LineVector<double> sums;
  int sumsWidth = 0;
  void resize(std::size_t n) { dvdt.resize(n), drhodt.resize(n), dhdt.resize(n); }
};

// Pass 1's neighbour lists (Verlet 1967): built with a skin (every pair within the kernel's
// support plus `skin` [m]), or the last build's reused. Reuse needs the same entries, each moved
// by at most d and grown in h by at most dh since that build, with 2 d + 2 dh <= skin (the
// support is 2 h; Simulation::rates checks it). Pairs beyond the support add nothing either way.
struct NeighbourLists {
  double skin = 0.0;
  bool reuse = false;
};

template <int D>
class ForceEvaluation {
 public:
  ForceEvaluation(KernelKind kernel, TermSwitches terms, const terms::TermParameters& parameters);
  ForceEvaluation(KernelKind kernel, TermSwitches terms, double beta);  // the paper's terms only

  // Continuity (eq. 11), pressure gradient (eq. 12) with the enabled viscosities, and dh/dt;
  // with Antuono et al.'s diffusion, after a pass of its own for every entry's renormalised
  // density gradient (terms/RenormalisedDensityGradient.hpp; one process's whole set only);
  // `g`, a uniform body acceleration, is added to dv/dt as the rates are written (F/rho in eq.
  // 12; no pass of its own). Each pair is evaluated once and every sum runs in an order that the
  // cell list fixes, so the result does not depend on the number of threads. With `ownSums`
  // false, the loop without the terms that only have sums of their own (out.sums: the
  // concentration gradient): the rates are the same bits either way.
  void operator()(const InteractionSet<D>& set, Derivatives<D>& out,
                  const Vec<D>& g = Vec<D>::Zero(), NeighbourLists lists = {}, bool ownSums = true);

  // Marks, for each fluid entry i of the last evaluated set with marked[i], every fluid entry
  // within the kernel's support of i (at h_ij), and the source of every halo entry within it:
  // near[k] = 1 (near sized nFluid, not cleared). Through the evaluation's cell list: a query
  // around the marked entries only.
  void markWithinSupport(const InteractionSet<D>& set, const char* marked, char* near) const;

  // The entries below `count` of the last evaluated set (its fluid), in the cell list's order;
  // with `cells`, each one's cell (in the whole grid of frameGrid).
  void cellOrder(std::size_t count, std::vector<int>& out,
                 std::vector<std::int64_t>* cells = nullptr) const;

  // The evaluations that follow build their cells as the whole domain's entries would have
  // them, the set being part of those (DomainDecomposition.hpp): `box` and `entries` of the
  // whole, and its largest h (CellList::Frame).
  void frameGrid(const double (&lo)[D], const double (&hi)[D], std::size_t entries, double hMax);

  // Names of the terms the chosen loop evaluates, for the run file.
  std::vector<std::string> termNames() const;
  KernelKind kernel() const { return kernel_; }
  const TermSwitches& terms() const { return terms_; }

  struct Workspace;  // cell list and cell-sorted copies, kept between calls (no allocation per
                     // step)

 private:
  using Loop = void (*)(const terms::TermParameters&, const InteractionSet<D>&, const Vec<D>& g,
                        NeighbourLists, Workspace&, Derivatives<D>&);
  void densityGradients(const InteractionSet<D>& set, NeighbourLists& lists);
  KernelKind kernel_;
  TermSwitches terms_;
  terms::TermParameters parameters_;
  Loop loop_, ownSumsLoop_, gradientLoop_ = nullptr;
  std::shared_ptr<Workspace> work_;
};

}  // namespace sph
