"""Figures of the report, each saved as its own PNG under the output directory; every function returns the
file name it wrote (relative to the output directory). Matplotlib is imported here only, with the Agg backend."""
from __future__ import annotations

import re
import textwrap
from pathlib import Path

import numpy as np

import references

OUTCOME_STYLE = {"stable": ("tab:green", "o"), "unstable": ("tab:red", "x"), "inaccurate": ("tab:orange", "s")}


def slug(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9._-]+", "-", text).strip("-") or "figure"


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig, out: Path, name: str, dpi: int) -> str:
    fig.savefig(Path(out) / name, dpi=dpi, bbox_inches="tight")
    _pyplot().close(fig)
    return name


def _pick(n: int, k: int) -> list:
    return sorted({int(round(i)) for i in np.linspace(0, n - 1, min(n, k))}) if n else []


def snapshots(run, out: Path, quick: bool = False):
    """Particle positions at several times in a grid, coloured by pressure or, with several phases, by phase."""
    picked = [run.snapshots[i] for i in _pick(len(run.snapshots), 2 if quick else 6)]
    if not picked:
        return None
    data = [run.snapshot_fields(s) for s in picked]
    if any("position" not in d for d in data):
        return None
    phases = np.unique(np.concatenate([d.get("phase", np.zeros(0, dtype=int)) for d in data]))
    by_phase = len(phases) > 1
    dim = int(run.attrs.get("dimension", 2))
    ax2 = 2 if dim == 3 else 1  # 3-D runs are shown as their x-z projection

    pressure = np.concatenate([d.get("pressure", np.zeros(0)) for d in data])
    vmin, vmax = (np.percentile(pressure, [1, 99]) if pressure.size else (0.0, 1.0))
    xy = np.concatenate([d["position"][:, [0, ax2]] for d in data])
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    pad = 0.03 * max(float((hi - lo).max()), 1e-12)

    plt = _pyplot()
    ncol = min(3, len(picked))
    nrow = -(-len(picked) // ncol)
    span = np.maximum(hi - lo, 1e-12)
    aspect = float(np.clip(span[1] / span[0], 0.2, 1.2)) if dim > 1 else 0.3
    panel = 4.0  # inches
    fig, axes = plt.subplots(nrow, ncol, figsize=(panel * ncol + 1.0, panel * aspect * nrow + 0.8),
                             squeeze=False, sharex=True, sharey=True)
    mappable = None
    for ax, snap, d in zip(axes.flat, picked, data):
        pos = d["position"]
        y = pos[:, ax2] if dim > 1 else np.zeros(len(pos))
        # marker about one particle spacing wide: spacing ~ sqrt(area / N), panel width 72 points per inch
        spacing = float(np.sqrt(span[0] * (span[1] if dim > 1 else span[0] * 0.01) / max(len(pos), 1)))
        size = float(np.clip((0.6 * 72 * panel * spacing / max(span[0], span[1] / aspect)) ** 2, 0.2, 30.0))
        if by_phase:
            for k, ph in enumerate(phases):
                sel = d.get("phase", np.zeros(len(pos), dtype=int)) == ph
                ax.scatter(pos[sel, 0], y[sel], s=size, color=f"C{k}", lw=0, label=f"phase {ph}")
        else:
            mappable = ax.scatter(pos[:, 0], y, s=size, c=d.get("pressure", np.zeros(len(pos))), cmap="viridis",
                                  vmin=vmin, vmax=vmax, lw=0)
        title = f"t = {snap.time:.4g} s" + (" (last good state)" if snap.last_good else "")
        ax.set_title(title, fontsize=9)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        if dim > 1:
            ax.set_ylim(lo[1] - pad, hi[1] + pad)
            ax.set_aspect("equal")
    for ax in axes.flat[len(picked):]:
        ax.set_visible(False)
    for ax in axes[-1]:
        ax.set_xlabel("x [m]")
    for ax in axes[:, 0]:
        ax.set_ylabel(("z" if dim == 3 else "y") + " [m]" if dim > 1 else "")
    if by_phase:
        axes.flat[0].legend(loc="upper right", fontsize=7, markerscale=max(1.0, 4.0 / np.sqrt(size)))
    elif mappable is not None:
        fig.colorbar(mappable, ax=axes.ravel().tolist(), shrink=0.8, label="pressure [Pa]")
    fig.suptitle(f"{run.label}: particles ({run.attrs.get('kernel', '?')} kernel)", fontsize=10)
    return _save(fig, out, f"{slug(run.label)}-snapshots.png", 80 if quick else 110)


def volume(run, run_criteria, out: Path, quick: bool = False):
    """Volume error over time, per phase where the run has phases, with the volume criteria as bands."""
    t = run.series.get("time")
    names = sorted(k for k in run.series if k == "volume_error" or k.startswith("volume_error_"))
    if t is None or not names:
        return None
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.4))
    for name in names:
        ax.plot(t, 100.0 * np.asarray(run.series[name], dtype=float), lw=1.2,
                label=name.replace("volume_error", "all fluid" if name == "volume_error" else "").lstrip("_"))
    for k, c in enumerate(c for c in run_criteria if c.metric.startswith("max_volume_variation")):
        level = 100.0 * float(c.threshold)
        ax.axhline(level, ls="--", lw=0.8, color=f"C{k + len(names)}",
                   label=f"limit {c.metric} {c.comparison} {c.threshold}: {c.source}")
        ax.axhline(-level, ls="--", lw=0.8, color=f"C{k + len(names)}")
    ax.set_xlabel("t [s]")
    ax.set_ylabel(r"$(V(t) - V(0))/V(0)$ [%]")
    ax.set_title(f"{run.label}: volume variation", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.18), frameon=False)
    return _save(fig, out, f"{slug(run.label)}-volume.png", 80 if quick else 110)


