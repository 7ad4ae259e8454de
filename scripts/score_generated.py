#!/usr/bin/env python3
"""Score Thinwall's stiffness features on generated parts against their
truth (scripts/generate_parts.py, docs/GENERATOR.md).

A truth wall counts as found when one of ours has exactly its side faces,
its kind, and its thickness (foot and top too, when drafted) within
0.01 mm; a hole or cut-out when one of ours has exactly its faces, its
kind, and sits in the wall found for the truth's wall; a connection when
ours links the two features found for its ends. Every thin wall, hole or
cut-out of ours that found nothing counts against us, and so does every
connection of ours between two found features that the truth lacks.
F1 = 2 TP / (2 TP + FP + FN) over all of them.

Pose: every part is also recognised in the frame it was drawn in; the
turned copy must give the same features with the same faces (ordinals),
kinds and figures within 1e-6 (reach fractions too, with --reach).

usage: target/python-venv/bin/python scripts/score_generated.py FIRST COUNT [--reach] [--jobs N]
"""
import math, os, sys
from collections import Counter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_parts  # noqa: E402

#: Thickness agreement with the truth, mm (issue 39).
THICKNESS_TOL = 0.01
#: Figures of a turned copy against the part as drawn (issue 39).
POSE_TOL = 1e-6
WALLS = ("web", "rib", "flange", "wall")
DEPRESSIONS = ("hole", "cutout", "notch")


def ordinals(feature, field):
    return frozenset(f.occ_index for f in feature.resolve(field))


def score(doc, result):
    """Counts and the differences, as (tp, fp, fn, problems)."""
    ours = list(result.stiffness_features)
    tp = fp = fn = 0
    problems = []
    found = {}  # truth id -> our id
    for t in doc["features"]:
        if t["kind"] in WALLS:
            want = frozenset(t["side_faces"])
            hit = [f for f in ours if f.get("side_faces") and ordinals(f, "side_faces") == want]
        else:
            want = frozenset(t["faces"])
            hit = [f for f in ours if ordinals(f, "faces") == want]
        why = wrong(t, hit[0], found) if hit else "not found"
        if why:
            fn += 1
            problems.append(f"{t['kind']} {t['id']}: {why}")
        else:
            tp += 1
            found[t["id"]] = hit[0]["id"]
    matched = set(found.values())
    for f in ours:
        counted = (f["kind"] in WALLS and f.get("thin")) or f["kind"] in DEPRESSIONS
        if counted and f["id"] not in matched:
            fp += 1
            problems.append(f"extra {f['kind']} {f['id']} faces {sorted(ordinals(f, 'faces'))}")
    ctp, cfp, cfn, cprob = connection_score(doc, result, found)
    return tp + ctp, fp + cfp, fn + cfn, problems + cprob


def wrong(t, f, found):
    """Why our feature `f`, with the truth's faces, is not the truth's `t`."""
    if f["kind"] != t["kind"]:
        return f"is a {f['kind']} ({f['id']})"
    if t["kind"] in WALLS:
        for key in ("thickness", "thickness_foot", "thickness_top"):
            if key in t and abs((f.get(key) or 0.0) - t[key]) > THICKNESS_TOL:
                return f"{key} {f.get(key)} (truth {t[key]:.4f})"
        if f.get("thin") is not True:
            return "not thin"
        return None
    if found.get(t["wall"]) is None or f.get("wall") != found[t["wall"]]:
        return f"in {f.get('wall')}, truth {t['wall']} ({found.get(t['wall'])})"
    return None


def connection_score(doc, result, found):
    def key(kind, a, b):
        return (kind,) + (tuple(sorted((a, b))) if kind == "crossing" else (a, b))

    want = set()
    for c in doc["connections"]:
        if c["base"] in found and c["leaf"] in found:
            want.add(key(c["kind"], found[c["base"]], found[c["leaf"]]))
    missing_end = sum(1 for c in doc["connections"] if c["base"] not in found or c["leaf"] not in found)
    known = set(found.values())
    got = set()
    for c in result.connections:
        if c["kind"] == "crossing":
            a, b = c["features"]
        else:
            a, b = c["base"], c["leaf"]
        if a in known and b in known:
            got.add(key(c["kind"], a, b))
    problems = [f"missing {' '.join(k)}" for k in sorted(want - got)]
    problems += [f"extra {' '.join(k)}" for k in sorted(got - want)]
    return len(want & got), len(got - want), len(want - got) + missing_end, problems


