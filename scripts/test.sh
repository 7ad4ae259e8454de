#!/usr/bin/env bash
# The whole test suite, as the README gives it and `.ci/run` runs it: the
# Rust workspace's tests (no Python needed), then the Python package's.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo test --workspace --release
scripts/test_python.sh
