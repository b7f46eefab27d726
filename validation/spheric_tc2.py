"""SPHERIC test 2, the MARIN dam break on a box (Kleefsman et al. 2005), against the experiment (issue 36).

Called by validate.py (case `spheric_dam_break`). The experiment's records are reference_data/spheric_tc2_*.csv
(reports/references.py keys kleefsman_2005_P1..P8, _H1..H4); the scene's probes carry those keys.
Definitions (the same for the experiment and the runs):
  arrival of a height probe   first time h > 0.02 m (the threshold the data file's header uses to order the gauges)
  arrival of a pressure probe first time p > 1 kPa: about 10 % of P1's first peak and 65 standard deviations of the
                              record before the impact (15 Pa over t < 0.3 s), so no noise triggers it
  smoothed record             centred moving average over 11 ms (11 samples of the experiment's 1 ms): it takes out
                              the transducer's sampling noise and the runs' acoustic noise (c0 / 2h > 300 Hz)
  first peak                  the largest value within 0.1 s after the arrival
  P1 scatter band             [smoothed first peak - 2 s, raw first peak + 2 s], s the standard deviation of the
                              record about its smoothed curve over the 0.5 s after the arrival (180 Pa): from the
                              smoothed to the raw maximum is how far the peak's reading moves with the filtering
                              of a noisy record, and 2 s its noise; one record, no repeats, so no run-to-run scatter
  error norm                  RMS of smoothed run minus smoothed experiment over the experiment's samples in
                              [0, T], T the shortest end time of the runs compared (all runs that reach 1 s)
  validation (V&V 20)         the arrivals of H2, H3 and P1 and P1's first peak of each model's three finest runs,
                              the smoke run included (it reaches the box), through reports/uncertainty.py: u_num from
                              their GCI; u_D of an arrival the record's sampling, dt / sqrt(12) for a crossing read
                              at 1 ms samples (the data state no uncertainty of the time origin, the door's lift,
                              so none is added); u_D of the peak the P1 band read as a 95 % interval, width / 3.92
"""
from __future__ import annotations

import math

import numpy as np

import references
from uncertainty import NORMAL_95

HEIGHTS = ("H1", "H2", "H3", "H4")
PRESSURES = tuple(f"P{k}" for k in range(1, 9))
WET_HEIGHT, WET_PRESSURE = 0.02, 1000.0  # m, Pa: the arrivals above
SMOOTH_S, PEAK_WINDOW_S, NOISE_WINDOW_S = 0.011, 0.1, 0.5
ARRIVAL_BAR = 0.05  # issue 36: H2 and P1 arrival times within 5 % of the experiment's at the finest resolution
NORM_FROM_S = 1.0  # scenes that end earlier (the quick smoke run) face the smoke checks, not the experiment


def experiment(probe: str) -> tuple:
    key = f"kleefsman_2005_{probe}"
    ref = references.REFERENCES[key]
    data = references.load(key)
    return data[ref.time_column], data[ref.value_columns[0]]


def smooth(t: np.ndarray, v: np.ndarray, width: float = SMOOTH_S) -> np.ndarray:
    """Centred moving average over `width` seconds (samples need not be even; uses cumulative sums)."""
    c = np.concatenate([[0.0], np.cumsum(v)])
    lo = np.searchsorted(t, t - 0.5 * width, side="left")
    hi = np.searchsorted(t, t + 0.5 * width, side="right")
    return (c[hi] - c[lo]) / np.maximum(hi - lo, 1)


def arrival(t: np.ndarray, v: np.ndarray, level: float) -> float:
    i = int(np.argmax(v > level))
    return float(t[i]) if v[i] > level else float("nan")


def first_peak(t: np.ndarray, v: np.ndarray, at: float) -> float:
    m = (t >= at) & (t <= at + PEAK_WINDOW_S)
    return float(v[m].max()) if m.any() else float("nan")


def p1_band() -> tuple:
    """(low, high, arrival, smoothed first peak) of the experiment's P1 (module docstring)."""
    t, p = experiment("P1")
    at = arrival(t, p, WET_PRESSURE)
    s = smooth(t, p)
    m = (t >= at) & (t <= at + NOISE_WINDOW_S)
    sigma = float(np.std(p[m] - s[m]))
    peak = first_peak(t, s, at)
    return peak - 2 * sigma, first_peak(t, p, at) + 2 * sigma, at, peak


def error_norm(run, probe: str, until: float) -> float:
    te, ve = experiment(probe)
    keep = te <= until
    t, v = run.time, run.probe(probe).values
    sim = np.interp(te[keep], t, smooth(t, v))
    return float(np.sqrt(np.mean((sim - smooth(te, ve)[keep]) ** 2)))


