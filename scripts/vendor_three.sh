#!/usr/bin/env bash
# Vendors three.js (MIT) for the HTML report: the parts of it the viewer
# uses, bundled into one minified script that defines `window.THREE`
# (with OrbitControls), and the licence beside it. The report inlines the
# bundle at build time (include_str!), so reports open from disk with no
# network. Run again to move to another version; commit both files.
#
#   scripts/vendor_three.sh [VERSION]        (default: the pinned one)
set -euo pipefail
version="${1:-0.187.0}"
here="$(cd "$(dirname "$0")/.." && pwd)"
out="$here/crates/thinwall-report/vendor/three"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
npm init -y >/dev/null
npm install --no-audit --no-fund "three@$version" esbuild@0.28.2 >/dev/null
cat > entry.js <<'JS'
import {
  WebGLRenderer, Scene, PerspectiveCamera, BufferGeometry, BufferAttribute,
  Mesh, MeshLambertMaterial, LineSegments, LineBasicMaterial, AmbientLight,
  DirectionalLight, Raycaster, Vector2, Vector3, Color, Box3, Sphere, Sprite,
  SpriteMaterial, CanvasTexture, Group, DoubleSide,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
window.THREE = {
  WebGLRenderer, Scene, PerspectiveCamera, BufferGeometry, BufferAttribute,
  Mesh, MeshLambertMaterial, LineSegments, LineBasicMaterial, AmbientLight,
  DirectionalLight, Raycaster, Vector2, Vector3, Color, Box3, Sphere, Sprite,
  SpriteMaterial, CanvasTexture, Group, DoubleSide, OrbitControls,
};
JS
npx esbuild entry.js --bundle --minify --format=iife --legal-comments=none \
  --outfile=bundle.js --log-level=warning
mkdir -p "$out"
{
  echo "/* three.js r${version#0.} (threejs.org), MIT licence: see LICENSE beside this file. Bundled by scripts/vendor_three.sh. */"
  cat bundle.js
} > "$out/three-bundle.min.js"
cp node_modules/three/LICENSE "$out/LICENSE"
echo "$version" > "$out/VERSION"
ls -l "$out"
