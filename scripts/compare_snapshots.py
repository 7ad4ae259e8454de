#!/usr/bin/env python3
"""Compare two output snapshots (scripts/snapshot_outputs.sh) byte for byte,
after removing from the newer one the JSON keys a change adds on purpose.

    scripts/compare_snapshots.py BEFORE AFTER [--tolerance KEY=REL ...] [--ignore-added KEY ...]

With --tolerance, numbers under KEY may differ by REL relatively; every
such difference is counted and the largest printed. Prints every file that
differs otherwise and exits 1 if any does."""
import json, os, sys

def strip(v, keys):
    if isinstance(v, dict):
        return {k: strip(x, keys) for k, x in v.items() if k not in keys}
    if isinstance(v, list):
        return [strip(x, keys) for x in v]
    return v

TOLERATED = {"count": 0, "worst": 0.0, "where": ""}

def close(a, b, tol, bound, where):
    """Compare JSON values; numbers under a tolerated key within its bound."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(
            close(a[k], b[k], tol, tol.get(k, bound), where + "/" + k) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(close(x, y, tol, bound, where) for x, y in zip(a, b))
    if bound is not None and isinstance(a, (int, float)) and isinstance(b, (int, float)):
        if a == b:
            return True
        rel = abs(a - b) / max(abs(a), abs(b), 1e-300)
        TOLERATED["count"] += 1
        if rel > TOLERATED["worst"]:
            TOLERATED.update(worst=rel, where=where)
        return rel <= bound
    return a == b

def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    before, after, keys, tol = args[0], args[1], set(), {}
    rest = args[2:]
    mode = None
    for a in rest:
        if a in ("--ignore-added", "--tolerance"):
            mode = a
        elif mode == "--ignore-added":
            keys.add(a)
        elif mode == "--tolerance":
            k, v = a.split("=")
            tol[k] = float(v)
    names = sorted(set(os.listdir(before)) | set(os.listdir(after)))
    bad = 0
    for n in names:
        a, b = os.path.join(before, n), os.path.join(after, n)
        if not (os.path.exists(a) and os.path.exists(b)):
            print("only in one:", n); bad += 1; continue
        x, y = open(a, "rb").read(), open(b, "rb").read()
        if x == y:
            continue
        if n.endswith(".json") and keys:
            try:
                jx = json.loads(x)
                jy = strip(json.loads(y), keys)
                if close(jx, jy, tol, None, n):
                    continue
            except ValueError:
                pass
        print("differs:", n); bad += 1
    if tol:
        print(f"{TOLERATED['count']} numbers differ within {tol} (largest {TOLERATED['worst']:.2e} at {TOLERATED['where']})")
    print(f"{len(names)} files compared, {bad} differ")
    sys.exit(1 if bad else 0)

main()
