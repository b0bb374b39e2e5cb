#!/usr/bin/env bash
# Installs the browser libraries (web/vendor/package.json: three.js, esbuild, axe-core,
# scorm-again) from the npm registry at the versions its lock file pins, into
# web/vendor/node_modules. Does nothing when they are there already at those versions.
set -euo pipefail
cd "$(dirname "$0")/../web/vendor"
if ! command -v npm >/dev/null; then
  echo "fetch-web-libs: npm is missing (scripts/install-deps.sh with RAYGRADE_EXTRA=web installs it)" >&2
  exit 2
fi
stamp=node_modules/.raygrade-lock
if [ -f "$stamp" ] && cmp -s package-lock.json "$stamp"; then
  exit 0
fi
# npm ci installs exactly the lock file's versions; a registry that does not answer fails it
# after npm's own retries.
npm ci --no-audit --no-fund --loglevel=error
cp package-lock.json "$stamp"