def probe(run, pr, out: Path, quick: bool = False):
    """A probe's time series; in the reference's scaling beside the reference when one applies.
    Returns (file name, notes)."""
    t = run.series.get("time")
    if t is None or len(t) != len(pr.values):
        return None, [f"probe {pr.name}: no matching /series/time"]
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    notes, scaled = [], None
    for key in references.keys_for(pr):
        ts, vs, note = references.scale_probe(run, pr, key)
        if ts is None:
            notes.append(f"{references.REFERENCES[key].citation} not drawn: {note}")
            continue
        if note:
            notes.append(note)
        ref = references.REFERENCES[key]
        same = scaled is None or (ref.time_g_factor, ref.value_scaling) == (scaled.time_g_factor, scaled.value_scaling)
        if not same:
            notes.append(f"{ref.citation} not drawn: its scaling differs from {scaled.citation}")
            continue
        if scaled is None:
            scaled = ref
            ax.plot(ts, vs, color="k", lw=1.4, label=f"SPH, {run.label}", zorder=2)  # under the markers
        data = references.load(key)
        rt = data[ref.time_column]
        if ref.band:
            lowc, midc, highc = ref.value_columns
            ax.fill_between(rt, data[lowc], data[highc], color="tab:blue", alpha=0.25, lw=0, label=ref.citation)
            ax.plot(rt, data[midc], color="tab:blue", lw=0.8)
        else:
            for col in ref.value_columns:
                label = ref.citation + (f" ({col})" if len(ref.value_columns) > 1 else "")
                if ref.scatter:
                    ax.plot(rt, data[col], ls="none", marker="s", ms=3.5, mfc="none", label=label, zorder=4)
                else:
                    dense = len(rt) > 500  # a sampled record (1 kHz), not a table: a line, no markers
                    ax.plot(rt, data[col], ls="-", marker="none" if dense else "o", ms=3, lw=0.8, label=label,
                            zorder=4)
    if scaled is not None:
        ax.set_xlabel(scaled.time_label)
        ax.set_ylabel(scaled.value_label)
        ax.set_xlim(left=0)
    else:
        ax.plot(t, pr.values, color="k", lw=1.4, label=f"SPH, {run.label}")
        ax.set_xlabel("t [s]")
        ax.set_ylabel(f"{pr.name} [{pr.attrs.get('units', '?')}]")
    ax.set_title(f"{run.label}: probe {pr.name} ({pr.attrs.get('type', '?')})", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # beside the data, never over it
    return _save(fig, out, f"{slug(run.label)}-probe-{slug(pr.name)}.png", 80 if quick else 110), notes


def convergence(entry: dict, out: Path, index: int, quick: bool = False):
    """Error against resolution on log axes, the fitted and the theory slope, and the criterion that decides the
    order with its PASS/FAIL in the corner (or "no criterion: a finding")."""
    x, err = np.asarray(entry["x"], dtype=float), np.asarray(entry["error"], dtype=float)
    if x.size == 0 or x.size != err.size:
        return None
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    ax.loglog(x, err, "o", color="k", label=f"measured ({entry['source']})" if entry["source"] else "measured")
    p = entry["fitted_order"]
    keep = (x > 0) & (err > 0) & np.isfinite(err)
    if p is not None:
        c = np.exp(np.mean(np.log(err[keep]) - p * np.log(x[keep])))
        xs = np.array([x[keep].min(), x[keep].max()])
        ax.loglog(xs, c * xs ** p, "-", color="tab:blue", label=f"fitted slope {p:.2f}")
    q = entry["theory_order"]
    if isinstance(q, (int, float)) and keep.any():
        x0, e0 = x[keep][np.argmin(x[keep])], err[keep][np.argmin(x[keep])]
        xs = np.array([x[keep].min(), x[keep].max()])
        ax.loglog(xs, e0 * (xs / x0) ** q, "--", color="tab:red", label=f"theory slope {q:g}")
    crit = entry.get("criterion")
    if crit:
        ok = bool(crit.get("pass"))
        measured = crit.get("measured")
        text = (f"{'PASS' if ok else 'FAIL'}: {crit['name']}\n{measured:.3g} {crit['comparison']} {crit['threshold']:g}"
                if isinstance(measured, (int, float)) else f"{'PASS' if ok else 'FAIL'}: {crit['name']}")
        color = "#2e7d32" if ok else "#c62828"
    else:
        text, color = "no criterion: a finding, reported as measured", "#555555"
    ax.set_xlabel(entry["x_label"])
    ax.set_ylabel(textwrap.fill(entry["name"], 40), fontsize=7)
    # The verdict above the axes, where it covers no data.
    ax.set_title(textwrap.fill(text, 70), fontsize=8, color=color, fontweight="bold")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    return _save(fig, out, f"convergence-{index:02d}-{slug(entry['name'])}.png", 80 if quick else 110)


def history(group: dict, out: Path, index: int, quick: bool = False):
    """The curves one test recorded against the same y label, on a log axis where all values are positive."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(5.6, 3.6))
    positive = True
    for c in group["curves"]:
        x = np.asarray([np.nan if v is None else v for v in c["x"]], dtype=float)
        y = np.asarray([np.nan if v is None else v for v in c["y"]], dtype=float)
        if x.size == 0 or x.size != y.size:
            continue
        positive = positive and bool(np.all(y[np.isfinite(y)] > 0))
        ax.plot(x, y, "-", lw=1.0, label=c["name"])
    if positive:
        ax.set_yscale("log")
    ax.set_xlabel(group["x_label"])
    ax.set_ylabel(group["y_label"])
    ax.set_title(group["test"], fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # beside the data, never over it
    return _save(fig, out, f"history-{index:02d}-{slug(group['test'] + '-' + group['y_label'])}.png",
                 80 if quick else 110)


def speed_accuracy(case: str, data: dict, out: Path, quick: bool = False):
    pts = [p for p in data["points"] if p["error"] is not None]
    if not pts:
        return None
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    methods = sorted({p["method"] for p in pts})
    for k, method in enumerate(methods):
        mine = sorted((p for p in pts if p["method"] == method), key=lambda p: p["wall_time_s"])
        ax.plot([p["wall_time_s"] for p in mine], [p["error"] for p in mine], "-o", color=f"C{k}",
                label=textwrap.fill(method.replace(",", ", "), 40))
        for p in mine:
            text = p.get("label") or (f"N={p['particles']}" if p["particles"] is not None else p["run"])
            ax.annotate(text, (p["wall_time_s"], p["error"]), fontsize=6, xytext=(3, 3), textcoords="offset points")
    for outcome in ("unstable", "inaccurate"):  # stability-sweep points: mark where a method stops working
        bad = [p for p in pts if p.get("outcome") == outcome]
        if bad:
            color, marker = OUTCOME_STYLE[outcome]
            style = dict(c=color) if marker == "x" else dict(facecolors="none", edgecolors=color)
            ax.scatter([p["wall_time_s"] for p in bad], [p["error"] for p in bad], s=70, marker=marker, zorder=3,
                       label=outcome, **style)
    if all(p["wall_time_s"] > 0 and p["error"] > 0 for p in pts):
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel("wall time [s] (/metrics/wall_time_s)")
    ax.set_ylabel(textwrap.fill(data["error"], 45), fontsize=7)
    ax.set_title(textwrap.fill(f"{case}: {data['error']}", 100), fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=6, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # beside the data, never over it
    return _save(fig, out, f"speed-accuracy-{slug(case)}.png", 80 if quick else 110)


def stability(sweep: dict, out: Path, index: int, quick: bool = False):
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(5.6, 4.0))
    for outcome, (color, marker) in OUTCOME_STYLE.items():
        pts = [p for p in sweep["points"] if p.get("outcome") == outcome]
        if pts:
            ax.scatter([p["x"] for p in pts], [p["y"] for p in pts], c=color, marker=marker, s=40, label=outcome)
    ax.set_xlabel(sweep.get("x_label", "x"))
    ax.set_ylabel(sweep.get("y_label", "y"))
    if sweep.get("x_log"):
        ax.set_xscale("log")
    if sweep.get("y_log"):
        ax.set_yscale("log")
    ticks = sweep.get("y_ticks")  # categorical axes (e.g. the kernel)
    if ticks:
        ax.set_yticks(ticks["values"], ticks["labels"])
    ax.set_title(str(sweep.get("sweep", "stability sweep")), fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # beside the data, never over it
    return _save(fig, out, f"stability-{index:02d}-{slug(str(sweep.get('sweep', '')))}.png", 80 if quick else 110)


def perf_series(bench: dict, out: Path, index: int, quick: bool = False):
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.0, 3.8))
    for k, s in enumerate(bench["series"]):
        if s.get("recorded"):  # a dated reference, not measured by this run: grey, dashed, hollow
            ax.plot(s["x"], s["y"], "--s", color="0.5", mfc="none",
                    label=textwrap.fill(f"{s.get('label', k)}: recorded reference ({s['recorded']}), "
                                        "not measured by this run", 45))
        else:
            ax.plot(s["x"], s["y"], "-o", color=f"C{k}", label=str(s.get("label", k)))
    ax.set_xlabel(bench.get("x_label", "x"))
    ax.set_ylabel(bench.get("y_label", "y"))
    ax.set_title(str(bench.get("benchmark", "benchmark")), fontsize=10)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)  # beside the data, never over it
    return _save(fig, out, f"perf-{index:02d}-{slug(str(bench.get('benchmark', '')))}.png", 80 if quick else 110)


def vv20(row: dict, out: Path, index: int, quick: bool = False):
    """One figure of merit at its three resolutions (reports/uncertainty.py): S against h, the extrapolated value at
    h = 0 with +- k u_num, and the experiment D with its +- k u_D band; the title gives E +- k u_val."""
    study = row["study"]
    h, phi = np.asarray(study["h"]), np.asarray(study["phi"])
    k = row["k"]
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    ax.plot(h, phi, "o-", color="k", label="SPH at three resolutions", zorder=3)
    if row.get("D") is not None:
        d, ud = row["D"], row.get("u_D") or 0.0
        ax.axhline(d, color="tab:blue", lw=1.2, label=f"D: {row['D_source']}")
        if ud > 0:
            ax.axhspan(d - k * ud, d + k * ud, color="tab:blue", alpha=0.18, lw=0, label=f"D +- {k:g} u_D")
    if study.get("phi_ext") is not None:
        ax.errorbar([0.0], [study["phi_ext"]], yerr=[[k * row["u_num"]], [k * row["u_num"]]], fmt="s",
                    color="tab:red", capsize=4, label=f"extrapolated to h = 0, +- {k:g} u_num")
    else:
        ax.errorbar([h[0]], [phi[0]], yerr=[[k * row["u_num"]], [k * row["u_num"]]], fmt="none", color="tab:red",
                    capsize=4, label=f"finest run +- {k:g} u_num ({study['kind']}: no extrapolation)")
    ax.set_xlim(left=-0.05 * h.max())
    ax.set_xlabel(row["x_label"])
    ax.set_ylabel(f"{row['name'].split(': ', 1)[-1]}" + (f" [{row['unit']}]" if row["unit"] not in ("", "-") else ""),
                  fontsize=8)
    if row.get("E") is not None:
        verdict = "band holds 0" if row["zero_in_band"] else "band excludes 0: model error"
        head = (f"E = S - D = {row['E']:.3g}, E \u00b1 {k:g} u_val = [{row['band'][0]:.3g}, {row['band'][1]:.3g}] "
                f"({verdict})")
    else:
        head = f"no experiment: u_num = {row['u_num']:.3g}"
    ax.set_title(textwrap.fill(row["name"], 90) + "\n" + textwrap.fill(head, 90), fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(0.0, -0.2), frameon=False, ncol=2)
    return _save(fig, out, f"vv20-{index:02d}-{slug(row['name'])}.png", 80 if quick else 110)


def trend(t: dict, entries: list, out: Path, index: int, quick: bool = False):
    """One figure's value over the stored report runs (reports/history.py): loaded runs hollow, the band
    mean +- noise of the earlier runs, the latest run red when it is flagged."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 3.0))
    x, y, ld = np.asarray(t["runs"]), np.asarray(t["values"], dtype=float), np.asarray(t["loaded"], dtype=bool)
    ax.plot(x, y, "-", color="0.6", lw=0.8)
    if (~ld).any():
        ax.plot(x[~ld], y[~ld], "o", color="k", ms=4, label="run on a quiet machine")
    if ld.any():
        ax.plot(x[ld], y[ld], "o", mfc="none", color="tab:orange", ms=5, label="run on a loaded machine")
    ax.axhspan(t["mean"] - t["noise"], t["mean"] + t["noise"], color="tab:blue", alpha=0.15, lw=0,
               label="earlier runs' mean +- noise")
    if t["flagged"]:
        ax.plot(x[-1:], y[-1:], "o", color="tab:red", ms=7, label="latest: change beyond the noise")
    # Plain tick labels (no "1e-11 + 8.5e-3" offset), and a window of at least 0.1 % of the value, so that a
    # figure that did not move reads as a flat line at its value.
    ax.ticklabel_format(axis="y", useOffset=False)
    half = max(3 * t["noise"], 1e-3 * abs(t["mean"]), float(np.ptp(y)), 1e-12)
    ax.set_ylim(min(y.min(), t["mean"]) - half, max(y.max(), t["mean"]) + half)
    labels = [f"{k}\n{str(entries[k].get('commit', ''))[:7]}" for k in x]
    ax.set_xticks(x, labels, fontsize=6)
    ax.set_xlabel("report run (index, commit)")
    ax.set_title(textwrap.fill(t["key"], 95), fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
    return _save(fig, out, f"trend-{index:02d}-{slug(t['key'])[:80]}.png", 80 if quick else 110)
