#!/usr/bin/env python3
"""Opens the HTML feedback page of students with hostile names in headless Chromium.

Grades three submissions with `raygrade grade --format html --out DIR`: one from a student
named `<script>alert(1)</script>`, one whose name and id try other ways of running script
(an `<img onerror>`, an `<svg onload>`, a `javascript:` link, an attribute break-out), and one
whose answers carry markup in free text. Each page is loaded with JavaScript enabled. Every
payload, if it ran, would mark the document (`data-pwned` on <html>, or a changed title); the
test checks in the resulting DOM that nothing was marked, that no <script>, <img>, <iframe>
or event-handler attribute exists, that the name is shown as text, and saves a screenshot.
Exit 77 (skipped) when Chromium is not installed.

usage: feedback_in_browser.py RAYGRADE_BINARY PROBLEMS_JSON OUTPUT_FOLDER
"""
import json
import os
import re
import shutil
import subprocess
import sys

from chromium import SKIPPED, PageBrowser, require_chromium

MARK = "document.documentElement.setAttribute('data-pwned','1')"
SCRIPT_NAME = "<script>alert(1)</script>"
OTHER_NAME = (f"<img src=x onerror=\"{MARK}\"><svg onload=\"{MARK}\"></svg>"
              f"<script>{MARK};document.title='pwned'</script>")
OTHER_ID = f"\"><a href=\"javascript:{MARK}\" id=x>x</a><body onload=\"{MARK}\">"
RIGHT = {
    "sphere-1": {"hits": [{"t": 1, "point": [1, 0, 0]}, {"t": 3, "point": [3, 0, 0]}]},
    "plane-1": {"hits": [{"t": 2, "point": [2, 0, 0]}]},
}
# Answers whose unparsable text is echoed in the feedback.
MARKUP_ANSWERS = {
    "sphere-1": {"hits": [{"t": f"<script>{MARK}</script>"}, {"t": 3}]},
    "plane-1": {"hits": [{"t": f"<img src=x onerror=\"{MARK}\">"}]},
}
SUBMISSIONS = {
    "script-name": {"student": {"name": SCRIPT_NAME, "id": "s1"}, "answers": RIGHT},
    "other-payloads": {"student": {"name": OTHER_NAME, "id": OTHER_ID}, "answers": RIGHT},
    "markup-answers": {"student": {"name": "Mallory", "id": "s3"}, "answers": MARKUP_ANSWERS},
}


def check_dom(dom):
    problems = []
    # As an attribute of an element (the same words inside text are serialized as &lt;...).
    if re.search(r"<[a-zA-Z][^<>]*\sdata-pwned=", dom) or "<title>pwned" in dom:
        problems.append("a payload ran")
    for tag in ("script", "img", "iframe", "object", "embed"):
        if re.search(rf"<{tag}\b", dom, re.IGNORECASE):
            problems.append(f"a <{tag}> element is in the DOM")
    if re.search(r"<[^>]*\son[a-z]+\s*=", dom, re.IGNORECASE):
        problems.append("an event-handler attribute is in the DOM")
    # In an element's attribute: the same words as text (a hostile id in the index's table)
    # serialize with their quotes but with < and > as entities.
    if re.search(r"<[a-zA-Z][^<>]*\shref\s*=\s*\"?\s*javascript:", dom, re.IGNORECASE):
        problems.append("a javascript: link is in the DOM")
    return problems


def main():
    binary, problems_json, out = sys.argv[1:4]
    browser = require_chromium()
    if not browser:
        return SKIPPED
    subs = os.path.join(out, "submissions")
    pages = os.path.join(out, "pages")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(subs)
    for name, data in SUBMISSIONS.items():
        with open(os.path.join(subs, name + ".json"), "w", encoding="utf-8") as f:
            json.dump(data, f)
    run = subprocess.run([binary, "grade", "--problems", problems_json, subs, "--format", "html",
                          "--out", pages], capture_output=True, text=True)
    if run.returncode != 0:
        print(f"raygrade grade exited {run.returncode}: {run.stderr}")
        return 1
    files = sorted(n for n in os.listdir(pages) if n.endswith(".html"))
    failures = []
    # One page per submission, and the index that links them (checked like the pages).
    if "index.html" not in files:
        failures.append("no index.html")
    if len(files) - 1 != len(SUBMISSIONS):
        failures.append(f"{len(files) - 1} pages for {len(SUBMISSIONS)} submissions")
    with PageBrowser() as browser:
        saw_script_name = check_pages(browser, pages, out, files, failures)
    if not saw_script_name:
        print(f"no page shows the name {SCRIPT_NAME} as text")
        failures.append("script-name")
    print(f"screenshots in {out}")
    return 1 if failures else 0


def check_pages(browser, pages, out, files, failures):
    """Loads each page; appends the name of each that fails a check to `failures`; whether a
    page shows the hostile student name as text."""
    saw_script_name = False
    for name in files:
        page = os.path.abspath(os.path.join(pages, name))
        dom = browser.dom(page)
        problems = check_dom(dom) if dom else ["Chromium returned no DOM"]
        # The name is text on the page: serialized back as escaped markup.
        if "&lt;script&gt;alert(1)&lt;/script&gt;" in dom:
            saw_script_name = True
        shot = os.path.join(out, name[:-5] + ".png")
        browser.screenshot(page, shot, (1000, 1200))
        if not os.path.exists(shot) or os.path.getsize(shot) < 1000:
            problems.append("no screenshot")
        print(f"{name}: {'ok' if not problems else '; '.join(problems)}")
        if problems:
            failures.append(name)
    return saw_script_name


if __name__ == "__main__":
    sys.exit(main())
