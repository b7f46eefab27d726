"""Experimental references: which probe compares with which CSV in reference_data/, and in which scaling.

The table REFERENCES is the only place that knows a file's columns and scaling (see reference_data/README.md);
PROBE_REFERENCES maps a probe name (the dataset /series/probe_<name>) to reference keys. A probe's optional
attribute `reference` (comma-separated keys) replaces that default.

Scaling constants come from the run file, never from here:
  scale_length   probe attribute [m]: the length of the reference's scaling (column width a for Martin & Moyce and
                 Koshizuka & Oka, initial column height H for Lobovsky and Buchner)
  scale_height   probe attribute [m], optional: initial column height for the Martin & Moyce height
                 (default: the probe's first sample)
  gravity        probe or root attribute [m/s^2] (a scalar or a vector); the solver writes the root attribute
  density / rho0 probe attribute `density` or root attribute `rho0` [kg/m^3], for pressures
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

DATA_DIR = Path(__file__).resolve().parent.parent / "reference_data"


@dataclass(frozen=True)
class Reference:
    key: str
    file: str
    citation: str
    time_column: str
    value_columns: tuple  # one curve per column; three columns with band=True are (low, median, high)
    time_g_factor: float  # t* = t sqrt(time_g_factor g / L)
    value_scaling: str  # "length": v / L, "initial": v / v0, "pressure": p / (rho g L), "dimensional": t, v as they are
    time_label: str
    value_label: str
    band: bool = False
    scatter: bool = False  # digitized points, not time-ordered


REFERENCES = {r.key: r for r in (
    Reference("martin_moyce_1952_front", "dambreak_front_martin_moyce1952.csv", "Martin & Moyce 1952 (experiment)",
              "T", ("Z",), 2.0, "length", r"$T = t\sqrt{2g/a}$", r"$Z = x_{front}/a$"),
    Reference("koshizuka_oka_1996_front", "dambreak_front_koshizuka_oka1996.csv",
              "Koshizuka & Oka 1996 (experiment, digitized)", "T", ("Z",), 2.0, "length",
              r"$T = t\sqrt{2g/a}$", r"$Z = x_{front}/a$", scatter=True),
    Reference("martin_moyce_1952_height", "dambreak_height_martin_moyce1952.csv", "Martin & Moyce 1952 (experiment)",
              "tau", ("H",), 1.0, "initial", r"$\tau = t\sqrt{g/a}$", r"$h / h_0$"),
    Reference("lobovsky_2014_sensor2", "dambreak_lobovsky2014_H300_sensor2_pressure_percentiles.csv",
              "Lobovsky et al. 2014, sensor 2: 2.5-97.5 % band and median", "t_star",
              ("p_star_p2.5", "p_star_median", "p_star_p97.5"), 1.0, "pressure",
              r"$t\sqrt{g/H}$", r"$p/(\rho g H)$", band=True),
    Reference("buchner_2002_wall_pressure", "dambreak_wall_pressure_buchner2002.csv",
              "Buchner 2002 (experiment, digitized)", "t_star", ("p_star",), 1.0, "pressure",
              r"$t\sqrt{g/H}$", r"$p/(\rho g H)$", scatter=True),
    Reference("lobovsky_2014_level_H1", "dambreak_lobovsky2014_H300_water_levels.csv",
              "Lobovsky et al. 2014, gauge H1", "t_star", ("h_over_H_H1_2",), 1.0, "length",
              r"$t\sqrt{g/H}$", r"$h/H$"),
    Reference("lobovsky_2014_level_H2", "dambreak_lobovsky2014_H300_water_levels.csv",
              "Lobovsky et al. 2014, gauge H2", "t_star", ("h_over_H_H2_3", "h_over_H_H2_4"), 1.0, "length",
              r"$t\sqrt{g/H}$", r"$h/H$"),
    Reference("lobovsky_2014_level_H3", "dambreak_lobovsky2014_H300_water_levels.csv",
              "Lobovsky et al. 2014, gauge H3", "t_star", ("h_over_H_H3_3", "h_over_H_H3_4"), 1.0, "length",
              r"$t\sqrt{g/H}$", r"$h/H$"),
    Reference("lobovsky_2014_level_H4", "dambreak_lobovsky2014_H300_water_levels.csv",
              "Lobovsky et al. 2014, gauge H4", "t_star", ("h_over_H_H4_4", "h_over_H_H4_5"), 1.0, "length",
              r"$t\sqrt{g/H}$", r"$h/H$"),
) + tuple(
    Reference(f"kleefsman_2005_P{k}", "spheric_tc2_kleefsman2005_pressures.csv",
              f"Kleefsman et al. 2005 (SPHERIC test 2), pressure P{k}", "t_s", (f"P{k}_Pa",), 1.0, "dimensional",
              "t [s]", "p [Pa]") for k in range(1, 9)
) + tuple(
    Reference(f"kleefsman_2005_H{k}", "spheric_tc2_kleefsman2005_water_heights.csv",
              f"Kleefsman et al. 2005 (SPHERIC test 2), water height H{k}", "t_s", (f"H{k}_m",), 1.0, "dimensional",
              "t [s]", "h [m]") for k in range(1, 5)
)}

PROBE_REFERENCES = {
    "surge_front": ("martin_moyce_1952_front", "koshizuka_oka_1996_front"),
    "column_height": ("martin_moyce_1952_height",),
    "p_sensor2": ("lobovsky_2014_sensor2",),
    "p_buchner": ("buchner_2002_wall_pressure",),
    "level_H1": ("lobovsky_2014_level_H1",),
    "level_H2": ("lobovsky_2014_level_H2",),
    "level_H3": ("lobovsky_2014_level_H3",),
    "level_H4": ("lobovsky_2014_level_H4",),
}


@lru_cache(maxsize=None)
def load(key: str, data_dir: Path = DATA_DIR) -> dict:
    """{column name: array} of a reference CSV. The '#' provenance lines and the header line are skipped by
    counting them: numpy's skiprows counts comment lines too, so skiprows=1 alone would land on the header."""
    ref = REFERENCES[key]
    path = Path(data_dir) / ref.file
    with open(path, encoding="utf-8") as f:
        lines = f.readlines()
    n_comments = next(i for i, line in enumerate(lines) if not line.lstrip().startswith("#"))
    header = [h.strip() for h in lines[n_comments].split(",")]
    data = np.loadtxt(path, delimiter=",", comments="#", skiprows=n_comments + 1, ndmin=2)
    return {name: data[:, i] for i, name in enumerate(header)}