def spheric_dam_break(res, runs: list, common_checks):
    exp_arrival = {g: arrival(*experiment(g), WET_HEIGHT) for g in HEIGHTS[:3]}
    low, high, exp_arrival["P1"], exp_peak = p1_band()
    by_dx = sorted(runs, key=lambda r: r.dx)
    figures = {}  # scene name -> its row's figures
    finest = {}  # model -> its finest run that is not the smoke run
    for run in by_dx:
        if not smoke(run):
            finest.setdefault(model(run), run)
    for run in runs:
        common_checks(res, run, 0.003, 'Lobovsky & Kren, section 3 (dam break): "volume variations are less then 0.3 %"'
                      " (their 2-D model's bar, carried to 3-D)")
        t = run.time
        fig = {"end_time_s": float(t[-1])}
        for g in ("H2", "H3", "P1"):
            v = run.probe(g).values
            a = arrival(t, v, WET_PRESSURE if g.startswith("P") else WET_HEIGHT)
            fig[f"arrival_{g}_s"] = a
            fig[f"arrival_{g}_rel_error"] = abs(a - exp_arrival[g]) / exp_arrival[g]
        p1 = run.probe("P1").values
        fig["P1_first_peak_Pa"] = first_peak(t, smooth(t, p1), fig["arrival_P1_s"])
        fig["P1_first_peak_raw_Pa"] = first_peak(t, p1, fig["arrival_P1_s"])
        fig["H4_start_m"] = float(run.probe("H4").values[0])
        if run is finest.get(model(run)) and not smoke(run):
            for g in ("H2", "P1"):
                res.check(run.scene_name, f"{g} arrival time: |error| / experiment's {exp_arrival[g]:.3f} s",
                          fig[f"arrival_{g}_rel_error"], "<=", ARRIVAL_BAR,
                          "issue 36 bar; Kleefsman et al. 2005 record (arrival: h > 0.02 m, p > 1 kPa)")
            res.check(run.scene_name, "P1 first peak (11 ms smoothed) >= band low", fig["P1_first_peak_Pa"], ">=",
                      low, "Kleefsman et al. 2005 P1: smoothed first peak - 2 sigma of the record's noise")
            res.check(run.scene_name, "P1 first peak (11 ms smoothed) <= band high", fig["P1_first_peak_Pa"], "<=",
                      high, "Kleefsman et al. 2005 P1: raw first peak + 2 sigma of the record's noise")
        if smoke(run):  # it ran, its probes recorded the start and the front at the box
            res.check(run.scene_name, "P1 wetted: largest P1 [Pa]", float(p1.max()), ">", WET_PRESSURE,
                      "smoke test: the front reaches the box by 0.6 s (experiment: 0.39 s)")
            res.check(run.scene_name, "H3 wetted: largest H3 [m]", float(run.probe("H3").values.max()), ">",
                      WET_HEIGHT, "smoke test: the front passes H3 by 0.6 s (experiment: 0.22 s)")
            res.check(run.scene_name, "H4 at t = 0 reads the column's depth: |H4 - depth| / dx",
                      abs(fig["H4_start_m"] - column_depth(run)) / run.dx, "<=", 0.25,
                      "WallProbeTest: the fluid fraction crosses 1/2 within dx/4 of a resting surface")
        res.row(run, **fig)
        figures[run.scene_name] = fig
    validate_against_experiment(res, by_dx, figures, exp_arrival, (low, high, exp_peak))
    # Error norms against the experiment, per model, over the window all its long runs cover.
    for m in sorted({model(r) for r in runs}):
        study = [r for r in by_dx if model(r) == m and not smoke(r)]
        if len(study) < 2:
            continue
        until = min(float(r.time[-1]) for r in study)  # as far as each got (a failed run ends early)
        for g in HEIGHTS + PRESSURES:
            err = [error_norm(r, g, until) for r in study]
            res.study(f"SPHERIC test 2 ({m}): {g} RMS error over [0, {until:g}] s", "dx [m]",
                      [r.dx for r in study], err, "Kleefsman et al. 2005 (SPHERIC test 2 data)")
            if g in ("H1", "H2", "H3", "H4", "P1", "P3", "P5", "P7"):
                res.check(f"{study[0].scene_name} vs {study[-1].scene_name}",
                          f"{g} RMS error over [0, {until:g}] s: finest / coarsest", err[0] / err[-1], "<", 1.0,
                          "issue 36 bar: the error norms decrease with dx")


def validate_against_experiment(res, by_dx: list, figures: dict, exp_arrival: dict, band: tuple):
    """V&V 20 entries (module docstring), one per model and figure; a model with fewer than three runs gets none.
    `band` is the P1 band's (low, high) and the experiment's smoothed first peak."""
    sampling = {}
    for g in ("H2", "H3", "P1"):
        t, _ = experiment(g)
        sampling[g] = float(np.median(np.diff(t)))
    for m in sorted({model(r) for r in by_dx}):
        mine = [r for r in by_dx if model(r) == m]
        for g in ("H2", "H3", "P1"):
            level = "p > 1 kPa" if g.startswith("P") else "h > 0.02 m"
            res.compare(f"SPHERIC test 2 ({m}): {g} arrival time ({level})", "s", "dx [m]",
                        [(r.dx, figures[r.scene_name][f"arrival_{g}_s"]) for r in mine], exp_arrival[g],
                        sampling[g] / math.sqrt(12.0), f"Kleefsman et al. 2005 {g} record, first {level}",
                        f"the record's sampling, {1e3 * sampling[g]:.2f} ms / sqrt(12); no uncertainty of the time "
                        "origin is stated")
        res.compare(f"SPHERIC test 2 ({m}): P1 first peak (11 ms smoothed)", "Pa", "dx [m]",
                    [(r.dx, figures[r.scene_name]["P1_first_peak_Pa"]) for r in mine],
                    band[2], (band[1] - band[0]) / (2 * NORMAL_95),
                    "Kleefsman et al. 2005 P1, smoothed first peak",
                    f"the P1 band [{band[0]:.0f}, {band[1]:.0f}] Pa read as a 95 % interval: width / 3.92")


def smoke(run) -> bool:
    """The quick smoke run: a scene that ends before 1 s (the front reaches the box at about 0.4 s)."""
    return float(run.scene["numerics"]["end_time"]) < NORM_FROM_S


def column_depth(run) -> float:
    """The scene's water depth: the top of its [[fluid]] block (from the scene text the run file stores)."""
    return float(run.scene["fluid"][0]["upper"][2])


def model(run) -> str:
    """The model a run belongs to in the studies: its kernel and h/dx (the paper's or the named one)."""
    n = run.scene.get("numerics", {})
    return f"{n.get('kernel', 'quadratic')}, h/dx {n.get('h_over_dx', 1.33):g}"
