#!/usr/bin/env python3
"""No code outside grader/kinds/ names a kind by string.

A kind is its file pair in grader/kinds/ and one line of grader/kinds/table.cpp; everything else
reaches it through the table (problems/kind.h) or its type (`FirstHitKind::kName`). A kind's
name written as a string elsewhere in grader/ or web/ is a branch or row the list does not
know about: it fails here with its file and line.

Nor does code outside grader/kinds/ and grader/grading/ (whose graders are each one kind's)
downcast a problem's Task to a kind's own class: what the checks, reports and exports need of
a kind, the kind answers through Task (`ray_cast()`, problems/ray_cast.h).

Nor does any file of the folders in KIND_BLIND include a kind's own header (one of grader/kinds/
that declares a kind's `kName` or a class derived from Task): a report asks the problem's Task
(`scene_givens()`, problems/scene_givens.h) for what a kind knows, and never reads a kind's own
types or functions. The headers of grader/kinds/ that declare no kind (the words all kinds share)
are not a kind's.

Flagged: a string literal that is a kind's name, on a line that speaks of a kind (`kind`), and
anywhere at all for the names nothing else is called (`first-hit`, `camera-ray`, ...). Comments
are not code. Usage: kind_names.py SOURCE_ROOT
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
kinds_dir = root / "grader" / "kinds"
names = set()
for header in kinds_dir.glob("*.h"):
    names.update(re.findall(r'kName\s*=\s*"([^"]+)"', header.read_text(encoding="utf-8")))
if len(names) < 5:
    sys.exit(f"kind_names: found only {sorted(names)} in {kinds_dir}: the kinds' kName moved?")

# Names that are also parts, keys, methods or material settings ("normal", "fresnel") are
# flagged only where the line speaks of a kind.
other_words = {"intersect", "reflect", "refract", "shade", "normal", "derive", "fresnel"}
literal = re.compile(r'"((?:[^"\\\n]|\\.)*)"|\'((?:[^\'\\\n]|\\.)*)\'')
faults = []
for path in sorted(list((root / "grader").rglob("*")) + list((root / "web").rglob("*"))):
    if not path.is_file() or kinds_dir in path.parents:
        continue
    # The browser libraries web/vendor/node_modules holds (three.js, axe-core) are not raygrade's.
    if "node_modules" in path.parts:
        continue
    if path.suffix not in {".cpp", ".h", ".in", ".py", ".js", ".json", ".css", ".html"}:
        continue
    comment = "#" if path.suffix == ".py" else "//"
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        code = line
        # Drop a trailing comment (outside strings, roughly: the marker after the last quote).
        cut = code.find(comment, code.rfind('"') + 1 if code.count('"') % 2 == 0 else len(code))
        if cut >= 0:
            code = code[:cut]
        if code.lstrip().startswith(comment):
            continue
        speaks_of_kind = "kind" in code.lower()
        for m in literal.finditer(code):
            text = m.group(1) if m.group(1) is not None else m.group(2)
            if text in names and (speaks_of_kind or text not in other_words):
                faults.append(f"{path.relative_to(root)}:{number}: names the kind '{text}' "
                              f"by string: {line.strip()}")
downcast = re.compile(r"(dynamic|static)_cast<\s*(const\s+)?[A-Za-z]+Task\s*[*&]")
grading_dir = root / "grader" / "grading"
for path in sorted((root / "grader").rglob("*")):
    if path.suffix not in {".cpp", ".h"} or kinds_dir in path.parents or grading_dir in path.parents:
        continue
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if downcast.search(line) and not line.lstrip().startswith("//"):
            faults.append(f"{path.relative_to(root)}:{number}: downcasts a Task to a kind's "
                          f"class: {line.strip()}")
# Folders whose code reaches every kind through Task alone.
KIND_BLIND = ("reports",)
include_kind = re.compile(r'^\s*#\s*include\s+"kinds/([^"]+)"')
declares_kind = re.compile(r'\bkName\s*=|:\s*public\s+Task\b|,\s*public\s+Task\b')


def kind_header(name):
    """Whether grader/kinds/NAME declares a kind or a kind's Task (a header that cannot be read
    counts as one)."""
    header = kinds_dir / name
    try:
        return bool(declares_kind.search(header.read_text(encoding="utf-8")))
    except OSError:
        return True


for folder in KIND_BLIND:
    for path in sorted((root / "grader" / folder).rglob("*")):
        if path.suffix not in {".cpp", ".h", ".in"}:
            continue
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            m = include_kind.match(line)
            if m and kind_header(m.group(1)):
                faults.append(f"{path.relative_to(root)}:{number}: includes a kind's header "
                              f"({folder}/ asks the problem's Task instead): {line.strip()}")
for f in faults:
    print(f)
if faults:
    sys.exit(f"kind_names: {len(faults)} place(s) outside grader/kinds/ name a kind by string, "
             "downcast its Task or include its header; take it from the table of kinds "
             "(problems/kind.h), from its type, or from what Task answers")
print(f"kind_names: no code outside grader/kinds/ names any of the {len(names)} kinds by string")
