#!/usr/bin/env python3
"""Make labelled MFCAD++ parts with the MFCAD++ generator, on OCP, with seeds of our own.

    python3 scripts/generate_mfcadpp.py --upstream DIR OUT FIRST COUNT [--seed S] [--jobs N]

DIR is a checkout of the generator (MIT): `git clone https://github.com/josephkwok986/mfcad2`.
It runs unchanged through `mfcadpp_compat` (OCP in place of pythonocc-core). Needs numba and
scipy besides OCP (`pip install cadquery-ocp-novtk numba scipy`).

Part i (FIRST <= i < FIRST+COUNT) reseeds Python's `random` with S*1000003 + i, draws its
feature combination as the upstream `main.py` does (3 to 9 features, uniform over all multisets
of the 24 classes) and builds it with the generator's `shape_from_directive`. It is written as
OUT/s<S>_<i>.step, each ADVANCED_FACE named by its class id as MFCAD++ files are, with
OUT/s<S>_<i>.labels.json ({"face_labels_by_step_id": {...}, "classes": [...]}, the shared set's
format) and a line in OUT/manifest.jsonl. Parts are built in child processes, because
OpenCascade's fillets can crash the process (the generator's README warns of it): a part that
crashes or times out is recorded in the manifest, written as no file, and the rest go on.

The parts are never committed: `cargo test --release --test machining_catalog -- --ignored`
scores a folder named by THINWALL_MFCADPP_DIR (docs/GENERATOR.md).
"""

import argparse
import json
import math
import os
import random
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

CLASSES = 24  # the generator's feature classes; 24 is stock
FEATURES = range(3, 10)  # features per part, as upstream main.py's combo range
BATCH = 20  # parts per child process


def combination(rng):
    """A multiset of 3-9 classes, uniform over all such multisets (as listing every
    `combinations_with_replacement` and shuffling would give, without listing them)."""
    counts = [math.comb(CLASSES + k - 1, k) for k in FEATURES]
    k = rng.choices(list(FEATURES), weights=counts)[0]
    # Stars and bars: k positions among CLASSES+k-1 mark the multiset, one to one.
    bars = sorted(rng.sample(range(CLASSES + k - 1), k))
    return [b - i for i, b in enumerate(bars)]


def build(upstream, seed):
    """(shape, {face: label}, combo) of the part with this seed; shape is None if no part."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import mfcadpp_compat

    mfcadpp_compat.install(upstream)
    import feature_creation

    random.seed(seed)
    combo = combination(random)
    shape, labels = feature_creation.shape_from_directive(combo)
    return shape, labels, combo


def write_step(shape, labels, path):
    """The STEP file with each face's ADVANCED_FACE named by its label; {step id: label}."""
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.STEPConstruct import STEPConstruct
    from OCP.STEPControl import STEPControl_AsIs, STEPControl_Writer
    from OCP.TCollection import TCollection_HAsciiString
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopLoc import TopLoc_Location

    writer = STEPControl_Writer()
    writer.Transfer(shape, STEPControl_AsIs)
    finder = writer.WS().TransferWriter().FinderProcess()
    explorer = TopExp_Explorer(shape, TopAbs_FACE)
    while explorer.More():
        face = explorer.Current()
        item = STEPConstruct.FindEntity_s(finder, face, TopLoc_Location())
        if item is None or face not in labels:
            raise RuntimeError(f"{path}: a face with no STEP entity or no label")
        item.SetName(TCollection_HAsciiString(str(labels[face])))
        explorer.Next()
    if writer.Write(str(path)) != IFSelect_RetDone:
        raise RuntimeError(f"{path}: STEP write failed")
    found = re.findall(r"#(\d+)\s*=\s*ADVANCED_FACE\('(\d+)'", path.read_text())
    return {int(i): int(c) for i, c in found}


