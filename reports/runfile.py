"""Read the solver's HDF5 run files and the GoogleTest JSON results (layout: reports/SCHEMA.md).

This module only reads; it holds no thresholds, no references and no plotting.
"""
from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

import h5py
import numpy as np

PROVENANCE = ("sph_version", "git_commit", "compiler", "cxx_flags", "build_type", "threads", "machine", "date")


def _plain(value):
    """HDF5 attribute value -> plain Python (str, int, float, list)."""
    if isinstance(value, bytes):
        return value.decode("utf-8", errors="replace")
    if isinstance(value, np.ndarray):
        if value.size == 1:
            return _plain(value.reshape(-1)[0])
        return [_plain(v) for v in value.tolist()]
    if isinstance(value, np.generic):
        return value.item()
    return value


def _attrs(obj) -> dict:
    return {key: _plain(obj.attrs[key]) for key in obj.attrs}


@dataclass
class Probe:
    name: str  # without the "probe_" prefix
    values: np.ndarray
    attrs: dict  # `type`, `units`, and the optional `reference`, `scale_length`, ... (reports/README.md)


@dataclass
class Snapshot:
    key: str
    time: float
    step: int
    last_good: bool


@dataclass
class Run:
    path: Path
    label: str  # path relative to the runs directory, without suffix
    attrs: dict
    series: dict = field(default_factory=dict)
    probes: list = field(default_factory=list)
    snapshots: list = field(default_factory=list)
    metrics: dict = field(default_factory=dict)
    read_error: str = ""

    @property
    def scene_name(self) -> str:
        return str(self.attrs.get("scene_name") or self.path.stem)

    @property
    def method(self) -> str:
        """Kernel and terms: what distinguishes one method from another in a speed/accuracy chart."""
        return f"{self.attrs.get('kernel', '?')} [{self.attrs.get('terms', '?')}]"

    def snapshot_fields(self, snap: Snapshot, names=("position", "pressure", "phase")) -> dict:
        with h5py.File(self.path, "r") as f:
            group = f["snapshots"][snap.key]
            return {n: group[n][()] for n in names if n in group}


def read_run(path: Path, root: Path) -> Run:
    """Read one run file. A file that cannot be read comes back with `read_error` set."""
    label = str(path.relative_to(root).with_suffix("")) if path.is_relative_to(root) else path.stem
    run = Run(path=path, label=label, attrs={})
    try:
        with h5py.File(path, "r") as f:
            run.attrs = _attrs(f)
            if "series" in f:
                for name, dset in f["series"].items():
                    if not isinstance(dset, h5py.Dataset):
                        continue
                    if name.startswith("probe_"):
                        run.probes.append(Probe(name[len("probe_"):], np.asarray(dset[()], dtype=float), _attrs(dset)))
                    else:
                        run.series[name] = np.asarray(dset[()])
            if "snapshots" in f:
                for key in sorted(f["snapshots"], key=lambda k: int(k) if k.isdigit() else -1):
                    a = _attrs(f["snapshots"][key])
                    run.snapshots.append(Snapshot(key, float(a.get("time", np.nan)), int(a.get("step", -1)),
                                                  bool(a.get("last_good", 0))))
            if "metrics" in f:
                run.metrics = _attrs(f["metrics"])
    except (OSError, KeyError, ValueError, TypeError) as err:
        run.read_error = f"{type(err).__name__}: {err}"
    return run


def read_runs(directory: Path | None) -> list:
    if directory is None or not Path(directory).is_dir():
        return []
    root = Path(directory)
    return [read_run(p, root) for p in sorted(root.rglob("*.h5"))]


@dataclass
class Result:
    path: Path
    data: dict
    read_error: str = ""

    @property
    def test(self) -> str:
        return str(self.data.get("test") or self.path.stem)


def read_results(directory: Path | None) -> list:
    if directory is None or not Path(directory).is_dir():
        return []
    out = []
    for p in sorted(Path(directory).rglob("*.json")):
        try:
            data = json.loads(p.read_text(encoding="utf-8"))
            if not isinstance(data, dict):
                raise ValueError("top level is not an object")
            out.append(Result(p, data))
        except (OSError, ValueError) as err:  # json.JSONDecodeError is a ValueError
            out.append(Result(p, {}, f"{type(err).__name__}: {err}"))
    return out


def read_json_dir(directory: Path | None) -> list:
    """(path, object) for every readable *.json under a directory; unreadable ones as (path, error string)."""
    if directory is None or not Path(directory).is_dir():
        return []
    out = []
    for p in sorted(Path(directory).rglob("*.json")):
        try:
            out.append((p, json.loads(p.read_text(encoding="utf-8"))))
        except (OSError, ValueError) as err:
            out.append((p, f"{type(err).__name__}: {err}"))
    return out


_RESOLUTION_SUFFIX = re.compile(r"_(dx|h|n|res)[0-9][0-9.eE+-]*$")


def family(scene_name: str, known=()) -> str:
    """The case a scene belongs to: the longest known case name that is the scene name or a prefix of it
    followed by '_' (dam_break_dx0.005 -> dam_break); otherwise the name without a resolution suffix."""
    matches = [k for k in known if scene_name == k or scene_name.startswith(k + "_")]
    if matches:
        return max(matches, key=len)
    return _RESOLUTION_SUFFIX.sub("", scene_name)
