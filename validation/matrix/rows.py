"""The JSON rows that run.py writes (ROWS/<name>.json), read back: the one reader of them.

A run is `done` when its row says exit code 0 with no missing output and its run file is there, `failed` when its
row says otherwise, `missing` when it has no row (never ran, or its task died before writing one: a node lost, a
job killed by the scheduler with SIGKILL).
"""
from __future__ import annotations

import json
from pathlib import Path


def read_rows(rows_dir: Path) -> dict:
    """{run name: row} of every readable ROWS/*.json; an unreadable row is left out (its run counts as missing)."""
    out = {}
    for p in sorted(Path(rows_dir).glob("*.json")):
        try:
            row = json.loads(p.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        if isinstance(row, dict) and isinstance(row.get("run"), str):
            out[row["run"]] = row
    return out


def state(row: dict | None, runs_dir: Path, run) -> str:
    if row is None:
        return "missing"
    if row.get("exit_code") != 0 or row.get("missing_outputs"):
        return "failed"
    return "done" if (Path(runs_dir) / run.tier / f"{run.name}.h5").is_file() else "missing"


def states(runs, rows_dir: Path, runs_dir: Path) -> dict:
    """{run name: "done" | "failed" | "missing"} for the matrix runs `runs`."""
    rows = read_rows(rows_dir)
    return {r.name: state(rows.get(r.name), runs_dir, r) for r in runs}
