#!/usr/bin/env python3
"""No code outside grader/kinds/ names a part of an answer by string.

A part (`t`, `point`, `direction`, `total_internal_reflection`, ...) is declared by its kind
(`parts()`, a `PartSpec` each: grader/kinds/) and listed in docs/grading.md's table of parts,
which `raygrade tables docs` writes from the code (the test reference_tables_up_to_date keeps it
so). Code above the kinds takes a part from its kind: its `PartSpec` (problems/kind.h, through
grading/parts.h), or a name the kind's header gives it, never a string of its own, so that a
part renamed or added in its kind cannot leave a branch behind that still tests the old name.

Flagged: a string literal that is a part's name, in a statement that handles an answer or a part (it
speaks of a part, an answer, a reference, expected or stated answer, points, a mistake, a column
or what a field asks, or reads a key: `.at(`, `.has(`, `allow_only`, `for_field`), in any C++
source, script or Python file of the folders that handle answers (grader/grading, assignments,
reports, check, serve, cli, generate, and web/), with comments taken out; and such a literal
compared with something (==, !=, `in (...)`) or chosen (`a ? "x" : "y"`) anywhere there. The same words as a
figure's ink or a page's CSS class are not parts. The folders below the kinds (shapes/, scenes/, problems/,
...) cannot know a kind's parts (folders include only downward), and the same words there are
keys of the problem format (a plane's "normal", a ray's "origin"), not parts.
The files that still name parts are listed in ALLOWED with the count of their lines that do: a
file not listed, or more lines of a listed one, fails; so does a listed one with fewer lines,
until its count is brought down, so that the list only shrinks.

A line whose comment says "not a part: <why>" is left out, and so is the statement (or the
braced row of a table) after a comment line that says it: the same word meaning something else there (a derivation's quantity,
a formula's symbol, a file's mode).

Usage: part_names.py SOURCE_ROOT
"""
import pathlib
import re
import sys

# path: the number of its lines that name a part. Each is a file not yet moved behind its
# kinds' declarations.
ALLOWED = {}

FOLDERS = ["grader/grading", "grader/assignments", "grader/reports", "grader/check",
           "grader/serve", "grader/cli", "grader/generate", "web"]
SUFFIXES = {".cpp", ".h", ".in", ".js", ".py"}
EXEMPT_FILES = {"grader/assignments/typed_reader.js"}  # generated (Emscripten's output)

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
text = (root / "docs" / "grading.md").read_text(encoding="utf-8")
begin = text.find("<!-- raygrade tables: parts -->")
end = text.find("<!-- raygrade tables: end -->", begin)
if begin < 0 or end < 0:
    sys.exit("part_names: docs/grading.md has no table of parts (raygrade tables docs)")
names = set()
for row in text[begin:end].splitlines():
    cells = row.split("|")
    if len(cells) > 3:
        name = cells[2].strip().strip("`")
        if re.fullmatch(r"[a-z][a-z0-9_]*", name) and name != "part":
            names.add(name)
if len(names) < 20:
    sys.exit(f"part_names: found only {sorted(names)} in docs/grading.md's table of parts")

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from source_scan import against_allowed, finish, strip_comments  # noqa: E402

handles_answers = re.compile(r"part|answer|\.at\(|\.has\(|allow_only|for_field|points|mistake|"
                             r"reference|expected|asks|column|stated|given", re.I)
typeof = re.compile(r'typeof\s+[\w.]+\s*[!=]==?\s*$')  # JavaScript's own types
# A comment saying so exempts its line: a word that is a part's name but means something else
# there (a derivation's quantity, a symbol, a file's mode), with the reason beside it.
NOT_A_PART = "not a part:"
compared_before = re.compile(r'(?:[!=]==?|\bin\s*[\(\[{][^\)\]}]*|\?)\s*$')
compared_after = re.compile(r'^\s*(?:[!=]==?|:)')


def compared(line, match):
    """The literal is compared with something, or is the value of a choice (`a ? "x" : "y"`)."""
    return bool(compared_before.search(line[:match.start()])
                or compared_after.search(line[match.end():]))


literal = re.compile(r'"((?:[^"\\\n]|\\.)*)"|\'((?:[^\'\\\n]|\\.)*)\'')
lines_of = {}
for folder in FOLDERS:
    for path in sorted((root / folder).rglob("*")):
        rel = path.relative_to(root).as_posix()
        if (not path.is_file() or path.suffix not in SUFFIXES or rel in EXEMPT_FILES
                or "node_modules" in path.parts):
            continue
        raw = path.read_text(encoding="utf-8").splitlines()
        code = strip_comments("\n".join(raw), path.suffix == ".py").splitlines()
        # The statement each line belongs to (up to a line ending in ; { } or :), so that a
        # call written over several lines is one: make_part(context_,\n "t", ...).
        statement_of, start = [], 0
        for i, line in enumerate(code):
            statement_of.append(start)
            if path.suffix == ".py" or not line.strip() or line.rstrip().endswith(
                    (";", "{", "}", ":")):
                start = i + 1
        statements = {}
        for i, s in enumerate(statement_of):
            statements[s] = statements.get(s, "") + " " + code[i]
        exempt = False  # within the statement after a comment line that says "not a part:"
        for number, line in enumerate(code, 1):
            here = raw[number - 1]
            if NOT_A_PART in here:
                exempt = here.strip().startswith(("//", "#"))
                continue
            if exempt:
                exempt = not line.rstrip().endswith((";", "{", "}", ":", "},"))
                continue
            statement = statements[statement_of[number - 1]]
            words = [(m.group(1) if m.group(1) is not None else m.group(2), m)
                     for m in literal.finditer(line)]
            if any(w in names and not typeof.search(line[:m.start()])
                   and (handles_answers.search(statement) or compared(line, m))
                   for w, m in words):
                lines_of.setdefault(rel, []).append(f"{rel}:{number}: {line.strip()}")

finish(against_allowed(lines_of, ALLOWED, "a part by string", "part_names"),
       "part_names: code outside grader/kinds/ names a part by string; take it from its kind "
       "(its PartSpec, or the name its kind's header gives it)",
       f"part_names: {len(names)} parts; {sum(ALLOWED.values())} line(s) in {len(ALLOWED)} "
       "file(s) still name one (ALLOWED, which only shrinks)")
