#!/usr/bin/env bash
# Benchmark of `raygrade check` on a 10,000-problem bank, on one core.
# Usage: scripts/bench-check.sh [RAYGRADE] [COUNT]. Generates the bank with `raygrade generate`
# (integer inputs), and a copy with every length divided by 10 (every input a one-decimal
# number, so the conditioning check perturbs each of them), then times the check of each.
set -euo pipefail
cd "$(dirname "$0")/.."
raygrade=${1:-build/release/grader/raygrade}
count=${2:-10000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$raygrade" generate --seed 1 -n "$count" > "$work/bank.json"
python3 - "$work/bank.json" "$work/scaled.json" <<'PY'
import json, sys
# Lengths scale by 1/10; t, pixels, resolutions and focal lengths do not.
LENGTHS = {"origin", "direction", "center", "radius", "point", "normal", "d", "vertices",
           "base", "height", "min", "max", "eye", "up"}
def scale(v):
    if isinstance(v, list): return [scale(x) for x in v]
    return round(v / 10, 10)
def walk(v, key=None):
    if isinstance(v, dict):
        return {k: (scale(x) if k in LENGTHS and k != "normal" and key != "camera" else walk(x, k))
                for k, x in v.items()}
    if isinstance(v, list): return [walk(x, key) for x in v]
    return v
bank = json.load(open(sys.argv[1]))
for p in bank["problems"]:
    p.pop("statement", None)
    if p.get("kind") == "camera-ray":
        p.pop("expected", None)
bank = walk(bank)
json.dump(bank, open(sys.argv[2], "w"), indent=1)
PY

cores=$(nproc)
pin=""
command -v taskset >/dev/null && pin="taskset -c $((cores - 1))"
TIMEFORMAT="  %R s wall, %U s user, %S s system"
for bank in bank scaled; do
  echo "raygrade check on $count problems ($bank.json), one core:"
  time $pin "$raygrade" check "$work/$bank.json" --no-solutions | tail -1
done
