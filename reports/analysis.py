"""Reduced numbers the report shows and summary.json keeps: convergence fits, speed/accuracy points, environment.

Everything here is computed from what the run and result files hold; plotting happens later, from these numbers.
"""
from __future__ import annotations

import json
import re

import numpy as np

import references
from runfile import PROVENANCE, family


def fit_order(x, error):
    """Least-squares slope of log(error) against log(x); None with fewer than two positive points."""
    x, error = np.asarray(x, dtype=float), np.asarray(error, dtype=float)
    keep = (x > 0) & (error > 0) & np.isfinite(x) & np.isfinite(error)
    if keep.sum() < 2:
        return None
    return float(np.polyfit(np.log(x[keep]), np.log(error[keep]), 1)[0])


_WORD = re.compile(r"[a-z0-9.]+")


_NORMS = {"l1", "l2", "linf"}


def order_criterion(entry: dict, checks: list):
    """The check of the same result file that decides this convergence entry's order: among the checks whose name
    says "order" and names no other error norm than the entry's (an L2 order check does not decide an Linf entry),
    the one sharing most words with the entry's name (None when the file has no such check; the entry is then a
    finding). Returns {name, measured, comparison, threshold, pass}."""
    words = set(_WORD.findall(str(entry.get("name", "")).lower()))
    best, score = None, -1
    for c in checks:
        name = str(c.get("name", ""))
        if "order" not in name.lower() or not isinstance(c.get("threshold"), (int, float)):
            continue
        named = set(_WORD.findall(name.lower()))
        if (named & _NORMS) and (words & _NORMS) and (named & _NORMS) != (words & _NORMS):
            continue
        shared = len(words & named)
        if shared > score:
            best, score = c, shared
    if best is None:
        return None
    return {k: best.get(k) for k in ("name", "measured", "comparison", "threshold", "pass")}


def convergence_entries(results: list) -> list:
    out = []
    for res in results:
        checks = [c for c in res.data.get("checks", []) if isinstance(c, dict)]
        for entry in res.data.get("convergence", []):
            x, err = entry.get("x", []), entry.get("error", [])
            out.append({"test": res.test, "name": str(entry.get("name", "?")), "x_label": entry.get("x_label", "x"),
                        "x": list(x), "error": list(err), "fitted_order": fit_order(x, err),
                        "observed_order": entry.get("observed_order"), "theory_order": entry.get("theory_order"),
                        "source": entry.get("source", ""), "criterion": order_criterion(entry, checks)})
    return out


def recorded_figures(results: list) -> list:
    """Figures the tests measured and report without a threshold (findings, not criteria)."""
    out = []
    for res in results:
        for f in res.data.get("figures", []) or []:
            if isinstance(f, dict):
                out.append({"test": res.test, "name": str(f.get("name", "?")), "measured": f.get("measured"),
                            "source": str(f.get("source", ""))})
    return out


def recorded_histories(results: list) -> list:
    """Measured curves y(x) the tests recorded (e.g. max|u| over time), grouped per test and y label: one figure each."""
    groups = {}
    for res in results:
        for h in res.data.get("histories", []) or []:
            if not isinstance(h, dict):
                continue
            key = (res.test, str(h.get("y_label", "y")))
            g = groups.setdefault(key, {"test": res.test, "y_label": key[1], "x_label": str(h.get("x_label", "x")),
                                        "curves": []})
            g["curves"].append({"name": str(h.get("name", "?")), "x": list(h.get("x", [])), "y": list(h.get("y", [])),
                                "source": str(h.get("source", ""))})
    return list(groups.values())


def _reference_pair(runs):
    """The first (probe name, reference key) for which every run has a computable reference error."""
    first = runs[0]
    for probe in first.probes:
        for key in references.keys_for(probe):
            errors = []
            for run in runs:
                match = next((p for p in run.probes if p.name == probe.name), None)
                errors.append(None if match is None else references.reference_error(run, match, key))
            if all(e is not None for e in errors):
                return probe.name, key, errors
    return None


