#!/usr/bin/env bash
# Benchmark of big batches: grading 10,000 submissions of 10 answers each to CSV, JSON and HTML,
# checking banks of 10,000 and 100,000 problems, and checking the single problems that used to
# take quadratic time (a first hit among thousands of spheres, a polygon of thousands of
# vertices, a bank of thousands of faulty problems). Quotes wall time, CPU time and peak memory
# of each run. Usage: scripts/bench-batch.sh [RAYGRADE] [SUBMISSIONS] [all|grade] (grade: the
# grading runs alone).
set -euo pipefail
cd "$(dirname "$0")/.."
raygrade=$(realpath "${1:-build/release/grader/raygrade}")
count=${2:-10000}
what=${3:-all}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# A bank of 10 generated problems, the solver's answers to it, and $count submissions built
# from them: every fifth answer has its first t off by 1 (feedback, a named part wrong).
"$raygrade" generate --seed 3 -n 10 > "$work/bank.json"
"$raygrade" solve "$work/bank.json" --format json > "$work/answers.json"
python3 - "$work" "$count" <<'PY'
import json, os, sys
work, count = sys.argv[1], int(sys.argv[2])
solved = json.load(open(os.path.join(work, "answers.json")))
items = solved["solutions"]
answers = {p["id"]: p["answer"] for p in items}
os.makedirs(os.path.join(work, "subs"))
for i in range(count):
    mine = json.loads(json.dumps(answers))
    if i % 5 == 0:
        for a in mine.values():
            if a.get("hits"):
                a["hits"][0]["t"] += 1
                break
    with open(os.path.join(work, "subs", f"s{i:05}.json"), "w") as f:
        json.dump({"student": {"name": f"Student {i}", "id": f"s{i:05}"}, "answers": mine}, f)
PY

# measure LABEL OUTPUT COMMAND...: runs COMMAND with its standard output in OUTPUT and prints
# its wall time, CPU time (user + system) and peak memory (maximum resident set).
measure() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
label, output, cmd = sys.argv[1], sys.argv[2], sys.argv[3:]
start = time.monotonic()
with open(output, "wb") as out:
    code = subprocess.run(cmd, stdout=out, stderr=subprocess.DEVNULL).returncode
wall = time.monotonic() - start
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"| {label} | {wall:.2f} s | {r.ru_utime + r.ru_stime:.2f} s | {r.ru_maxrss / 1024:.0f} MB | {code} |")
PY
}

answers=$((count * 10))
echo "Grading $count submissions ($answers answers) against 10 problems, $(nproc) cores:"
echo "| run | wall | CPU | peak memory | exit |"
echo "| --- | --- | --- | --- | --- |"
grade=("$raygrade" grade --problems "$work/bank.json" "$work/subs")
measure "grade, CSV on standard output, one thread (--jobs 1)" "$work/grades1.csv" "${grade[@]}" --format csv --jobs 1
measure "grade, CSV on standard output" "$work/grades.csv" "${grade[@]}" --format csv
cmp -s "$work/grades1.csv" "$work/grades.csv" || echo "(the gradebooks of one thread and of $(nproc) differ)"
measure "grade, JSON on standard output" "$work/grades.json" "${grade[@]}" --format json
measure "grade, HTML pages (--out)" /dev/null "$raygrade" grade --problems "$work/bank.json" "$work/subs" --format html --out "$work/html"
echo "(rows: $(($(wc -l < "$work/grades.csv") - 1)), pages: $(find "$work/html" -name '*.html' | wc -l))"
[ "$what" = grade ] && exit 0

# Banks of 10,000 and 100,000 problems: files of 10,000 problems each (one file may hold at
# most 16 MiB), different seeds.
for n in 1 10; do
  mkdir -p "$work/bank$n"
  for s in $(seq 1 "$n"); do
    "$raygrade" generate --seed "$s" -n 10000 > "$work/bank$n/part$s.json"
  done
done
echo
echo "| check | wall | CPU | peak memory | exit |"
echo "| --- | --- | --- | --- | --- |"
measure "check, 10,000 problems" /dev/null "$raygrade" check --no-solutions "$work/bank1"
measure "check, 100,000 problems" /dev/null "$raygrade" check --no-solutions "$work/bank10"

# Single large problems and a bank of faulty ones, twice the size each time.
python3 - "$work" <<'PY'
import json, math, os, sys
work = sys.argv[1]
def bank(name, problems):
    json.dump({"problems": problems}, open(os.path.join(work, name), "w"), indent=1)
for n in (1000, 2000, 4000):
    objects = [{"name": f"s{i}", "type": "sphere", "center": [i + 10.5, 5.25, 0], "radius": 1.25}
               for i in range(n)]
    objects[n // 2] = {"name": "near", "type": "sphere", "center": [5.25, 0.5, 0], "radius": 1.25}
    bank(f"spheres{n}.json", [{"id": f"spheres-{n}", "kind": "first-hit",
          "ray": {"origin": [0, 0, 0], "direction": [1, 0, 0]}, "objects": objects}])
for n in (2000, 4000, 8000):
    vertices = [[round(1.25 * math.cos(2 * math.pi * k / n), 6),
                 round(1.25 * math.sin(2 * math.pi * k / n), 6), 0] for k in range(n)]
    bank(f"polygon{n}.json", [{"id": f"polygon-{n}", "ray": {"origin": [0.125, 0.25, 3],
          "direction": [0, 0, -1]}, "object": {"type": "polygon", "vertices": vertices}}])
for n in (5000, 10000, 20000):
    bank(f"faulty{n}.json", [{"id": f"bad-{i}", "ray": {"origin": [0, 0, 0],
          "direction": [1, 0, 0]}, "object": {"type": "sphere", "center": [5, 0, 0],
          "radius": -1}, "colour": "red"} for i in range(n)])
PY
echo
echo "| check of one file | wall | CPU | peak memory | exit |"
echo "| --- | --- | --- | --- | --- |"
for f in spheres1000 spheres2000 spheres4000 polygon2000 polygon4000 polygon8000 faulty5000 faulty10000 faulty20000; do
  measure "$f" /dev/null "$raygrade" check --no-solutions "$work/$f.json"
done
