#!/usr/bin/env bash
# The hard set in raygrade.js against the native raygrade (docs/web.md): every eighth problem
# of `raygrade bench --corpus-problems` (144 of the accuracy study's hard cases, which need
# the precision ladder's top), solved as JSON natively (the whole process) and by raygrade.js
# in node (the solve call alone, the module loaded; and the whole node process). Each figure
# is the best of RUNS runs; the outputs must be identical.
# Usage: scripts/bench-web.sh [RAYGRADE_JS] [NATIVE_RAYGRADE] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
raygrade_js=$(realpath "${1:-build/web/web/raygrade.js}")
native=$(realpath "${2:-build/release/grader/raygrade}")
runs=${3:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$native" bench --corpus-problems "$work/all.json"
cat > "$work/solve.js" <<'JS'
'use strict';
// Solves the bank RUNS times with raygrade.js; prints the best wall and CPU times of the call
// in seconds.
const fs = require('fs');
const [raygradeJs, bank, out, runs] = process.argv.slice(2);
require(raygradeJs)().then((raygrade) => {
  const text = fs.readFileSync(bank, 'utf8');
  let best = Infinity, bestCpu = Infinity, answer = '';
  for (let k = 0; k < Number(runs); ++k) {
    const start = process.hrtime.bigint(), cpu = process.cpuUsage();
    answer = raygrade.solve({[bank.slice(1)]: text});
    best = Math.min(best, Number(process.hrtime.bigint() - start) / 1e9);
    const used = process.cpuUsage(cpu);
    bestCpu = Math.min(bestCpu, (used.user + used.system) / 1e6);
  }
  fs.writeFileSync(out, answer);
  console.log(best, bestCpu);
});
JS
python3 - "$work" "$raygrade_js" "$native" "$runs" <<'PY'
import json, resource, subprocess, sys, time
work, raygrade_js, native, runs = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
bank = json.load(open(f"{work}/all.json"))
bank["problems"] = bank["problems"][::8]
hard = f"{work}/hard.json"
json.dump(bank, open(hard, "w"), indent=2)

def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime

# The best wall time and the best CPU time of a command (its own processes).
def best(args, **kw):
    times, cpus = [], []
    for _ in range(runs):
        start, cpu = time.perf_counter(), children_cpu()
        out = subprocess.run(args, check=True, capture_output=True, **kw).stdout
        times.append(time.perf_counter() - start)
        cpus.append(children_cpu() - cpu)
    return min(times), min(cpus), out

# Both name the file by its path from / (raygrade.js's file system has its own root).
native_time, native_cpu, native_out = best([native, "solve", hard[1:], "--format", "json"],
                                           cwd="/")
process_time, process_cpu, _ = best(["node", f"{work}/solve.js", raygrade_js, hard,
                                     f"{work}/web1.json", "1"])
call = subprocess.run(["node", f"{work}/solve.js", raygrade_js, hard, f"{work}/web.json", str(runs)],
                      check=True, capture_output=True, text=True).stdout
call_time, call_cpu = map(float, call.split())
if open(f"{work}/web.json", "rb").read() != native_out:
    sys.exit("bench-web: raygrade.js and the native raygrade answer differently")
print(f"hard set: {len(bank['problems'])} problems, best of {runs} runs, outputs identical")
print("                              wall (times native)   CPU (times native)")
def line(what, wall, cpu):
    print(f"{what:<30}{wall:7.3f} s ({wall / native_time:6.1f})  {cpu:7.3f} s ({cpu / native_cpu:6.1f})")
line("native, whole process", native_time, native_cpu)
line("raygrade.js, the solve call", call_time, call_cpu)
line("raygrade.js, node process", process_time, process_cpu)
PY
