"""Opens a run's XDMF sidecar in ParaView as a user would and checks what it shows.

    pvpython open_in_paraview.py RUN.xdmf OUT_DIR [--at T]    (needs an X display: xvfb-run, see CMakeLists.txt)

OpenDataFile picks ParaView's default reader for .xdmf (Xdmf3ReaderS in ParaView 5.11). Against the HDF5 run
file beside it (reports/SCHEMA.md) it checks the time steps, and at every step the points, the cells (one vertex
cell a particle), the arrays and their values; then the same counts through the legacy XDMFReader. It renders the
middle snapshot (with --at, the one nearest T s) coloured by pressure to OUT_DIR/<name>_pressure.png, seen from
the side in 2-D and from above the downstream corner in 3-D, checks the picture is not blank, and writes
OUT_DIR/paraview.json (what it found, for the V&V report's ParaView section). Exit 1 with the reasons when a check
fails.
"""
import json
import sys
from pathlib import Path

import h5py
import numpy as np
from paraview import simple
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import VTK_POLY_VERTEX, VTK_VERTEX
from vtkmodules.vtkIOImage import vtkPNGReader

ARRAYS = {"velocity": 3, "density": 1, "pressure": 1, "h": 1, "mass": 1, "phase": 1}
# The sidecar writes <Time Value> with the stream's default 6 significant digits (XdmfSidecar.cpp).
TIME_RTOL = 5e-6
# The rendered picture: 800 x 600 pixels on white; the particles' pixels are those that differ from the same view
# without them (the colour bar alone takes 1.0 % of the pixels, in 408 colours). Measured on the dam break's middle
# snapshot (t = 0.65 s, 1250 particles drawn as 4-pixel points): 4.3 % of the pixels, in 4698 distinct colours.
# The sidecar without cells gives 0 % (measured); particles drawn without the colour map would give one colour.
MIN_DRAWN_FRACTION = 0.01
MIN_COLOURS = 50


def snapshots(h5):
    with h5py.File(h5, "r") as f:
        names = sorted(f["snapshots"])
        return [{"time": float(f["snapshots"][n].attrs["time"]),
                 **{a: f["snapshots"][n][a][()] for a in ("position", *ARRAYS)}} for n in names]


def fetch(reader, t):
    reader.UpdatePipeline(t)
    return servermanager.Fetch(reader)


