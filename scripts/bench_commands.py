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

With panels, a second table gives each command's growth from one panel to
the next larger against n log n × 1.5 (n: the panel's faces), the issue's
target for cost that grows as n log n.

usage: python3 scripts/bench_commands.py [SHARED_DATA_DIR] [--commands recognize,plan,operations,access]
       [--sets nist,thinwall] [--only NAME]... [--panels DIR] [--panel-up X,Y,Z] [--repeat N] [--timeout SECONDS]
(--only keeps the parts whose file name holds NAME; --panels adds the STEP
files of DIR, e.g. the generated panels of scripts/make_bench_panels.py;
--panel-up runs plan and operations on the panels in that one set-up, e.g.
0,0,1, rather than proposing set-ups)
Needs cadquery-ocp-novtk (for the OpenCascade column) and a release build.
"""
import argparse, glob, math, os, platform, re, subprocess, sys, tempfile, time

sys.path.insert(0, os.path.dirname(__file__))

COMMANDS = ["recognize", "plan", "operations", "access"]


def occ_seconds(path, repeat):
    try:
        from bench_load import occ_once  # noqa: E402
    except ImportError:
        return None
    return min(occ_once(path) for _ in range(repeat)) / 1e3


def run_once(exe, command, path, timeout, extra=()):
    """(seconds, peak MB, None) or (None, None, why)."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        cmd = ["/usr/bin/time", "-f", "%M", exe, command, path, *extra, "--format", "json", "-o", out.name]
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


def best(exe, command, path, timeout, repeat, extra=()):
    runs = []
    for _ in range(repeat):
        s, mb, why = run_once(exe, command, path, timeout, extra)
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


def faces_of(path):
    """A generated panel's faces, from its name (`rib_grid_10131_faces`)."""
    m = re.search(r"(\d+)_faces", os.path.basename(path))
    return int(m.group(1)) if m else None


def growth(rows, commands):
    """Per command, its growth from each panel to the next larger (by
    faces) against n log n × 1.5: the second table."""
    rows = sorted(rows, key=lambda r: r[0])
    print("\n| panels (faces) | faces × | allowed × (n log n × 1.5) |" + "".join(f" {c} × |" for c in commands))
    print("|---|---:|---:|" + "---:|" * len(commands))
    steps = list(zip(rows, rows[1:]))
    if len(rows) > 2:
        steps.append((rows[0], rows[-1]))
    for (n0, t0), (n1, t1) in steps:
        allowed = 1.5 * (n1 * math.log(n1)) / (n0 * math.log(n0))
        cells = [f"{n0} → {n1}", f"{n1 / n0:.1f}", f"{allowed:.1f}"]
        for c in commands:
            a, b = t0.get(c), t1.get(c)
            ok = a and b and b / a <= allowed
            cells.append(f"{b / a:.1f}" + ("" if ok else " (over)") if a and b else "-")
        print("| " + " | ".join(cells) + " |")


def name_of(path):
    return os.path.basename(path).split("_asme")[0].rsplit(".", 1)[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("data", nargs="?", default=os.path.join(os.path.dirname(__file__), "../../shared/data"))
    ap.add_argument("--commands", default=",".join(COMMANDS))
    ap.add_argument("--sets", default="nist,thinwall")
    ap.add_argument("--only", action="append", default=[])
    ap.add_argument("--panels")
    ap.add_argument("--panel-up")
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
    panel_rows = []
    for f in files:
        occ = occ_seconds(f, a.repeat)
        cells = [name_of(f), f"{occ:.3f}" if occ is not None else "-"]
        panel = a.panels and os.path.dirname(os.path.abspath(f)) == os.path.abspath(a.panels)
        times = {}
        for c in commands:
            extra = ("--up", a.panel_up) if panel and a.panel_up and c in ("plan", "operations") else ()
            s, mb, why = best(exe, c, f, a.timeout, a.repeat, extra)
            if why:
                cells += [why, "-", "-"]
            else:
                times[c] = s
                ratio = f"{s / occ:.1f}" if occ else "-"
                cells += [f"{s:.3f}", f"{mb:.0f}", ratio]
        print("| " + " | ".join(cells) + " |", flush=True)
        if panel and faces_of(f):
            panel_rows.append((faces_of(f), times))
    if len(panel_rows) > 1:
        growth(panel_rows, commands)


if __name__ == "__main__":
    main()
