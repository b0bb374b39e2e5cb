#!/usr/bin/env python3
"""No code outside grader/kinds/ names a field type of the answer forms by string.

A field type (a number box, a vector box, a table of hits, ...) is its header in
grader/kinds/fields/ and one line of the list `FieldTypes` (kinds/fields/field_types.h). The
kinds write forms with it (`form::field<field_types::Vector>(...)`); everything else takes what
it does with a field from the field's shape and value through the table (`field_type_of`), and
the pages from the table the page carries (`data.field_types`). A type's name written as a
string elsewhere is a branch the list does not know about: the next type silently shown or
exported as another.

Flagged, in every C++ source, script and Python file of grader/ and web/ outside grader/kinds/
(comments taken out):
- a string literal that is a field type's name, compared with something (==, !=, ===, !==, or
  `in (...)`/`in [...]` in Python);
- such a literal anywhere on a line that speaks of a type (`type`, `ctype`, `FieldType`), but
  for JSON text's own `"type": "number"` (a schema's, not a form's) and JavaScript's
  `typeof x === "number"`;
- the names no other word is spelled as (`yesno`) anywhere.
The files that still do are listed in ALLOWED with the count of their flagged lines: a file not
listed, or more lines of a listed one, fails; so does a listed one with fewer, until its count is
brought down, so that the list only shrinks.

Usage: field_names.py SOURCE_ROOT
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from source_scan import against_allowed, finish, strip_comments  # noqa: E402

# path: the number of its flagged lines. Each is a file not yet moved behind the table.
ALLOWED = {}

SUFFIXES = {".cpp", ".h", ".in", ".js", ".py"}
EXEMPT_FILES = {"grader/assignments/typed_reader.js"}  # generated (Emscripten's output)

def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    fields_dir = root / "grader" / "kinds" / "fields"
    names = set()
    for header in fields_dir.glob("*.h"):
        names.update(re.findall(r'kName\s*=\s*"([^"]+)"', header.read_text(encoding="utf-8")))
    if len(names) < 5:
        sys.exit(f"field_names: found only {sorted(names)} in {fields_dir}: the types' kName moved?")
    only_types = {n for n in names if n in {"yesno"}}

    literal = re.compile(r'"((?:[^"\\\n]|\\.)*)"|\'((?:[^\'\\\n]|\\.)*)\'')
    compared = re.compile(r'(?:[!=]==?|\bin\s*[\(\[][^\)\]]*)\s*$')
    compared_after = re.compile(r'^\s*(?:[!=]==?)')
    json_type = re.compile(r'"type"\s*:\s*$')
    typeof = re.compile(r'typeof\s+[\w.]+\s*[!=]==?\s*$')  # JavaScript's own types
    speaks_of_type = re.compile(r"type", re.I)


    lines_of = {}
    for path in sorted(list((root / "grader").rglob("*")) + list((root / "web").rglob("*"))):
        rel = path.relative_to(root).as_posix()
        if (not path.is_file() or path.suffix not in SUFFIXES or rel in EXEMPT_FILES
                or (root / "grader" / "kinds") in path.parents or "node_modules" in path.parts):
            continue
        text = strip_comments(path.read_text(encoding="utf-8"), path.suffix == ".py")
        for number, line in enumerate(text.splitlines(), 1):
            for m in literal.finditer(line):
                word = m.group(1) if m.group(1) is not None else m.group(2)
                if word not in names:
                    continue
                before, after = line[:m.start()], line[m.end():]
                if json_type.search(before) or typeof.search(before):
                    continue
                if (word in only_types or compared.search(before) or compared_after.search(after)
                        or speaks_of_type.search(line)):
                    lines_of.setdefault(rel, []).append(f"{rel}:{number}: {line.strip()}")
                    break

    finish(against_allowed(lines_of, ALLOWED, "a field type by string", "field_names"),
           "field_names: code outside grader/kinds/ names a field type by string; take what a "
           "field does from its shape and value (kinds/fields/field_type.h, field_type_of) or, in "
           "a page, from data.field_types",
           f"field_names: no code outside grader/kinds/ names any of the {len(names)} field "
           f"types by string ({sum(ALLOWED.values())} allowed line(s) in {len(ALLOWED)} file(s))")


if __name__ == "__main__":
    main()
