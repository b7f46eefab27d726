"""Tests of the report code on small generated run files (tests/conftest.py)."""
import json
import re
import xml.etree.ElementTree as ET

import h5py
import matplotlib.image
import numpy as np
import numpy.testing as npt
import pytest

import analysis
import criteria
import history
import references
import vv_report
from conftest import GRAVITY
from runfile import family, read_run

A = 0.05  # column width of the synthetic dam break [m]


def front(t):
    return A * (1.0 + 0.4 * (t * np.sqrt(2 * GRAVITY / A)) ** 1.5)


def report(tmp_path, runs, results=None, *extra):
    out = tmp_path / "out"
    rc = vv_report.main(["--runs", str(runs), "--results", str(results or tmp_path / "no_results"),
                         "--out", str(out), "--quick", *extra])
    summary = json.loads((out / "summary.json").read_text())
    return rc, out, summary


def site_html(out):
    """Every page of the report, index first (reports/report_site.py)."""
    pages = sorted(out.glob("*.html"), key=lambda p: (p.name != "index.html", p.name))
    return "".join(p.read_text() for p in pages)


def images_exist(out):
    html = site_html(out)
    names = re.findall(r'<img src="([^"]+)"', html)
    for name in names:
        assert (out / name).is_file(), name
    return html, names


def by_run(summary, run):
    return {c["metric"]: c for c in summary["criteria"] if c["run"] == run}


def test_stable_passing_run(tmp_path, make_run):
    make_run(tmp_path / "runs" / "dam_break.h5", "dam_break", max_volume_variation=0.001,
             probes=[("surge_front", front, {"type": "front", "units": "m", "scale_length": A})])
    rc, out, summary = report(tmp_path, tmp_path / "runs")
    assert rc == 0
    html, names = images_exist(out)
    assert "dam_break-snapshots.png" in names and "dam_break-volume.png" in names
    assert "dam_break-probe-surge_front.png" in names
    assert "PASS" in html and not summary["problems"]
    assert summary["counts"] == {"total": 6, "passed": 2, "failed": 0, "not_run": 4}
    mine = by_run(summary, "dam_break")
    assert mine["status"]["outcome"] == "pass"
    npt.assert_allclose(mine["max_volume_variation"]["measured"], 0.001, rtol=0, atol=1e-15)
    npt.assert_allclose(mine["max_volume_variation"]["run_time_s"], 12.5, rtol=1e-12, atol=0)
    env = {r["attribute"]: r["value"] for r in summary["environment"]["rows"]}
    assert env["git_commit"] == "abc1234" and env["threads"] == "4"


def test_unstable_run_fails_and_exits_nonzero(tmp_path, make_run):
    make_run(tmp_path / "runs" / "drop_into_pool.h5", "drop_into_pool", status="unstable")
    rc, out, summary = report(tmp_path, tmp_path / "runs")
    assert rc != 0
    images_exist(out)
    status = by_run(summary, "drop_into_pool")["status"]
    assert status["outcome"] == "fail" and "nan" in status["message"]
    assert summary["counts"]["failed"] == 1
    assert summary["criteria"][0]["outcome"] == "fail"  # failures first
    assert "FAIL" in (out / "index.html").read_text()  # the verdict is on the index


def test_criterion_failure_exits_nonzero(tmp_path, make_run):
    make_run(tmp_path / "runs" / "sub" / "dam_break_dx0.01.h5", "dam_break_dx0.01", max_volume_variation=0.01)
    rc, out, summary = report(tmp_path, tmp_path / "runs")
    assert rc == 1
    vv = by_run(summary, "sub/dam_break_dx0.01")["max_volume_variation"]
    assert vv["case"] == "dam_break" and vv["outcome"] == "fail"
    assert summary["counts"] == {"total": 6, "passed": 1, "failed": 1, "not_run": 4}


def test_empty_directory_is_not_run(tmp_path):
    (tmp_path / "runs").mkdir()
    rc, out, summary = report(tmp_path, tmp_path / "runs")
    assert rc == 0
    html, names = images_exist(out)
    assert names == []
    n = sum(len(v) for v in criteria.load_criteria().values())
    assert summary["counts"] == {"total": n, "passed": 0, "failed": 0, "not_run": n}
    assert "NOT RUN" in html and "not run: no --stability" in html and "not run: no --perf" in html


