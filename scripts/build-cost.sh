#!/usr/bin/env bash
# What building costs: a target of the release preset from an empty build folder (build/cost,
# removed after), in CPU seconds (user + system of every compiler and linker process) and wall
# seconds. Usage: scripts/build-cost.sh [TARGET]   (default: raygrade)
set -euo pipefail
cd "$(dirname "$0")/.."
target="${1:-raygrade}"
folder=build/cost
rm -rf "$folder"
trap 'rm -rf "$folder"' EXIT
cmake --preset release -B "$folder" >/dev/null
python3 - "$folder" "$target" <<'PY'
import os, resource, subprocess, sys, time
folder, target = sys.argv[1], sys.argv[2]
start = time.monotonic()
subprocess.run(["cmake", "--build", folder, "--target", target], check=True,
               stdout=subprocess.DEVNULL)
wall = time.monotonic() - start
# Every process the build waited for, its compilers included.
use = resource.getrusage(resource.RUSAGE_CHILDREN)
print(f"{target}: {use.ru_utime + use.ru_stime:.0f} s of CPU (user {use.ru_utime:.0f} s, "
      f"system {use.ru_stime:.0f} s), {wall:.0f} s wall on {os.cpu_count()} cores, "
      f"from an empty build folder")
PY
