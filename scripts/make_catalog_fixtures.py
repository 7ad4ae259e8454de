#!/usr/bin/env python3
"""Generate catalogue fixtures: what other cuts leave of an MFCAD++ feature, drawn small, each a
class of failure the MFCAD++ generator's parts showed (docs/GENERATOR.md):

- `hexagon_pocket_three_walls.step`: a hexagonal pocket (circumradius 6, 8 deep) whose far half a
  rectangular passage took, leaving three of its walls (normals 60 degrees apart) and a floor;
- `blind_hole_from_step_floor.step`: a blind hole Ø4, 8 deep, drilled from a step's floor (not a
  block face), a quarter of it taken by a rectangular passage along its axis.

usage: python3 scripts/make_catalog_fixtures.py [OUT_DIR]   (default fixtures/machining/catalog)
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, cut, write  # noqa: E402
from make_access_fixtures import prism_z  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt  # noqa: E402


def hexagon_pocket_three_walls():
    """Block 40 x 40 x 20; a hexagon (corners at 30 + 60k degrees) pocketed 8 deep from the top
    round (20, 20); a 10 x 20 passage through the block over x > 19 takes its far half."""
    hexagon = [(20 + 6 * math.cos(math.radians(30 + 60 * k)),
                20 + 6 * math.sin(math.radians(30 + 60 * k))) for k in range(6)]
    part = cut(box(0, 0, 0, 40, 40, 20), prism_z(hexagon, 12, 22))
    return cut(part, box(19, 10, -1, 29, 30, 21))


def blind_hole_from_step_floor():
    """Block 40 x 30 x 30 with a step along x (y < 10, z > 20); a hole Ø4 from the step's floor
    down 8 round (20, 5); a 5.5 x 2.5 passage down through the block over x > 20.5, y > 5.5."""
    part = cut(box(0, 0, 0, 40, 30, 30), box(-1, -1, 20, 41, 10, 31))
    hole = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 5, 12), gp_Dir(0, 0, 1)), 2.0, 9.0).Shape()
    part = cut(part, hole)
    return cut(part, box(20.5, 5.5, -1, 26, 8, 21))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "fixtures/machining/catalog"
    os.makedirs(out, exist_ok=True)
    write(hexagon_pocket_three_walls(), os.path.join(out, "hexagon_pocket_three_walls.step"))
    write(blind_hole_from_step_floor(), os.path.join(out, "blind_hole_from_step_floor.step"))


if __name__ == "__main__":
    main()
