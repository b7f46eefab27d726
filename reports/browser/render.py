"""Render report pages in headless Chromium (Debian's `chromium`, no network) and measure what a reader would trip
on: a page wider than the window (document.scrollWidth > innerWidth at 1280 px) and an image that did not load
(naturalWidth == 0). The measurement is a script added to a copy of each page, written beside it (so that its
images resolve) and removed afterwards; the page itself is not changed."""
from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

WIDTH = 1280  # a laptop's window (issue 33: readable at a laptop's width)
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync", "--hide-scrollbars",
         "--allow-file-access-from-files"]
PROBE = """<script>window.addEventListener("load", function () {
  var broken = [];
  for (var i = 0; i < document.images.length; i++) {
    var im = document.images[i];
    if (!im.complete || im.naturalWidth === 0) broken.push(im.getAttribute("src"));
  }
  var r = {scrollWidth: document.documentElement.scrollWidth, innerWidth: window.innerWidth,
           images: document.images.length, broken: broken};
  var pre = document.createElement("pre");
  pre.id = "vv-render-check"; pre.style.display = "none"; pre.textContent = JSON.stringify(r);
  document.body.appendChild(pre);
});</script>"""
RESULT = re.compile(r'<pre id="vv-render-check"[^>]*>(.*?)</pre>', re.S)


def chromium() -> str:
    exe = shutil.which("chromium") or "/usr/bin/chromium"
    if not Path(exe).exists():
        raise FileNotFoundError("Debian's chromium is not installed (scripts/install-deps.sh --report)")
    return exe


def check_page(page: Path, scratch: Path, shot: Path | None = None, height: int = 1600) -> dict:
    """{"page", "scrollWidth", "innerWidth", "images", "broken", "problems"} of one page; `shot` a screenshot."""
    scratch.mkdir(parents=True, exist_ok=True)
    probe_page = page.parent / f".render-check-{page.name}"
    text = page.read_text(encoding="utf-8")
    probe_page.write_text(text.replace("</body>", PROBE + "</body>") if "</body>" in text else text + PROBE,
                          encoding="utf-8")
    profile = scratch / "profile"
    try:
        dom = subprocess.run([chromium(), *FLAGS, f"--user-data-dir={profile}", f"--window-size={WIDTH},{height}",
                              "--virtual-time-budget=5000", "--dump-dom", probe_page.as_uri()],
                             capture_output=True, text=True, timeout=120)
    finally:
        probe_page.unlink(missing_ok=True)
    found = RESULT.search(dom.stdout)
    if dom.returncode != 0 or not found:
        return {"page": page.name, "problems": [f"{page.name}: chromium gave no measurement (exit {dom.returncode}): "
                                                f"{dom.stderr[-400:]}"]}
    r = json.loads(found.group(1).replace("&quot;", '"').replace("&amp;", "&"))
    r["page"] = page.name
    r["problems"] = []
    if r["scrollWidth"] > r["innerWidth"]:
        r["problems"].append(f"{page.name}: overflows horizontally, scrollWidth {r['scrollWidth']} > "
                             f"innerWidth {r['innerWidth']}")
    r["problems"] += [f"{page.name}: image {src} did not load (naturalWidth 0)" for src in r["broken"]]
    if shot is not None:
        subprocess.run([chromium(), *FLAGS, f"--user-data-dir={profile}", f"--screenshot={shot}",
                        f"--window-size={WIDTH},{height}", "--virtual-time-budget=5000", page.as_uri()],
                       capture_output=True, timeout=120)
    return r


def check_site(report: Path, scratch: Path, shots: Path | None = None) -> list:
    """check_page for every *.html of a report directory (index.html first)."""
    pages = sorted(report.glob("*.html"), key=lambda p: (p.name != "index.html", p.name))
    if shots is not None:
        shots.mkdir(parents=True, exist_ok=True)
    out = []
    for p in pages:
        shot = None if shots is None else shots / (p.stem + ".png")
        out.append(check_page(p, scratch, shot))
    return out
