"""The report's sections as HTML fragments (site.py puts them on pages). Images are PNG files beside the pages.
(Not named html.py, which would shadow the standard library's html module.)"""
from __future__ import annotations

import re
from html import escape

from criteria import FAIL, NOT_RUN, PASS
from runfile import NAMED, PAPER




def _fmt(v) -> str:
    if v is None:
        return "&mdash;"
    if isinstance(v, float):
        return f"{v:.4g}"
    return escape(str(v))


def anchor(name: str) -> str:
    """The id of a figure: its file name without the suffix (file names are slugs, plots.slug)."""
    return "fig-" + re.sub(r"[^A-Za-z0-9_-]+", "-", str(name).rsplit(".", 1)[0])


def _img(name, alt) -> str:
    """A figure with its own anchor and a link to it, so that every figure can be linked to."""
    if not name:
        return ""
    fid = anchor(name)
    return (f'<figure id="{fid}"><img src="{escape(name)}" alt="{escape(alt)}">'
            f'<figcaption><a href="#{fid}" title="link to this figure">#</a> {escape(alt)}</figcaption></figure>')


def _fig(name, alt, _kind="") -> str:
    return _img(name, alt)


def _notes(notes) -> str:
    return "".join(f'<p class="note">{escape(n)}</p>' for n in notes)


def banner(c: dict, problems: list, paper: dict | None = None) -> str:
    """The verdict on `c` (the named model's criteria and the verification tests'); `paper`, the paper's model's
    tally where the named model runs too, is shown under it and decides nothing."""
    if c["failed"] or problems:
        cls, word = "b-fail", "FAIL"
    elif c["passed"]:
        cls, word = "b-pass", "PASS"
    else:
        cls, word = "b-none", "NOT RUN"
    detail = f"{c['passed']} passed, {c['failed']} failed, {c['not_run']} not run, of {c['total']} criteria"
    if paper and paper.get("total"):
        detail = (f"the named model and the verification tests: {detail}<br>the paper's model (findings, not in the "
                  f"verdict): {paper['passed']} passed, {paper['failed']} failed, {paper['not_run']} not run")
    extra = "".join(f'<p class="warn">{escape(p)}</p>' for p in problems)
    return f'<div class="banner {cls}">{word}<small>{detail}</small></div>{extra}'


def _twin(text: str) -> str:
    """A run or check name with the named model's tag taken off every run in it (issue 31)."""
    return re.sub(r"_named(?=$|[ :/])", "", str(text))


def _pair_key(c) -> tuple:
    if c.kind == "validation":  # a criteria.toml criterion or the run status, on one run file
        return (c.family, "run", _twin(c.run).rsplit("/", 1)[-1], c.metric, c.comparison)  # quick/x -> x
    run, _, what = c.metric.partition(": ")  # validate.py: "<run>: <figure of merit>"
    return (c.family, _twin(c.case), _twin(run), what, c.comparison)


def model_rows(criteria: list) -> dict:
    """{validation case: [{"key", "paper", "named"}]}: each criterion of the paper's model beside the named model's
    criterion on the twin run (<run>_named) with the same figure of merit; either may be missing."""
    cases: dict = {}
    for c in criteria:
        if c.model not in (PAPER, NAMED):
            continue
        rows = cases.setdefault(c.family or c.case, {})
        row = rows.setdefault(_pair_key(c), {"key": _pair_key(c), PAPER: None, NAMED: None})
        row[c.model] = row[c.model] or c
    return {k: sorted(v.values(), key=lambda r: (r["key"][2], r["key"][1] != "run", r["key"][3]))
            for k, v in sorted(cases.items())}


def _measured(c) -> str:
    if c is None:
        return '<td class="r-notrun">&mdash;</td>'
    cls = {FAIL: "r-fail", NOT_RUN: "r-notrun", PASS: "r-pass"}[c.outcome]
    return (f'<td class="num" title="{escape(c.message, quote=True)}">{_fmt(c.measured)} '
            f'<span class="{cls}">{escape(c.outcome.upper())}</span></td>')


