#!/usr/bin/env python3
"""Reads `raygrade check --format junit` back and checks its structure.

Usage: check_junit.py RAYGRADE SOURCE_DIR. Runs the check on the broken-bank fixtures (plus a
problem whose id and statement hold XML's special characters) and on the bundled bank, parses
the XML with the standard library's parser (which rejects anything not well-formed), and
checks testsuites/testsuite/testcase/failure and the counts against the JSON report: every
suite and case carries a time, the root's tests, failures and errors are the sums of its
suites', and a file that cannot be read is an error (not a failure) in both.
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


def seconds(element):
    """The element's time attribute, which must be a number of seconds, 0 or more."""
    text = element.get("time")
    if text is None:
        fail(f"<{element.tag} name={element.get('name')!r}> has no time")
    value = float(text)
    if not value >= 0:
        fail(f"<{element.tag} name={element.get('name')!r}> has time={text}")
    return value


def check_structure(xml_text, report):
    root = ET.fromstring(xml_text)  # raises on malformed XML
    if root.tag != "testsuites":
        fail(f"root is <{root.tag}>, not <testsuites>")
    for attribute in ("tests", "failures", "errors", "time"):
        if root.get(attribute) is None:
            fail(f"<testsuites> has no {attribute}")
    seconds(root)
    sums = {"tests": 0, "failures": 0, "errors": 0}
    cases = []
    for suite in root:
        if suite.tag != "testsuite":
            fail(f"<testsuites> holds <{suite.tag}>")
        tests = int(suite.get("tests"))
        failures = int(suite.get("failures"))
        errors = int(suite.get("errors"))
        sums["tests"] += tests
        sums["failures"] += failures
        sums["errors"] += errors
        seconds(suite)
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
            seconds(c)
            for f in c.findall("failure"):
                if not f.get("message") or not f.get("type") or not (f.text or "").strip():
                    fail(f"testcase {c.get('name')}: failure without message, type or text")
        cases.extend(children)
    if int(root.get("tests")) != len(cases):
        fail("testsuites/@tests does not count the testcases")
    for attribute, total in sums.items():
        if int(root.get(attribute)) != total:
            fail(f"testsuites/@{attribute}={root.get(attribute)}, its suites' sum is {total}")
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
        # A path that cannot be read: an error, counted as one at the root and in its suite.
        missing = os.path.join(work, "no-such-file.json")
        args = [bank, missing, "--solutions", solutions, "--format"]
        code, xml_text = run(binary, args + ["junit"])
        if code != 2:
            fail(f"exit code {code} with an unreadable file, not 2")
        _, json_text = run(binary, args + ["json"])
        cases = check_structure(xml_text, json.loads(json_text))
        if cases.get(missing) is None or cases[missing].find("error") is None:
            fail("the unreadable file is not a testcase with an <error>")
        if ET.fromstring(xml_text).get("errors") != "1":
            fail("testsuites/@errors does not count the unreadable file")
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
