#!/usr/bin/env bash
# Write the recognition (JSON and text) and classification outputs of every
# shared part and fixture into DIR, one file each, so that two builds can be
# compared with `diff -r` (or scripts/compare_snapshots.py, which ignores
# keys a change adds on purpose).
#   scripts/snapshot_outputs.sh DIR [THINWALL_BINARY]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: snapshot_outputs.sh DIR [BINARY]}
bin=${2:-target/release/thinwall}
mkdir -p "$out"
list=$(mktemp)
{
  find ../shared/data -name '*.step' -o -name '*.stp' | sort
  find fixtures -name '*.step' -not -path 'fixtures/classify/*' | sort
} >"$list"
run_one() {
  bin=$1 out=$2 f=$3
  key=$(echo "$f" | sed 's|^\.\./shared/data/|shared/|; s|/|__|g')
  "$bin" recognize --format json "$f" >"$out/$key.json" 2>"$out/$key.err" || echo "exit $?" >>"$out/$key.err"
  "$bin" recognize --format text "$f" >"$out/$key.txt" 2>/dev/null || true
}
export -f run_one
xargs -P 2 -I{} bash -c 'run_one "$0" "$1" "$2"' "$bin" "$out" {} <"$list"
rm -f "$list"
for d in fixtures/classify/*/; do
  name=$(basename "$d")
  args=()
  for v in "$d"v*.step; do args+=(--volume "$v"); done
  befores=$(python3 -c "import json,sys;print(' '.join(f'--before {a}:{b}' for a,b in json.load(open(sys.argv[1])).get('before',[])))" "$d/expected.json")
  up=$(python3 -c "import json,sys;print(','.join(str(x) for x in json.load(open(sys.argv[1])).get('up',[0,0,1])))" "$d/expected.json")
  # shellcheck disable=SC2086
  "$bin" classify --part "$d/part.step" "${args[@]}" $befores --up="$up" --format json >"$out/classify__$name.json" 2>&1 || true
  # shellcheck disable=SC2086
  "$bin" classify --part "$d/part.step" "${args[@]}" $befores --up="$up" --format text >"$out/classify__$name.txt" 2>&1 || true
done
echo "$(ls "$out" | wc -l) files in $out"