def models_side_by_side(criteria: list) -> str:
    """Per validation case, one row per criterion: measured with the paper's model and with the named model, the
    threshold and its source. The named model's result is the one the verdict counts; a case without named-model
    runs is judged on the paper's rows (criteria.judged)."""
    parts = []
    for case, rows in model_rows(criteria).items():
        has_named = any(r[NAMED] for r in rows)
        body = []
        for r in rows:
            p, n = r[PAPER], r[NAMED]
            judged = n if has_named else p
            c = n or p
            cls = "fail" if judged is not None and judged.outcome == FAIL else ""
            what = c.metric.partition(": ")[2] if c.kind != "validation" else c.metric
            where = "run file, validation/criteria.toml" if c.kind == "validation" else f"validate.py, {_twin(c.case)}"
            run = _twin(r["key"][2])
            if p is not None and n is not None and (p.threshold, p.source) != (n.threshold, n.source):
                thr = (f"paper: {escape(p.comparison)} {_fmt(p.threshold)}<br>named: {escape(n.comparison)} "
                       f"{_fmt(n.threshold)}")
                src = f"paper: {escape(p.source)}<br>named: {escape(n.source)}"
            else:
                thr, src = f"{escape(c.comparison)} {_fmt(c.threshold)}", escape(c.source)
            body.append(f'<tr class="{cls}"><td>{escape(run)}</td><td class="crit">{escape(what)}'
                        f'<br><span class="note">{escape(where)}</span></td>{_measured(p)}{_measured(n)}'
                        f'<td class="num">{thr}</td><td>{src}</td></tr>')
        note = ("the named model's column is the verdict's; the paper's failures are findings" if has_named else
                "no named-model run in this case: the paper's model is its model and its rows are the verdict's")
        parts.append(f"<h3>{escape(case)}</h3><p class=\"note\">{note}.</p>"
                     '<table class="criteria models"><tr><th>run (paper; named: <code>&lt;run&gt;_named</code>)</th>'
                     "<th>criterion</th><th>measured, paper's model</th><th>measured, named model</th>"
                     f"<th>threshold</th><th>source</th></tr>{''.join(body)}</table>")
    if not parts:
        return '<p class="note">not run: no validation run files or checks.</p>'
    return ('<p class="note">The paper\'s model: Lobovsky &amp; Kren (2008) as published. The named model: the same '
            "scenes with Fourtakas et al. (2019) density diffusion (delta 0.1) and the Wendland C2 kernel at h/dx 2 "
            "(validation/make_variants.py, NAMED); each run file's kernel and terms are on its page below.</p>"
            + "".join(parts))


def case_tally(criteria: list) -> str:
    """One line per case: how many of its criteria passed, failed, were not run (failing cases first)."""
    tally: dict = {}
    for c in criteria:
        t = tally.setdefault(c.case + (f" ({c.model}'s model)" if c.model == PAPER else
                                       " (named model)" if c.model == NAMED else ""), {PASS: 0, FAIL: 0, NOT_RUN: 0})
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
        crit = e.get("criterion")
        if crit:
            word = '<span class="r-pass">PASS</span>' if crit.get("pass") else '<span class="r-fail">FAIL</span>'
            decided = (f"{word} criterion: {escape(str(crit['name']))}: {_fmt(crit.get('measured'))} "
                       f"{escape(str(crit.get('comparison')))} {_fmt(crit.get('threshold'))}")
        else:
            decided = '<span class="r-notrun">no criterion</span>: a finding, reported as measured'
        parts.append(f"<h3>{escape(e['test'])}: {escape(e['name'])}</h3>"
                     f"<p>{decided}<br>fitted slope <b>{fitted}</b> &nbsp; theory <b>{_fmt(e['theory_order'])}</b> "
                     f"&nbsp; (the test reported {_fmt(e['observed_order'])}; {escape(str(e['source']))})</p>"
                     + _img(e.get("figure"), e["name"]))
    return "".join(parts)


def _g(v, fmt="{:.4g}") -> str:
    return "&mdash;" if v is None else fmt.format(v)


