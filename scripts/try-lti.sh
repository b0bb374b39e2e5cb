#!/usr/bin/env bash
# raygrade as an LTI 1.3 tool without an LMS: starts the test platform of tests/lti beside
# `raygrade serve` (the bundled assignments, data in a temporary folder), registers the tool by
# Dynamic Registration, places homework-rays in a course, and prints the addresses a person
# opens in a browser to be a student or an instructor. Ctrl-C stops both.
# The platform is at http://localhost:P and the tool at http://127.0.0.1:T: two sites, as an
# LMS and a tool are. Needs Debian's python3-jwcrypto and python3-requests.
# Usage: scripts/try-lti.sh [RAYGRADE] (default build/release/grader/raygrade)
set -euo pipefail
cd "$(dirname "$0")/.."
raygrade=${1:-build/release/grader/raygrade}
python=/usr/bin/python3
[[ -x $python ]] || python=python3
[[ -x $raygrade ]] || { echo "try-lti: $raygrade is not built (cmake -DRAYGRADE_SERVE=ON ...)" >&2; exit 2; }
work=$(mktemp -d -t raygrade-lti-XXXXXX)
pids=()
stop() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  wait 2>/dev/null || true
  echo "try-lti: stopped; the data is kept in $work"
}
trap stop EXIT
trap 'exit 130' INT TERM

wait_line() {  # FILE PATTERN: the first line of FILE matching PATTERN, within 30 s
  for _ in $(seq 300); do
    if line=$(grep -m1 -E "$2" "$1" 2>/dev/null); then echo "$line"; return 0; fi
    sleep 0.1
  done
  echo "try-lti: no '$2' in $1:" >&2; cat "$1" >&2; return 1
}

mkdir -p "$work/platform" "$work/data"
$python tests/lti/platform.py --port 0 --public-host localhost --state "$work/platform" \
  >"$work/platform.out" 2>"$work/platform.log" &
pids+=($!)
platform=$(wait_line "$work/platform.out" '^platform: ' | sed 's/^platform: //')

port=$($python -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
tool="http://127.0.0.1:$port"
"$raygrade" serve --data "$work/data" --listen "127.0.0.1:$port" --public-url "$tool" \
  --assignments assignments >"$work/serve.out" 2>"$work/serve.log" &
pids+=($!)
wait_line "$work/serve.out" '^JWKS URL: ' >/dev/null

json() {  # PYTHON-EXPRESSION on the JSON of standard input (as j)
  $python -c "import json, sys; j = json.load(sys.stdin); print($1)"
}
token=$(curl -sf -X POST "$platform/test/registration-token")
config=$(echo "$token" | json 'j["openid_configuration"]')
secret=$(echo "$token" | json 'j["token"]')
curl -sf -G "$tool/lti/register" --data-urlencode "openid_configuration=$config" \
  --data-urlencode "registration_token=$secret" >/dev/null
points=$($python -c 'import json; print(sum(p.get("points", 1) if isinstance(p, dict) else 1 for p in json.load(open("assignments/homework-rays.json"))["problems"]))')
link=$(curl -sf -X POST "$platform/test/link" -H 'Content-Type: application/json' \
  -d "{\"title\": \"Homework: rays, surfaces and light\", \"custom\": {\"assignment\": \"homework-rays.json\"}, \"scoreMaximum\": $points}" |
  json 'j["id"]')

cat <<TEXT

raygrade serve at $tool, registered with the test platform at $platform.
Open one of these in a browser (each logs that browser in as the user it names):

  a student, Ada:          $platform/test/launch?user=ada&name=Ada%20Lovelace&link=$link
  another student, Alan:   $platform/test/launch?user=alan&name=Alan%20Turing&link=$link
  the instructor:          $platform/test/launch?user=teacher&role=Instructor&link=$link
  the instructor placing an assignment (deep linking):
                           $platform/test/launch?user=teacher&role=Instructor&message=deeplink&context=course-1

  the scores the platform has received:  $platform/test/scores
  (one browser is one user: use a private window for a second student)

Data: $work (the tool's database in data/, its log in serve.log). Ctrl-C stops.
TEXT
wait
