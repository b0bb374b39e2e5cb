#!/usr/bin/env python3
"""No code outside grader/assignments/platforms/ names a learning platform.

A platform (Gradescope, PrairieLearn, Canvas, Moodle, Blackboard, SCORM) is its file pair in
grader/assignments/platforms/ and one line of the list `Platforms` (platforms/platforms.h);
everything else reaches it through the list: its export, its gradebook layout, the naming of its
bulk download and its options on the command line. A platform named anywhere else is a branch
the list does not know about (the next platform silently skipped), and fails here.

The rule: in every C++ source (.cpp, .h, .in), script (.js) and Python file (.py) of grader/
outside grader/assignments/platforms/, with comments taken out, no identifier or string
literal holds one of NAMES, in any case, anywhere inside it (`canvas_ids`, "csv-Moodle" and
`kScormScript` all count). Comments may name platforms: they explain, they do not branch.
Exempt:
- grader/serve/: the LTI 1.3 tool. LTI is a standard every platform speaks, not a platform
  (no row of the list), so "lti" is not among NAMES; serve/ names no platform either.
- HTML's <canvas> element (a web page's drawing surface, not the LMS): `<canvas`, and `canvas`
  as a CSS selector followed by `{`, `:` or `,`, inside a string literal.
- generated files (typed_reader.js, Emscripten's output).
The files that still name platforms are listed in ALLOWED with the count of their lines that
do: a file not listed, or more lines of a listed one, fails the test; so does a listed one with
fewer lines, until its count is brought down, so that the list only shrinks.

Usage: platform_names.py SOURCE_ROOT
"""
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from source_scan import against_allowed, finish, strip_comments  # noqa: E402

NAMES = ["gradescope", "prairielearn", "prairie_learn", "canvas", "moodle", "blackboard",
         "scorm", "d2l", "brightspace", "sakai"]

# path (from the source root): the number of its lines that name a platform. Each entry is a
# file not yet moved behind the list; the list only shrinks.
ALLOWED = {}

EXEMPT_DIRS = ["grader/assignments/platforms", "grader/serve"]
EXEMPT_FILES = {"grader/assignments/typed_reader.js"}
SUFFIXES = {".cpp", ".h", ".in", ".js", ".py"}

NAME = re.compile("|".join(NAMES), re.I)
HTML_CANVAS = re.compile(r"<canvas\b|\bcanvas(?=\s*[{:,])", re.I)


def naming_lines(path):
    """[(line number, line)] of the lines of `path` whose code names a platform."""
    text = path.read_text(encoding="utf-8")
    code = strip_comments(text, path.suffix == ".py")
    lines = text.splitlines()
    found = []
    for number, line in enumerate(code.splitlines(), 1):
        line = HTML_CANVAS.sub(" ", line)
        if NAME.search(line):
            found.append((number, lines[number - 1].strip()))
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    if not (root / "grader" / "assignments" / "platforms").is_dir():
        sys.exit("platform_names: grader/assignments/platforms/ is missing")
    found = {}
    for path in sorted((root / "grader").rglob("*")):
        rel = path.relative_to(root).as_posix()
        if not path.is_file() or path.suffix not in SUFFIXES or rel in EXEMPT_FILES:
            continue
        if any(rel.startswith(d + "/") for d in EXEMPT_DIRS):
            continue
        lines = [f"{rel}:{number}: names a platform: {line}" for number, line in naming_lines(path)]
        if lines:
            found[rel] = lines
    finish(against_allowed(found, ALLOWED, "a platform", "platform_names"),
           "platform_names: code outside grader/assignments/platforms/ names a platform; reach "
           "it through the list of platforms (assignments/platforms/platforms.h)",
           "platform_names: no code outside grader/assignments/platforms/ names a platform "
           f"({len(ALLOWED)} files still listed in ALLOWED)")


main()