def test_missing_directories_do_not_crash(tmp_path):
    rc, out, summary = report(tmp_path, tmp_path / "does_not_exist")
    assert rc == 0 and summary["inputs"]["run_files"] == 0


def test_junit_has_one_testcase_per_criterion(tmp_path, make_run, make_result):
    make_run(tmp_path / "runs" / "two_fluids.h5", "two_fluids", phases=("light", "heavy"), max_volume_variation=0.003)
    make_result(tmp_path / "results" / "Poiseuille.SteadyProfile.json")
    rc, out, summary = report(tmp_path, tmp_path / "runs", tmp_path / "results")
    assert rc == 1  # heavy phase: 0.003 > 0.002
    cases = list(ET.parse(out / "junit.xml").getroot().iter("testcase"))
    assert len(cases) == summary["counts"]["total"] == len(summary["criteria"])
    names = " ".join(c.get("name") for c in cases)
    assert "max_volume_variation_heavy < 0.002 | Lobovsky & Kren" in names
    assert "L2 error / v_max at dx = L/20 <= 0.03" in names
    failed = [c for c in cases if c.find("failure") is not None]
    assert len(failed) == summary["counts"]["failed"] == 1  # heavy 0.003 fails, light 0.0015 passes
    assert not summary["problems"]


def test_verification_recheck_disagreeing_with_the_test_fails(tmp_path, make_result):
    make_result(tmp_path / "results" / "A.B.json", test="A.B", measured=0.05, threshold=0.03, passed=True)
    (tmp_path / "results" / "broken.json").write_text("{not json")
    rc, out, summary = report(tmp_path, tmp_path / "runs", tmp_path / "results")
    assert rc == 1
    ver = [c for c in summary["criteria"] if c["kind"] == "verification"]
    assert {c["outcome"] for c in ver} == {"fail"} and len(ver) == 2
    assert any("re-check disagrees" in c["message"] for c in ver)


def test_convergence_fit_and_plot(tmp_path, make_result):
    make_result(tmp_path / "results" / "Poiseuille.SteadyProfile.json")
    rc, out, summary = report(tmp_path, tmp_path / "runs", tmp_path / "results")
    assert rc == 0
    (entry,) = summary["convergence"]
    npt.assert_allclose(entry["fitted_order"], 2.0, rtol=1e-9, atol=0)
    html, names = images_exist(out)
    assert entry["figure"] in names and "fitted slope <b>2.00</b>" in html


def test_speed_accuracy_uses_reference_error(tmp_path, make_run):
    attrs = {"type": "front", "units": "m", "scale_length": A}
    for dx, wall, kernel in ((0.01, 5.0, "cubic_spline"), (0.005, 40.0, "cubic_spline"), (0.01, 6.0, "wendland_c2")):
        name = f"dam_break_dx{dx}"
        make_run(tmp_path / "runs" / kernel / f"{name}.h5", name, wall_time_s=wall, kernel=kernel,
                 probes=[("surge_front", front, attrs)])
    rc, out, summary = report(tmp_path, tmp_path / "runs")
    sa = summary["speed_accuracy"]["dam_break"]
    assert "Martin & Moyce 1952" in sa["error"]
    assert len(sa["points"]) == 3 and all(p["error"] is not None for p in sa["points"])
    _, names = images_exist(out)
    assert sa["figure"] in names


def test_stability_and_perf_sections(tmp_path):
    (tmp_path / "stab").mkdir()
    (tmp_path / "perf").mkdir()
    (tmp_path / "stab" / "lattice.json").write_text(json.dumps(
        {"sweep": "Cartesian lattice, Wendland", "x_label": "h/dx", "y_label": "perturbation / dx",
         "points": [{"x": 0.8, "y": 0.01, "outcome": "stable"}, {"x": 3.2, "y": 0.01, "outcome": "unstable",
                                                                  "cause": "density_band"}]}))
    (tmp_path / "perf" / "scaling.json").write_text(json.dumps(
        {"benchmark": "force loop", "x_label": "threads", "y_label": "particle evaluations / s",
         "series": [{"label": "cubic_spline", "x": [1, 2, 4], "y": [1e6, 1.9e6, 3.5e6]}]}))
    (tmp_path / "perf" / "gbench.json").write_text(json.dumps(
        {"context": {"host_name": "h"}, "benchmarks": [{"name": "BM_Neighbours/1000", "real_time": 12.0,
                                                        "cpu_time": 11.0, "time_unit": "us", "iterations": 100}]}))
    rc, out, summary = report(tmp_path, tmp_path / "runs", None, "--stability", str(tmp_path / "stab"),
                              "--perf", str(tmp_path / "perf"))
    html, names = images_exist(out)
    assert any(n.startswith("stability-") for n in names) and any(n.startswith("perf-") for n in names)
    assert "BM_Neighbours/1000" in html and "density_band" in html
    assert summary["stability"][0]["counts"] == {"stable": 1, "unstable": 1, "inaccurate": 0}


