"""The FreeCAD add-on (hosts/freecad) under `freecadcmd`: each face of a
recognized fixture gets the colour of its feature's kind, checked face by
face on FreeCAD's own faces (their geometry is the face the result names)."""
from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
from pathlib import Path

import pytest

import thinwall
from conftest import ROOT

FREECADCMD = shutil.which("freecadcmd")
PARTS = [
    "fixtures/recognition/rib_grid_panel.step",
    "fixtures/bracket_with_pocket.step",
    "fixtures/revolved_details.step",
]

pytestmark = pytest.mark.skipif(
    FREECADCMD is None and not os.environ.get("THINWALL_REQUIRE_FREECAD"),
    reason="freecadcmd is not installed (Debian: apt-get install freecad)",
)


def _hex(c):
    return "#{:02x}{:02x}{:02x}".format(*(round(x * 255) for x in c[:3]))


def test_the_addon_colours_every_face_by_its_features_kind(tmp_path):
    assert FREECADCMD, "THINWALL_REQUIRE_FREECAD is set but freecadcmd is missing"
    out = tmp_path / "colours.json"
    # Only the package on FreeCAD's path, not the environment it is
    # installed in (its other packages are for another Python).
    only = tmp_path / "path"
    only.mkdir()
    (only / "thinwall").symlink_to(Path(thinwall.__file__).parent)
    env = dict(os.environ)
    env.update(
        THINWALL_SYS_PATH=os.pathsep.join([str(ROOT / "hosts" / "freecad"), str(only)]),
        THINWALL_PARTS=os.pathsep.join(str(ROOT / p) for p in PARTS),
        THINWALL_OUT=str(out),
    )
    script = Path(__file__).with_name("freecad_colours.py")
    run = subprocess.run([FREECADCMD, str(script)], env=env, capture_output=True, text=True, timeout=600)
    assert out.exists(), run.stdout + run.stderr
    got = json.loads(out.read_text())
    assert got["error"] is None, got["error"]
    assert len(got["parts"]) == len(PARTS)
    palette = thinwall.palette()
    for part in got["parts"]:
        result = thinwall.Recognition(part["result"])
        n = len(part["faces"])
        assert len(result.occ_faces) == n == len(part["kinds"]) == len(part["colours"])
        expected = ["other"] * n
        for f in result.machining_features:
            for face in f.faces:
                expected[face.occ_index] = f"machining.{f.kind}"
        for f in result.stiffness_features:
            for face in f.faces:
                expected[face.occ_index] = f"stiffness.{f.kind}"
        # Stiffness features win over machining ones, the last one listing
        # a face over earlier ones.
        assert part["kinds"] == expected, part["path"]
        for kind, colour in zip(part["kinds"], part["colours"]):
            assert _hex(colour) == palette.get(kind, "#cdcdcd")
        # The face FreeCAD numbers i is the face the result names i: the
        # same area and centroid as Thinwall's own figures for it.
        ours = {(f["body"], f["step_id"]): f for f in part["inspected"]["faces"]}
        size = math.dist(*(part["result"]["part"]["bounding_box"][k] for k in ("min", "max")))
        for i, key in enumerate(part["result"]["opencascade_faces"]):
            mine = ours[(key["body"], key["step_id"])]
            fc = part["faces"][i]
            assert abs(fc["area"] - mine["area"]) <= 1e-3 * max(mine["area"], 1.0), (part["path"], i)
            assert math.dist(fc["centroid"], mine["centroid"]) <= 1e-3 * size, (part["path"], i)
