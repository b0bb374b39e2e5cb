#!/usr/bin/env bash
# Builds everything and runs every test (unit tests, bank checks, conformance), the WebAssembly
# build's tests, then the same tests under AddressSanitizer and UndefinedBehaviorSanitizer, then
# each fuzz target briefly.
set -euo pipefail
cd "$(dirname "$0")/.."
# The browser extra: the HTML worked solutions are checked in headless Chromium.
RAYGRADE_EXTRA="${RAYGRADE_EXTRA:-} browser" bash scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
ctest --preset release
# The browser build (docs/web.md): raygrade.js against the native binary, byte for byte, on the
# whole bank, the sample submissions and the hard cases; then a practice page in headless
# Chromium, from file:// (screenshots in build/web/practice-check).
bash scripts/build-web.sh
node tests/web_node_test.js build/web/web/raygrade.js build/release/grader/raygrade .
/usr/bin/python3 tests/practice_in_browser.py build/release/grader/raygrade \
  build/web/web/raygrade.js assignments/homework-rays.json build/web/practice-check
# The static binary the LMS exports ship (a second build of the library, without tests): the
# conformance set, every subcommand against the release binary's output, and the Gradescope
# autograder and the PrairieLearn questions run with it.
cmake --preset static >/dev/null
cmake --build --preset static
python3 tests/conformance.py build/static/grader/raygrade tests/data/conformance
bash scripts/static-check.sh build/static/grader/raygrade build/release/grader/raygrade
/usr/bin/python3 tests/gradescope_autograder.py build/release/grader/raygrade \
  assignments/homework-rays.json build/static/grader/raygrade
/usr/bin/python3 tests/prairielearn_export.py build/release/grader/raygrade \
  assignments/homework-rays.json build/static/grader/raygrade
# The whole suite again with ASan and UBSan (the asan preset).
cmake --preset asan >/dev/null
cmake --build --preset asan
ctest --preset asan
# Each fuzz target for 30 seconds (scripts/fuzz.sh TARGET SECONDS runs longer campaigns).
bash scripts/fuzz.sh all 30