def test_sweep_runs_feed_speed_accuracy_with_unstable_points_marked(tmp_path):
    (tmp_path / "stab").mkdir()
    pts = [{"x": c, "y": k, "outcome": o, "cause": why, "params": {"cfl": c, "kernel": k},
            "wall_time": 1.0 / c, "volume_variation": v}
           for (c, o, why, v) in [(0.1, "stable", "", 1e-3), (0.4, "inaccurate", "volume", 5e-3),
                                  (1.0, "unstable", "density_band", 0.2)] for k in (0, 1)]
    doc = {"sweep": "cfl", "x_label": "CFL", "y_label": "kernel", "points": pts,
           "y_ticks": {"values": [0, 1], "labels": ["quadratic", "wendland_c2"]}}
    (tmp_path / "stab" / "cfl.json").write_text(json.dumps(doc))
    # The same runs drawn as a second map (y = a measured quantity) give no second chart.
    (tmp_path / "stab" / "cfl_volume.json").write_text(json.dumps(dict(doc, sweep="cfl_volume", y_label="max x",
                                                                       y_ticks=None)))
    rc, out, summary = report(tmp_path, tmp_path / "runs", None, "--stability", str(tmp_path / "stab"))
    html, names = images_exist(out)
    sa = summary["speed_accuracy"]
    assert list(sa) == ["cfl (stability sweep)"]
    points = sa["cfl (stability sweep)"]["points"]
    assert {p["method"] for p in points} == {"quadratic", "wendland_c2"}
    assert sorted(p["outcome"] for p in points if p["method"] == "quadratic") == ["inaccurate", "stable", "unstable"]
    assert any(n.startswith("speed-accuracy-cfl") for n in names) and "density_band" in html


def test_recorded_figures_are_shown_but_decide_nothing(tmp_path, make_result):
    path = make_result(tmp_path / "results" / "Demo.Figure.json", "Demo.Figure", convergence=False)
    data = json.loads(path.read_text())
    data["figures"] = [{"name": "decay rate / theory", "measured": 1.76, "source": "theory 1"}]
    path.write_text(json.dumps(data))
    rc, out, summary = report(tmp_path, tmp_path / "runs", tmp_path / "results")
    html, _ = images_exist(out)
    assert summary["figures"] == [{"test": "Demo.Figure", "name": "decay rate / theory", "measured": 1.76,
                                   "source": "theory 1"}]
    assert "decay rate / theory" in html and summary["counts"]["failed"] == 0
    assert summary["counts"]["passed"] == 1  # the one check; the figure is no criterion


def test_references_load_with_their_scaling():
    for key in references.REFERENCES:
        data = references.load(key)
        ref = references.REFERENCES[key]
        assert data[ref.time_column].size > 5
        for col in ref.value_columns:
            assert np.all(np.isfinite(data[col]))
    mm = references.load("martin_moyce_1952_front")
    npt.assert_allclose([mm["T"][0], mm["Z"][0]], [0.41, 1.11], rtol=0, atol=1e-12)


