#!/usr/bin/env bash
# The static binary against the release one: every subcommand run by both on the bundled
# bank, assignment and submissions must write the same bytes (the conformance set runs
# separately; bench's timings differ from run to run, so bench writes its MPFR corpus only).
# Usage: scripts/static-check.sh [STATIC] [RELEASE]
set -euo pipefail
cd "$(dirname "$0")/.."
static="${1:-build/static/grader/raygrade}"
release="${2:-build/release/grader/raygrade}"
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
    bin=$(realpath "$bin")
    mkdir -p "$work/$which/$name"
    local args=("${@//BIN/$bin}")
    args=("${args[@]//OUT/$work/$which/$name/out}")
    set +e
    "${args[@]}" > "$work/$which/$name.stdout" 2> "$work/$which/$name.stderr"
    echo $? > "$work/$which/$name.status"
    set -e
  done
  # Paths of the two folders differ; everything else must not.
  if ! diff -r <(sed "s|$work/static|W|g" "$work/static/$name.stdout") \
               <(sed "s|$work/release|W|g" "$work/release/$name.stdout") > /dev/null ||
     ! diff "$work/static/$name.status" "$work/release/$name.status" > /dev/null ||
     { [ -d "$work/static/$name/out" ] && ! diff -r "$work/static/$name/out" "$work/release/$name/out" > /dev/null; }; then
    echo "static-check: $name differs between $static and $release" >&2
    failures=$((failures + 1))
  else
    echo "static-check: $name: same (exit $(cat "$work/static/$name.status"))"
  fi
}

same solve BIN solve problems --format json
same solve-html BIN solve assignments/homework-rays.json --student s001 --format html
same run BIN run --problems problems --submissions submissions --solutions OUT
same solutions-check BIN solutions problems --check --out solutions
same grade-csv BIN grade --problems problems submissions --format csv
same grade-json BIN grade --problems problems submissions --format json
same check BIN check problems --format junit
same generate BIN generate --seed 42 -n 20 --out OUT
same handout BIN handout assignments/homework-rays.json --student s001 --out OUT
same bench-corpus BIN bench --write-corpus OUT
same export BIN export gradescope assignments/homework-rays.json --out OUT --binary "$static"
[ "$failures" -eq 0 ] || exit 1
echo "static-check: every subcommand gives the same output with the static binary"
