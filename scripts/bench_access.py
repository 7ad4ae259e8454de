#!/usr/bin/env python3
"""Wall-clock time of `thinwall access` (reach of every face with its largest
tool, and flank milling) per NIST part, release build, on all cores.

One run per part (the long parts take minutes): prints a Markdown table of
faces, floors, seconds, and the floors' and faces' results as a checksum
(sum of reached fractions, sum of largest tools), so that a speed change
can show it changed nothing else. No OpenCascade peer: OCC has no reach
computation to set beside it.

usage: python3 scripts/bench_access.py [SHARED_DATA_DIR] [NAME_FILTER ...]
  e.g. python3 scripts/bench_access.py ../shared/data ctc_05 ftc_07
"""
import glob, json, os, subprocess, sys, time


def main():
    args = sys.argv[1:]
    data = args.pop(0) if args and os.path.isdir(args[0]) else os.path.join(
        os.path.dirname(__file__), "../../shared/data")
    files = sorted(glob.glob(os.path.join(data, "nist/*.stp")))
    if args:
        files = [f for f in files if any(a in f for a in args)]
    root = os.path.join(os.path.dirname(__file__), "..")
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "thinwall-cli"], cwd=root, check=True)
    exe = os.path.join(root, "target/release/thinwall")
    print("| part | faces | floors | seconds | sum of fractions | sum of largest tools, mm |")
    print("|---|---:|---:|---:|---:|---:|")
    for f in files:
        start = time.monotonic()
        out = subprocess.run([exe, "access", f, "--format", "json"], capture_output=True, text=True,
                             check=True).stdout
        seconds = time.monotonic() - start
        faces = json.loads(out)["faces"]
        floors = [x for x in faces if x["contact"] == "floor"]
        fractions = sum(x["fraction"] for x in faces)
        tools = sum(x.get("largest_tool_mm") or 0.0 for x in floors)
        name = os.path.basename(f).split("_asme")[0]
        print(f"| {name} | {len(faces)} | {len(floors)} | {seconds:.1f} | {fractions:.6f} | {tools:.3f} |",
              flush=True)


if __name__ == "__main__":
    main()
