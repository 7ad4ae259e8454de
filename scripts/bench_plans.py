#!/usr/bin/env python3
"""`thinwall plan` and `thinwall operations` as the CLI runs them by default
(no `--up`: the set-ups proposed and planned in turn), one process per run,
on every NIST B-rep part and on the rib-grid panel, beside OpenCascade's read
+ adjacency of the same file in the same run (the anchor: any OpenCascade-based
host pays that to load the part). Prints a Markdown table: seconds and peak
memory (`/usr/bin/time`), the set-ups, the machining features or operations
per set-up, and the residue.

usage: python3 scripts/bench_plans.py [SHARED_DATA_DIR] [--panel PANEL.step]
       [--only plan|operations] [--skip NAME]... [--timeout SECONDS]
(--skip leaves out the NIST parts whose file name holds NAME, e.g. ctc_02)
Needs cadquery-ocp-novtk (for the OpenCascade column) and a release build.
"""
import argparse, glob, json, os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(__file__))


def occ_ms(path):
    try:
        from bench_load import occ_once  # noqa: E402
    except ImportError:
        return None
    return occ_once(path)


def axis_name(u):
    names = {(1, 0, 0): "+X", (-1, 0, 0): "−X", (0, 1, 0): "+Y", (0, -1, 0): "−Y", (0, 0, 1): "+Z", (0, 0, -1): "−Z"}
    key = tuple(round(c) if abs(abs(c) - 1) < 1e-9 or abs(c) < 1e-9 else None for c in u)
    return names.get(key, "(" + ", ".join(f"{c:.2f}" for c in u) + ")")


def run(exe, command, path, timeout):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        cmd = ["/usr/bin/time", "-f", "%e %M", exe, command, path, "--format", "json", "-o", out.name]
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, f"over {timeout} s", None
        seconds, kb = p.stderr.strip().splitlines()[-1].split()
        if p.returncode != 0:
            why = next((l for l in p.stderr.splitlines() if l.startswith("error")), p.stderr.strip()[:160])
            return (float(seconds), int(kb) // 1024), f"refused: {why}", None
        return (float(seconds), int(kb) // 1024), None, json.load(open(out.name))


def plan_row(v):
    sets = [v] + v.get("then", [])
    ups = " ".join(axis_name(p["up"]) for p in sets)
    feats = " + ".join(str(len(p["machining_features"])) for p in sets)
    residue = v.get("residue")
    return ups, feats, residue


def ops_row(v):
    sets = [v] + v.get("then", [])
    ups = " ".join(axis_name(p["up"]) for p in sets)
    ops = " + ".join(str(len(p["setup"]["operations"])) for p in sets)
    return ups, ops, v.get("residue")


def residue_text(r):
    if r is None:
        return "—"
    text = f"{r['volume_mm3']:.0f}"
    return text + (" (at points)" if r["judged"] == "at_points" else "")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("data", nargs="?", default=os.path.join(os.path.dirname(__file__), "../../shared/data"))
    ap.add_argument("--panel", action="append", default=[])
    ap.add_argument("--only", choices=["plan", "operations"])
    ap.add_argument("--skip", action="append", default=[])
    ap.add_argument("--timeout", type=float, default=1800)
    a = ap.parse_args()
    root = os.path.join(os.path.dirname(__file__), "..")
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "thinwall-cli"], cwd=root, check=True)
    exe = os.path.join(root, "target/release/thinwall")
    files = [f for f in sorted(glob.glob(os.path.join(a.data, "nist/*.stp")))
             if "-tg" not in f and not any(k in os.path.basename(f) for k in a.skip)] + a.panel
    commands = [a.only] if a.only else ["plan", "operations"]
    print("| part | command | s | peak MB | OCC read+adjacency s | set-ups | features / operations per set-up | residue mm³ |")
    print("|---|---|---:|---:|---:|---|---:|---:|")
    for f in files:
        name = os.path.basename(f).split("_asme")[0].replace(".step", "")
        occ = occ_ms(f)
        occ_s = f"{occ / 1000:.2f}" if occ is not None else "—"
        for c in commands:
            cost, why, v = run(exe, c, f, a.timeout)
            s, mb = (f"{cost[0]:.1f}", str(cost[1])) if cost else ("—", "—")
            if v is None:
                print(f"| {name} | {c} | {s} | {mb} | {occ_s} | {why} | | |", flush=True)
                continue
            ups, per, residue = plan_row(v) if c == "plan" else ops_row(v)
            print(f"| {name} | {c} | {s} | {mb} | {occ_s} | {ups} | {per} | {residue_text(residue)} |", flush=True)


if __name__ == "__main__":
    main()
