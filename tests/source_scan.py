"""What the tests that keep a name inside its own folder share (platform_names, field_names,
part_names): a source file's code with its comments taken out, and the check of the files that
still name something against the test's list of them, which may only shrink."""
import re
import sys


def strip_comments(text, python):
    """The text with comments blanked (line count kept), string literals left as they are."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if python and c == "#":
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if not python and text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if not python and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
            continue
        m = re.match(r'R"([^(\s]*)\(', text[i:]) if not python else None
        if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(text[i:j])
            i = j
            continue
        if python and (text.startswith('"""', i) or text.startswith("'''", i)):
            end = text.find(text[i:i + 3], i + 3)
            j = n if end < 0 else end + 3
            out.append(text[i:j])
            i = j
            continue
        if c in "\"'`":
            j = i + 1
            while j < n and text[j] != c and (c == "`" or text[j] != "\n"):
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(text[i:j])
            i = j
            continue
        out.append(c)
        i += 1
    return "".join(out)


def against_allowed(found, allowed, what, test):
    """The faults of `found` ({path: [its lines that name one, as "path:line: text"]}) against
    `allowed` ({path: how many of its lines may}): every line of a file over its count, and a
    listed file now under its count (bring it down, so that the lines cannot come back)."""
    faults = []
    for rel, lines in sorted(found.items()):
        limit = allowed.get(rel, 0)
        if len(lines) > limit:
            faults.extend(lines)
            faults.append(f"  {rel}: {len(lines)} line(s) name {what}"
                          + (f" (allowed {limit})" if limit else ""))
    for rel, limit in sorted(allowed.items()):
        now = len(found.get(rel, []))
        if now < limit:
            faults.append(f"  {rel}: {now} line(s) now, {limit} allowed: lower its count in "
                          f"ALLOWED (tests/{test}.py), so that it cannot come back")
    return faults


def finish(faults, failure, success):
    """Prints the faults and exits 1 with `failure`, or prints `success`."""
    for f in faults:
        print(f)
    if faults:
        sys.exit(failure)
    print(success)