def test_scaled_probe_and_missing_attributes(tmp_path, make_run):
    # g = 5 m/s^2, not the Earth's: the scaling must take g from the run file.
    path = make_run(tmp_path / "r.h5", "dam_break", gravity=5.0, probes=[
        ("surge_front", front, {"type": "front", "units": "m", "scale_length": A}),
        ("p_sensor2", lambda t: 0 * t, {"type": "pressure", "units": "Pa"})])
    run = read_run(path, tmp_path)
    front_probe, pressure = run.probe("surge_front"), run.probe("p_sensor2")
    ts, zs, note = references.scale_probe(run, front_probe, "martin_moyce_1952_front")
    npt.assert_allclose(zs[0], 1.0, rtol=1e-12, atol=0)
    npt.assert_allclose(ts[-1], 0.4 * np.sqrt(2 * 5.0 / A), rtol=1e-12, atol=0)
    assert note == ""
    assert references.scale_probe(run, pressure, "lobovsky_2014_sensor2")[0] is None  # no scale_length

    no_g = read_run(make_run(tmp_path / "no_g.h5", "dam_break", gravity=None, probes=[
        ("surge_front", front, {"type": "front", "units": "m", "scale_length": A})]), tmp_path)
    ts, zs, note = references.scale_probe(no_g, no_g.probe("surge_front"), "martin_moyce_1952_front")
    assert ts is None and "gravity" in note


def test_reader_gives_what_the_run_file_stores(tmp_path, make_run):
    path = make_run(tmp_path / "runs" / "two_fluids.h5", "two_fluids", phases=("light", "heavy"), dx=0.004,
                    gravity=3.5, rho0=998.0, probes=[("p", lambda t: 2 * t, {"type": "pressure", "units": "Pa"})])
    run = read_run(path)
    assert run.read_error == "" and run.label == "two_fluids"
    npt.assert_allclose([run.gravity, run.rho0, run.dx], [3.5, 998.0, 0.004], rtol=0, atol=0)
    assert list(run.phases()) == ["light", "heavy"] and run.phases()["heavy"]["rho0"] == 1497.0
    npt.assert_allclose(run.scene["physics"]["gravity"], [0.0, -3.5], rtol=0, atol=0)
    npt.assert_allclose(run.probe("p").values, 2 * run.time, rtol=0, atol=0)
    with pytest.raises(KeyError, match="no probe `q`"):
        run.probe("q")
    fields = list(run.each_snapshot(("position", "mass")))
    assert [s.key for s, _ in fields] == ["00000", "00001", "00002"]
    npt.assert_allclose(fields[0][1]["mass"], 998.0 * 0.004 ** 2, rtol=1e-15, atol=0)
    assert run.snapshot_at(0.39) is run.snapshots[-1]

    bare = read_run(make_run(tmp_path / "bare.h5", "bare", gravity=None, rho0=None))
    with pytest.raises(KeyError, match="root attribute `gravity` missing"):
        bare.gravity
    with pytest.raises(KeyError, match="root attribute `rho0` missing"):
        bare.rho0


def test_unreadable_scene_text_is_a_read_error(tmp_path, make_run):
    path = make_run(tmp_path / "r.h5", "dam_break")
    with h5py.File(path, "a") as f:
        del f["scene"]
        f["scene"] = "name = = broken"
    run = read_run(path)
    assert "TOMLDecodeError" in run.read_error


@pytest.mark.parametrize("measured, comparison, threshold, expected", [
    (0.001, "<", 0.003, True), (0.003, "<", 0.003, False), (0.002, "<=", 0.002, True),
    (float("nan"), "<", 1.0, False), (None, ">", 0.0, False), ("stable", "==", "stable", True)])
def test_compare(measured, comparison, threshold, expected):
    assert criteria.compare(measured, comparison, threshold) is expected


def test_family():
    known = {"dam_break": [], "drop_into_pool": []}
    assert family("dam_break_dx0.005", known) == "dam_break"
    assert family("dam_break", known) == "dam_break"
    assert family("poiseuille_dx1e-05", known) == "poiseuille"


def test_fit_order_needs_two_points():
    assert analysis.fit_order([1.0], [1.0]) is None
    npt.assert_allclose(analysis.fit_order([1, 2, 4], [1, 0.5, 0.25]), -1.0, rtol=1e-12, atol=0)


def test_fixed_length_string_attributes_as_cpp_writes_them(tmp_path, make_run):
    path = make_run(tmp_path / "runs" / "dam_break.h5", "dam_break")
    with h5py.File(path, "a") as f:
        for key in ("status", "scene_name", "kernel"):
            value = str(f.attrs[key])
            del f.attrs[key]
            f.attrs.create(key, np.bytes_(value), dtype=h5py.string_dtype("ascii", len(value)))
    run = read_run(path, tmp_path / "runs")
    assert (run.attrs["status"], run.scene_name, run.label) == ("stable", "dam_break", "dam_break")
    assert isinstance(run.metrics["particles"], int)


