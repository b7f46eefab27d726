"""Read the solver's HDF5 run files and the GoogleTest JSON results (layout: reports/SCHEMA.md).

The one reader of run files: the report (reports/), validation/validate.py and validation/stability/sweep.py
all read through `read_run`. Values the run file stores (rho0, g, the scene and its parameters) are taken from it
here, never restated by a caller. This module only reads; it holds no thresholds, no references and no plotting.
"""
from __future__ import annotations

import json
import re
import tomllib
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
    scene_text: str = ""  # the dataset /scene: the scene file the run was made from
    scene: dict = field(default_factory=dict)  # scene_text parsed (TOML)
    read_error: str = ""

    @property
    def scene_name(self) -> str:
        return str(self.attrs.get("scene_name") or self.path.stem)

    @property
    def method(self) -> str:
        """Kernel and terms: what distinguishes one method from another in a speed/accuracy chart."""
        return f"{self.attrs.get('kernel', '?')} [{self.attrs.get('terms', '?')}]"

    def _number(self, where: dict, key: str, what: str) -> float:
        value = where.get(key)
        if not isinstance(value, (int, float)) or isinstance(value, bool):
            raise KeyError(f"{self.path}: {what} `{key}` missing or not a number (reports/SCHEMA.md)")
        return float(value)

    @property
    def rho0(self) -> float:
        """Root attribute `rho0`: the first phase's rest density [kg/m^3]."""
        return self._number(self.attrs, "rho0", "root attribute")

    @property
    def gravity(self) -> float:
        """Root attribute `gravity`: |body acceleration| [m/s^2]."""
        return self._number(self.attrs, "gravity", "root attribute")

    @property
    def dx(self) -> float:
        """The scene's particle spacing, `numerics.dx` of /scene [m]."""
        return self._number(self.scene.get("numerics", {}), "dx", "scene key numerics.")

    @property
    def time(self) -> np.ndarray:
        return np.asarray(self.series["time"], dtype=float)

    def probe(self, name: str) -> Probe:
        """The probe /series/probe_<name>; KeyError naming the run when it has none."""
        for p in self.probes:
            if p.name == name:
                return p
        raise KeyError(f"{self.path}: no probe `{name}` in /series (probes: {[p.name for p in self.probes]})")

    def phases(self) -> dict:
        """{phase name: its [[phase]] table of the scene} in the scene's order (the phase index of snapshots)."""
        return {p["name"]: p for p in self.scene.get("phase", [])}

    def snapshot_at(self, t: float) -> Snapshot:
        return min(self.snapshots, key=lambda s: abs(s.time - t))

    def snapshot_fields(self, snap: Snapshot, names=("position", "pressure", "phase")) -> dict:
        with h5py.File(self.path, "r") as f:
            group = f["snapshots"][snap.key]
            return {n: group[n][()] for n in names if n in group}

    def each_snapshot(self, names=("position", "phase")):
        """(snapshot, {field: array}) for every snapshot in order, the file opened once."""
        with h5py.File(self.path, "r") as f:
            for snap in self.snapshots:
                group = f["snapshots"][snap.key]
                yield snap, {n: group[n][()] for n in names if n in group}


def read_run(path: Path, root: Path | None = None) -> Run:
    """Read one run file (labelled relative to `root`, default its directory). A file that cannot be read comes
    back with `read_error` set."""
    path = Path(path)
    root = path.parent if root is None else Path(root)
    label = str(path.relative_to(root).with_suffix("")) if path.is_relative_to(root) else path.stem
    run = Run(path=path, label=label, attrs={})
    try:
        with h5py.File(path, "r") as f:
            run.attrs = _attrs(f)
            if "scene" in f:
                run.scene_text = str(_plain(f["scene"][()]))
                run.scene = tomllib.loads(run.scene_text)
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
    except (OSError, KeyError, ValueError, TypeError) as err:  # tomllib.TOMLDecodeError is a ValueError
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


_RESOLUTION_SUFFIX = re.compile(r"_(dx|h|n|res|a)[0-9][0-9.eE+-]*$")  # a: Martin & Moyce's a/dx

# The two models of a validation case (issue 31): the paper's (Lobovsky & Kren), in the scenes as the paper gives
# them, and the named model, the same scene with density diffusion and the Wendland kernel, named <scene>_named
# (validation/make_variants.py, NAMED). The report judges the named model and shows the paper's beside it.
PAPER, NAMED = "paper", "named"
NAMED_SUFFIX = "_named"


def model_of(scene_name: str) -> str:
    """PAPER or NAMED: the model a scene (or a check named after its runs, "a_named vs b_named") runs."""
    return NAMED if str(scene_name).endswith(NAMED_SUFFIX) else PAPER


def in_verdict(model: str, case: str, named_cases) -> bool:
    """Whether a criterion of `model` (PAPER, NAMED or "" for a verification test) in validation case `case` counts
    in the verdict (issue 31): every one but the paper's model's in a case the named model runs too (`named_cases`,
    the cases with a named-model criterion), which are findings, shown and not decided on. The one rule of the
    report (criteria.judged) and of validate.py's exit code (validation/validate.py, Results.write)."""
    return model != PAPER or case not in named_cases


def paper_twin(scene_name: str) -> str:
    """The paper's scene a named-model scene is the variant of (dam_break_dx0.025_named -> dam_break_dx0.025)."""
    return str(scene_name).removesuffix(NAMED_SUFFIX)


def family(scene_name: str, known=()) -> str:
    """The case a scene belongs to: the longest known case name that is the scene name or a prefix of it
    followed by '_' (dam_break_dx0.005 -> dam_break); otherwise the name without a resolution suffix. A named-model
    scene belongs to its paper twin's case."""
    scene_name = paper_twin(scene_name)
    matches = [k for k in known if scene_name == k or scene_name.startswith(k + "_")]
    if matches:
        return max(matches, key=len)
    return _RESOLUTION_SUFFIX.sub("", scene_name)
