"""The matrix of long runs (validation/matrix/matrix.toml): its one reader.

A matrix lists runs (`[[run]]`: one `sph run` of a scene) and checks (`[[check]]`: validation/validate.py over
some runs' files). Every runner reads it through `load`: the ctest include (to_ctest.py), one run and its JSON row
(run.py), the gathering of results (gather.py) and the Slurm submission (scripts/slurm_submit.py). A bad key or
value raises MatrixError naming the file, the entry and the key.
"""
from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
DEFAULT_MATRIX = HERE / "matrix.toml"
TIERS = ("quick", "nightly")
RUN_KEYS = {"name", "scene", "tier", "threads", "timeout_s", "recover_timeout_s", "args", "outputs"}
CHECK_KEYS = {"name", "case", "tier", "runs"}


class MatrixError(ValueError):
    pass


@dataclass
class Run:
    name: str  # the scene's `name`: its run file is <name>.h5
    scene: Path  # absolute
    tier: str
    threads: int
    timeout_s: int
    recover_timeout_s: int | None = None
    args: list = field(default_factory=list)  # further `sph run` options
    outputs: list = field(default_factory=list)  # files the run must leave in its tier's directory


@dataclass
class Check:
    name: str
    case: str  # a validate.py CASE
    tier: str
    runs: list


@dataclass
class Matrix:
    path: Path
    runs: list
    checks: list

    def run(self, name: str) -> Run:
        for r in self.runs:
            if r.name == name:
                return r
        raise MatrixError(f"{self.path}: no [[run]] named `{name}` (runs: {', '.join(r.name for r in self.runs)})")

    def select(self, tiers=(), names=()) -> list:
        """The runs of the given tiers and names (all runs when both are empty), in the matrix's order."""
        for n in names:
            self.run(n)
        return [r for r in self.runs if (not tiers or r.tier in tiers) and (not names or r.name in names)]

    def checks_over(self, runs) -> list:
        """The checks all of whose runs are among `runs`."""
        have = {r.name for r in runs}
        return [c for c in self.checks if set(c.runs) <= have]


def _need(entry: dict, key: str, kind, where: str):
    if key not in entry:
        raise MatrixError(f"{where}: missing key `{key}`")
    value = entry[key]
    if not isinstance(value, kind) or isinstance(value, bool):
        raise MatrixError(f"{where}: `{key}` = {value!r} is not of type {kind.__name__}")
    return value


def _positive_int(entry: dict, key: str, where: str, default=None):
    if key not in entry and default is not None:
        return default
    value = _need(entry, key, int, where)
    if value < 1:
        raise MatrixError(f"{where}: `{key}` = {value} must be at least 1")
    return value


def _scene_name(scene: Path, where: str) -> str:
    try:
        with open(scene, "rb") as f:
            name = tomllib.load(f).get("name")
    except OSError as err:
        raise MatrixError(f"{where}: scene {scene}: {err.strerror}") from err
    except tomllib.TOMLDecodeError as err:
        raise MatrixError(f"{where}: scene {scene}: {err}") from err
    if not isinstance(name, str):
        raise MatrixError(f"{where}: scene {scene} has no string `name` (the run file's name)")
    return name


def load(path: Path = DEFAULT_MATRIX) -> Matrix:
    path = Path(path).resolve()
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except OSError as err:
        raise MatrixError(f"{path}: {err.strerror}") from err
    except tomllib.TOMLDecodeError as err:
        raise MatrixError(f"{path}: {err}") from err
    unknown = set(data) - {"defaults", "run", "check", "base"}
    if unknown:
        raise MatrixError(f"{path}: unknown table {sorted(unknown)} (known: defaults, run, check, base)")
    # `base` (optional): the directory scene paths are relative to (default: validation/, this file's parent's).
    base = (path.parent / data["base"]).resolve() if "base" in data else HERE.parent
    threads = _positive_int(data.get("defaults", {}), "threads", f"{path} [defaults]", default=1)
    runs, names = [], set()
    for k, e in enumerate(data.get("run", [])):
        where = f"{path} [[run]] #{k + 1}"
        bad = set(e) - RUN_KEYS
        if bad:
            raise MatrixError(f"{where}: unknown key {sorted(bad)} (known: {', '.join(sorted(RUN_KEYS))})")
        scene = (base / _need(e, "scene", str, where)).resolve()
        name = _scene_name(scene, where)
        if "name" in e and e["name"] != name:
            raise MatrixError(f"{where}: `name` = {e['name']!r} but the scene's name is {name!r}")
        if name in names:
            raise MatrixError(f"{where}: a second run named `{name}`")
        names.add(name)
        tier = _need(e, "tier", str, where)
        if tier not in TIERS:
            raise MatrixError(f"{where}: `tier` = {tier!r} (known: {', '.join(TIERS)})")
        args = e.get("args", [])
        if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
            raise MatrixError(f"{where}: `args` must be a list of strings")
        outputs = e.get("outputs", [f"{name}.h5", f"{name}.xdmf"])
        if not isinstance(outputs, list) or not all(isinstance(a, str) for a in outputs):
            raise MatrixError(f"{where}: `outputs` must be a list of strings")
        recover = _positive_int(e, "recover_timeout_s", where) if "recover_timeout_s" in e else None
        runs.append(Run(name, scene, tier, _positive_int(e, "threads", where, default=threads),
                        _positive_int(e, "timeout_s", where), recover, list(args), list(outputs)))
    checks = []
    for k, e in enumerate(data.get("check", [])):
        where = f"{path} [[check]] #{k + 1}"
        bad = set(e) - CHECK_KEYS
        if bad:
            raise MatrixError(f"{where}: unknown key {sorted(bad)} (known: {', '.join(sorted(CHECK_KEYS))})")
        tier = _need(e, "tier", str, where)
        if tier not in TIERS:
            raise MatrixError(f"{where}: `tier` = {tier!r} (known: {', '.join(TIERS)})")
        over = _need(e, "runs", list, where)
        missing = [n for n in over if n not in names]
        if missing or not over:
            raise MatrixError(f"{where}: `runs` names no [[run]] {missing}" if missing else f"{where}: `runs` is empty")
        checks.append(Check(_need(e, "name", str, where), _need(e, "case", str, where), tier, list(over)))
    if not runs:
        raise MatrixError(f"{path}: no [[run]]")
    return Matrix(path, runs, checks)
