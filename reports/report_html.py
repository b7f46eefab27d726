"""index.html from the assembled report: inline styles, images as PNG files beside it, no scripts, no network.
(Not named html.py, which would shadow the standard library's html module.)"""
from __future__ import annotations

from html import escape

from criteria import FAIL, NOT_RUN, PASS

STYLE = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:1.5em auto;max-width:1200px;
color:#222;padding:0 1em}
.banner{font-size:2.4em;font-weight:700;padding:.5em .8em;border-radius:8px;color:#fff;margin-bottom:.4em}
.banner small{font-size:.45em;font-weight:400;display:block}
.b-pass{background:#2e7d32}.b-fail{background:#c62828}.b-none{background:#757575}
table{border-collapse:collapse;margin:.6em 0;font-size:.88em;max-width:100%}
th,td{border:1px solid #ccc;padding:.25em .5em;text-align:left;vertical-align:top;overflow-wrap:anywhere}
th{overflow-wrap:normal}table.criteria td.crit{min-width:18em}
table.criteria td.num,table.criteria td:first-child{white-space:nowrap;overflow-wrap:normal}
th{background:#f0f0f0}
tr.fail td{background:#fdecea}tr.notrun td{background:#f5f5f5;color:#666}
.r-pass{color:#2e7d32;font-weight:700}.r-fail{color:#c62828;font-weight:700}.r-notrun{color:#666}
.note{color:#555;font-size:.9em}.warn{color:#c62828;font-weight:700}
img{max-width:100%;border:1px solid #eee;margin:.3em 0}
section{margin-top:2em;border-top:2px solid #ddd}
code{background:#f4f4f4;padding:0 .2em}
"""


def _fmt(v) -> str:
    if v is None:
        return "&mdash;"
    if isinstance(v, float):
        return f"{v:.4g}"
    return escape(str(v))


def _img(name, alt) -> str:
    return f'<p><img src="{escape(name)}" alt="{escape(alt)}"></p>' if name else ""


def _notes(notes) -> str:
    return "".join(f'<p class="note">{escape(n)}</p>' for n in notes)


def banner(c: dict, problems: list) -> str:
    if c["failed"] or problems:
        cls, word = "b-fail", "FAIL"
    elif c["passed"]:
        cls, word = "b-pass", "PASS"
    else:
        cls, word = "b-none", "NOT RUN"
    detail = f"{c['passed']} passed, {c['failed']} failed, {c['not_run']} not run, of {c['total']} criteria"
    extra = "".join(f'<p class="warn">{escape(p)}</p>' for p in problems)
    return f'<div class="banner {cls}">{word}<small>{detail}</small></div>{extra}'


def case_tally(criteria: list) -> str:
    """One line per case: how many of its criteria passed, failed, were not run (failing cases first)."""
    tally: dict = {}
    for c in criteria:
        t = tally.setdefault(c.case, {PASS: 0, FAIL: 0, NOT_RUN: 0})
        t[c.outcome] += 1
    order = sorted(tally, key=lambda k: (-tally[k][FAIL], -tally[k][NOT_RUN], k))
    rows = "".join(
        f'<tr class="{"fail" if tally[k][FAIL] else "pass"}"><td>{escape(k)}</td><td>{tally[k][PASS]}</td>'
        f'<td class="{"r-fail" if tally[k][FAIL] else ""}">{tally[k][FAIL]}</td><td>{tally[k][NOT_RUN]}</td></tr>'
        for k in order)
    return ("<table><tr><th>case</th><th>passed</th><th>failed</th><th>not run</th></tr>" + rows + "</table>"
            if rows else "")


def summary_table(criteria: list) -> str:
    rows = []
    for c in criteria:
        cls = {FAIL: "fail", NOT_RUN: "notrun", PASS: "pass"}[c.outcome]
        title = escape(c.message, quote=True)
        detail = f'<br><span class="note">{escape(c.message)}</span>' if c.outcome == FAIL else ""
        run = f'<br><span class="note">{escape(c.run)}</span>' if c.run else ""
        rows.append(
            f'<tr class="{cls}" title="{title}"><td class="r-{cls}">{escape(c.outcome.upper())}</td>'
            f"<td>{escape(c.case)}{run}</td><td class=\"crit\">{escape(c.metric)}{detail}</td>"
            f'<td class="num">{_fmt(c.measured)}</td><td class="num">{escape(c.comparison)} {_fmt(c.threshold)}</td>'
            f'<td>{escape(c.source)}</td><td class="num">{_fmt(c.run_time_s)}</td></tr>')
    head = ("<tr><th>result</th><th>case (run / result file)</th><th>criterion</th><th>measured</th>"
            "<th>threshold</th><th>source</th><th>run time [s]</th></tr>")
    return f'<table class="criteria">{head}{"".join(rows)}</table>' if rows else '<p class="note">No criteria.</p>'


def environment(env: dict) -> str:
    if not env["rows"]:
        return '<p class="note">not run: no readable run file.</p>'
    rows = []
    for r in env["rows"]:
        if r["per_run"] is None:
            value = escape(str(r["value"]))
        else:
            value = "<br>".join(f"{escape(k)}: {escape(v)}" for k, v in sorted(r["per_run"].items()))
        rows.append(f"<tr><th>{escape(r['attribute'])}</th><td>{value}</td></tr>")
    total = env["total_wall_time_s"]
    rows.append(f"<tr><th>total wall time of the {env['runs']} runs [s]</th><td>{_fmt(total)}</td></tr>")
    return f"<table>{''.join(rows)}</table><p class=\"note\">Read from the run files' root attributes and /metrics.</p>"


def case_section(case: dict) -> str:
    parts = [f"<h3>{escape(case['title'])}</h3>"]
    if case.get("not_run"):
        return parts[0] + '<p class="r-notrun">not run: no run file of this scene.</p>'
    a = case["attrs"]
    facts = [("scene", a.get("scene_name")), ("scene file", a.get("scene_file")), ("file", case["path"]),
             ("dimension", a.get("dimension")), ("kernel", a.get("kernel")), ("terms", a.get("terms")),
             ("status", a.get("status")), ("failure cause", a.get("failure_cause")), ("failure", a.get("failure"))]
    facts += [(f"/metrics/{k}", v) for k, v in sorted(case["metrics"].items())]
    parts.append("<table>" + "".join(f"<tr><th>{escape(k)}</th><td>{_fmt(v)}</td></tr>"
                                      for k, v in facts if v not in (None, "")) + "</table>")
    if case.get("read_error"):
        parts.append(f'<p class="warn">{escape(case["read_error"])}</p>')
    for fig, alt in case["figures"]:
        parts.append(_img(fig, alt))
    parts.append(_notes(case["notes"]))
    return "".join(parts)


def convergence(entries: list) -> str:
    if not entries:
        return '<p class="note">not run: no convergence entries in the verification results.</p>'
    parts = []
    for e in entries:
        fitted = "&mdash;" if e["fitted_order"] is None else f"{e['fitted_order']:.2f}"
        parts.append(f"<h3>{escape(e['test'])}: {escape(e['name'])}</h3>"
                     f"<p>fitted slope <b>{fitted}</b> &nbsp; theory <b>{_fmt(e['theory_order'])}</b> &nbsp; "
                     f"(the test reported {_fmt(e['observed_order'])}; {escape(str(e['source']))})</p>"
                     + _img(e.get("figure"), e["name"]))
    return "".join(parts)


def figures(items: list) -> str:
    if not items:
        return '<p class="note">none recorded.</p>'
    rows = "".join(f"<tr><td>{escape(f['test'])}</td><td>{escape(f['name'])}</td><td>{_fmt(f['measured'])}</td>"
                   f"<td>{escape(f['source'])}</td></tr>" for f in items)
    return ('<p class="note">Measured and reported without a threshold: findings, not criteria.</p>'
            f"<table><tr><th>test</th><th>figure</th><th>measured</th><th>source</th></tr>{rows}</table>")


def histories(groups: list) -> str:
    if not groups:
        return '<p class="note">none recorded.</p>'
    parts = []
    for g in groups:
        sources = "; ".join(sorted({c["source"] for c in g["curves"] if c["source"]}))
        parts.append(f"<h3>{escape(g['test'])}: {escape(g['y_label'])}</h3>"
                     + (f'<p class="note">{escape(sources)}</p>' if sources else "")
                     + _img(g.get("figure"), g["y_label"]))
    return '<p class="note">Measured curves, reported without a threshold.</p>' + "".join(parts)


def speed_accuracy(items: dict) -> str:
    if not items:
        return ('<p class="note">not run: no scene has runs at two or more resolutions '
                "(scene names like <code>dam_break_dx0.005</code>).</p>")
    parts = []
    for case, d in items.items():
        swept = any("outcome" in p for p in d["points"])  # stability-sweep points carry their outcome
        rows = "".join(f"<tr><td>{escape(p['run'])}</td><td>{escape(p['method'])}</td><td>{_fmt(p['particles'])}</td>"
                       f"<td>{_fmt(p['wall_time_s'])}</td><td>{_fmt(p['error'])}</td>"
                       + (f"<td>{escape(str(p.get('outcome')))} {escape(str(p.get('cause') or ''))}</td>" if swept else "")
                       + "</tr>" for p in d["points"])
        parts.append(f"<h3>{escape(case)}</h3><p class=\"note\">error: {escape(d['error'])}</p>"
                     + _img(d.get("figure"), case)
                     + "<table><tr><th>run</th><th>method (kernel [terms])</th><th>particles</th>"
                     f"<th>wall time [s]</th><th>error</th>{'<th>outcome</th>' if swept else ''}</tr>{rows}</table>")
    return "".join(parts)


def stability(items: list) -> str:
    if not items:
        return '<p class="note">not run: no --stability directory with sweep results.</p>'
    parts = []
    for s in items:
        if s.get("error"):
            parts.append(f'<p class="warn">{escape(s["path"])}: {escape(s["error"])}</p>')
            continue
        counts = ", ".join(f"{k}: {v}" for k, v in s["counts"].items())
        causes = sorted({str(p.get("cause")) for p in s["points"] if p.get("cause")})
        parts.append(f"<h3>{escape(str(s['sweep']))}</h3><p>{escape(counts)}</p>" + _img(s.get("figure"), s["sweep"])
                     + (f'<p class="note">causes: {escape(", ".join(causes))}</p>' if causes else ""))
    return "".join(parts)


def performance(items: list) -> str:
    if not items:
        return '<p class="note">not run: no --perf directory with benchmark results.</p>'
    parts = []
    for b in items:
        if b.get("error"):
            parts.append(f'<p class="warn">{escape(b["path"])}: {escape(b["error"])}</p>')
        elif b.get("figure"):
            parts.append(f"<h3>{escape(str(b['title']))}</h3>" + _img(b["figure"], b["title"])
                         + (f'<p class="note">{escape(str(b["source"]))}</p>' if b.get("source") else ""))
        else:
            rows = "".join("<tr>" + "".join(f"<td>{_fmt(r.get(k))}</td>" for k in b["columns"]) + "</tr>"
                           for r in b["rows"])
            head = "".join(f"<th>{escape(k)}</th>" for k in b["columns"])
            ctx = "; ".join(f"{k}: {v}" for k, v in b.get("context", {}).items())
            parts.append(f"<h3>{escape(str(b['title']))}</h3><table><tr>{head}</tr>{rows}</table>"
                         + (f'<p class="note">{escape(ctx)}</p>' if ctx else ""))
    return "".join(parts)


def _span(values: list) -> str:
    return f"{min(values)} .. {max(values)}" if values else "none"


def paraview(item: dict | None) -> str:
    """The run file as ParaView shows it (paraview_view.py)."""
    if item is None:
        return '<p class="note">not run: no --paraview directory (the nightly test ' \
               'paraview.DamBreakOpensWithDefaultReader writes one).</p>'
    if not item.get("cells_per_step") and item.get("error"):
        return f'<p class="warn">{escape(item["error"])}</p>'
    failures = item.get("failures") or []
    word, cls = ("FAIL", "r-fail") if failures or item.get("error") else ("PASS", "r-pass")
    rows = [("run file", f"<code>{escape(str(item.get('xdmf', '')))}</code>"),
            ("ParaView, reader chosen by OpenDataFile", escape(f"{item.get('paraview')}, {item.get('reader')}")),
            ("time steps", _fmt(item.get("time_steps"))),
            ("points a step", escape(_span(item.get("points_per_step") or []))),
            ("cells a step", escape(_span(item["cells_per_step"]))),
            ("cells a step, legacy XDMFReader", escape(_span(item.get("legacy_reader_cells_per_step") or []))),
            ("point arrays", escape(", ".join(item.get("arrays") or [])))]
    table = "".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in rows)
    caption = (f"the snapshot at t = {_fmt(item.get('picture_time'))} s as pvpython draws it, points coloured by "
               "pressure [Pa] over its 2nd to 98th percentile")
    warn = "".join(f'<p class="warn">{escape(f)}</p>' for f in failures + ([item["error"]] if item.get("error")
                                                                                 else []))
    return (f'<p>Opened with ParaView\'s default reader: <span class="{cls}">{word}</span> '
            '(validation/paraview/open_in_paraview.py: every step\'s points, cells and arrays against the run '
            f'file).</p><table>{table}</table>{warn}' + _img(item.get("figure"), caption)
            + f'<p class="note">{escape(caption)}.</p>')


def page(report: dict) -> str:
    r = report
    cases = "".join(case_section(c) for c in r["cases"]) or '<p class="note">not run: no run files.</p>'
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>SPH V&amp;V report</title><style>{STYLE}</style></head>
<body>
<h1>SPH verification &amp; validation report</h1>
{banner(r['counts'], r['problems'])}
<p class="note">runs: <code>{escape(r['inputs']['runs'])}</code> ({r['inputs']['run_files']} files) &middot;
results: <code>{escape(r['inputs']['results'])}</code> ({r['inputs']['result_files']} files) &middot;
criteria: <code>{escape(r['inputs']['criteria'])}</code> &middot; generated {escape(r['generated'])}.
Also: <a href="summary.json">summary.json</a>, <a href="junit.xml">junit.xml</a>.</p>
<section><h2>Criteria</h2>{case_tally(r['criteria'])}{summary_table(r['criteria'])}</section>
<section><h2>Environment</h2>{environment(r['environment'])}</section>
<section><h2>Validation cases</h2>{cases}</section>
<section><h2>Convergence (verification)</h2>{convergence(r['convergence'])}</section>
<section><h2>Recorded figures (verification)</h2>{figures(r['figures'])}</section>
<section><h2>Recorded histories (verification)</h2>{histories(r.get('histories', []))}</section>
<section><h2>Speed versus accuracy</h2>{speed_accuracy(r['speed_accuracy'])}</section>
<section><h2>Stability map</h2>{stability(r['stability'])}</section>
<section><h2>Performance</h2>{performance(r['performance'])}</section>
<section><h2>The run file in ParaView</h2>{paraview(r.get('paraview'))}</section>
</body></html>
"""
