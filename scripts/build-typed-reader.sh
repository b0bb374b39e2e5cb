#!/usr/bin/env bash
# Builds grader/assignments/typed_reader.js: the grader's reader of typed answers alone
# (web/typed_reader.cpp, grading/typed_box.cpp, grading/answer_reader.cpp, derivation/formula.cpp,
# the table of field types and what they call) in WebAssembly, one file with the module in base64, compiled synchronously
# so that a page opened from file:// reads a typed box at once (docs/web.md). The file is kept in
# the repository, so that the grader's own build needs no Emscripten; the ctest
# typed_reader_up_to_date rebuilds it and compares (--check).
# Usage: scripts/build-typed-reader.sh [--check]
set -euo pipefail
cd "$(dirname "$0")/.."
out=grader/assignments/typed_reader.js
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/include"
for folder in nlohmann fmt; do ln -s "/usr/include/$folder" "$work/include/$folder"; done
export NODE_PATH="${NODE_PATH:+$NODE_PATH:}/usr/share/nodejs"
# Sources in a fixed order and no paths in the output: the same file on every machine. Small:
# -Oz with link-time optimization, emmalloc, and fmt without std::locale (no format of the
# reader groups digits by locale; the locale's facets were a third of the module): 248 KB, not
# 412 KB with -Os alone.
em++ -std=c++20 -Oz -flto -DNDEBUG -DFMT_HEADER_ONLY -DFMT_STATIC_THOUSANDS_SEPARATOR=0x2c -fwasm-exceptions -Igrader -isystem "$work/include" \
  web/typed_reader.cpp grader/grading/typed_box.cpp grader/grading/answer_reader.cpp \
  grader/kinds/fields/field_type.cpp grader/derivation/formula.cpp grader/core/escape.cpp grader/core/error.cpp grader/json/cursor.cpp \
  -sMODULARIZE=1 -sEXPORT_NAME=createTypedReader -sSINGLE_FILE=1 -sWASM_ASYNC_COMPILATION=0 \
  -sENVIRONMENT=web,node -sFILESYSTEM=0 -sALLOW_MEMORY_GROWTH=1 -flto -sMALLOC=emmalloc \
  -sEXPORTED_FUNCTIONS=_raygrade_read_typed -sEXPORTED_RUNTIME_METHODS=ccall \
  -o "$work/typed_reader.js"
{
  echo "// The grader's reader of typed answers in WebAssembly: written by"
  echo "// scripts/build-typed-reader.sh from web/typed_reader.cpp; do not edit."
  cat "$work/typed_reader.js"
} >"$work/out.js"
if [[ "${1:-}" == "--check" ]]; then
  if cmp -s "$work/out.js" "$out"; then echo "$out is up to date."; exit 0; fi
  echo "$out is out of date: run scripts/build-typed-reader.sh"; exit 1
fi
mv "$work/out.js" "$out"
ls -l "$out"
