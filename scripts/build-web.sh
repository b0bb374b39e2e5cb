#!/usr/bin/env bash
# Builds raygrade.js (build/web/web/raygrade.js), the grader in WebAssembly, with Debian's
# emscripten (RAYGRADE_EXTRA=web of scripts/install-deps.sh); docs/web.md.
set -euo pipefail
cd "$(dirname "$0")/.."
RAYGRADE_EXTRA="web" bash scripts/install-deps.sh
# three.js and esbuild: the library embeds the pages' 3D view, bundled when it is configured.
bash scripts/fetch-web-libs.sh
# Emscripten's JavaScript optimizer needs Debian's acorn, which a node from elsewhere does not
# find by itself.
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"
cmake --preset web >/dev/null
cmake --build --preset web -j"${RAYGRADE_WEB_JOBS:-2}"
ls -l build/web/web/raygrade.js
