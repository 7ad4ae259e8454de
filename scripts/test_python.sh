#!/usr/bin/env bash
# The Python package's tests: build its wheel (maturin, abi3), install it
# with the test dependencies in a virtual environment under target/, and
# run pytest (python/tests). The tests compare with the release CLI and C
# library, which are built here too. FreeCAD's test runs where `freecadcmd`
# is (Debian: apt-get install freecad); THINWALL_REQUIRE_FREECAD=1 makes its
# absence a failure (CI sets it).
set -euo pipefail
cd "$(dirname "$0")/.."
VENV=target/python-venv
if [ ! -x "$VENV/bin/python" ]; then
  python3 -m venv "$VENV"
fi
"$VENV/bin/pip" install -q --disable-pip-version-check \
  "maturin>=1.5,<2" "pytest>=8" "pytest-xdist>=3" \
  "cadquery-ocp-novtk==8.0.1.1.0" "dask[distributed]>=2024.1" "pyarrow>=15"
cargo build --release -q -p thinwall-cli -p thinwall-clib
rm -rf target/wheels
"$VENV/bin/maturin" build --release --quiet -m python/Cargo.toml -o target/wheels
"$VENV/bin/pip" install -q --disable-pip-version-check --force-reinstall --no-deps target/wheels/thinwall-*.whl
# From the tests' folder: `import thinwall` is the installed wheel, not the
# source folder beside them.
cd python/tests
exec "../../$VENV/bin/python" -m pytest -q -n 2 -p no:cacheprovider .
