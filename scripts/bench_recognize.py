#!/usr/bin/env python3
"""Whole recognition per NIST B-rep part against OpenCascade's read + adjacency,
same files, same run.

Thinwall: the `recognize_bench` example (release build, median of 5 runs per
file): read, graph, and `thinwall_pipeline::run` (face properties, stiffness
features, connections, machining features). OpenCascade: STEP read +
transfer + edge/face map + BRepOffset_Analyse (median of 3 runs per file).
Prints a Markdown table; the target is recognition <= 0.2 x OpenCascade.
Needs cadquery-ocp-novtk.

usage: python3 scripts/bench_recognize.py [SHARED_DATA_DIR]
"""
import glob, os, statistics, subprocess, sys

sys.path.insert(0, os.path.dirname(__file__))
from bench_load import occ_once  # noqa: E402


def main():
    data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "../../shared/data")
    files = [f for f in sorted(glob.glob(os.path.join(data, "nist/*.stp"))) if "-tg" not in f]
    root = os.path.join(os.path.dirname(__file__), "..")
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "thinwall-cli", "--example", "recognize_bench"],
                   cwd=root, check=True)
    exe = os.path.join(root, "target/release/examples/recognize_bench")
    print("| file | faces | read ms | graph ms | recognition ms | OCC read+adjacency ms | recognition / OCC | all / OCC |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    worst = 0.0
    for f in files:
        out = subprocess.run([exe, "--repeat", "5", f], capture_output=True, text=True, check=True).stdout
        faces, read, graph, rec, total, _ = out.splitlines()[1].split()
        read, graph, rec, total = (float(x) * 1e3 for x in (read, graph, rec, total))
        occ = statistics.median(occ_once(f) for _ in range(3))
        worst = max(worst, rec / occ)
        name = os.path.basename(f).split("_asme")[0]
        print(f"| {name} | {faces} | {read:.1f} | {graph:.1f} | {rec:.1f} | {occ:.1f} | {rec / occ:.3f} | {total / occ:.3f} |",
              flush=True)
    print(f"\nworst recognition / OCC: {worst:.3f}")


if __name__ == "__main__":
    main()
