"""Validation uncertainty after ASME V&V 20-2009, the numerical part by the grid convergence index.

Numerical uncertainty from three resolutions (Celik et al. 2008, "Procedure for estimation and reporting of
uncertainty due to discretization in CFD applications", J. Fluids Eng. 130, 078001; Roache's GCI), with 1 the
finest and 3 the coarsest run, h the particle spacing:
    r21 = h2/h1, r32 = h3/h2, eps21 = phi2 - phi1, eps32 = phi3 - phi2, s = sign(eps32/eps21)      (Celik eq. 3)
    p = |ln|eps32/eps21| + q(p)| / ln r21,  q(p) = ln((r21^p - s)/(r32^p - s))                    (Celik eq. 4)
    phi_ext = (r21^p phi1 - phi2)/(r21^p - 1)                                                      (Celik eq. 5)
    e_a21 = |(phi1 - phi2)/phi1|, e_ext21 = |(phi_ext - phi1)/phi_ext|                             (Celik eq. 6)
    GCI_fine21 = Fs e_a21/(r21^p - 1), Fs = 1.25                                                   (Celik eq. 7)
Asymptotic range (Roache): GCI_fine32 / (r21^p GCI_fine21) near 1.
Convergence type from R = eps21/eps32 (Celik: "negative values of eps32/eps21 are an indication of oscillatory
convergence"): monotonic 0 < R < 1, oscillatory -1 < R < 0, divergent |R| > 1 (the differences grow as h falls).

Validation (V&V 20, sections 1-2): E = S - D with S the finest run, D the experiment (or theory);
u_val = sqrt(u_num^2 + u_input^2 + u_D^2); the model error lies in E +- k u_val. Here k = 2: for an error
distribution near normal that is about 95 % coverage (the GUM's convention, which V&V 20 adopts for its examples);
the inputs are not known well enough to justify any other distribution.

u_num from the GCI: the GCI with Fs = 1.25 is taken as an expanded uncertainty of about 95 % coverage; V&V 20
(section 5) turns it into a standard uncertainty with the factor 1.15 used here (GCI_FACTOR; the standard's text is not
in the project's stored material, so this factor is quoted, not checked). Where the convergence
is oscillatory, u_num is at least half the data range of the three runs (the band must cover the oscillation it has
seen). Where it is divergent there is no GCI: u_num is then the whole data range of the three runs, max - min (the
anomalous-convergence estimate of Eca & Hoekstra's least-squares procedure takes the data range too), a number to read
as "the runs disagree by this much", not as a converged estimate; the table says which basis each row has.
"""
from __future__ import annotations

import math

FS = 1.25  # Roache's factor of safety for three or more resolutions (Celik et al. 2008, eq. 7)
GCI_FACTOR = 1.15  # V&V 20-2009 section 5: u_num = GCI / 1.15 for Fs = 1.25
K_COVERAGE = 2.0  # E +- 2 u_val: about 95 % for a near-normal error (module docstring)
NORMAL_95 = 1.96  # half width of a normal distribution's 2.5-97.5 % interval in standard deviations
MONOTONIC, OSCILLATORY, DIVERGENT, CONVERGED = "monotonic", "oscillatory", "divergent", "no change"


def observed_order(r21: float, r32: float, eps21: float, eps32: float, tol: float = 1e-12, max_iter: int = 200):
    """Celik's eq. 4 by fixed-point iteration from q = 0; returns (p, iterations). With r21 = r32, q = 0."""
    s = math.copysign(1.0, eps32 / eps21)
    ratio = math.log(abs(eps32 / eps21))
    p = abs(ratio) / math.log(r21)
    for n in range(1, max_iter + 1):
        a, b = r21 ** p - s, r32 ** p - s
        q = math.log(a / b) if a > 0 and b > 0 else 0.0
        nxt = abs(ratio + q) / math.log(r21)
        if abs(nxt - p) < tol:
            return nxt, n
        p = nxt
    return p, max_iter