def test_paraview_section_shows_what_pvpython_found(tmp_path):
    pv = tmp_path / "paraview"
    pv.mkdir()
    matplotlib.image.imsave(pv / "dam_break_pressure.png", np.zeros((4, 4, 3)))
    found = {"xdmf": "runs/nightly/dam_break.xdmf", "paraview": "paraview version 5.11.0", "reader": "Xdmf3ReaderS",
             "time_steps": 3, "points_per_step": [1250] * 3, "cells_per_step": [1250, 1250, 1249],
             "legacy_reader_cells_per_step": [1250] * 3, "arrays": ["pressure"], "picture": "dam_break_pressure.png",
             "picture_time": 0.65, "failures": ["Xdmf3ReaderS, t = 1.3 s: 1250 points, 1249 cells"]}
    (pv / "paraview.json").write_text(json.dumps(found))
    rc, out, summary = report(tmp_path, tmp_path / "runs", None, "--paraview", str(pv))
    html, names = images_exist(out)
    assert "paraview-dam_break_pressure.png" in names
    assert "1249 .. 1250" in html and "1249 cells" in html and "r-fail" in html
    assert summary["paraview"]["reader"] == "Xdmf3ReaderS"


def test_paraview_directory_without_its_file_is_a_warning(tmp_path):
    (tmp_path / "empty").mkdir()
    rc, out, summary = report(tmp_path, tmp_path / "runs", None, "--paraview", str(tmp_path / "empty"))
    assert "paraview.json: not read" in (out / "provenance.html").read_text()
    assert "not run: no --paraview directory" in report(tmp_path, tmp_path / "runs")[1].joinpath(
        "provenance.html").read_text()


def test_history_appends_each_run_and_flags_a_change(tmp_path, make_run):
    db = tmp_path / "build" / "vv-history.jsonl"
    for k, dv in enumerate((0.001, 0.001, 0.0015)):
        make_run(tmp_path / "runs" / "dam_break.h5", "dam_break", max_volume_variation=dv)
        rc, out, summary = report(tmp_path, tmp_path / "runs", None, "--history", str(db),
                                  "--load-start", "1000" if k == 1 else "0")
    lines = db.read_text().splitlines()
    assert len(lines) == 3
    runs = [json.loads(x) for x in lines]
    assert runs[1]["loaded"] and runs[1]["load_start"] == 1000  # 1000 > nproc / 2
    # The others' end load is the machine's own at the time: their mark follows from what they stored.
    assert all(r["loaded"] == history.loaded(r["load_start"], r["load_end"], r["nproc"]) for r in runs)
    assert history.loaded(0.5, 0.9, 2) is False and history.loaded(0.5, 1.1, 2) is True
    assert {"commit", "build_type", "hostname", "nproc", "load_start", "load_end"} <= set(runs[0])
    trends = {t["key"]: t for t in summary["history"]["trends"]}
    vv = trends["dam_break | max_volume_variation"]
    assert vv["flagged"] and vv["values"] == [0.001, 0.001, 0.0015]
    assert not trends["wall time [s] | dam_break"]["flagged"]  # 12.5 s each time: within its 20 % floor
    html = (out / "history.html").read_text()
    assert "loaded" in html and "changed beyond" in html
    _, names = images_exist(out)
    assert any(n.startswith("trend-") for n in names)


def test_vv20_comparison_in_table_and_figure(tmp_path, make_result):
    path = make_result(tmp_path / "results" / "validation.dam_break.json", test="validation.dam_break",
                       convergence=False)
    data = json.loads(path.read_text())
    data["comparisons"] = [{"name": "impact time t*", "unit": "-", "x_label": "dx / H", "h": [0.02, 0.01, 0.005],
                            "S": [2.30, 2.34, 2.35], "D": 2.46, "u_D": 0.0153, "D_source": "Lobovsky median",
                            "u_D_source": "percentiles", "u_input": 0.0, "u_input_source": "0: none stated"}]
    path.write_text(json.dumps(data))
    rc, out, summary = report(tmp_path, tmp_path / "runs", tmp_path / "results")
    (row,) = summary["uncertainty"]
    assert row["study"]["kind"] == "monotonic" and row["study"]["p"] > 0
    npt.assert_allclose(row["E"], 2.35 - 2.46, rtol=0, atol=1e-12)
    html, names = images_exist(out)
    assert row["figure"] in names
    page = (out / "validation.html").read_text()
    assert "GCI<sub>fine</sub>" in page and "excludes 0" in page