def one(args, i):
    """Build and write part i; its manifest line."""
    seed = args.seed * 1000003 + i
    stem = f"s{args.seed}_{i:04d}"
    shape, labels, combo = build(args.upstream, seed)
    line = {"stem": stem, "seed": seed, "combination": combo}
    if shape is None:
        line["status"] = "no part"
        return line
    from OCP.BRepCheck import BRepCheck_Analyzer

    out = Path(args.out)
    by_id = write_step(shape, labels, out / f"{stem}.step")
    faces = count_faces(shape)
    if len(by_id) != faces or not all(0 <= c <= CLASSES for c in by_id.values()):
        raise RuntimeError(f"{stem}: {len(by_id)} named faces of {faces}, or a bad class")
    (out / f"{stem}.labels.json").write_text(
        json.dumps({"face_labels_by_step_id": {str(k): v for k, v in sorted(by_id.items())},
                    "classes": class_names(args.upstream)})
        + "\n"
    )
    counts = {}
    for c in by_id.values():
        counts[c] = counts.get(c, 0) + 1
    line.update(status="ok", faces=len(by_id), per_class=dict(sorted(counts.items())),
                brep_valid=BRepCheck_Analyzer(shape).IsValid())
    return line


def child(args):
    """Child process: build the parts it is given in order, one manifest line each."""
    for i in args.parts:
        print(json.dumps(one(args, i)), flush=True)


def count_faces(shape):
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer

    explorer, n = TopExp_Explorer(shape, TopAbs_FACE), 0
    while explorer.More():
        n += 1
        explorer.Next()
    return n


def class_names(upstream):
    import Utils.parameters as param  # the generator's own list, already imported by build()

    assert Path(param.__file__).resolve().is_relative_to(Path(upstream).resolve())
    return list(param.feat_names)


def run_batch(args, parts):
    """Manifest lines of `parts`, built in child processes (numba compiles once per process).
    A part that crashes its process or runs out of time is recorded, and the rest go on."""
    lines, todo = [], list(parts)
    while todo:
        cmd = [sys.executable, __file__, "--upstream", args.upstream, "--seed", str(args.seed),
               "--parts", ",".join(map(str, todo)), args.out, "0", "0"]
        try:
            done = subprocess.run(cmd, capture_output=True, text=True,
                                  timeout=args.timeout * len(todo))
            why = (done.stderr.strip().splitlines() or ["no message"])[-1][:200]
            out, status = done.stdout, f"crashed (exit {done.returncode}): {why}"
        except subprocess.TimeoutExpired as e:
            out, status = e.stdout or "", "timed out"
            out = out.decode() if isinstance(out, bytes) else out
        got = [json.loads(x) for x in out.splitlines() if x.startswith("{")]
        lines += got
        todo = todo[len(got):]
        if todo:  # the first part not reported took the process down
            lines.append({"stem": f"s{args.seed}_{todo[0]:04d}", "status": status})
            todo = todo[1:]
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("first", type=int)
    ap.add_argument("count", type=int)
    ap.add_argument("--upstream", default=os.environ.get("MFCADPP_UPSTREAM"),
                    help="checkout of josephkwok986/mfcad2 (or MFCADPP_UPSTREAM)")
    ap.add_argument("--seed", type=int, default=31415, help="the corpus seed S (default 31415)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds per part")
    ap.add_argument("--parts", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if not args.upstream:
        sys.exit("--upstream DIR (a checkout of josephkwok986/mfcad2) is required")
    args.upstream = str(Path(args.upstream).resolve())
    if args.parts is not None:
        args.parts = [int(x) for x in args.parts.split(",")]
        return child(args)
    Path(args.out).mkdir(parents=True, exist_ok=True)
    parts = list(range(args.first, args.first + args.count))
    batches = [parts[i:i + BATCH] for i in range(0, len(parts), BATCH)]
    done = 0
    with ThreadPoolExecutor(max(1, args.jobs)) as pool, \
            open(Path(args.out) / "manifest.jsonl", "a") as manifest:
        for lines in pool.map(lambda b: run_batch(args, b), batches):
            for line in lines:
                done += 1
                manifest.write(json.dumps(line) + "\n")
                print(f"[{done}/{len(parts)}] {line['stem']}: {line['status']}",
                      file=sys.stderr, flush=True)
            manifest.flush()


if __name__ == "__main__":
    main()
