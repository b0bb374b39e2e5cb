#!/usr/bin/env bash
# Builds everything and runs every test (unit tests, bank checks, conformance), the WebAssembly
# build's tests, then the same tests under AddressSanitizer and UndefinedBehaviorSanitizer, then
# each fuzz target briefly.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each step's wall time, printed as it ends and again at the end (a failing step stops the run
# with its status; the times so far are printed then too).
timings="$(mktemp)"
step() {
  local name="$1" start=$SECONDS
  shift
  "$@"
  local took=$((SECONDS - start))
  printf '%5d s  %s\n' "$took" "$name" >>"$timings"
  printf '== %s: %d s\n' "$name" "$took" >&2
}
trap 'printf "\nStep times:\n" >&2; cat "$timings" >&2; rm -f "$timings"' EXIT
# Steps that wait more than they compute run beside a build: started by in_background (their
# output kept until then), waited for by wait_background, which shows it and fails when one did.
background_pid=""
background_log=""
in_background() {
  background_log="$(mktemp)"
  "$@" >"$background_log" 2>&1 &
  background_pid=$!
}
wait_background() {
  local status=0
  wait "$background_pid" || status=$?
  cat "$background_log" >&2
  rm -f "$background_log"
  return "$status"
}
# The browser extra: the HTML worked solutions are checked in headless Chromium; the fuzz extra:
# clang and its sanitizer runtime, for the asan preset (the tests and the fuzz targets).
step "install" env RAYGRADE_EXTRA="${RAYGRADE_EXTRA:-} browser fuzz" bash scripts/install-deps.sh
step "web libraries" bash scripts/fetch-web-libs.sh
step "configure release" cmake --preset release >/dev/null
# clang-tidy with .clang-tidy's checks over the sources the last commit changes (docs/architecture.md#clang-tidy),
# from the tidy preset's compile database (configured only: clang, no unity batches, no
# precompiled header).
step "clang-tidy" bash -c 'cmake --preset tidy >/dev/null && bash scripts/tidy.sh'
step "build release" cmake --build --preset release
# The accessibility audit and the SCORM package's test wait for the web build: both need the
# practice page's raygrade.js.
step "test release" ctest --preset release -E "axe_in_browser|scorm_in_browser"
# The browser build (docs/web.md): raygrade.js against the native binary, byte for byte, on the
# whole bank, the sample submissions and the hard cases; then a practice page in headless
# Chromium, from file:// (screenshots in build/web/practice-check).
step "build web" bash scripts/build-web.sh
# Two processes side by side, each making every other comparison.
web_test() {
  local log status=0 other=0
  log="$(mktemp)"
  node tests/web_node_test.js build/web/web/raygrade.js build/release/grader/raygrade . 1/2 \
    >"$log" 2>&1 &
  local pid=$!
  node tests/web_node_test.js build/web/web/raygrade.js build/release/grader/raygrade . 0/2 ||
    status=$?
  wait "$pid" || other=$?
  cat "$log"
  rm -f "$log"
  [ "$status" -eq 0 ] && [ "$other" -eq 0 ]
}
step "test web" web_test
# The practice page, the SCORM package and the accessibility audit in headless Chromium, beside
# the static build (they wait on the browser more than they compute).
browser_pages() {
  step "practice page" /usr/bin/python3 tests/practice_in_browser.py build/release/grader/raygrade \
    build/web/web/raygrade.js assignments/homework-rays.json build/web/practice-check
  # The SCORM package under scorm-again's LMS API, SCORM 1.2 and 2004 (docs/assignments.md).
  step "scorm" ctest --preset release -R scorm_in_browser --output-on-failure
  # axe-core over the handout, practice, worked-solution and feedback pages (docs/web.md).
  step "accessibility" ctest --preset release -R axe_in_browser --output-on-failure
}
in_background browser_pages
# The static binary the LMS exports ship (a second build of the library, without tests): the
# conformance set, every subcommand against the release binary's output, and the Gradescope
# autograder and the PrairieLearn questions run with it.
step "configure static" cmake --preset static >/dev/null
step "build static" cmake --build --preset static
step "browser pages (beside the static build)" wait_background
step "conformance static" python3 tests/conformance.py build/static/grader/raygrade tests/data/conformance
step "static check" bash scripts/static-check.sh build/static/grader/raygrade build/release/grader/raygrade
step "gradescope" /usr/bin/python3 tests/gradescope_autograder.py build/release/grader/raygrade \
  assignments/homework-rays.json build/static/grader/raygrade
step "prairielearn" /usr/bin/python3 tests/prairielearn_export.py build/release/grader/raygrade \
  assignments/homework-rays.json build/static/grader/raygrade
# The whole suite again with ASan and UBSan (the asan preset: clang, which also builds the
# libFuzzer targets there, so that the library is compiled under the sanitizers once).
step "configure asan" cmake --preset asan >/dev/null
step "build asan" cmake --build --preset asan
step "test asan" ctest --preset asan
# Each fuzz target for 30 seconds, from the asan build (scripts/fuzz.sh TARGET SECONDS runs longer
# campaigns).
step "fuzz" bash scripts/fuzz.sh all 30
