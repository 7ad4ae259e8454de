#!/usr/bin/env bash
# Renders a Thinwall HTML report to a PNG with headless Chromium (Debian
# package `chromium`), WebGL by its software renderer (SwiftShader).
#
#   scripts/screenshot.sh REPORT.html[#VIEW] OUT.png [WIDTHxHEIGHT]   (default 1600x1000)
#
# VIEW opens the page at a chosen view, as in a link: `#wall=R3` (a
# plan's volumes around one wall, numbered as Popma fig. 4.1), `#step=5`,
# `#select=H1`, `#tab=Machining features` (docs/REPORTS.md).
# The report needs no network; Chromium runs with its background
# networking off, in a fresh profile that is removed afterwards.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 REPORT.html OUT.png [WIDTHxHEIGHT]" >&2
  exit 2
fi
report="${1%%#*}"; view=""; out="$2"; size="${3:-1600x1000}"
[ "$report" = "$1" ] || view="#${1#*#}"
[ -f "$report" ] || { echo "$0: no such report: $report" >&2; exit 1; }
browser="$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)"
[ -n "$browser" ] || { echo "$0: Chromium not found (apt-get install chromium)" >&2; exit 1; }
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
# --run-all-compositor-stages-before-draw: without it a large part's first
# WebGL frame may not be on the page yet when the picture is taken (seen
# with NIST CTC-02 at 1600x1000: an empty view).
abs="$(cd "$(dirname "$report")" && pwd)/$(basename "$report")"
"$browser" --headless --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --disable-quic \
  --enable-unsafe-swiftshader --use-angle=swiftshader \
  --run-all-compositor-stages-before-draw \
  --user-data-dir="$profile" --hide-scrollbars \
  --window-size="${size/x/,}" --virtual-time-budget=8000 \
  --screenshot="$(cd "$(dirname "$out")" && pwd)/$(basename "$out")" "file://$abs$view" 2>"$profile/log" || {
    cat "$profile/log" >&2; exit 1; }
[ -s "$out" ] || { cat "$profile/log" >&2; echo "$0: no picture written" >&2; exit 1; }
echo "$out"
