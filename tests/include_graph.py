#!/usr/bin/env python3
"""The folders of grader/ include only downward, and functions stay short.

The order of the folders, lowest first, is the one docs/architecture.md gives on its line
"Folders, lowest first: ...". A file may include its own folder's headers and those of any
folder below it. The includes that still go up are listed in UPWARD, each with the count of
its #include lines: a new one, or more of a listed one, fails the test, and so does a listed
one that has gone (take it off the list, so that it cannot come back unseen).

No function of grading/ or cli/ may be longer than 120 lines; the ones that still are are
listed in LONG with their length, which may shrink but not grow.

Usage: include_graph.py SOURCE_DIR
"""
import collections
import pathlib
import re
import sys

# (from, to): how many #include lines of `from` name a header of `to`, a folder above it.
UPWARD = {}

# (file, function's first line): its length in lines.
LONG = {}

MAX_LINES = 120


def folder_order(root):
    text = (root / "docs" / "architecture.md").read_text()
    match = re.search(r"^Folders, lowest first: (.*)$", text, re.M)
    if not match:
        sys.exit("docs/architecture.md has no line 'Folders, lowest first: ...'")
    return re.findall(r"`([a-z_]+)`", match.group(1))


def includes(root):
    """(from folder, to folder) -> [file:line] of each #include of another folder's header."""
    found = collections.defaultdict(list)
    for path in sorted((root / "grader").rglob("*")):
        if path.suffix not in (".h", ".cpp", ".in"):
            continue
        folder = path.relative_to(root / "grader").parts[0]
        for number, line in enumerate(path.read_text().splitlines(), 1):
            m = re.match(r'\s*#\s*include\s+"([a-z_]+)/', line)
            if m and m.group(1) != folder and (root / "grader" / m.group(1)).is_dir():
                where = f"{path.relative_to(root)}:{number}"
                found[(folder, m.group(1))].append(where)
    return found


def code_lines(text):
    """The file's lines with string and character literals and comments blanked out (raw
    strings included), so that only the code's own braces are left; as many lines as before."""
    def blank(m):
        return "\n" * m.group(0).count("\n")
    text = re.sub(r'R"([^(\s]*)\((.*?)\)\1"', lambda m: '""' + blank(m), text, flags=re.S)
    text = re.sub(r"/\*.*?\*/", blank, text, flags=re.S)
    text = re.sub(r'"(?:\\.|[^"\\\n])*"', '""', text)
    text = re.sub(r"'(?:\\.|[^'\\\n])+'", "''", text)
    text = re.sub(r"//[^\n]*", "", text)
    return text.split("\n")


def long_functions(root):
    """(file, first line) -> length, for each function of grading/ and cli/ over MAX_LINES.

    A function is a block at namespace level whose head starts at the first column and is no
    namespace, type or variable: from its head's first line to its closing brace.
    """
    out = {}
    for folder in ("grading", "cli"):
        for path in sorted((root / "grader" / folder).glob("*.cpp")):
            lines = code_lines(path.read_text())
            depth, head, start = 0, None, None
            for i, line in enumerate(lines):
                if depth == 0:
                    if re.match(r"(namespace\b.*\{|\}\s*$)", line):
                        continue  # a namespace opens or closes
                    if head is None and line[:1] not in ("", " ", "#", "}"):
                        head = i
                opened = line.count("{")
                if depth == 0 and opened:
                    start = head if head is not None else i
                depth += opened - line.count("}")
                if depth == 0:
                    if start is not None:
                        text = " ".join(lines[start:i + 1])
                        first = text.split("{")[0]
                        kind = re.match(r"\s*(template\s*<[^>]*>\s*)?(struct|class|enum|union)\b",
                                        first)
                        if "(" in first and "=" not in first.split("(")[0] and not kind:
                            length = i - start + 1
                            if length > MAX_LINES:
                                out[(str(path.relative_to(root)), lines[start].strip())] = length
                        start = None
                    if line.rstrip().endswith((";", "}")) or line.strip() == "":
                        head = None
    return out


def main():
    root = pathlib.Path(sys.argv[1])
    order = folder_order(root)
    rank = {name: i for i, name in enumerate(order)}
    faults = []
    folders = {p.name for p in (root / "grader").iterdir() if p.is_dir()}
    for name in sorted(folders - set(rank)):
        faults.append(f"grader/{name}/ is not on the line 'Folders, lowest first' of "
                      "docs/architecture.md")
    found = includes(root)
    upward = {}
    for (low, high), where in sorted(found.items()):
        if low in rank and high in rank and rank[high] > rank[low]:
            upward[(low, high)] = where
    for pair, where in upward.items():
        known = UPWARD.get(pair, 0)
        if len(where) > known:
            faults.append(f"{pair[0]}/ includes {pair[1]}/, a folder above it, {len(where)} times "
                          f"({known} known): {', '.join(where[:6])}")
    for pair in UPWARD:
        if pair not in upward:
            faults.append(f"{pair[0]}/ no longer includes {pair[1]}/: take it off UPWARD")
        elif len(upward[pair]) < UPWARD[pair]:
            faults.append(f"{pair[0]}/ includes {pair[1]}/ {len(upward[pair])} times, "
                          f"fewer than the {UPWARD[pair]} listed: lower the count in UPWARD")
    for (path, head), length in long_functions(root).items():
        known = LONG.get((path, head))
        if known is None or length > known:
            faults.append(f"{path}: '{head}' is {length} lines long "
                          f"(at most {known or MAX_LINES})")
    for fault in faults:
        print(f"FAIL {fault}")
    print(f"{len(order)} folders in order; {sum(len(w) for w in upward.values())} includes go up "
          f"({len(upward)} pairs, all known)" if not faults else f"{len(faults)} faults")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
