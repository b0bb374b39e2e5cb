#!/usr/bin/env bash
# The main job: install what is missing, build, solve the bundled bank, write the worked
# solutions, grade the bundled sample submissions and print a short summary.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# three.js and esbuild for the pages' 3D view, which the build bundles (nothing when present).
bash scripts/fetch-web-libs.sh
cmake --preset release >/dev/null
# The raygrade binary alone: the tests and benchmarks are scripts/test.sh's.
cmake --build --preset release --target raygrade
exec build/release/grader/raygrade run --problems problems --submissions submissions --solutions solutions
