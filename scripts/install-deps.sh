#!/usr/bin/env bash
# Installs the Debian 12 packages raygrade needs, skipping those already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build python3
  nlohmann-json3-dev libfmt-dev libcli11-dev libgtest-dev libgmock-dev
  libbenchmark-dev libmpfr-dev libglm-dev
  python3-jsonschema pkg-config clang-format strace
  libgmp-dev file
)
# Extra groups, asked for by name: RAYGRADE_EXTRA="browser fuzz web".
for extra in ${RAYGRADE_EXTRA:-}; do
  case "$extra" in
    browser) packages+=(chromium chromium-driver python3-selenium) ;;
    fuzz) packages+=(clang libclang-rt-14-dev) ;;
    web) packages+=(emscripten nodejs) ;;
    *) echo "install-deps: unknown extra '$extra'" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  # Captured, not piped into grep -q: with pipefail an early exit of grep could fail the pipe.
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  if [ "$status" != "install ok installed" ]; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
