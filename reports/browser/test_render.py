"""The report renders in a real browser (issue 5): headless Chromium (Debian's `chromium`, no network)
loads index.html, the page's banner is in the rendered DOM, every image the page references exists and
is a PNG, and a screenshot is produced. Nightly tier: it needs the chromium package, which
scripts/vv-report.sh installs.

REPORT_DIR names a report to check (scripts/vv-report.sh passes reports/out); without it the test builds
a report from small generated run files (reports/tests/conftest.py) in a temporary directory."""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

REPORTS = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPORTS / "tests"))
sys.path.insert(0, str(REPORTS))

import conftest  # noqa: E402  (the run-file writer of the report's own tests)

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--hide-scrollbars"]


def chromium():
    exe = shutil.which("chromium") or "/usr/bin/chromium"
    assert Path(exe).exists(), "Debian's chromium is not installed (scripts/install-deps.sh --report)"
    return exe


def build_report(tmp_path: Path) -> Path:
    runs, out = tmp_path / "runs", tmp_path / "out"
    conftest.write_run(runs / "dam_break.h5", "dam_break")
    conftest.write_run(runs / "two_fluids.h5", "two_fluids", phases=("light", "heavy"))
    subprocess.run([sys.executable, str(REPORTS / "vv_report.py"), "--runs", str(runs), "--results",
                    str(tmp_path / "none"), "--out", str(out), "--quick"], check=False)
    return out


def test_report_renders_in_chromium(tmp_path):
    report = Path(os.environ["REPORT_DIR"]).resolve() if os.environ.get("REPORT_DIR") else build_report(tmp_path)
    index = report / "index.html"
    assert index.exists(), f"no report at {index}"
    profile = tmp_path / "profile"
    dom = subprocess.run([chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "--dump-dom",
                          index.as_uri()], capture_output=True, text=True, timeout=120)
    assert dom.returncode == 0, dom.stderr[-2000:]
    assert re.search(r"\b(PASS|FAIL|NOT RUN)\b", dom.stdout), "the pass/fail banner is not in the rendered page"
    images = re.findall(r'<img[^>]+src="([^"]+)"', dom.stdout)
    assert images, "the rendered page shows no figure"
    for src in images:
        path = report / src
        assert path.exists(), f"the page references {src}, which does not exist"
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", f"{src} is not a PNG"
    shot = tmp_path / "screenshot.png"
    subprocess.run([chromium(), *CHROMIUM_FLAGS, f"--user-data-dir={profile}", f"--screenshot={shot}",
                    "--window-size=1280,1600", index.as_uri()], capture_output=True, timeout=120)
    assert shot.exists() and shot.stat().st_size > 10_000, "no screenshot (or a blank one)"