def keys_for(probe) -> tuple:
    named = probe.attrs.get("reference")
    if named:
        return tuple(k.strip() for k in str(named).split(",") if k.strip() in REFERENCES)
    return PROBE_REFERENCES.get(probe.name, ())


def _gravity(probe, run_attrs):
    """|g| from the probe's or else the run's `gravity` attribute; None when neither gives a positive value."""
    for source in (probe.attrs, run_attrs):
        g = source.get("gravity")
        if g is not None:
            g = float(np.linalg.norm(np.atleast_1d(np.asarray(g, dtype=float))))
            if g > 0:
                return g
    return None


def scale_probe(run, probe, key: str):
    """(t*, v*, note) of a probe in the reference's scaling, or (None, None, why not)."""
    ref = REFERENCES[key]
    t = run.series.get("time")
    if t is None or len(t) != len(probe.values):
        return None, None, "no /series/time of the probe's length"
    if ref.value_scaling == "dimensional":
        return np.asarray(t, dtype=float), np.asarray(probe.values, dtype=float), ""
    length = probe.attrs.get("scale_length")
    if not isinstance(length, (int, float)) or not length > 0:
        return None, None, "probe has no `scale_length` attribute"
    g = _gravity(probe, run.attrs)
    if g is None:
        return None, None, "no positive `gravity` probe or root attribute"
    t_star = np.asarray(t, dtype=float) * math.sqrt(ref.time_g_factor * g / length)
    v = probe.values
    if ref.value_scaling == "length":
        v_star = v / length
    elif ref.value_scaling == "initial":
        h0 = probe.attrs.get("scale_height", v[0] if len(v) else float("nan"))
        v_star = v / float(h0)
    else:
        rho = probe.attrs.get("density", run.attrs.get("rho0"))
        if not isinstance(rho, (int, float)) or not rho > 0:
            return None, None, "no `density` probe attribute or `rho0` root attribute"
        v_star = v / (rho * g * length)
    return t_star, v_star, ""


def reference_error(run, probe, key: str):
    """RMS difference between the scaled probe and the reference's central curve, over the reference points
    inside the run's time range; None when it cannot be computed."""
    ref = REFERENCES[key]
    t_star, v_star, _ = scale_probe(run, probe, key)
    if t_star is None or len(t_star) < 2:
        return None
    data = load(key)
    column = ref.value_columns[len(ref.value_columns) // 2] if ref.band else ref.value_columns[0]
    rt, rv = data[ref.time_column], data[column]
    inside = (rt >= t_star.min()) & (rt <= t_star.max())
    if inside.sum() < 2:
        return None
    order = np.argsort(t_star)
    sim = np.interp(rt[inside], t_star[order], v_star[order])
    return float(np.sqrt(np.mean((sim - rv[inside]) ** 2)))
