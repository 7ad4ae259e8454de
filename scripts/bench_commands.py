#!/usr/bin/env python3
"""Every command as a user runs it (issue 43): `thinwall recognize`, `plan`,
`operations` and `access` with the CLI's defaults (recognize judges the reach
of wall sides; plan and operations propose their set-ups; access: three axes,
the preferred tool), one process per run, best of N, beside OpenCascade's
STEP read + transfer + edge/face map + BRepOffset_Analyse of the same file in
the same run (the anchor: any OpenCascade-based host pays that to load the
part). Peak memory from `/usr/bin/time`.

Prints a Markdown table: per part and command, seconds, peak MB and the ratio
to OpenCascade's read + adjacency; a run past the timeout is `> T s`, a
refused run names why. The issue's targets: recognize ≤ 0.2 ×, access ≤ 1 ×
OpenCascade on every NIST part; plan + operations under 1 s per NIST part.

usage: python3 scripts/bench_commands.py [SHARED_DATA_DIR] [--commands recognize,plan,operations,access]
       [--sets nist,thinwall] [--only NAME]... [--panels DIR] [--repeat N] [--timeout SECONDS]
(--only keeps the parts whose file name holds NAME; --panels adds the STEP
files of DIR, e.g. the generated panels of scripts/make_bench_panels.py)
Needs cadquery-ocp-novtk (for the OpenCascade column) and a release build.
"""
import argparse, glob, os, platform, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(__file__))

COMMANDS = ["recognize", "plan", "operations", "access"]


def occ_seconds(path, repeat):
    try:
        from bench_load import occ_once  # noqa: E402
    except ImportError:
        return None
    return min(occ_once(path) for _ in range(repeat)) / 1e3


def run_once(exe, command, path, timeout):
    """(seconds, peak MB, None) or (None, None, why)."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        cmd = ["/usr/bin/time", "-f", "%M", exe, command, path, "--format", "json", "-o", out.name]
        t0 = time.perf_counter()
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, None, f"> {timeout:.0f} s"
        # The process's wall time (to the millisecond; /usr/bin/time's %e
        # has centiseconds), its peak memory from /usr/bin/time.
        seconds = time.perf_counter() - t0
        kb = int(p.stderr.strip().splitlines()[-1].split()[0])
        if p.returncode != 0:
            why = next((l for l in p.stderr.splitlines() if l.startswith("error")), "failed")
            return None, None, f"refused ({why[:60]})"
        return seconds, kb / 1024, None


def best(exe, command, path, timeout, repeat):
    runs = []
    for _ in range(repeat):
        s, mb, why = run_once(exe, command, path, timeout)
        if why:
            return None, None, why
        runs.append((s, mb))
        if s > 30:  # a long run once is enough: its noise is small beside it
            break
    s = min(r[0] for r in runs)
    return s, max(r[1] for r in runs), None


def parts(data, sets, only, panels):
    found = []
    if "nist" in sets:
        found += [f for f in sorted(glob.glob(os.path.join(data, "nist/*.stp"))) if "-tg" not in f]
    if "thinwall" in sets:
        found += sorted(glob.glob(os.path.join(data, "thinwall/*.step")))
    if panels:
        found += sorted(glob.glob(os.path.join(panels, "*.step")) + glob.glob(os.path.join(panels, "*.stp")))
    if only:
        found = [f for f in found if any(o in os.path.basename(f) for o in only)]
    return found


def name_of(path):
    return os.path.basename(path).split("_asme")[0].rsplit(".", 1)[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("data", nargs="?", default=os.path.join(os.path.dirname(__file__), "../../shared/data"))
    ap.add_argument("--commands", default=",".join(COMMANDS))
    ap.add_argument("--sets", default="nist,thinwall")
    ap.add_argument("--only", action="append", default=[])
    ap.add_argument("--panels")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=900)
    a = ap.parse_args()
    commands = [c for c in a.commands.split(",") if c]
    for c in commands:
        if c not in COMMANDS:
            sys.exit(f"bench_commands.py: unknown command '{c}' (one of {', '.join(COMMANDS)})")
    root = os.path.join(os.path.dirname(__file__), "..")
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "thinwall-cli"], cwd=root, check=True)
    exe = os.path.join(root, "target/release/thinwall")
    files = parts(a.data, a.sets.split(","), a.only, a.panels)
    if not files:
        sys.exit("bench_commands.py: no parts (see --sets, --only, --panels)")
    print(f"{time.strftime('%Y-%m-%d')}, {platform.machine()}, {os.cpu_count()} cores; best of {a.repeat}, one process per run\n")
    head = "| part | OCC read+adjacency s |" + "".join(f" {c} s | MB | × OCC |" for c in commands)
    print(head)
    print("|---|---:|" + "---:|---:|---:|" * len(commands))
    for f in files:
        occ = occ_seconds(f, a.repeat)
        cells = [name_of(f), f"{occ:.3f}" if occ is not None else "-"]
        for c in commands:
            s, mb, why = best(exe, c, f, a.timeout, a.repeat)
            if why:
                cells += [why, "-", "-"]
            else:
                ratio = f"{s / occ:.1f}" if occ else "-"
                cells += [f"{s:.3f}", f"{mb:.0f}", ratio]
        print("| " + " | ".join(cells) + " |", flush=True)


if __name__ == "__main__":
    main()
