#!/usr/bin/env bash
# Builds everything and runs every test (unit tests, bank checks, conformance).
set -euo pipefail
cd "$(dirname "$0")/.."
# The browser extra: the HTML worked solutions are checked in headless Chromium.
RAYGRADE_EXTRA="${RAYGRADE_EXTRA:-} browser" bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
