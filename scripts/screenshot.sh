#!/usr/bin/env bash
# Renders a Thinwall HTML report to a PNG with headless Chromium (Debian
# package `chromium`), WebGL by its software renderer (SwiftShader).
#
#   scripts/screenshot.sh REPORT.html OUT.png [WIDTHxHEIGHT]   (default 1600x1000)
#
# The report needs no network; Chromium runs with its background
# networking off, in a fresh profile that is removed afterwards.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 REPORT.html OUT.png [WIDTHxHEIGHT]" >&2
  exit 2
fi
report="$1"; out="$2"; size="${3:-1600x1000}"
[ -f "$report" ] || { echo "$0: no such report: $report" >&2; exit 1; }
browser="$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)"
[ -n "$browser" ] || { echo "$0: Chromium not found (apt-get install chromium)" >&2; exit 1; }
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
abs="$(cd "$(dirname "$report")" && pwd)/$(basename "$report")"
"$browser" --headless --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --disable-quic \
  --enable-unsafe-swiftshader --use-angle=swiftshader \
  --user-data-dir="$profile" --hide-scrollbars \
  --window-size="${size/x/,}" --virtual-time-budget=8000 \
  --screenshot="$(cd "$(dirname "$out")" && pwd)/$(basename "$out")" "file://$abs" 2>"$profile/log" || {
    cat "$profile/log" >&2; exit 1; }
[ -s "$out" ] || { cat "$profile/log" >&2; echo "$0: no picture written" >&2; exit 1; }
echo "$out"