def vv20(rows: list) -> str:
    """The V&V 20 table (reports/uncertainty.py): one row per figure of merit with three resolutions."""
    if not rows:
        return ('<p class="note">not run: no figure of merit at three resolutions in the verification results '
                "(validate.py writes them from the nightly tier's runs).</p>")
    head = ("<tr><th>#</th><th>figure of merit</th><th>h: S</th><th>convergence, p</th><th>S<sub>ext</sub></th>"
            "<th>GCI<sub>fine</sub></th><th>asympt. ratio</th><th>u<sub>num</sub></th><th>D</th><th>u<sub>D</sub></th>"
            "<th>u<sub>val</sub></th><th>E = S &minus; D</th><th>E &plusmn; 2u<sub>val</sub></th></tr>")
    body, notes = [], []
    for n, r in enumerate(rows, 1):
        if r.get("error"):
            body.append(f'<tr class="fail"><td>{n}</td><td>{escape(r["name"])}</td>'
                        f'<td colspan="11" class="warn">{escape(r["error"])}</td></tr>')
            continue
        st = r["study"]
        hs = "<br>".join(f"{h:.4g}: {v:.4g}" for h, v in zip(st["h"], st["phi"]))
        kind = escape(st["kind"]) + ("" if st["p"] is None else f", p = {st['p']:.2f}")
        cls = "" if r["zero_in_band"] in (None, True) else ' class="fail"'
        band = "&mdash;" if r["band"] is None else (
            f"[{r['band'][0]:.3g}, {r['band'][1]:.3g}]<br>"
            + ('<span class="r-pass">holds 0</span>' if r["zero_in_band"] else '<span class="r-fail">excludes 0</span>'))
        body.append(f"<tr{cls}><td>{n}</td><td>{escape(r['name'])}<br><span class=\"note\">{escape(r['test'])}</span></td>"
                    f"<td class=\"num\">{hs}</td><td>{kind}</td><td>{_g(st['phi_ext'])}</td>"
                    f"<td>{_g(st['gci_fine21'] and 100 * st['gci_fine21'], '{:.2g} %')}</td>"
                    f"<td>{_g(st['asymptotic_ratio'], '{:.3g}')}</td>"
                    f"<td>{_g(r['u_num'], '{:.3g}')}<br><span class=\"note\">{escape(r['u_num_basis'])}</span></td>"
                    f"<td>{_g(r['D'])}</td><td>{_g(r['u_D'], '{:.3g}')}</td><td>{_g(r['u_val'], '{:.3g}')}</td>"
                    f"<td>{_g(r['E'], '{:+.3g}')}</td><td>{band}</td></tr>")
        notes.append(f"<li>#{n}: D: {escape(r['D_source'])}" + (f"; u<sub>D</sub>: {escape(r['u_D_source'])}"
                                                                 if r["u_D_source"] else "") + "</li>")
    u_input = sorted({r["u_input_source"] for r in rows if r.get("u_input_source")})
    return ('<p>ASME V&amp;V 20-2009 with the numerical part from Celik et al. (2008): S the finest run, GCI with '
            'F<sub>s</sub> = 1.25, u<sub>num</sub> = GCI/1.15 (oscillatory: at least half the data range; divergent: '
            'the data range, no GCI), u<sub>val</sub> = (u<sub>num</sub>&sup2; + u<sub>input</sub>&sup2; + '
            'u<sub>D</sub>&sup2;)<sup>1/2</sup>, k = 2 (about 95 % for a near-normal error). Asymptotic ratio: '
            'GCI<sub>32</sub> / (r<sub>21</sub><sup>p</sup> GCI<sub>21</sub>), near 1 in the asymptotic range. '
            'A band that excludes 0 is a model error this study resolves; one that holds it, an error below what '
            'the uncertainties can separate.</p>'
            f'<table class="vv20">{head}{"".join(body)}</table><ul class="note">{"".join(notes)}</ul>'
            + "".join(f'<p class="note">u<sub>input</sub> = {escape(u)}.</p>' for u in u_input))


def traceability(m: dict) -> str:
    """Requirement -> criteria -> verdict (reports/traceability.py)."""
    rows = []
    for r in m["rows"]:
        cls = {"FAIL": "fail", "PASS": "pass", "NOT RUN": "notrun", "NO RECORD": "notrun"}[r["verdict"]]
        rcls = {"FAIL": "r-fail", "PASS": "r-pass", "NOT RUN": "r-notrun", "NO RECORD": "r-notrun"}[r["verdict"]]
        rows.append(f'<tr class="{cls}" id="{escape(r["id"])}"><td class="{rcls}">{escape(r["verdict"])}</td>'
                    f'<td class="num">{escape(r["id"])}</td><td>{escape(r["requirement"])}<br>'
                    f'<span class="note">source: {escape(str(r["source"]))}</span></td>'
                    f'<td class="num">{r["passed"]} / {r["failed"]} / {r["not_run"]}</td></tr>')
    untraced = m.get("untraced") or []
    warn = (f'<p class="warn">{len(untraced)} criteria trace to no requirement: '
            + escape("; ".join(untraced[:10])) + (" ..." if len(untraced) > 10 else "") + "</p>") if untraced else ""
    return ('<p class="note">Requirement IDs: validation/criteria.toml (each criterion) and '
            'verification/requirements.toml (each test group). Criteria: passed / failed / not run. '
            "NO RECORD: no result file of the group's tests reached the report (ctest runs them and decides them by "
            "their exit code; they record no checks the report could re-check).</p>" + warn
            + '<table class="trace"><tr><th>verdict</th><th>ID</th><th>requirement</th><th>criteria</th></tr>'
            + "".join(rows) + "</table>")


