"""--paraview DIR: what validation/paraview/open_in_paraview.py found when ParaView opened the dam break
(DIR/paraview.json) and the picture it rendered, copied beside index.html."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

WRITER = "the nightly test paraview.DamBreakOpensWithDefaultReader"


def read(directory: Path | None, out: Path) -> dict | None:
    """None without --paraview; else paraview.json's entries, with "figure" (the picture's name in `out`, or None)
    and "error" (why something is missing, or empty); "others", the same for each folder in DIR that holds a
    paraview.json (paraview.SphericImpactOpensWithDefaultReader's spheric_dam_break/)."""
    if directory is None:
        return None
    found = read_one(directory, out)
    found["others"] = [read_one(sub, out) for sub in sorted(directory.iterdir())
                       if sub.is_dir() and (sub / "paraview.json").is_file()]
    return found


def read_one(directory: Path, out: Path) -> dict:
    path = directory / "paraview.json"
    try:
        found = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        return {"error": f"{path}: not read ({type(err).__name__}: {err}); {WRITER} writes it"}
    if not isinstance(found, dict) or not isinstance(found.get("cells_per_step"), list):
        return {"error": f"{path}: expected the object {WRITER} writes, with cells_per_step"}
    found["figure"], found["error"] = None, ""
    picture = directory / str(found.get("picture", ""))
    if found.get("picture") and picture.is_file():
        found["figure"] = f"paraview-{picture.name}"
        shutil.copyfile(picture, out / found["figure"])
    else:
        found["error"] = f"{picture}: the picture is missing"
    return found
