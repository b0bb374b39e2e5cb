#!/usr/bin/env bash
# clang-tidy, with the checks of .clang-tidy (every one an error), over the C++ sources of
# grader/, tests/, bench/ and fuzz/.
#   scripts/tidy.sh           the files the last commit changes (a merge: against its first parent)
#   scripts/tidy.sh --all     every source file
#   scripts/tidy.sh FILE...   the files named
# A changed header is checked through the source file beside it, or else the first source file
# that includes it. A change to .clang-tidy checks the files the commit changes, like any other:
# every file takes about 19 minutes on two cores, beyond CI's budget (run --all after changing
# the checks). The compile
# database is build/tidy's (the tidy preset: clang, no unity batches, no precompiled header,
# the fuzz targets included), configured here when it is missing. Prints the files it checks;
# exits 1 on any warning.
set -euo pipefail
cd "$(dirname "$0")/.."
db=build/tidy
jobs="${RAYGRADE_TIDY_JOBS:-2}"
if [ ! -f "$db/compile_commands.json" ]; then
  cmake --preset tidy >/dev/null
fi
# Every source file of the project in the database, relative to the root, once each (the fuzz
# sources are compiled once per target).
mapfile -t known < <(python3 - "$db/compile_commands.json" "$PWD" <<'PY'
import json, os, sys
root = sys.argv[2] + "/"
seen = set()
for entry in json.load(open(sys.argv[1])):
    path = os.path.normpath(os.path.join(entry["directory"], entry["file"]))
    if path.startswith(root) and path not in seen:
        seen.add(path)
        print(path[len(root):])
PY
)
is_known() {
  local f
  for f in "${known[@]}"; do [ "$f" = "$1" ] && return 0; done
  return 1
}
files=()
if [ "${1:-}" = "--all" ]; then
  files=("${known[@]}")
  echo "clang-tidy: every source file (${#files[@]})" >&2
elif [ $# -gt 0 ]; then
  for f in "$@"; do
    f="${f#./}"
    is_known "$f" || { echo "clang-tidy: $f is not in $db/compile_commands.json" >&2; exit 2; }
    files+=("$f")
  done
else
  if git rev-parse -q --verify HEAD^1 >/dev/null; then
    changed="$(git diff --name-only --diff-filter=d HEAD^1 HEAD)"
    what="the last commit ($(git rev-parse --short HEAD)) against $(git rev-parse --short HEAD^1)"
  else
    changed="$(git ls-files)"
    what="the first commit"
  fi
  {
    declare -A picked=()
    while IFS= read -r f; do
      case "$f" in
        grader/* | tests/* | bench/* | fuzz/*) ;;
        *) continue ;;
      esac
      case "$f" in
        *.cpp) is_known "$f" && picked["$f"]=1 ;;
        *.h)
          if is_known "${f%.h}.cpp"; then
            picked["${f%.h}.cpp"]=1
          else
            # Included as "dir/name.h" from grader/ (the include root) or by its own name.
            rel="${f#grader/}"
            for k in "${known[@]}"; do
              if grep -qE "#include \"($rel|${f##*/})\"" "$k"; then
                picked["$k"]=1
                break
              fi
            done
          fi
          ;;
      esac
    done <<<"$changed"
    files=("${!picked[@]}")
    if [ ${#files[@]} -eq 0 ]; then
      echo "clang-tidy: $what changes no C++ source or header of grader/, tests/, bench/ or" \
        "fuzz/: nothing to check" >&2
      exit 0
    fi
    echo "clang-tidy: $what; ${#files[@]} file(s)" >&2
  }
fi
printf '  %s\n' "${files[@]}" >&2
# Each file's output printed whole once it ends, so that two running side by side do not mix.
start=$SECONDS
status=0
printf '%s\0' "${files[@]}" | xargs -0 -n 1 -P "$jobs" bash -c '
  out="$(clang-tidy-14 -p "$0" --quiet "$1" 2>&1)" && exit 0
  printf "%s\n" "$out"
  exit 1' "$db" || status=1
echo "clang-tidy: ${#files[@]} file(s) in $((SECONDS - start)) s: $([ $status -eq 0 ] && echo clean || echo WARNINGS)" >&2
exit $status
