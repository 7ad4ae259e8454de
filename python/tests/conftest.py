"""Shared pieces of the Python package's tests: where the repository, the
shared third-party parts and the command line are, and an OpenCascade
oracle of which STEP entity each of its faces came from."""
from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path
from typing import List, Optional

import pytest

ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THINWALL_DATA", ROOT.parent / "shared" / "data"))


def step_files(folder: Path) -> List[Path]:
    return sorted(p for p in folder.rglob("*") if p.suffix.lower() in (".step", ".stp"))


FIXTURES = step_files(ROOT / "fixtures")
SHARED = step_files(DATA) if DATA.is_dir() else []


def cli_path() -> Path:
    """The release `thinwall` binary (built by the test command first)."""
    path = Path(os.environ.get("THINWALL_CLI", ROOT / "target" / "release" / "thinwall"))
    if not path.exists():
        pytest.fail(f"{path} is missing: build it with `cargo build --release -p thinwall-cli`")
    return path


def run_cli(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([str(cli_path()), *args], capture_output=True, text=True, cwd=cwd)


def _labels_in_order(path: Path) -> List[int]:
    """The `#id`s of the file's DATA section in file order (OpenCascade's
    entity numbers count them in that order)."""
    text = path.read_text(encoding="latin-1")
    data = text[text.find("DATA;"):]
    data = re.sub(r"/\*.*?\*/", "", data, flags=re.S)
    data = re.sub(r"'(?:[^']|'')*'", "''", data)
    return [int(x) for x in re.findall(r"(?:^|;)\s*#(\d+)\s*=", data)]


class OccPart:
    """A STEP file as OpenCascade reads it: its faces in `TopExp::MapShapes`
    order, each with the `#id` of the STEP entity it was made from."""

    def __init__(self, path: Path):
        from OCP.STEPControl import STEPControl_Reader
        from OCP.IFSelect import IFSelect_RetDone
        from OCP.TopAbs import TopAbs_FACE
        from OCP.TopExp import TopExp
        from OCP.OCP.collections import IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as Map

        reader = STEPControl_Reader()
        assert reader.ReadFile(str(path)) == IFSelect_RetDone, path
        reader.TransferRoots()
        self.shape = reader.OneShape()
        faces = Map()
        TopExp.MapShapes_s(self.shape, TopAbs_FACE, faces)
        self.faces = [faces.FindKey(i) for i in range(1, faces.Extent() + 1)]
        model = reader.StepModel()
        transfer = reader.WS().TransferReader()
        # OCP hands back the same Python object for the same entity, so an
        # entity's number in the model is found by identity.
        entities = [model.Value(k) for k in range(1, model.NbEntities() + 1)]
        number = {id(e): k for k, e in enumerate(entities, 1)}
        labels = _labels_in_order(path)
        assert len(labels) == len(entities), (path, len(labels), len(entities))
        self.labels: List[Optional[int]] = []
        for f in self.faces:
            e = transfer.EntityFromShapeResult(f, -1)
            k = number.get(id(e)) if e is not None else None
            self.labels.append(labels[k - 1] if k else None)

    @staticmethod
    def props(face):
        """Area (mm²) and centroid of a face."""
        from OCP.BRepGProp import BRepGProp
        from OCP.GProp import GProp_GProps

        p = GProp_GProps()
        BRepGProp.SurfaceProperties_s(face, p)
        c = p.CentreOfMass()
        return p.Mass(), (c.X(), c.Y(), c.Z())
