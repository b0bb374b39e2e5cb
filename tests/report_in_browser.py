#!/usr/bin/env python3
"""The class report in headless Chromium: every number on the page is a number of report.json.

Makes a class of twelve students for the example assignment: each student's right answers (from
`raygrade solve ASSIGNMENT --student ID`), some of them changed (t doubled, a problem left out),
runs `raygrade report`, loads report.html in headless Chromium and reads the DOM it built. Each
element with a data-j attribute must show the JSON value at that pointer; every other number on
the page must be part of a string of the JSON (a title, a student id, an example answer), or one
of the histogram's axis labels. The feedback pages linked must exist. A screenshot is saved in
OUTPUT_FOLDER. Exit 77 (skipped) when Chromium is not installed.

usage: report_in_browser.py RAYGRADE_BINARY ASSIGNMENT_JSON OUTPUT_FOLDER
"""
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys

from chromium import SKIPPED, require_chromium, run_browser

STUDENTS = [f"s{i:03}" for i in range(1, 13)]
AXIS_LABELS = {"0%", "100%"}


def right_answers(binary, assignment, student):
    out = subprocess.run([binary, "solve", assignment, "--student", student, "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    return {s["id"]: s["answer"] for s in json.loads(out)["solutions"]}


def doubled_t(answer):
    """The same answer with every t doubled (a wrong answer)."""
    if isinstance(answer, dict):
        return {k: (v * 2 if k == "t" and isinstance(v, (int, float)) else doubled_t(v))
                for k, v in answer.items()}
    if isinstance(answer, list):
        return [doubled_t(v) for v in answer]
    return answer


def write_class(binary, assignment, folder):
    os.makedirs(folder)
    for i, student in enumerate(STUDENTS):
        answers = right_answers(binary, assignment, student)
        for k, problem in enumerate(sorted(answers)):
            if (i + k) % 4 == 0:
                answers[problem] = doubled_t(answers[problem])
            elif (i + k) % 7 == 0:
                del answers[problem]
        with open(os.path.join(folder, student + ".json"), "w", encoding="utf-8") as f:
            json.dump({"student": {"id": student}, "answers": answers}, f)


class Page(html.parser.HTMLParser):
    """The page's text, split into what is inside a data-j element and what is not."""

    def __init__(self):
        super().__init__()
        self.stack = []  # data-j pointer (or None) of each open element
        self.values = []  # (pointer, text)
        self.loose = []  # text outside every data-j element
        self.links = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "a" and a.get("href"):
            self.links.append(a["href"])
        if tag in ("meta", "br", "hr", "link", "img", "input", "rect"):
            return
        self.stack.append(a.get("data-j"))
        if tag in ("style", "title", "script"):
            self.stack[-1] = "skip"

    def handle_endtag(self, tag):
        if tag in ("meta", "br", "hr", "link", "img", "input", "rect"):
            return
        if self.stack:
            self.stack.pop()

    def handle_data(self, data):
        inner = next((p for p in reversed(self.stack) if p is not None), None)
        if inner == "skip":
            return
        if inner is None:
            self.loose.append(data)
        elif self.stack[-1] is not None:
            self.values.append((inner, data))


def at(report, pointer):
    v = report
    for token in pointer.split("/")[1:]:
        v = v[int(token)] if isinstance(v, list) else v[token]
    return v


def strings_of(j, out):
    if isinstance(j, dict):
        for v in j.values():
            strings_of(v, out)
    elif isinstance(j, list):
        for v in j:
            strings_of(v, out)
    elif isinstance(j, str):
        out.append(j)
    return out


def shown(v):
    """A JSON value as the page shows it (JSON's own spelling; null as n/a)."""
    return "n/a" if v is None else json.dumps(v, separators=(",", ":"), ensure_ascii=False)


def check(report, dom, out):
    page = Page()
    page.feed(dom)
    faults = []
    for pointer, text in page.values:
        try:
            want = shown(at(report, pointer))
        except (KeyError, IndexError, ValueError):
            faults.append(f"{pointer}: no such number in report.json")
            continue
        if text.strip() != want:
            faults.append(f"{pointer}: page shows {text.strip()!r}, report.json has {want!r}")
    strings = "\n".join(strings_of(report, []))
    for text in page.loose:
        for token in re.findall(r"[0-9][0-9.%]*", text):
            if token not in AXIS_LABELS and token not in strings:
                faults.append(f"the number {token!r} in {text.strip()[:60]!r} is not in report.json")
    for link in page.links:
        if not os.path.isfile(os.path.join(out, link)):
            faults.append(f"the link {link} leads to no file")
    numbers = len(page.values)
    return faults, numbers


def main():
    binary, assignment, out = sys.argv[1:4]
    browser = require_chromium()
    if not browser:
        return SKIPPED
    shutil.rmtree(out, ignore_errors=True)
    write_class(binary, assignment, os.path.join(out, "class"))
    report_dir = os.path.join(out, "report")
    subprocess.run([binary, "report", "--assignment", assignment, os.path.join(out, "class"),
                    "--out", report_dir], check=True, capture_output=True)
    with open(os.path.join(report_dir, "report.json"), encoding="utf-8") as f:
        report = json.load(f)
    page = os.path.abspath(os.path.join(report_dir, "report.html"))
    dom = run_browser(browser, ["--dump-dom"], page).stdout
    faults, numbers = check(report, dom, report_dir)
    if len(report["problems"]) != 10 or report["problems"][0]["students"] != len(STUDENTS):
        faults.append("the report does not have the class's 10 problems and 12 students")
    if numbers < 500:
        faults.append(f"only {numbers} numbers found on the page")
    shot = os.path.join(out, "report.png")
    run_browser(browser, [f"--screenshot={shot}", "--window-size=1200,2400"], page)
    if not os.path.isfile(shot):
        faults.append("no screenshot was written")
    for f in faults:
        print(f)
    print(f"{numbers} numbers on the page checked against report.json; screenshot {shot}")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