def check_step(grid, snap, failures, where):
    n = len(snap["position"])
    if grid.GetNumberOfPoints() != n or grid.GetNumberOfCells() != n:
        failures.append(f"{where}: {grid.GetNumberOfPoints()} points, {grid.GetNumberOfCells()} cells; "
                        f"the run file has {n} particles")
        return
    kinds = {grid.GetCellType(i) for i in range(n)}
    sizes = {grid.GetCell(i).GetNumberOfPoints() for i in range(0, n, max(1, n // 50))}
    if not kinds <= {VTK_VERTEX, VTK_POLY_VERTEX} or sizes != {1}:
        failures.append(f"{where}: cell types {sorted(kinds)}, points a cell {sorted(sizes)}; expected one vertex each")
    points = vtk_to_numpy(grid.GetPoints().GetData())
    if not np.array_equal(points, snap["position"]):
        failures.append(f"{where}: the points differ from the run file's positions")
    data = grid.GetPointData()
    for name, components in ARRAYS.items():
        array = data.GetArray(name)
        if array is None:
            failures.append(f"{where}: no point array '{name}'")
            continue
        values = vtk_to_numpy(array)
        if array.GetNumberOfComponents() != components or not np.array_equal(values.reshape(snap[name].shape),
                                                                           snap[name]):
            failures.append(f"{where}: point array '{name}' differs from the run file's")


def render(reader, t, pressure, png, solid=False):
    """The snapshot at time t drawn as points coloured by pressure, its colour range the 2nd to 98th percentile of
    the snapshot's `pressure` (the impact's few peaks would leave the rest of the water one colour)."""
    view = simple.CreateView("RenderView")
    view.ViewSize = [800, 600]
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 0
    view.ViewTime = t
    shown = simple.Show(reader, view)
    shown.SetRepresentationType("Points")
    shown.PointSize = 4
    simple.ColorBy(shown, ("POINTS", "pressure"))
    low, high = np.percentile(pressure, [2, 98])
    simple.GetColorTransferFunction("pressure").RescaleTransferFunction(float(low), float(high))
    shown.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(simple.GetColorTransferFunction("pressure"), view)
    bar.Title, bar.ComponentTitle = "pressure", "[Pa]"
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.WindowLocation = "Upper Right Corner"
    if solid:  # from above the corner at the first face of x and y (SPHERIC test 2: the box and the reservoir)
        view.InteractionMode = "3D"
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraPosition = [-1.0, -1.6, 1.2]
        view.CameraViewUp = [0.0, 0.0, 1.0]
    else:
        view.InteractionMode = "2D"
    simple.ResetCamera(view)
    simple.SaveScreenshot(str(png), view, ImageResolution=[800, 600])
    # The same view without the particles (the colour bar alone): the pixels that differ are the particles'.
    shown.Visibility = 0
    bare = png.with_name(png.stem + "_without_particles.png")
    simple.SaveScreenshot(str(bare), view, ImageResolution=[800, 600])
    simple.Delete(shown)
    simple.Delete(view)
    with_particles, without = rgb(png), rgb(bare)
    bare.unlink()
    particles = np.any(with_particles != without, axis=1)
    return float(particles.mean()), len(np.unique(with_particles[particles], axis=0))


def rgb(png):
    image = vtkPNGReader()
    image.SetFileName(str(png))
    image.Update()
    return vtk_to_numpy(image.GetOutput().GetPointData().GetScalars())[:, :3]


def main(argv):
    at = None
    if len(argv) == 5 and argv[3] == "--at":
        try:
            at = float(argv[4])
        except ValueError:
            print(f"--at {argv[4]}: not a time in seconds", file=sys.stderr)
            return 2
        argv = argv[:3]
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    xdmf, out = Path(argv[1]).resolve(), Path(argv[2])  # Xdmf3 resolves the HDF5 file from the sidecar's folder
    h5 = xdmf.with_suffix(".h5")
    for path in (xdmf, h5):
        if not path.is_file():
            print(f"{path}: no such file (run the scene first)", file=sys.stderr)
            return 1
    out.mkdir(parents=True, exist_ok=True)
    snaps = snapshots(h5)
    failures = []

    reader = simple.OpenDataFile(str(xdmf))
    name = reader.GetXMLName()
    if name != "Xdmf3ReaderS":
        failures.append(f"OpenDataFile chose {name}, not ParaView 5.11's default Xdmf3ReaderS")
    times = list(reader.TimestepValues)
    expected = [s["time"] for s in snaps]
    if len(times) != len(expected) or not np.allclose(times, expected, rtol=TIME_RTOL, atol=0):
        failures.append(f"time steps {times}; the run file's snapshots are at {expected}")
    points, cells = [], []
    for t, snap in zip(times, snaps):
        grid = fetch(reader, t)
        points.append(grid.GetNumberOfPoints())
        cells.append(grid.GetNumberOfCells())
        check_step(grid, snap, failures, f"{name}, t = {t:g} s")

    legacy = simple.XDMFReader(FileNames=[str(xdmf)])
    legacy_cells = [fetch(legacy, t).GetNumberOfCells() for t in legacy.TimestepValues]
    if legacy_cells != [len(s["position"]) for s in snaps]:
        failures.append(f"legacy XDMFReader: cells a step {legacy_cells}")

    k = len(times) // 2 if at is None else int(np.argmin(np.abs(np.asarray(times) - at))) if times else 0
    middle = times[k] if times else 0.0
    png = out / f"{xdmf.stem}_pressure.png"
    solid = bool(snaps) and bool(np.any(snaps[k]["position"][:, 2] != 0.0))  # a 3-D run (z = 0 in 1- and 2-D)
    drawn, colours = render(reader, middle, snaps[k]["pressure"], png, solid)
    if drawn < MIN_DRAWN_FRACTION or colours < MIN_COLOURS:
        failures.append(f"{png}: the particles drew {100 * drawn:.2f} % of the pixels, in {colours} colours; "
                        f"expected at least {100 * MIN_DRAWN_FRACTION:g} % and {MIN_COLOURS}")

    version = servermanager.vtkSMProxyManager.GetParaViewSourceVersion()
    found = {"run_file": str(h5), "xdmf": str(xdmf), "paraview": version, "reader": name,
             "time_steps": len(times), "points_per_step": points, "cells_per_step": cells, "legacy_reader_cells_per_step": legacy_cells,
             "arrays": sorted(ARRAYS), "picture": png.name, "picture_time": middle,
             "picture_drawn_fraction": drawn, "picture_colours": colours, "failures": failures}
    (out / "paraview.json").write_text(json.dumps(found, indent=1), encoding="utf-8")
    print(f"{version}, {name}: {len(times)} time steps, points a step {min(points, default=0)}.."
          f"{max(points, default=0)}, cells a step "
          f"{min(cells, default=0)}..{max(cells, default=0)}, arrays {', '.join(sorted(ARRAYS))}; "
          f"legacy XDMFReader cells {min(legacy_cells, default=0)}..{max(legacy_cells, default=0)}; "
          f"{png} (t = {middle:g} s, {100 * drawn:.1f} % of the pixels drawn by the particles, in {colours} colours)")
    for f in failures:
        print(f"FAIL: {f}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
