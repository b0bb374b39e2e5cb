#!/usr/bin/env bash
# Measures how long raygrade takes to write the worked solutions of a 1,000-problem bank
# (every kind and primitive, fixed pseudo-random numbers), in all four formats and in Markdown
# alone. Usage: scripts/bench-solutions.sh [path to raygrade] [number of problems]
set -euo pipefail
cd "$(dirname "$0")/.."
binary="${1:-build/release/grader/raygrade}"
count="${2:-1000}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

python3 - "$work/bank.json" "$count" <<'PY'
import json, random, sys
random.seed(20261121)
path, count = sys.argv[1], int(sys.argv[2])
r = lambda: random.randint(-5, 5)
v = lambda: [r(), r(), r()]
def direction():
    while True:
        d = v()
        if d != [0, 0, 0]:
            return d
def obj(i):
    k = i % 6
    if k == 0: return {"type": "sphere", "center": v(), "radius": random.randint(1, 3)}
    if k == 1: return {"type": "plane", "point": v(), "normal": direction()}
    if k == 2: return {"type": "triangle", "vertices": [[0, 0, 0], [4, 0, 0], [0, 4, random.randint(0, 3)]]}
    if k == 3: return {"type": "polygon", "vertices": [[0, 0, 1], [3, 0, 1], [3, 2, 1], [1, 1, 1], [0, 2, 1]]}
    if k == 4: return {"type": "cylinder", "base": [r(), r(), 0], "axis": [0, 0, 1], "radius": 2,
                       "height": 4, "capped": True}
    lo = v()
    return {"type": "box", "min": lo, "max": [c + random.randint(1, 3) for c in lo]}
problems = []
for i in range(count):
    ray = {"origin": v(), "direction": direction()}
    if i % 10 == 8:
        objs = [dict(obj(j), name=f"object {j}") for j in (0, 4, 5)]
        problems.append({"id": f"p{i:04d}", "kind": "first-hit", "ray": ray, "objects": objs})
    elif i % 10 == 9:
        problems.append({"id": f"p{i:04d}", "kind": "camera-ray", "pixel": [r() + 5, r() + 5],
                         "camera": {"eye": v(), "direction": [0, 0, -1], "up": [0, 1, 0],
                                    "focal_length": 2, "resolution": [10, 10]}})
    else:
        problems.append({"id": f"p{i:04d}", "title": f"Problem {i}", "ray": ray, "object": obj(i)})
json.dump({"problems": problems}, open(path, "w"))
PY

run() {
  local label="$1" out="$2"; shift 2
  local start end
  start=$(date +%s%N)
  "$binary" solutions "$work/bank.json" --out "$out" "$@" >/dev/null
  end=$(date +%s%N)
  printf '%-34s %5d ms  (%d files, %s)\n' "$label" $(( (end - start) / 1000000 )) \
    "$(find "$out" -type f | wc -l)" "$(du -sh "$out" | cut -f1)"
}
echo "$count problems"
run "all four formats" "$work/all"
run "again, nothing changed" "$work/all"
run "check only" "$work/all" --check
run "markdown only" "$work/md" --format md
