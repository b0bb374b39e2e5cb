#!/usr/bin/env bash
# Installs the Debian 12 packages raygrade needs, skipping those already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build python3
  nlohmann-json3-dev libfmt-dev libcli11-dev libgtest-dev libgmock-dev
  libbenchmark-dev libmpfr-dev libglm-dev
  python3-jsonschema pkg-config clang-format strace
  libgmp-dev file nodejs libboost-dev
  libzip-dev libpugixml-dev libxml2-utils libutf8proc-dev
  # raygrade serve (RAYGRADE_SERVE), and its tests' stand-in platforms; PostgreSQL's client
  # library, and its server for the tests on a throwaway cluster (tests/lti/pgcluster.py)
  libcpp-httplib-dev libssl-dev libsqlite3-dev python3-jwcrypto python3-requests
  libpq-dev postgresql
)
# npm fetches the browser libraries the build bundles (scripts/fetch-web-libs.sh). Debian ships
# it as its own package; a nodejs from elsewhere (NodeSource) carries it already.
if ! command -v npm >/dev/null; then
  packages+=(npm)
fi
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

# Another apt-get or dpkg (an unattended upgrade, a second terminal) may hold the dpkg or
# package-list lock: wait for it, up to RAYGRADE_APT_WAIT seconds (default 900), saying so,
# then give up with apt's own message.
wait_limit=${RAYGRADE_APT_WAIT:-900}
deadline=$(( $(date +%s) + wait_limit ))
apt_waiting() {
  local log status
  log=$(mktemp)
  while true; do
    # DPkg::Lock::Timeout makes apt itself wait for the dpkg frontend lock; the loop covers the
    # locks it does not wait for (the package lists' during an update).
    status=0
    $sudo apt-get -o DPkg::Lock::Timeout="$wait_limit" "$@" 2>"$log" || status=$?
    if [ "$status" -eq 0 ]; then
      cat "$log" >&2
      rm -f "$log"
      return 0
    fi
    if grep -qiE 'could not get lock|unable to acquire|another process' "$log" &&
       [ "$(date +%s)" -lt "$deadline" ]; then
      echo "install-deps: another apt-get or dpkg holds its lock; waiting (at most ${wait_limit} s in all)" >&2
      sleep 5
      continue
    fi
    cat "$log" >&2
    rm -f "$log"
    return "$status"
  done
}
apt_waiting update -qq
apt_waiting install -y -qq --no-install-recommends "${missing[@]}"
