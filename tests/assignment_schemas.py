#!/usr/bin/env python3
"""The assignment and submission schemas: valid draft 2020-12 schemas; the bundled assignments,
the sample submissions and a handout's answers template conform; broken files are rejected.

Usage: assignment_schemas.py RAYGRADE SOURCE_DIR
"""
import json
import pathlib
import subprocess
import sys
import tempfile

try:
    import jsonschema
except ImportError:
    sys.exit("assignment_schemas: the python3 module jsonschema is missing "
             "(Debian package python3-jsonschema; run scripts/install-deps.sh)")


def validator(path):
    schema = json.loads(path.read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def main(raygrade, source):
    root = pathlib.Path(source)
    assignment = validator(root / "docs/assignment.schema.json")
    submission = validator(root / "docs/submission.schema.json")
    failures = []

    def expect(v, doc, ok, what):
        errors = list(v.iter_errors(doc))
        if ok and errors:
            failures.append(f"{what}: {errors[0].message}")
        if not ok and not errors:
            failures.append(f"the schema accepts {what}")

    for f in sorted((root / "assignments").glob("*.json")):
        expect(assignment, json.loads(f.read_text()), True, str(f))
    for f in sorted((root / "submissions").glob("*.json")):
        expect(submission, json.loads(f.read_text()), True, str(f))
    example = json.loads((root / "assignments/homework-rays.json").read_text())
    expect(assignment, {**example, "feedbak": "full"}, False, "an unknown key")
    expect(assignment, {**example, "due": "2026-12-04T23:59:00"}, False, "a due time without a zone")
    expect(assignment, {**example, "feedback": "all"}, False, "an unknown policy")
    expect(submission, {"answers": {}, "studnet": "x"}, False, "an unknown top-level key")
    expect(submission, {"answers": {"p": {"hits": [{"t": 1, "pint": [1, 2, 3]}]}}}, False,
           "a hit with an unknown key")
    with tempfile.TemporaryDirectory() as out:
        r = subprocess.run([raygrade, "handout", str(root / "assignments/homework-rays.json"),
                            "--student", "s001", "--out", out], capture_output=True, text=True)
        if r.returncode != 0:
            failures.append(f"handout exited {r.returncode}: {r.stderr}")
        else:
            template = json.loads((pathlib.Path(out) / "s001/answers-template.json").read_text())
            expect(submission, template, True, "the answers template")
    for f in failures:
        print("FAIL", f)
    print(f"assignment_schemas: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
