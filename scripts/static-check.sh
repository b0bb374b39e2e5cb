#!/usr/bin/env bash
# The static binary against the release one: every subcommand run by both on the bundled
# bank, assignment and submissions must write the same bytes (the conformance set runs
# separately; bench's timings differ from run to run, so bench writes its MPFR corpus only).
# Usage: scripts/static-check.sh [STATIC] [RELEASE]
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
static=$(realpath "${1:-build/static/grader/raygrade}")
release=$(realpath "${2:-build/release/grader/raygrade}")
kind=$(file "$static")
case "$kind" in
  *"statically linked"*) echo "static-check: $kind" ;;
  *) echo "static-check: $static is not statically linked: $kind" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

failures=0
# Runs one command line with each binary (BIN stands for it) in its own folder; compares
# the exit status, standard output and every file written.
same() {
  local name="$1"; shift
  for which in static release; do
    local bin; bin=$([ "$which" = static ] && echo "$static" || echo "$release")
    mkdir -p "$work/$which/$name"
    local args=("${@//BIN/$bin}")
    args=("${args[@]//REPO/$repo}")
    # Each in its own folder, writing into out/: files that quote their command line agree.
    set +e
    (cd "$work/$which/$name" && "${args[@]}") > "$work/$which/$name.stdout" \
      2> "$work/$which/$name.stderr"
    echo $? > "$work/$which/$name.status"
    set -e
  done
  # Paths of the two folders differ; everything else must not.
  if ! diff -r <(sed "s|$work/static|W|g" "$work/static/$name.stdout") \
               <(sed "s|$work/release|W|g" "$work/release/$name.stdout") > /dev/null ||
     ! diff "$work/static/$name.status" "$work/release/$name.status" > /dev/null ||
     { [ -e "$work/static/$name/out" ] && ! diff -r "$work/static/$name/out" "$work/release/$name/out" > /dev/null; }; then
    echo "static-check: $name differs between $static and $release" >&2
    failures=$((failures + 1))
  else
    echo "static-check: $name: same (exit $(cat "$work/static/$name.status"))"
  fi
}

same solve BIN solve REPO/problems --format json
same solve-html BIN solve REPO/assignments/homework-rays.json --student s001 --format html
same run BIN run --problems REPO/problems --submissions REPO/submissions --solutions out
same solutions BIN solutions REPO/problems --out out
same grade-csv BIN grade --problems REPO/problems REPO/submissions --format csv
same grade-json BIN grade --problems REPO/problems REPO/submissions --format json
# Text: the JUnit report carries timings, which differ from run to run.
same check BIN check REPO/problems --format text
same generate BIN generate --seed 42 -n 20 --out out
same handout BIN handout REPO/assignments/homework-rays.json --student s001 --out out
same bench-corpus BIN bench --write-corpus out
# Writing autograder.zip takes libzip, which Debian ships as a shared library only: the static
# binary (the one the platforms run to grade) does not export to Gradescope, and says why; the
# release binary exports (the gradescope step of scripts/test.sh packs this static binary).
set +e
message=$("$static" export gradescope "$repo/assignments/homework-rays.json" \
  --roster "$repo/assignments/roster.csv" --out "$work/static-export" --binary "$static" 2>&1)
status=$?
set -e
if [ "$status" -ne 2 ] || [[ "$message" != *"without libzip"* ]]; then
  echo "static-check: export gradescope with the static binary: exit $status, not 2 with a" \
    "message about libzip: $message" >&2
  failures=$((failures + 1))
fi
same export-prairielearn BIN export prairielearn REPO/assignments/homework-rays.json --out out \
  --binary "$static"
[ "$failures" -eq 0 ] || exit 1
echo "static-check: every subcommand gives the same output with the static binary"