def gci(h: list, phi: list, fs: float = FS) -> dict:
    """Celik et al.'s three-resolution procedure. `h` and `phi` in any order; sorted finest first here.
    Returns the reduced numbers, with `kind` the convergence type; p and the extrapolation are None where the
    procedure does not apply (divergence, or no change between two runs)."""
    if len(h) != 3 or len(phi) != 3:
        raise ValueError(f"the GCI needs three resolutions, got h = {h}, phi = {phi}")
    (h1, f1), (h2, f2), (h3, f3) = sorted(zip(map(float, h), map(float, phi)))
    if not (0 < h1 < h2 < h3):
        raise ValueError(f"the GCI needs three distinct positive spacings, got {sorted(h)}")
    r21, r32 = h2 / h1, h3 / h2
    eps21, eps32 = f2 - f1, f3 - f2
    out = {"h": [h1, h2, h3], "phi": [f1, f2, f3], "r21": r21, "r32": r32, "eps21": eps21, "eps32": eps32,
           "p": None, "phi_ext": None, "e_a21": None, "e_ext21": None, "gci_fine21": None, "gci_fine32": None,
           "asymptotic_ratio": None, "fs": fs}
    scale = max(abs(f1), abs(f2), abs(f3), 1e-300)
    if abs(eps21) <= 1e-12 * scale or abs(eps32) <= 1e-12 * scale:
        # Celik: "if either eps32 or eps21 is very close to zero, the procedure will not work".
        out["kind"] = CONVERGED
        return out
    R = eps21 / eps32
    out["R"] = R
    if abs(R) >= 1.0:
        out["kind"] = DIVERGENT
        return out
    out["kind"] = MONOTONIC if R > 0 else OSCILLATORY
    p, _ = observed_order(r21, r32, eps21, eps32)
    rp21, rp32 = r21 ** p, r32 ** p
    phi_ext = (rp21 * f1 - f2) / (rp21 - 1.0)
    e_a21 = abs((f1 - f2) / f1)
    e_a32 = abs((f2 - f3) / f2)
    g21 = fs * e_a21 / (rp21 - 1.0)
    g32 = fs * e_a32 / (rp32 - 1.0)
    out.update(p=p, phi_ext=phi_ext, e_a21=e_a21, e_ext21=abs((phi_ext - f1) / phi_ext), gci_fine21=g21,
               gci_fine32=g32, asymptotic_ratio=g32 / (rp21 * g21))
    return out


def u_num(study: dict) -> tuple:
    """(standard numerical uncertainty of the finest run, its basis in words): module docstring."""
    spread = max(study["phi"]) - min(study["phi"])
    if study["kind"] == CONVERGED:
        return 0.0, "no change between two runs: Celik's procedure does not apply"
    if study["kind"] == DIVERGENT:
        return spread, "divergent, no GCI: the data range of the three runs"
    u = study["gci_fine21"] * abs(study["phi"][0]) / GCI_FACTOR
    if study["kind"] == OSCILLATORY and 0.5 * spread > u:
        return 0.5 * spread, "oscillatory: half the data range (above GCI/1.15)"
    return u, "GCI_fine21 / 1.15"


def validation(entry: dict) -> dict:
    """One figure of merit through V&V 20: `entry` has h, S (one per h), and optionally D, u_D, u_input.
    Returns the GCI study and E, u_num, u_val, the band E +- k u_val and whether the band holds zero."""
    study = gci(entry["h"], entry["S"])
    un, basis = u_num(study)
    ui = float(entry.get("u_input") or 0.0)
    d, ud = entry.get("D"), entry.get("u_D")
    out = {"study": study, "S": study["phi"][0], "D": d, "u_num": un, "u_num_basis": basis, "u_input": ui, "u_D": ud, "k": K_COVERAGE,
           "E": None, "u_val": None, "band": None, "zero_in_band": None}
    if d is None:
        return out
    E = out["S"] - float(d)
    parts = [un, ui, float(ud or 0.0)]
    uval = math.sqrt(sum(x * x for x in parts))
    out.update(E=E, u_val=uval, band=[E - K_COVERAGE * uval, E + K_COVERAGE * uval],
               zero_in_band=abs(E) <= K_COVERAGE * uval)
    return out


def table(results: list) -> list:
    """Every `comparisons` entry of the verification results (validate.py writes them), through `validation`;
    an entry that cannot be evaluated comes back with its `error`."""
    rows = []
    for res in results:
        for entry in res.data.get("comparisons", []) or []:
            row = {"test": res.test, "name": str(entry.get("name", "?")), "unit": str(entry.get("unit", "")),
                   "x_label": str(entry.get("x_label", "h")), "D_source": str(entry.get("D_source", "")),
                   "u_D_source": str(entry.get("u_D_source", "")),
                   "u_input_source": str(entry.get("u_input_source", "")), "error": ""}
            try:
                row.update(validation(entry))
            except (KeyError, TypeError, ValueError, ZeroDivisionError) as err:
                row["error"] = f"{type(err).__name__}: {err}"
            rows.append(row)
    return rows
