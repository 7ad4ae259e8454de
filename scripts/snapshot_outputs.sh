#!/usr/bin/env bash
# Write the outputs of every command (inspect, recognize, plan, operations,
# access: JSON and text; classify on its fixtures; the C ABI's JSON through
# the exported functions) on every shared part and fixture into DIR, one
# file each, so that two builds can be compared with `diff -r` (or
# scripts/compare_snapshots.py, which ignores keys a change adds on purpose).
#   scripts/snapshot_outputs.sh DIR [THINWALL_BINARY [CAPI_JSON_BINARY]]
# CAPI_JSON_BINARY is plugin-api's example `capi_json` (cargo build --release
# -p thinwall-capi --example capi_json). COMMANDS (environment) limits the
# commands, e.g. COMMANDS="recognize classify"; ACCESS_TIMEOUT (seconds,
# default 900) bounds one access run (a timeout is written as such); PARTS
# (environment) names a file listing the parts to run (default: every
# shared part and fixture).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: snapshot_outputs.sh DIR [BINARY [CAPI_BINARY]]}
bin=${2:-target/release/thinwall}
capi=${3:-target/release/examples/capi_json}
export COMMANDS=${COMMANDS:-"inspect recognize plan operations access capi classify"}
export ACCESS_TIMEOUT=${ACCESS_TIMEOUT:-900}
mkdir -p "$out"
list=$(mktemp)
if [ -n "${PARTS:-}" ]; then
  cp "$PARTS" "$list"
else
  {
    find ../shared/data -name '*.step' -o -name '*.stp' | sort
    find fixtures -name '*.step' -not -path 'fixtures/classify/*' | sort
  } >"$list"
fi
has() { [[ " $COMMANDS " == *" $1 "* ]]; }
export -f has
run_one() {
  bin=$1 capi=$2 out=$3 f=$4
  key=$(echo "$f" | sed 's|^\.\./shared/data/|shared/|; s|/|__|g')
  one() { # command format suffix [timeout]
    local cmd=$1 fmt=$2 suffix=$3 t=${4:-0}
    local pre=()
    [ "$t" != 0 ] && pre=(timeout "$t")
    "${pre[@]}" "$bin" "$cmd" --format "$fmt" "$f" >"$out/$key$suffix" 2>"$out/$key$suffix.err" \
      || echo "exit $?" >>"$out/$key$suffix.err"
  }
  if has recognize; then one recognize json .json; one recognize text .txt; fi
  if has inspect; then one inspect json .inspect.json; one inspect text .inspect.txt; fi
  if has plan; then one plan json .plan.json; one plan text .plan.txt; fi
  if has operations; then one operations json .ops.json; one operations text .ops.txt; fi
  if has access; then one access json .access.json "$ACCESS_TIMEOUT"; one access text .access.txt "$ACCESS_TIMEOUT"; fi
  if has capi; then "$capi" "$f" >"$out/$key.capi.json" 2>/dev/null || echo "exit $?" >>"$out/$key.capi.json"; fi
}
export -f run_one
xargs -P 2 -I{} bash -c 'run_one "$0" "$1" "$2" "$3"' "$bin" "$capi" "$out" {} <"$list"
rm -f "$list"
if has classify; then
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
fi
echo "$(ls "$out" | wc -l) files in $out"
