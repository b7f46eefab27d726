#!/usr/bin/python3
"""Compares two run files (reports/SCHEMA.md) dataset by dataset, bit for bit.

    compare_runs.py A.h5 B.h5

Every dataset of /series and /snapshots, the /scene text and the root attributes that say what
ran (kernel, terms, status, failure) must be equal; provenance and timing (date, commit, wall
time, threads, the thread tuner's fraction) may differ. Prints the count of datasets compared
and exits 1 at the first difference, naming it.
"""
import sys

import h5py
import numpy as np

PHYSICS_ATTRIBUTES = ("dimension", "gravity", "rho0", "kernel", "integrator", "terms", "status",
                      "failure_cause", "failure")
# What a run file written before the attribute existed ran.
DEFAULTS = {"integrator": b"predictor_corrector"}
TIMING_METRICS = ("wall_time_s", "particle_evaluations_per_s", "steps_on_all_threads")


def datasets(f):
    out = {}
    f.visititems(lambda name, obj: out.__setitem__(name, obj) if isinstance(obj, h5py.Dataset) else None)
    return out


def main(a_path, b_path):
    with h5py.File(a_path, "r") as a, h5py.File(b_path, "r") as b:
        for key in PHYSICS_ATTRIBUTES:
            x, y = a.attrs.get(key, DEFAULTS.get(key)), b.attrs.get(key, DEFAULTS.get(key))
            if (x is None) != (y is None) or (x is not None and np.any(x != y)):
                sys.exit(f"root attribute {key}: {x!r} != {y!r}")
        for key in set(a["metrics"].attrs) | set(b["metrics"].attrs):
            if key in TIMING_METRICS:
                continue
            if np.any(a["metrics"].attrs.get(key) != b["metrics"].attrs.get(key)):
                sys.exit(f"/metrics {key}: {a['metrics'].attrs.get(key)} != {b['metrics'].attrs.get(key)}")
        da, db = datasets(a), datasets(b)
        if set(da) != set(db):
            sys.exit(f"datasets differ: only in A {sorted(set(da) - set(db))[:5]}, only in B {sorted(set(db) - set(da))[:5]}")
        for name in sorted(da):
            x, y = da[name][()], db[name][()]
            if isinstance(x, np.ndarray) and x.dtype.kind == "f":
                same = x.shape == y.shape and np.array_equal(x.view(np.uint64 if x.itemsize == 8 else np.uint32),
                                                             y.view(np.uint64 if y.itemsize == 8 else np.uint32))
            else:
                same = np.array_equal(x, y)
            if not same:
                sys.exit(f"dataset /{name} differs")
        print(f"{len(da)} datasets bit-identical")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