def speed_accuracy(runs: list) -> dict:
    """{case: {"error": what the error is, "points": [...]}} for cases with two or more readable runs."""
    groups = {}
    for run in runs:
        if not run.read_error and isinstance(run.metrics.get("wall_time_s"), (int, float)):
            # One line per scene at its resolutions (the paper's dam break and Lobovsky's are two scenes of one
            # criteria case, never one line).
            groups.setdefault(family(run.scene_name), []).append(run)
    out = {}
    for case, members in sorted(groups.items()):
        if len(members) < 2:
            continue
        pair = _reference_pair(members)
        if pair:
            probe_name, key, errors = pair
            what = f"RMS of probe {probe_name} - {references.REFERENCES[key].citation} (scaled)"
        else:
            errors = [r.metrics.get("max_volume_variation") for r in members]
            what = "max_volume_variation (no reference error available)"
        points = [{"run": r.label, "method": r.method, "wall_time_s": float(r.metrics["wall_time_s"]),
                   "error": None if e is None else float(e), "particles": r.metrics.get("particles")}
                  for r, e in zip(members, errors)]
        out[case] = {"error": what, "points": sorted(points, key=lambda p: (p["method"], p["wall_time_s"]))}
    return out


def sweep_speed_accuracy(items: list) -> dict:
    """Speed against accuracy across a stability sweep's runs: max volume variation against wall time, one
    line per category of the sweep's y axis (the kernel), each point marked by its outcome, so a reader sees
    which settings buy accuracy cheapest and where they stop working (issue 8)."""
    out, seen = {}, set()
    # Of two maps drawn from the same runs, keep the one whose y axis is a setting (a line per value).
    for item in sorted(items, key=lambda it: str(it.get("y_label", "")).startswith("max")):
        points = item.get("points") or []
        usable = [pt for pt in points if isinstance(pt.get("wall_time"), (int, float))
                  and isinstance(pt.get("volume_variation"), (int, float))]
        runs = json.dumps([pt.get("params") for pt in points], sort_keys=True)
        if len(usable) < 2 or runs in seen:  # two maps drawn from the same runs: one chart
            continue
        seen.add(runs)
        labels = (item.get("y_ticks") or {}).get("labels")
        y_is_setting = not str(item.get("y_label", "")).startswith("max")  # else y is a measured quantity
        rows = []
        for pt in usable:
            y = pt.get("y")
            if labels and isinstance(y, int) and 0 <= y < len(labels):
                method = labels[y]
            else:
                method = f"{item.get('y_label', 'y')} = {y}" if y_is_setting else "all runs"
            rows.append({"run": f"{item.get('x_label', 'x')} = {pt['x']}", "label": f"{pt['x']}",
                         "method": method, "wall_time_s": float(pt["wall_time"]),
                         "error": float(pt["volume_variation"]), "particles": None,
                         "outcome": pt.get("outcome"), "cause": pt.get("cause", "")})
        out[f"{item['sweep']} (stability sweep)"] = {
            "error": f"max_volume_variation; points labelled by {item.get('x_label', 'x')}",
            "points": sorted(rows, key=lambda r: (r["method"], r["wall_time_s"]))}
    return out


def environment(runs: list) -> dict:
    """Provenance attributes as the run files give them: one value when all runs agree, else each run's value."""
    readable = [r for r in runs if not r.read_error]
    rows = []
    for name in PROVENANCE:
        values = {r.label: r.attrs.get(name, "(not in run file)") for r in readable}
        distinct = sorted({str(v) for v in values.values()})
        rows.append({"attribute": name, "value": distinct[0] if len(distinct) == 1 else None,
                     "per_run": None if len(distinct) <= 1 else {k: str(v) for k, v in values.items()}})
    walls = [r.metrics["wall_time_s"] for r in readable if isinstance(r.metrics.get("wall_time_s"), (int, float))]
    return {"rows": rows if readable else [], "runs": len(readable),
            "total_wall_time_s": float(sum(walls)) if walls else None}