def signature(result):
    """What must not change with the pose: features by faces and figures."""
    out = {}
    for f in list(result.stiffness_features) + list(result.machining_features):
        d = f.to_dict()
        figures = {k: v for k, v in d.items() if isinstance(v, (int, float)) and not isinstance(v, bool)}
        for i, side in enumerate(d.get("access") or []):
            figures[f"access{i}.fraction"] = side.get("fraction", 0.0)
            figures[f"access{i}.reachable"] = float(bool(side.get("reachable")))
            figures[f"access{i}.blocked_by"] = float(len(side.get("blocked_by") or []))
        out[(d["kind"], ordinals(f, "faces"))] = (d.get("thin"), figures)
    return out


def pose_differences(built, turned, tol=POSE_TOL):
    a, b = signature(built), signature(turned)
    problems = [f"pose: {k[0]} {sorted(k[1])} only as drawn" for k in a.keys() - b.keys()]
    problems += [f"pose: {k[0]} {sorted(k[1])} only turned" for k in b.keys() - a.keys()]
    for k in a.keys() & b.keys():
        (thin_a, fa), (thin_b, fb) = a[k], b[k]
        if thin_a != thin_b:
            problems.append(f"pose: {k[0]} {sorted(k[1])} thin {thin_a} / {thin_b}")
        for name in fa.keys() | fb.keys():
            x, y = fa.get(name), fb.get(name)
            if x is None or y is None or abs(x - y) > tol * max(1.0, abs(x)):
                problems.append(f"pose: {k[0]} {sorted(k[1])} {name} {x} / {y}")
    return problems


def check(seed, reach=False):
    """(family, tp, fp, fn, problems) of part `seed`, turned, plus its pose
    differences against the part as drawn."""
    import thinwall
    import thinwall.occ
    options = {} if reach else {"no_reach": True}
    (flat, flat_doc), (shape, doc) = generate_parts.drawn(seed)
    turned = thinwall.occ.recognize(shape, up=",".join(map(repr, doc["up"])), **options)
    tp, fp, fn, problems = score(doc, turned)
    built = thinwall.occ.recognize(flat, up=",".join(map(repr, flat_doc["up"])), **options)
    problems += pose_differences(built, turned)
    return doc["family"], tp, fp, fn, problems


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    first, count = int(args[0]), int(args[1])
    reach = "--reach" in sys.argv
    jobs = int(sys.argv[sys.argv.index("--jobs") + 1]) if "--jobs" in sys.argv else os.cpu_count()
    from concurrent.futures import ProcessPoolExecutor
    totals, classes = Counter(), Counter()
    posed_ok = 0
    with ProcessPoolExecutor(jobs) as pool:
        for seed, (family, tp, fp, fn, problems) in zip(
                range(first, first + count),
                pool.map(check, range(first, first + count), [reach] * count)):
            totals[family, "tp"] += tp
            totals[family, "fp"] += fp
            totals[family, "fn"] += fn
            posed_ok += not any(p.startswith("pose:") for p in problems)
            for p in problems:
                print(f"seed {seed} ({family}): {p}")
                classes[p.split(":")[0] if p.startswith("pose") else " ".join(p.split()[:1] + p.split()[2:3])] += 1
    print(f"\nseeds {first}..{first + count - 1}:")
    for family in sorted({k[0] for k in totals}):
        tp, fp, fn = (totals[family, x] for x in ("tp", "fp", "fn"))
        f1 = 2 * tp / (2 * tp + fp + fn) if tp else 0.0
        print(f"  {family}: F1 {f1:.4f} (tp {tp}, fp {fp}, fn {fn})")
    tp, fp, fn = (sum(v for k, v in totals.items() if k[1] == x) for x in ("tp", "fp", "fn"))
    print(f"  all: F1 {2 * tp / (2 * tp + fp + fn):.4f}; same answer turned: {posed_ok} of {count}")
    for c, n in classes.most_common(12):
        print(f"  {n:5d}  {c}")


if __name__ == "__main__":
    main()