def test_convergence_plot_carries_its_order_criterion(tmp_path, make_result):
    path = make_result(tmp_path / "results" / "Operators.Order.json", test="Operators.Order")
    data = json.loads(path.read_text())
    data["checks"].append({"name": "Poiseuille observed order", "measured": 1.2, "threshold": 1.8,
                           "comparison": ">=", "source": "theory 2", "pass": False})
    path.write_text(json.dumps(data))
    rc, out, summary = report(tmp_path, tmp_path / "runs", tmp_path / "results")
    (entry,) = summary["convergence"]
    assert entry["criterion"]["name"] == "Poiseuille observed order" and entry["criterion"]["pass"] is False
    assert 'class="r-fail">FAIL</span> criterion' in (out / "verification.html").read_text()


def test_an_order_check_of_one_norm_does_not_decide_another_norms_plot():
    from analysis import order_criterion
    l2 = {"name": "Poiseuille L2 observed order at t = 0.0225 s", "measured": 2.09, "threshold": 1.5,
          "comparison": ">=", "pass": True}
    assert order_criterion({"name": "Poiseuille Linf error / v_max at t = 0.0225 s"}, [l2]) is None
    assert order_criterion({"name": "Poiseuille L2 error / v_max at t = 0.0225 s"}, [l2])["measured"] == 2.09
    assert order_criterion({"name": "Poiseuille error / v_max at t = 0.0225 s"}, [l2])["measured"] == 2.09


def test_every_page_has_the_navigation_and_figures_have_anchors(tmp_path, make_run):
    make_run(tmp_path / "runs" / "dam_break.h5", "dam_break")
    rc, out, summary = report(tmp_path, tmp_path / "runs")
    pages = sorted(p.name for p in out.glob("*.html"))
    assert len(pages) == 11
    for p in pages:
        html = (out / p).read_text()
        assert all(f'href="{q}"' in html for q in pages), p
    val = (out / "validation.html").read_text()
    ids = re.findall(r'<figure id="([^"]+)"', val)
    assert ids and all(f'href="#{i}"' in val for i in ids)


def test_a_recorded_peer_series_is_shown_as_a_dated_reference(tmp_path):
    (tmp_path / "perf").mkdir()
    (tmp_path / "perf" / "db.json").write_text(json.dumps(
        {"benchmark": "dam break", "x_label": "particles", "y_label": "wall time [s]",
         "series": [{"label": "ours, 2 thread(s)", "x": [1250, 5000], "y": [2.5, 13.0]},
                    {"label": "DualSPHysics 5.4, 2 threads", "x": [1484, 5467], "y": [5.2, 57.5],
                     "recorded": "issue 7's table, 2026-11-23"}]}))
    rc, out, summary = report(tmp_path, tmp_path / "runs", None, "--perf", str(tmp_path / "perf"))
    page = (out / "performance.html").read_text()
    assert "a recorded reference (issue 7&#x27;s table, 2026-11-23), not measured by this run" in page
    assert "This run: load average" in page


