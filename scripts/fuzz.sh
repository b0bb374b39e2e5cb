#!/usr/bin/env bash
# Runs the libFuzzer targets (fuzz/) for a chosen time: scripts/fuzz.sh TARGET|all SECONDS.
# Builds them first (clang, ASan and UBSan: the `asan` preset, whose build also holds the tests
# under the sanitizers, so CI builds the library with clang once for both), then runs as many
# targets at once as there are processors. New inputs found go to build/asan/corpus/<target>/ (the
# seeds in fuzz/corpus/ are only read); a crash is saved in build/asan/artifacts/<target>/ and makes
# the script fail: add it to tests/fixtures/fuzz/<target>/ so that the regression test replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 2 ]; then
  echo "usage: scripts/fuzz.sh TARGET|all SECONDS" >&2
  exit 2
fi
what=$1
seconds=$2
RAYGRADE_EXTRA="${RAYGRADE_EXTRA:-} fuzz" bash scripts/install-deps.sh
cmake --preset asan >/dev/null
cmake --build --preset asan --target raygrade_fuzzers
build=build/asan

if [ "$what" = all ]; then
  targets=$(ls fuzz/corpus)
else
  targets=$what
fi
# One target's run; its status is the run's.
fuzz_one() {
  local t=$1
  local work=$build/corpus/$t artifacts=$build/artifacts/$t log=$build/fuzz-$t.log
  mkdir -p "$work" "$artifacts"
  # -timeout: an input that takes 10 s is a hang; -rss_limit_mb: a leak or a memory bomb.
  if "$build/fuzz/fuzz_$t" "$work" "fuzz/corpus/$t" -dict=fuzz/json.dict \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
    echo "fuzz: $t: ${runs:-?} runs in ${seconds} s, no crash"
  else
    echo "fuzz: $t: FAILED, see $log and $artifacts/" >&2
    grep -m 20 -E 'ERROR|SUMMARY|runtime error|terminate called|what\(\)|Test unit written' "$log" >&2 || true
    return 1
  fi
}
for t in $targets; do
  if [ ! -x "$build/fuzz/fuzz_$t" ]; then
    echo "fuzz: no target '$t' (known: $(ls fuzz/corpus | tr '\n' ' '))" >&2
    exit 2
  fi
done
# As many targets at once as there are processors, each on its own.
status=0
running=0
for t in $targets; do
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz_one "$t" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