LOADED_ROW = ' class="notrun"'


def history(h: dict) -> str:
    """The results database's runs and the figures' trends (reports/history.py)."""
    if not h:
        return '<p class="note">not run.</p>'
    where = (f"<code>{escape(h['path'])}</code>" if h.get("path")
             else "none named (<code>--history FILE</code>): this run alone, not stored")
    rows = "".join(
        f"<tr{LOADED_ROW if e.get('loaded') else ''}><td>{k}</td><td>{escape(str(e.get('date')))}</td>"
        f"<td><code>{escape(str(e.get('commit')))[:12]}</code></td><td>{escape(str(e.get('build_type')))}</td>"
        f"<td>{escape(str(e.get('hostname')))}</td><td>{e.get('nproc')}</td>"
        f"<td>{_g(e.get('load_start'), '{:.2f}')} / {_g(e.get('load_end'), '{:.2f}')}</td>"
        f"<td>{'<b>loaded</b>' if e.get('loaded') else 'quiet'}</td><td>{escape(str(e.get('verdict')))}</td></tr>"
        for k, e in enumerate(h.get("runs", [])))
    trends = h.get("trends", [])
    flagged = [t for t in trends if t["flagged"]]
    ftable = "".join(f"<tr class='fail'><td>{escape(t['key'])}</td><td>{_g(t['mean'])}</td><td>{_g(t['noise'], '{:.3g}')}</td>"
                     f"<td>{_g(t['latest'])}</td><td>{_g(t['change'], '{:+.3g}')}</td></tr>" for t in flagged)
    parts = [f"<p>Database: {where}. A run is <b>loaded</b> when the 1-minute load average at its start or end "
             "exceeds half the processor count (reports/history.py); its figures are drawn hollow and left out of "
             "the noise. Noise of a figure: 3 standard deviations of its earlier quiet runs, at least a floor of "
             "1e-9 relative (results are bitwise reproducible) or 20 % for wall times.</p>",
             f'<table><tr><th>#</th><th>date</th><th>commit</th><th>build</th><th>host</th><th>nproc</th>'
             f"<th>load start / end</th><th>machine</th><th>verdict</th></tr>{rows}</table>"]
    parts += [f'<p class="warn">{escape(p)}</p>' for p in h.get("problems", [])]
    if len(h.get("runs", [])) < 2:
        parts.append('<p class="note">One stored run: no trend yet.</p>')
    else:
        parts.append(f"<p>{len(trends)} figures tracked over the stored runs; <b>{len(flagged)}</b> changed beyond "
                     "their noise in the latest run.</p>")
    if flagged:
        parts.append("<table><tr><th>figure</th><th>earlier mean</th><th>noise</th><th>latest</th><th>change</th>"
                     f"</tr>{ftable}</table>")
    for t in trends:
        if t.get("figure"):
            parts.append(_fig(t["figure"], t["key"], "trend"))
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
        rows = "".join(f"<tr><td>{escape(p['run'])}</td><td>{escape(p['method']).replace(',', ',<wbr>')}</td><td>{_fmt(p['particles'])}</td>"
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
            refs = [x for x in b["data"].get("series", []) if isinstance(x, dict) and x.get("recorded")]
            recorded = "".join(f'<p class="note">{escape(str(x.get("label")))}: a recorded reference '
                               f'({escape(str(x["recorded"]))}), not measured by this run.</p>' for x in refs)
            parts.append(f"<h3>{escape(str(b['title']))}</h3>" + recorded + _img(b["figure"], b["title"])
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
    """The run files as ParaView shows them (paraview_view.py): the dam break, then each other run opened."""
    if item is None:
        return '<p class="note">not run: no --paraview directory (the nightly test ' \
               'paraview.DamBreakOpensWithDefaultReader writes one).</p>'
    return "".join(paraview_one(i) for i in [item, *(item.get("others") or [])])


def paraview_one(item: dict) -> str:
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
