#pragma once
// Fourtakas et al.'s (2019) density diffusion (DensityDiffusionFourtakas.hpp) in a scene of
// several immiscible phases: each phase diffuses its own density, and a pair of two phases adds
// nothing. Across an interface the density jumps by the phases' rho0 (1000 to 1050 kg/m^3 in a
// lock exchange, against the 0.5 % of hydrostatic compression the term is built to leave alone),
// so a Laplacian of the density taken across it would drive a mass flux from the heavy phase to
// the light one that no flow has. Diffusing within each phase only is what the multi-phase
// delta-SPH codes do (Fourtakas & Rogers 2016, Adv. Water Resour. 92, 186-199; Hammani et al.
// 2020, Comput. Methods Appl. Mech. Engrg. 368, 113189).
//
// Each particle carries its phase's rest density (Side::rho0); a pair is of one phase where the
// two are equal. The phases share c0 and gamma (Scene.cpp refuses others), so each phase's
// K = rho0 c0^2 / gamma and the hydrostatic difference's rho0^2 g / K = rho0 gamma g / c0^2
// follow from its rho0. Two phases of one rest density are one fluid to the equation of state,
// and diffuse into each other. In each phase the term conserves sum_i V_i rho_i, as the
// one-phase form does.
#include "sph/terms/DensityDiffusionFourtakas.hpp"
#include "sph/terms/PairValues.hpp"

namespace sph::terms {

class DensityDiffusionFourtakasPhases {
 public:
  static constexpr std::string_view name = "density_diffusion_fourtakas_phases";
  static constexpr Reads reads{.mass = true,
                               .density = true,
                               .densityInverse = true,
                               .restDensity = true,
                               .etaInverse = true};
  static constexpr Writes writes{.density = true};
  // Fourtakas et al.'s 24 with rho0_i's factor of g . r 1, the phases' compare-select 2.
  static constexpr Flops flops{27, 3};
  explicit DensityDiffusionFourtakasPhases(const TermParameters& t)
      : deltaC0_(t.diffusionDelta * t.soundSpeed),
        gamma_(t.gammaInteger),
        hydrostatic_{t.gammaInteger / (t.soundSpeed * t.soundSpeed) * t.g[0],
                     t.gammaInteger / (t.soundSpeed * t.soundSpeed) * t.g[1],
                     t.gammaInteger / (t.soundSpeed * t.soundSpeed) * t.g[2]} {}
  template <class S, class V>
  void pair(const PairValues<S, V>& p, PairSums<V>& s) const {
    // rho0 of the pair's phase: i's, where j's is the same (else the pair adds nothing).
    const S rho0 = p.i.rho0, rho0Inverse = 1.0 / rho0;
    const V gr = rho0 * (hydrostatic_[0] * p.rx + hydrostatic_[1] * p.ry + hydrostatic_[2] * p.rz);
    const V difference = fourtakasDifference(p.i.rho, p.j.rho, rho0Inverse, gr, gamma_);
    const V psi = (deltaC0_ * p.hSum) * difference * (p.F * p.r2) * p.rEta2Inv;
    const V ofOnePhase = p.j.rho0 == rho0 ? psi : V{};
    s.rhoI += p.j.m * p.j.rhoInv * ofOnePhase;
    s.rhoJ -= p.i.m * p.i.rhoInv * ofOnePhase;
  }

 private:
  double deltaC0_;
  int gamma_;
  double hydrostatic_[3];  // gamma g / c0^2: rho0^2 g / K per unit rho0
};

}  // namespace sph::terms
