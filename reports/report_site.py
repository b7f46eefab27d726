"""The report as a small static site: index.html (verdict and contents) and one page per part, every page with the
same navigation bar, inline styles, no scripts and no network. Sections are rendered by report_html.py."""
from __future__ import annotations

from html import escape

import report_html as H
from criteria import FAIL

STYLE = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:0 auto;max-width:1200px;
color:#222;padding:0 1em 2em}
nav{position:sticky;top:0;background:#fff;border-bottom:2px solid #ddd;padding:.4em 0;font-size:.9em;z-index:1}
nav a{margin-right:.9em;white-space:nowrap;text-decoration:none;color:#1565c0}nav a.here{font-weight:700;color:#222}
.banner{font-size:2.4em;font-weight:700;padding:.5em .8em;border-radius:8px;color:#fff;margin:.4em 0}
.banner small{font-size:.45em;font-weight:400;display:block}
.b-pass{background:#2e7d32}.b-fail{background:#c62828}.b-none{background:#757575}
.tw{overflow-x:auto;max-width:100%}
table{border-collapse:collapse;margin:.6em 0;font-size:.88em;max-width:100%}
th,td{border:1px solid #ccc;padding:.25em .5em;text-align:left;vertical-align:top;overflow-wrap:break-word}
th{background:#f0f0f0;overflow-wrap:normal}table.criteria td.crit{min-width:18em}
td.num,table.criteria td:first-child{white-space:nowrap}
tr.fail td{background:#fdecea}tr.notrun td{background:#f5f5f5;color:#666}
.r-pass{color:#2e7d32;font-weight:700}.r-fail{color:#c62828;font-weight:700}.r-notrun{color:#666}
.note{color:#555;font-size:.9em}.warn{color:#c62828;font-weight:700}
figure{margin:.8em 0}figure img{max-width:100%;border:1px solid #eee}
figcaption{font-size:.85em;color:#555}figcaption a{text-decoration:none;color:#999}
section{margin-top:1.5em;border-top:2px solid #ddd}
code{background:#f4f4f4;padding:0 .2em;overflow-wrap:anywhere}
ul.toc li{margin:.3em 0}
"""

# (file, title, one line on what the page holds)
PAGES = [
    ("index.html", "Verdict", "the verdict, the criteria by case and the failures"),
    ("validation.html", "Validation", "the paper's model beside the named model, V&V 20 uncertainty of every "
                                      "figure of merit, then each run of the cases"),
    ("verification.html", "Verification & convergence", "observed orders against theory, recorded figures"),
    ("speed.html", "Speed vs accuracy", "error against wall time across resolutions and sweeps"),
    ("stability.html", "Stability", "the stability maps of the sweeps"),
    ("performance.html", "Performance", "benchmarks of this run; the peer code as a dated recorded reference"),
    ("packing.html", "Packing", "the particle packing's tests (Colagrossi et al. 2012)"),
    ("provenance.html", "Provenance", "build, machine and inputs; the run file in ParaView"),
    ("traceability.html", "Traceability", "requirement -> criteria -> verdict"),
    ("history.html", "History", "every stored report run and the figures' trends"),
    ("criteria.html", "All criteria", "every criterion with its measured value, threshold and source"),
]

# The GoogleTest suites of the packing paper's tests (verification/packing/): shown on the packing page.
PACKING_GROUPS = ("PackingDynamics", "PackingGeometry", "LatticeStability", "LatticeStabilityNightly",
                  "TrapezoidalTank", "TrapezoidalTankNightly", "TrapezoidalTankRun", "ComplexTankRun",
                  "InitialState", "FixedWalls")


def _packing(test: str) -> bool:
    return test.split(".", 1)[0] in PACKING_GROUPS


HERE_CLASS = ' class="here"'


def nav(current: str) -> str:
    return "<nav>" + "".join(f'<a href="{f}"{HERE_CLASS if f == current else ""}>{escape(t)}</a>'
                             for f, t, _ in PAGES) + "</nav>"


def layout(current: str, title: str, body: str, report: dict) -> str:
    word = report.get("verdict", "")
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">'
            f"<title>{escape(title)} - SPH V&amp;V report ({escape(word)})</title><style>{STYLE}</style></head>"
            f"<body>{nav(current)}<h1>{escape(title)}</h1>{body}"
            f'<p class="note">Generated {escape(report["generated"])}; verdict {escape(word)}.</p></body></html>\n')


def _wrap(html: str) -> str:
    """Wide tables scroll inside their own box, never the page."""
    return html.replace("<table", '<div class="tw"><table').replace("</table>", "</table></div>")


def index(r: dict) -> str:
    found = set(map(id, r.get("findings", [])))
    failed = [c for c in r["criteria"] if c.outcome == FAIL and id(c) not in found]
    toc = "".join(f'<li><a href="{f}">{escape(t)}</a>: {escape(what)}</li>' for f, t, what in PAGES[1:])
    i = r["inputs"]
    return (H.banner(r["counts"], r["problems"], r.get("counts_paper"))
            + f'<p class="note">runs: <code>{escape(i["runs"])}</code> ({i["run_files"]} files) &middot; results: '
            f'<code>{escape(i["results"])}</code> ({i["result_files"]} files) &middot; criteria: '
            f'<code>{escape(i["criteria"])}</code>. Also: <a href="summary.json">summary.json</a>, '
            f'<a href="junit.xml">junit.xml</a>.</p>'
            f'<section><h2>Contents</h2><ul class="toc">{toc}</ul></section>'
            f"<section><h2>Failed criteria ({len(failed)})</h2>"
            + (H.summary_table(failed) if failed else '<p class="r-pass">none</p>')
            + '<p class="note">Every criterion: <a href="criteria.html">All criteria</a>.</p></section>'
            + (f"<section><h2>Findings: the paper's model's failed criteria ({len(r['findings'])})</h2>"
               '<p class="note">The paper\'s model where the named model runs too: shown, not in the verdict; the '
               'two models side by side on the <a href="validation.html">Validation</a> page.</p>'
               + H.summary_table(r["findings"]) + "</section>" if r.get("findings") else "")
            + f"<section><h2>Criteria by case</h2>{H.case_tally(r['criteria'])}</section>")


def pages(r: dict) -> dict:
    """{file name: html} of the whole site."""
    conv = [e for e in r["convergence"] if not _packing(e["test"])]
    pconv = [e for e in r["convergence"] if _packing(e["test"])]
    figs = [f for f in r["figures"] if not _packing(f["test"])]
    pfigs = [f for f in r["figures"] if _packing(f["test"])]
    hist = [g for g in r.get("histories", []) if not _packing(g["test"])]
    phist = [g for g in r.get("histories", []) if _packing(g["test"])]
    pcrit = [c for c in r["criteria"] if c.kind == "verification" and _packing(c.case)]
    cases = "".join(H.case_section(c) for c in r["cases"]) or '<p class="note">not run: no run files.</p>'
    this = (r.get("history") or {}).get("this") or {}
    load = ""
    if this:
        load = (f'<p class="{"warn" if this.get("loaded") else "note"}">This run: load average '
                f'{H._g(this.get("load_start"), "{:.2f}")} at the start, {H._g(this.get("load_end"), "{:.2f}")} at '
                f'the end, {this.get("nproc")} processors: '
                + ("<b>a loaded machine</b> (load above half the processors): its timings are not a measurement of "
                   "the code." if this.get("loaded") else "a quiet machine.") + "</p>")
    body = {
        "index.html": index(r),
        "validation.html": (f"<section><h2>The paper's model and the named model</h2>"
                            f"{H.models_side_by_side(r['criteria'])}</section>"
                            f"<section><h2>Validation uncertainty (ASME V&amp;V 20)</h2>{H.vv20(r.get('uncertainty', []))}"
                            + "".join(H._img(u.get("figure"), u["name"]) for u in r.get("uncertainty", []))
                            + f"</section><section><h2>Validation cases</h2>{cases}</section>"),
        "verification.html": (f"<section><h2>Convergence</h2>{H.convergence(conv)}</section>"
                              f"<section><h2>Recorded figures</h2>{H.figures(figs)}</section>"
                              f"<section><h2>Recorded histories</h2>{H.histories(hist)}</section>"),
        "speed.html": H.speed_accuracy(r["speed_accuracy"]),
        "stability.html": H.stability(r["stability"]),
        "performance.html": load + H.performance(r["performance"]),
        "packing.html": (f"<section><h2>Criteria of the packing tests</h2>"
                         + (H.summary_table(pcrit) if pcrit else '<p class="note">not run: no packing results.</p>')
                         + f"</section><section><h2>Convergence</h2>{H.convergence(pconv)}</section>"
                         f"<section><h2>Recorded figures</h2>{H.figures(pfigs)}</section>"
                         f"<section><h2>Recorded histories</h2>{H.histories(phist)}</section>"),
        "provenance.html": (f"<section><h2>Build and machine</h2>{H.environment(r['environment'])}</section>"
                            f"<section><h2>The run file in ParaView</h2>{H.paraview(r.get('paraview'))}</section>"),
        "traceability.html": H.traceability(r["traceability"]),
        "history.html": H.history(r.get("history")),
        "criteria.html": H.case_tally(r["criteria"]) + H.summary_table(r["criteria"]),
    }
    titles = {f: t for f, t, _ in PAGES}
    titles["index.html"] = "SPH verification & validation report"
    return {f: layout(f, titles[f], _wrap(html), r) for f, html in body.items()}
