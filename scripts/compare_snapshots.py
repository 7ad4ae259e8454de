#!/usr/bin/env python3
"""Compare two output snapshots (scripts/snapshot_outputs.sh) byte for byte,
after removing from the newer one the JSON keys a change adds on purpose.

    scripts/compare_snapshots.py BEFORE AFTER [--ignore-added KEY ...]

Prints every file that differs and exits 1 if any does."""
import json, os, sys

def strip(v, keys):
    if isinstance(v, dict):
        return {k: strip(x, keys) for k, x in v.items() if k not in keys}
    if isinstance(v, list):
        return [strip(x, keys) for x in v]
    return v

def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    before, after, keys = args[0], args[1], set()
    if "--ignore-added" in args:
        keys = set(args[args.index("--ignore-added") + 1:])
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
                # Re-serialised the way the tool writes it (2-space, insertion order).
                if json.dumps(jx, indent=2) == json.dumps(jy, indent=2):
                    continue
            except ValueError:
                pass
        print("differs:", n); bad += 1
    print(f"{len(names)} files compared, {bad} differ")
    sys.exit(1 if bad else 0)

main()
