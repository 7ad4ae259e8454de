"""Property tests over generated thin-walled parts (issue 39,
docs/GENERATOR.md): pocketed panels (drafts 0-5 degrees, corner radii,
floor fillets, holes, cut-outs) and curved skins with stringers on either
side, each in a random pose, against the truth the generator writes.

The sample is in-sample seeds (rules were tuned on 0..999); the held-out
range (1,000,000 on) is scored only by `scripts/score_generated.py` and
reported in docs/GENERATOR.md, never looked at here.
"""
from __future__ import annotations

import sys

import pytest

from conftest import ROOT

sys.path.insert(0, str(ROOT / "scripts"))
import score_generated  # noqa: E402

SAMPLE = range(0, 400)
CHUNK = 20
#: Issue 39's acceptance: stiffness features F1 at least this, turned.
F1_FLOOR = 0.999


#: Seeds also judged with the reach of every wall side (the CLI's default):
#: each side's fraction, `reachable` flag and blockers the same turned.
REACH_SAMPLE = range(0, 40)


def chunk(first: int, reach: bool = False, size: int = CHUNK):
    counts, problems, posed = [0, 0, 0], [], []
    for seed in range(first, first + size):
        family, tp, fp, fn, found = score_generated.check(seed, reach)
        counts = [counts[0] + tp, counts[1] + fp, counts[2] + fn]
        problems += [f"seed {seed} ({family}): {p}" for p in found if not p.startswith("pose:")]
        posed += [f"seed {seed} ({family}): {p}" for p in found if p.startswith("pose:")]
    return counts, problems, posed


@pytest.mark.parametrize("first", range(SAMPLE.start, SAMPLE.stop, CHUNK))
def test_generated_parts_match_their_truth_in_any_pose(first):
    (tp, fp, fn), problems, posed = chunk(first)
    assert tp > 100, f"only {tp} truth items matched"
    f1 = 2 * tp / (2 * tp + fp + fn)
    assert f1 >= F1_FLOOR, f"F1 {f1:.4f} (tp {tp}, fp {fp}, fn {fn}):\n" + "\n".join(problems)
    # Turned: the same features, faces, kinds and figures (within 1e-6)
    # as the part in the frame it was drawn in.
    assert not posed, "\n".join(posed)


@pytest.mark.parametrize("first", range(REACH_SAMPLE.start, REACH_SAMPLE.stop, CHUNK // 2))
def test_generated_parts_reach_the_same_in_any_pose(first):
    """Reach fractions within 1e-6 and the same blockers turned (issue 39):
    arcs sampled from their own parametrisation, boolean slivers named as
    blockers and a wall side's band heights counted with their copies each
    once changed them with the pose."""
    _, problems, posed = chunk(first, reach=True, size=CHUNK // 2)
    assert not problems, "\n".join(problems)
    assert not posed, "\n".join(posed)


def test_the_truth_sees_what_it_was_drawn_with():
    """The truth of a part names faces that exist and are what they claim:
    a wall's sides are planes or the skin's cylinders, a hole is a cylinder."""
    import generate_parts
    for seed in (0, 1, 2, 3):
        shape, doc = generate_parts.part(seed)
        n = doc["face_count"]
        assert n == len(generate_parts.faces_of(shape))
        named = [i for f in doc["features"] for i in f.get("side_faces", []) + f.get("faces", [])]
        assert named and all(0 <= i < n for i in named)
        assert len(named) == len(set(named)), "a face in two features"
        kinds = {f["kind"] for f in doc["features"]}
        assert "web" in kinds