def validate_result(path, name, case, checks):
    """A validate.py results file (validation/validate.py, Results.write): one check per (run, measured, pass)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    data = {"test": f"validation.{name}", "case": case, "issue": 4,
            "checks": [{"name": f"{run}: wall impact time error", "measured": m, "threshold": 0.1, "comparison": "<=",
                        "source": "Lobovsky et al. 2014 sensor 2 onset", "pass": m <= 0.1,
                        "model": "named" if run.endswith("_named") else "paper"} for run, m in checks]}
    path.write_text(json.dumps(data))


def test_both_models_are_shown_and_the_verdict_follows_the_named_model(tmp_path, make_run):
    """Issue 31: the paper's model's row and the named model's row of the same criterion are both on the validation
    page; the banner is about the named model: a paper failure is a finding (listed, xfail in junit), a named
    failure fails the report."""
    runs, results = tmp_path / "runs", tmp_path / "results"
    make_run(runs / "quick" / "dam_break_dx0.025.h5", "dam_break_dx0.025", max_volume_variation=0.0041)
    make_run(runs / "quick" / "dam_break_dx0.025_named.h5", "dam_break_dx0.025_named", max_volume_variation=0.0017,
             kernel="wendland_c2")
    validate_result(results / "validation.dam_break_quick.json", "dam_break_quick", "dam_break",
                    [("dam_break_dx0.025", 0.0489)])
    validate_result(results / "validation.dam_break_quick_named.json", "dam_break_quick_named", "dam_break",
                    [("dam_break_dx0.025_named", 0.0262)])
    rc, out, summary = report(tmp_path, runs, results)
    assert rc == 0 and not summary["problems"]  # the paper's volume 0.0041 > 0.003 fails: a finding only
    assert summary["verdict"] == "PASS" and summary["counts"]["failed"] == 0
    assert summary["counts_paper"]["failed"] == 1 and len(summary["findings"]) == 1
    assert "quick/dam_break_dx0.025 | max_volume_variation < 0.003" in summary["findings"][0]
    index = (out / "index.html").read_text()
    assert 'class="banner b-pass">PASS' in index and "Findings: the paper's model's failed criteria (1)" in index
    junit = ET.parse(out / "junit.xml").getroot()
    xfails = [c for c in junit.iter("testcase") if (s := c.find("skipped")) is not None
              and s.get("type") == "pytest.xfail"]
    assert len(xfails) == 1 and not [c for c in junit.iter("testcase") if c.find("failure") is not None]
    page = (out / "validation.html").read_text()
    table = page[page.index("The paper's model and the named model"):page.index("Validation uncertainty")]
    rows = re.findall(r"<tr[^>]*>(.*?)</tr>", table)
    volume = [r for r in rows if ">max_volume_variation<" in r]
    assert len(volume) == 1  # one row, both models in it
    assert "0.0041 <span class=\"r-fail\">FAIL</span>" in volume[0] and "0.0017 <span class=\"r-pass\">PASS" in volume[0]
    assert "&lt; 0.003" in volume[0] and "Lobovsky &amp; Kren" in volume[0]  # threshold and source
    onset = [r for r in rows if "wall impact time error" in r]
    assert len(onset) == 1 and "0.0489 <span" in onset[0] and "0.0262 <span" in onset[0]

    # The same runs with the named model failing and the paper's passing: the report fails.
    make_run(runs / "quick" / "dam_break_dx0.025.h5", "dam_break_dx0.025", max_volume_variation=0.0017)
    make_run(runs / "quick" / "dam_break_dx0.025_named.h5", "dam_break_dx0.025_named", max_volume_variation=0.0041,
             kernel="wendland_c2")
    rc, out, summary = report(tmp_path, runs, results)
    assert rc == 1 and summary["verdict"] == "FAIL" and not summary["problems"]
    assert summary["counts"]["failed"] == 1 and summary["counts_paper"]["failed"] == 0 and not summary["findings"]
    assert 'class="banner b-fail">FAIL' in (out / "index.html").read_text()


def test_a_case_without_named_runs_is_judged_on_the_paper_model(tmp_path, make_run):
    """A case whose runs are the paper's model alone (here two-fluid runs without their named twins): its paper
    rows decide the verdict even when other cases run the named model."""
    runs = tmp_path / "runs"
    make_run(runs / "two_fluids.h5", "two_fluids", phases=("light", "heavy"), max_volume_variation=0.004)
    make_run(runs / "dam_break.h5", "dam_break", max_volume_variation=0.004)
    make_run(runs / "dam_break_named.h5", "dam_break_named", max_volume_variation=0.001, kernel="wendland_c2")
    rc, out, summary = report(tmp_path, runs)
    assert rc == 1 and summary["verdict"] == "FAIL"
    failed = {c["run"] for c in summary["criteria"] if c["outcome"] == "fail"}
    assert failed == {"two_fluids", "dam_break"}
    assert [f.split(" | ")[0] for f in summary["findings"]] == ["dam_break"]  # a finding, not in the verdict
    assert summary["counts"]["failed"] == 2  # two_fluids' two phase volumes
