#!/usr/bin/env python3
"""Reads `raygrade check --format junit` back and checks its structure.

Usage: check_junit.py RAYGRADE SOURCE_DIR. Runs the check on the broken-bank fixtures (plus a
problem whose id and statement hold XML's special characters) and on the bundled bank, parses
the XML with the standard library's parser (which rejects anything not well-formed), and
checks testsuites/testsuite/testcase/failure and the counts against the JSON report.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


def run(binary, args):
    p = subprocess.run([binary, "check", *args], capture_output=True, text=True)
    return p.returncode, p.stdout


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def check_structure(xml_text, report):
    root = ET.fromstring(xml_text)  # raises on malformed XML
    if root.tag != "testsuites":
        fail(f"root is <{root.tag}>, not <testsuites>")
    cases = []
    for suite in root:
        if suite.tag != "testsuite":
            fail(f"<testsuites> holds <{suite.tag}>")
        tests = int(suite.get("tests"))
        failures = int(suite.get("failures"))
        errors = int(suite.get("errors"))
        children = list(suite)
        if any(c.tag != "testcase" for c in children):
            fail("a testsuite holds something other than testcases")
        if len(children) != tests:
            fail(f"suite {suite.get('name')}: tests={tests} but {len(children)} testcases")
        failed = [c for c in children if c.find("failure") is not None]
        errored = [c for c in children if c.find("error") is not None]
        if len(failed) != failures or len(errored) != errors:
            fail(f"suite {suite.get('name')}: failure counts do not match its testcases")
        for c in children:
            if not c.get("name") or not c.get("classname"):
                fail("a testcase without name or classname")
            for f in c.findall("failure"):
                if not f.get("message") or not f.get("type") or not (f.text or "").strip():
                    fail(f"testcase {c.get('name')}: failure without message, type or text")
        cases.extend(children)
    if int(root.get("tests")) != len(cases):
        fail("testsuites/@tests does not count the testcases")
    by_name = {c.get("name"): c for c in cases}
    problems = report["problems"]
    if len(cases) != len(problems):
        fail(f"{len(cases)} testcases for {len(problems)} problems in the JSON report")
    for p in problems:
        case = by_name.get(p["name"])
        if case is None:
            fail(f"no testcase for {p['name']!r}")
        if (case.find("failure") is not None or case.find("error") is not None) != (
            p["status"] == "failed"
        ):
            fail(f"testcase {p['name']!r} disagrees with the JSON report")
    return by_name


def main():
    binary, source = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp(prefix="raygrade-junit-")
    try:
        bank = os.path.join(work, "bank")
        shutil.copytree(os.path.join(source, "tests/fixtures/broken-bank"), bank)
        nasty = 'x<&>"\'\u00e9'
        with open(os.path.join(bank, "nasty.json"), "w", encoding="utf-8") as f:
            json.dump(
                {
                    "id": nasty,
                    "statement": "]]> </testcase> <!-- " + nasty,
                    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
                    "object": {"type": "sphere", "center": [0, 0, 9], "radius": 2},
                    "expected": {"hits": [{"t": 7}, {"t": 12}]},
                },
                f,
            )
        solutions = os.path.join(source, "tests/fixtures/broken-bank-solutions")
        code, xml_text = run(binary, [bank, "--solutions", solutions, "--format", "junit"])
        if code != 1:
            fail(f"exit code {code} on the broken bank, not 1")
        _, json_text = run(binary, [bank, "--solutions", solutions, "--format", "json"])
        cases = check_structure(xml_text, json.loads(json_text))
        case = cases.get(nasty)
        if case is None or case.find("failure") is None:
            fail("the problem with special characters in its id is missing or passed")
        if "wrong-expected" != case.find("failure").get("type"):
            fail("its failure is not typed wrong-expected")
        # A clean bank: one testcase per problem, none failing.
        problems = os.path.join(source, "problems")
        code, xml_text = run(binary, [problems, "--no-solutions", "--format", "junit"])
        if code != 0:
            fail(f"exit code {code} on the bundled bank")
        _, json_text = run(binary, [problems, "--no-solutions", "--format", "json"])
        cases = check_structure(xml_text, json.loads(json_text))
        if any(c.find("failure") is not None for c in cases.values()):
            fail("the bundled bank has failing testcases")
    finally:
        shutil.rmtree(work)
    print("JUnit output well-formed:", len(cases), "testcases in the bundled bank")


if __name__ == "__main__":
    main()
