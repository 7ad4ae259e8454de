#!/usr/bin/env python3
"""Load + adjacency time: Thinwall against OpenCascade, same files, same run.

For each data set, the median over files of: Thinwall's read + graph (the
`load_bench` example, release build, median of 5 runs per file) and
OpenCascade's STEP read + transfer + edge/face map + BRepOffset_Analyse
(median of 3 runs per file). Prints a table; needs cadquery-ocp-novtk.

usage: python3 scripts/bench_load.py [SHARED_DATA_DIR]
"""
import glob, json, os, statistics, subprocess, sys, time

from OCP.STEPControl import STEPControl_Reader
from OCP.TopExp import TopExp
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
try:  # OpenCascade 7.x
    from OCP.TopTools import TopTools_IndexedDataMapOfShapeListOfShape as EdgeFaceMap
except ImportError:  # 8.x
    from OCP.OCP.collections import IndexedDataMap_TopoDS_Shape_List_TopoDS_Shape_TopTools_ShapeMapHasher as EdgeFaceMap
from OCP.BRepOffset import BRepOffset_Analyse


def occ_once(path):
    t0 = time.perf_counter()
    r = STEPControl_Reader()
    r.ReadFile(path)
    r.TransferRoots()
    shape = r.OneShape()
    m = EdgeFaceMap()
    TopExp.MapShapesAndAncestors_s(shape, TopAbs_EDGE, TopAbs_FACE, m)
    BRepOffset_Analyse(shape, 0.01)
    return (time.perf_counter() - t0) * 1e3


def main():
    data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "../../shared/data")
    sets = {
        "mfcad/train": sorted(glob.glob(os.path.join(data, "mfcad/train/*.step"))),
        "nist": [f for f in sorted(glob.glob(os.path.join(data, "nist/*.stp"))) if "-tg" not in f],
        "thinwall": sorted(glob.glob(os.path.join(data, "thinwall/*.step"))),
        "mfinstseg": sorted(glob.glob(os.path.join(data, "mfinstseg/*.step"))),
    }
    root = os.path.join(os.path.dirname(__file__), "..")
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "thinwall-cli", "--example", "load_bench"],
                   cwd=root, check=True)
    exe = os.path.join(root, "target/release/examples/load_bench")
    print(f"{'set':<12}{'files':>6}{'thinwall read+graph ms':>24}{'(+face props)':>15}{'OCC read+adjacency ms':>24}{'speed-up':>10}")
    for name, files in sets.items():
        out = subprocess.run([exe, "--repeat", "5", *files], capture_output=True, text=True, check=True).stdout
        ours = [json.loads(l) for l in out.splitlines()]
        tw = [o["read_ms"] + o["graph_ms"] for o in ours]
        twp = [o["read_ms"] + o["graph_ms"] + o["props_ms"] for o in ours]
        occ = [statistics.median(occ_once(f) for _ in range(3)) for f in files]
        ratio = statistics.median(occ) / statistics.median(tw)
        print(f"{name:<12}{len(files):>6}{statistics.median(tw):>24.2f}{statistics.median(twp):>15.2f}"
              f"{statistics.median(occ):>24.2f}{ratio:>9.1f}x", flush=True)


if __name__ == "__main__":
    main()
