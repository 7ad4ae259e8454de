#!/usr/bin/env python3
"""Generate plates whose curved faces rise above all their edges, with
their truth: a half-torus bead standing on the top face (its circles on
the plate, its crest r above it), a spherical dome (a cap of a sphere, its
pole above the plate), and a bead hanging from the underside. Sizes and
places come from a seeded generator.

Each part is `bulges_SEED.step` with `bulges_SEED.truth.json`: the plate's
size, each bulge's kind, centre and radii, and the part's extent along the
world axes (`lo`, `hi`, mm): along z the crests, not the edges; and its
volume in closed form (`volume`, mm³).

usage: python3 scripts/make_bulge_fixtures.py [OUT_DIR [FIRST_SEED [COUNT]]]
       (default fixtures/bulges, seeds 1..3)
"""
import math, os, random, sys

sys.path.insert(0, os.path.dirname(__file__))
from make_recognition_fixtures import box, fuse, write_generated  # noqa: E402
from OCP.BRepPrimAPI import BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeTorus  # noqa: E402
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt  # noqa: E402

UP = gp_Dir(0, 0, 1)


def part(seed):
    rnd = random.Random(seed)
    length = round(rnd.uniform(80.0, 140.0), 2)
    width = round(rnd.uniform(50.0, 90.0), 2)
    t = round(rnd.uniform(5.0, 9.0), 2)
    body = box(0, 0, 0, length, width, t)
    bulges = []

    # A bead on the top face, in the plate's left half.
    r = round(rnd.uniform(1.0, min(3.0, t / 2 - 0.5)), 3)
    big = round(rnd.uniform(8.0, min(18.0, width / 2 - r - 4.0)), 3)
    c = (round(rnd.uniform(big + r + 3, length / 2 - big - r - 2), 3),
         round(rnd.uniform(big + r + 3, width - big - r - 3), 3), t)
    body = fuse(body, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(*c), UP), big, r).Shape())
    bulges.append({"kind": "bead", "centre": list(c), "major_radius": big, "minor_radius": r,
                   "crest": t + r})

    # A dome in the right half: a cap of a sphere, h high on the plate.
    rs = round(rnd.uniform(8.0, 20.0), 3)
    h = round(rnd.uniform(2.0, min(6.0, rs - 1.0)), 3)
    foot = math.sqrt(rs * rs - (rs - h) ** 2)
    centre = (round(rnd.uniform(length / 2 + foot + 2, length - foot - 3), 3),
              round(rnd.uniform(foot + 3, width - foot - 3), 3), t - (rs - h))
    cap = BRepPrimAPI_MakeSphere(gp_Ax2(gp_Pnt(*centre), UP), rs,
                                 math.asin((rs - h) / rs), math.pi / 2).Shape()
    body = fuse(body, cap)
    bulges.append({"kind": "dome", "centre": list(centre), "radius": rs, "crest": t + h})

    # A bead hanging from the underside.
    ru = round(rnd.uniform(1.0, min(2.5, t / 2 - 0.5)), 3)
    bu = round(rnd.uniform(6.0, 12.0), 3)
    cu = (round(rnd.uniform(bu + ru + 3, length - bu - ru - 3), 3), round(width / 2, 3), 0.0)
    body = fuse(body, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(*cu), UP), bu, ru).Shape())
    bulges.append({"kind": "bead", "centre": list(cu), "major_radius": bu, "minor_radius": ru,
                   "crest": -ru})

    hi = max(b["crest"] for b in bulges)
    lo = min(b["crest"] for b in bulges)
    # The plate, the beads' halves outside it (pi^2 R r^2 each: half a
    # torus) and the dome's cap (pi h^2 (3 rs - h) / 3).
    volume = (length * width * t + math.pi ** 2 * big * r * r + math.pi ** 2 * bu * ru * ru
              + math.pi * h * h * (3 * rs - h) / 3)
    truth = {"seed": seed, "length": length, "width": width, "thickness": t,
             "bulges": bulges, "lo": [0.0, 0.0, lo], "hi": [length, width, hi],
             "volume": volume}
    return body, truth


def main():
    write_generated("bulges", part, "fixtures/bulges", 3)


if __name__ == "__main__":
    main()
