#!/usr/bin/env bash
# scripts/install-deps.sh with another apt-get holding the dpkg lock: it waits, says so, and
# goes on once the lock is free; past RAYGRADE_APT_WAIT seconds it gives up with apt's message.
# apt-get and dpkg-query are stand-ins on the PATH (this test installs nothing): dpkg-query says
# one package is missing, and apt-get fails as apt does while the lock is held, for as many
# calls as the counter file says.
set -u
repo=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
cat > "$work/bin/dpkg-query" <<'SH'
#!/usr/bin/env bash
# Every package is installed except ninja-build.
for a in "$@"; do last=$a; done
[ "$last" = ninja-build ] && exit 1
printf 'install ok installed'
SH
cat > "$work/bin/apt-get" <<'SH'
#!/usr/bin/env bash
# Fails as apt does while another process holds the lock, LOCKED_CALLS times, then succeeds.
n=$(cat "$COUNTER")
echo $((n + 1)) > "$COUNTER"
if [ "$n" -lt "$LOCKED_CALLS" ]; then
  echo "E: Could not get lock /var/lib/dpkg/lock-frontend. It is held by process 4242 (apt-get)" >&2
  exit 100
fi
echo "apt-get $*" >> "$CALLS"
SH
chmod +x "$work/bin/dpkg-query" "$work/bin/apt-get"
failures=0
fail() { echo "FAIL: $1"; failures=$((failures + 1)); }

# Held for the first two calls: waits (5 s a try), then updates and installs.
echo 0 > "$work/counter"
out=$(PATH="$work/bin:$PATH" COUNTER="$work/counter" CALLS="$work/calls" LOCKED_CALLS=2 \
  RAYGRADE_APT_WAIT=60 bash "$repo/scripts/install-deps.sh" 2>&1)
status=$?
[ "$status" -eq 0 ] || fail "with the lock freed it exited $status: $out"
grep -q "holds its lock; waiting" <<<"$out" || fail "it did not say it waits: $out"
grep -q "install .*ninja-build" "$work/calls" 2>/dev/null || fail "ninja-build was not installed"
grep -q "update" "$work/calls" 2>/dev/null || fail "the package lists were not updated"

# Held for good: gives up after RAYGRADE_APT_WAIT seconds, with apt's own message.
echo 0 > "$work/counter"
rm -f "$work/calls"
start=$(date +%s)
out=$(PATH="$work/bin:$PATH" COUNTER="$work/counter" CALLS="$work/calls" LOCKED_CALLS=1000 \
  RAYGRADE_APT_WAIT=6 bash "$repo/scripts/install-deps.sh" 2>&1)
status=$?
took=$(( $(date +%s) - start ))
[ "$status" -ne 0 ] || fail "with the lock held for good it exited 0"
grep -q "Could not get lock" <<<"$out" || fail "apt's message was not passed on: $out"
[ "$took" -lt 30 ] || fail "it waited $took s past a limit of 6 s"

echo "$(( 5 - failures < 0 ? 0 : 5 - failures )) passed, $failures failed"
[ "$failures" -eq 0 ]
