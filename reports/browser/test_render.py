"""The report renders in a real browser (issues 5 and 33): headless Chromium (Debian's `chromium`, no network) loads
index.html and every other page at 1280 px; each page must have the verdict in its DOM, no horizontal overflow and
no image that fails to load; every page gets a screenshot. Nightly tier: it needs the chromium package, which
scripts/vv-report.sh installs (scripts/install-deps.sh --report).

REPORT_DIR names a report to check (scripts/vv-report.sh passes reports/out) and SCREENSHOT_DIR where the
screenshots go (default: the test's temporary directory); without REPORT_DIR the test builds a report from small
generated run files (reports/tests/conftest.py)."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPORTS = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPORTS / "tests"))
sys.path.insert(0, str(REPORTS))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import conftest  # noqa: E402  (the run-file writer of the report's own tests)
import render  # noqa: E402

EXPECTED_PAGES = {"index.html", "validation.html", "verification.html", "speed.html", "stability.html",
                  "performance.html", "packing.html", "provenance.html", "traceability.html", "history.html",
                  "criteria.html"}


def build_report(tmp_path: Path) -> Path:
    runs, out = tmp_path / "runs", tmp_path / "out"
    conftest.write_run(runs / "dam_break.h5", "dam_break")
    conftest.write_run(runs / "two_fluids.h5", "two_fluids", phases=("light", "heavy"))
    conftest.write_result(tmp_path / "results" / "Poiseuille.SteadyProfile.json")
    subprocess.run([sys.executable, str(REPORTS / "vv_report.py"), "--runs", str(runs), "--results",
                    str(tmp_path / "results"), "--out", str(out), "--quick"], check=False)
    return out


def test_every_page_renders_without_overflow_or_missing_images(tmp_path):
    report = Path(os.environ["REPORT_DIR"]).resolve() if os.environ.get("REPORT_DIR") else build_report(tmp_path)
    assert (report / "index.html").exists(), f"no report at {report / 'index.html'}"
    assert EXPECTED_PAGES <= {p.name for p in report.glob("*.html")}
    shots = Path(os.environ.get("SCREENSHOT_DIR") or tmp_path / "shots")
    shots.mkdir(parents=True, exist_ok=True)
    results = render.check_site(report, tmp_path / "chromium", shots)
    problems = [p for r in results for p in r["problems"]]
    assert not problems, "\n".join(problems)
    assert sum(r["images"] for r in results) > 0, "the rendered pages show no figure"
    for r in results:
        shot = shots / (Path(r["page"]).stem + ".png")
        assert shot.exists() and shot.stat().st_size > 10_000, f"no screenshot (or a blank one) of {r['page']}"


def test_the_check_fails_on_a_broken_page(tmp_path):
    """A page 2000 px wide with an image that is not there: both faults must be reported."""
    page = tmp_path / "broken.html"
    page.write_text('<!DOCTYPE html><html><body><div style="width:2000px">wide</div>'
                    '<img src="missing.png" alt="missing"></body></html>', encoding="utf-8")
    r = render.check_page(page, tmp_path / "chromium")
    assert r["scrollWidth"] > r["innerWidth"] == render.WIDTH
    assert r["broken"] == ["missing.png"]
    assert len(r["problems"]) == 2 and "overflows" in r["problems"][0]


@pytest.mark.parametrize("width", [render.WIDTH])
def test_a_good_page_passes(tmp_path, width):
    page = tmp_path / "good.html"
    page.write_text('<!DOCTYPE html><html><body><p>fits</p></body></html>', encoding="utf-8")
    r = render.check_page(page, tmp_path / "chromium")
    assert r["problems"] == [] and r["innerWidth"] == width
