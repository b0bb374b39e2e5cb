#!/usr/bin/env python3
"""No output of raygrade holds a non-finite number.

Usage: finite_outputs.py RAYGRADE SOURCE_DIR WORK_DIR [EVERY]

EVERY: take every EVERY-th case of the corpus (default 1: all); the sanitizer build takes 4.

Runs every command that prints numbers (solve in every format, with every method; grade in
every format; check in every format; solutions in every format) on the bundled bank, on the
conformance set and on the hard-case corpus (tests/data/hard_cases.json, written out as
intersect problems), and scans what they print and write for "nan", "inf", "infinity" as
words, and, in JSON, for NaN or Infinity tokens and for null where a number belongs (a
null is allowed only under the keys listed in ALLOWED_NULL). The submissions graded are the
bundled ones, and for the conformance set and the corpus one made from the reference answers
and one with every t off by 0.1%, so that the feedback on wrong numbers is printed too.
Prints one line per fault and exits 1 if there is any.
"""
import json
import os
import re
import subprocess
import sys

# Keys whose value may be null: a first-hit answer when nothing is hit, the root of a ray tree
# (no parent), the refracted direction under total internal reflection.
ALLOWED_NULL = {"object", "parent", "direction"}

# How C++ prints a non-finite double ("nan", "-nan", "inf"). ("infinity" is a word of the
# statements: "the closed interval [0, infinity)"; in JSON it is caught as a token.)
NON_FINITE_WORD = re.compile(r"(?<![A-Za-z_])-?(nan|inf)(?![A-Za-z_])", re.IGNORECASE)

faults = []


def scan_json_value(value, where, key=None):
    if value is None:
        if key not in ALLOWED_NULL:
            faults.append(f"{where}: null at key {key!r}")
    elif isinstance(value, float):
        if value != value or value in (float("inf"), float("-inf")):
            faults.append(f"{where}: non-finite number at key {key!r}")
    elif isinstance(value, dict):
        for k, v in value.items():
            scan_json_value(v, where, k)
    elif isinstance(value, list):
        for v in value:
            scan_json_value(v, where, key)


def scan_text(text, where, is_json):
    for line_number, line in enumerate(text.splitlines(), 1):
        m = NON_FINITE_WORD.search(line)
        if m:
            faults.append(f"{where}:{line_number}: {m.group(0)!r} in {line.strip()[:120]!r}")
    if is_json:
        def reject(token):
            faults.append(f"{where}: JSON token {token}")
            return 0
        try:
            scan_json_value(json.loads(text, parse_constant=reject), where)
        except json.JSONDecodeError as e:
            faults.append(f"{where}: not JSON ({e})")


def run(raygrade, args, where, is_json, bad_input_ok=False):
    p = subprocess.run([raygrade] + args, capture_output=True, text=True)
    if p.returncode not in ((0, 1, 2) if bad_input_ok else (0, 1)):
        faults.append(f"{where}: exit {p.returncode}: {p.stderr.strip()[:300]}")
    scan_text(p.stdout, where + " (stdout)", is_json)
    scan_text(p.stderr, where + " (stderr)", False)
    return p.stdout


def scan_folder(folder, where):
    for root, _, files in os.walk(folder):
        for name in sorted(files):
            # The 3D view's script (three.js) is a library, not an output of numbers.
            if name == "scene_view.js":
                continue
            path = os.path.join(root, name)
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            scan_text(text, f"{where}/{os.path.relpath(path, folder)}", name.endswith(".json"))


def corpus_problems(raygrade, source, out_path, every):
    """The hard cases as intersect problems (every `every`-th one), posed by raygrade itself
    (each primitive writes its own object), so that no primitive is left out."""
    corpus = os.path.join(source, "tests/data/hard_cases.json")
    subprocess.run([raygrade, "bench", "--corpus", corpus, "--corpus-problems", out_path],
                   check=True, capture_output=True)
    with open(out_path) as f:
        problems = json.load(f)["problems"][::every]
    with open(out_path, "w") as f:
        json.dump({"problems": problems}, f)


def submissions_from(raygrade, problems, folder, tag):
    """A submission of the reference answers and one with every t off by 0.1%."""
    answers = json.loads(subprocess.run([raygrade, "solve", problems, "--format", "json"],
                                        capture_output=True, text=True).stdout)
    exact, off = {}, {}
    for s in answers["solutions"] if "solutions" in answers else answers:
        a = s.get("answer")
        if not isinstance(a, dict) or "hits" not in a:
            continue
        exact[s["id"]] = {"hits": a["hits"]}
        off[s["id"]] = {"hits": [dict(h, t=h["t"] * 1.001) for h in a["hits"]]}
    os.makedirs(folder, exist_ok=True)
    paths = []
    for name, ans in (("exact", exact), ("off", off)):
        path = os.path.join(folder, f"{tag}-{name}.json")
        with open(path, "w") as f:
            json.dump({"student": f"{tag} {name}", "answers": ans}, f)
        paths.append(path)
    return paths


def main():
    raygrade, source, work = sys.argv[1], sys.argv[2], sys.argv[3]
    # A sanitizer build checks the code paths rather than the volume: every 4th hard case.
    every = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    os.makedirs(work, exist_ok=True)
    corpus = os.path.join(work, "hard_cases_problems.json")
    corpus_problems(raygrade, source, corpus, every)
    # The corpus holds a few polygons that the problem reader rejects as non-planar beyond its
    # tolerance (exit 2, the rest still answered).
    banks = {
        "bank": (os.path.join(source, "problems"), [os.path.join(source, "submissions")], False),
        "conformance": (os.path.join(source, "tests/data/conformance/problems.json"), None,
                        False),
        "corpus": (corpus, None, True),
    }
    for tag, (problems, submissions, bad_ok) in banks.items():
        if submissions is None:
            submissions = submissions_from(raygrade, problems, os.path.join(work, "submissions"),
                                           tag)
        for fmt in ("json", "txt", "md", "html"):
            run(raygrade, ["solve", problems, "--format", fmt], f"{tag}: solve --format {fmt}",
                fmt == "json", bad_ok)
        run(raygrade, ["solve", problems, "--format", "txt", "--method", "all"],
            f"{tag}: solve --method all", False, bad_ok)
        run(raygrade, ["solve", problems, "--format", "json", "--steps"],
            f"{tag}: solve --steps", True, bad_ok)
        for fmt in ("text", "json", "junit"):
            run(raygrade, ["check", problems, "--format", fmt], f"{tag}: check --format {fmt}",
                fmt == "json", bad_ok)
        for fmt in ("text", "json", "csv"):
            run(raygrade, ["grade", "--problems", problems, *submissions, "--format", fmt],
                f"{tag}: grade --format {fmt}", fmt == "json", bad_ok)
        for fmt in ("gradescope", "prairielearn", "html"):
            out = os.path.join(work, f"grade-{tag}-{fmt}")
            run(raygrade, ["grade", "--problems", problems, *submissions, "--format", fmt,
                           "--out", out], f"{tag}: grade --format {fmt}", False, bad_ok)
            scan_folder(out, f"{tag}: grade --format {fmt}")
        out = os.path.join(work, f"solutions-{tag}")
        run(raygrade, ["solutions", problems, "--out", out], f"{tag}: solutions", False, bad_ok)
        scan_folder(out, f"{tag}: solutions")
    for f in faults:
        print(f)
    print(f"{len(faults)} non-finite outputs")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
