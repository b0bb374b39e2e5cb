#!/usr/bin/env python3
"""An accessibility audit with axe-core of every kind of page raygrade writes, in headless
Chromium driven by Selenium, each page opened from disk (file://).

The pages, for the example assignment: one student's handout (as loaded, then with an extra
hit row and an unreadable entry flagged); the practice page (once its grader is ready, after a
wrong Check that names a mistake, after a right one that shows the worked solution); the worked
solution of each of the assignment's problems (`raygrade solutions --format html`) and the
student's own variants (`raygrade solve --student --format html`); the HTML feedback pages of
a graded class (`raygrade grade --assignment --format html --out`: right answers, a named
mistake, an unreadable submission, and the index). axe-core runs every rule of WCAG 2.0 to 2.2
at levels A and AA, its best practices and its experimental rules (level AAA and the deprecated
rules left out), `region` (no content outside a landmark) and `landmark-one-main` among them;
any violation, whatever its impact, fails the test, listed with its rule, impact, element and
page. Every page must also have exactly one <main>. Prints each page audited, with the number
of rules run and of violations.

The browser runs in the time zone America/New_York: the handout's due date must show the
student's local time with the UTC time beside it, and the page's HTML must hold the UTC text
alone (what a browser without JavaScript shows) in a <time datetime> element.

Exit 77 (skipped) without Chromium, chromedriver, python3-selenium or axe.min.js; without
raygrade.js the practice page is left out (said so).

Usage: axe_in_browser.py RAYGRADE RAYGRADE_JS ASSIGNMENT AXE_JS OUT
"""
import csv
import datetime
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import zoneinfo

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, failures  # noqa: E402
from chromium import FLAGS, SKIPPED, require_chromium, wait_for  # noqa: E402

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.webdriver.common.by import By
except ImportError:
    print("python3-selenium is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(SKIPPED)

RAYGRADE, RAYGRADE_JS, ASSIGNMENT, AXE_JS, OUT = sys.argv[1:6]
STUDENT = "s001"
ROSTER = "id,name,email\ns001,Ada Lovelace,ada@example.edu\n"
ZONE = "America/New_York"
# The practice page's problem to answer, its right formulas and a wrong c (r for r²).
DERIVE = "seed000-cylinder-derive-origin"
RIGHT = {"a": "v_x^2 + v_y^2", "b": "2(p_x v_x + p_y v_y)", "c": "p_x^2 + p_y^2 - r^2"}
WRONG_C = "p_x^2 + p_y^2 - r"
# Rules that must have run on every page (a rule turned off would pass silently).
REQUIRED_RULES = ("region", "landmark-one-main", "color-contrast", "label", "heading-order",
                  "target-size")
# The rules of every run: WCAG 2.0 to 2.2 at levels A and AA, axe's best practices and its
# experimental rules, each turned on, even those axe leaves off by default (target-size);
# the deprecated ones and level AAA (color-contrast-enhanced) are left out. All results but
# the violations are left out of the answer, to keep it quick.
AXE_RUN = """
const done = arguments[arguments.length - 1];
const tags = ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa', 'best-practice',
              'experimental'];
const rules = {};
for (const r of axe.getRules()) {
  rules[r.ruleId] = {enabled: !r.tags.includes('deprecated') && !r.tags.includes('wcag2aaa')};
}
axe.run(document, {resultTypes: ['violations'], runOnly: {type: 'tag', values: tags}, rules: rules})
  .then((r) => done({violations: r.violations.map((v) => ({
                       id: v.id, impact: v.impact, help: v.help,
                       targets: v.nodes.map((n) => n.target.join(' '))})),
                     ran: [].concat(r.violations, r.passes, r.incomplete, r.inapplicable)
                            .map((v) => v.id),
                     mains: document.querySelectorAll('main').length, version: axe.version}),
        (e) => done({error: String(e)}));
"""
audited = []
versions = set()


def run(*args, statuses=(0,)):
    r = subprocess.run([RAYGRADE, *args], capture_output=True, text=True, timeout=300)
    check(r.returncode in statuses,
          f"raygrade {' '.join(args)} exited {r.returncode}: {r.stderr}")
    return r


def audit(driver, axe_source, name):
    """Runs axe-core on the page as it is now; records each violation as a failure."""
    if not driver.execute_script("return typeof axe !== 'undefined'"):
        driver.execute_script(axe_source)
    start = time.time()
    r = driver.execute_async_script(AXE_RUN)
    took = time.time() - start
    if "error" in r:
        check(False, f"{name}: axe-core failed: {r['error']}")
        return
    for rule in REQUIRED_RULES:
        check(rule in r["ran"], f"{name}: the rule {rule} did not run")
    check(r["mains"] == 1, f"{name}: {r['mains']} <main> elements, not one")
    nodes = 0
    for v in r["violations"]:
        for target in v["targets"]:
            nodes += 1
            check(False, f"{name}: {v['id']} ({v['impact']}) at {target}: {v['help']}")
    audited.append(name)
    versions.add(r["version"])
    print(f"audited {name}: {len(r['ran'])} rules, {nodes} violations ({took:.1f} s)")


def open_page(driver, path):
    driver.get("file://" + os.path.abspath(path))


def write_pages(out, practice):
    """Writes every page to audit; returns {name: path} and the practice page's path (or None)."""
    pages = {}
    with open(ASSIGNMENT, encoding="utf-8") as f:
        spec = json.load(f)
    ids = [p["id"] for p in spec["problems"]]
    banks = spec["bank"] if isinstance(spec["bank"], list) else [spec["bank"]]
    home = os.path.dirname(os.path.abspath(ASSIGNMENT))

    # (a) The handout of one student of a roster.
    roster = os.path.join(out, "roster.csv")
    with open(roster, "w", encoding="utf-8") as f:
        f.write(ROSTER)
    run("handout", ASSIGNMENT, "--roster", roster, "--out", os.path.join(out, "handout"))
    with open(os.path.join(out, "handout", "handouts.csv"), encoding="utf-8") as f:
        folder = next(csv.DictReader(f))["folder"]
    handout = os.path.join(out, "handout", folder, "index.html")

    # (b) The practice page of the same student.
    practice_page = None
    if practice:
        run("handout", ASSIGNMENT, "--student", STUDENT, "--out", os.path.join(out, "practice"),
            "--practice", "--grader-js", RAYGRADE_JS)
        practice_page = os.path.join(out, "practice", STUDENT, "index.html")

    # (c) The worked solution of each of the assignment's problems, and of the student's own.
    solutions = os.path.join(out, "solutions")
    run("solutions", *[os.path.join(home, b) for b in banks], "--out", solutions,
        "--format", "html")
    for i in ids:
        pages[f"worked solution {i}"] = os.path.join(solutions, i + ".html")
    mine = run("solve", ASSIGNMENT, "--student", STUDENT, "--format", "html")
    pages["worked solutions of the student's variants"] = os.path.join(out, "mine.html")
    with open(pages["worked solutions of the student's variants"], "w", encoding="utf-8") as f:
        f.write(mine.stdout)

    # (d) The feedback pages: right answers, a named mistake, an unreadable file, the index.
    answers = json.loads(run("solve", ASSIGNMENT, "--student", STUDENT, "--format",
                             "json").stdout)
    right = {s["id"]: s["answer"] for s in answers["solutions"]}
    wrong = json.loads(json.dumps(right))
    wrong[DERIVE] = {**RIGHT, "c": WRONG_C}
    subs = os.path.join(out, "submissions")
    os.makedirs(subs)
    identity = {"id": STUDENT, "name": "Ada Lovelace"}
    for name, content in (("right", {"student": identity, "answers": right}),
                          ("wrong", {"student": {**identity, "id": "s002"}, "answers": wrong}),
                          ("unreadable", None)):
        with open(os.path.join(subs, name + ".json"), "w", encoding="utf-8") as f:
            f.write(json.dumps(content) if content else "{ not json")
    feedback = os.path.join(out, "feedback")
    # Exit 1 for the wrong answers, 2 for the unreadable file: both expected.
    run("grade", "--assignment", ASSIGNMENT, subs, "--format", "html", "--out", feedback,
        "--now", "2026-12-01T00:00:00Z", statuses=(2,))
    for n in sorted(os.listdir(feedback)):
        if n.endswith(".html"):
            pages[f"feedback {n}"] = os.path.join(feedback, n)
    for name, path in pages.items():
        check(os.path.exists(path), f"{name}: {path} was not written")
    return handout, practice_page, {k: v for k, v in pages.items() if os.path.exists(v)}


def check_due_date(driver, html_path):
    """The due date: UTC in the HTML, local time with UTC beside it once the script ran."""
    with open(ASSIGNMENT, encoding="utf-8") as f:
        due = json.load(f).get("due")
    if not due:
        print("the assignment has no due date: its display is not checked")
        return
    when = datetime.datetime.fromisoformat(due.replace("Z", "+00:00")).astimezone(
        datetime.timezone.utc)
    local = when.astimezone(zoneinfo.ZoneInfo(ZONE))

    def day(d):
        return f"{d:%A} {d.day} {d:%B %Y}"

    utc_text = f"{day(when)}, {when:%H:%M} UTC"
    beside = f"{when:%H:%M} UTC" if day(when) == day(local) else utc_text
    want = f"Due {day(local)}, {local:%H:%M} (your time; {beside})"
    with open(html_path, encoding="utf-8") as f:
        html = f.read()
    iso = when.strftime("%Y-%m-%dT%H:%M:%SZ")
    check(f'<time datetime="{iso}">{utc_text}</time>' in html,
          f"the handout's HTML does not hold <time datetime=\"{iso}\">{utc_text}</time>")
    shown = driver.find_element(By.CSS_SELECTOR, ".due").text
    check(shown == want, f"in {ZONE} the due date reads {shown!r}, not {want!r}")
    print(f"due date in {ZONE}: {shown!r}")


def audit_handout(driver, axe_source, page):
    open_page(driver, page)
    check_due_date(driver, page)
    audit(driver, axe_source, "handout")
    # A second hit row and an unreadable entry, as a student makes them.
    add = driver.find_elements(By.CSS_SELECTOR, "button.add")
    if add:
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", add[0])
        add[0].click()
    box = driver.find_element(By.CSS_SELECTOR, "input[type=text]")
    box.send_keys("2 +* 3")
    audit(driver, axe_source, "handout with an added row and an unreadable entry")


def audit_practice(driver, axe_source, page):
    open_page(driver, page)
    ready = wait_for(driver, "window.raygradePractice && window.raygradePractice.ready", 120)
    check(ready, "the practice page's grader never became ready")
    if not ready:
        return
    audit(driver, axe_source, "practice page")
    data = json.loads(driver.find_element(By.ID, "handout-data").get_attribute("textContent"))
    problem = next(p for p in data["problems"] if p["id"] == DERIVE)
    section = driver.find_element(By.ID, f"problem-{problem['index']}")
    names = {f["key"]: f"{DERIVE}.{i}" for i, f in enumerate(problem["form"]["fields"])}

    def answer_and_check(answers):
        for key, text in answers.items():
            box = driver.find_element(By.NAME, names[key])
            box.clear()
            box.send_keys(text)
        button = section.find_element(By.CSS_SELECTOR, "button.check")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", button)
        button.click()

    answer_and_check({**RIGHT, "c": WRONG_C})
    check(section.find_elements(By.CSS_SELECTOR, ".mistake"), "no mistake named after a wrong c")
    audit(driver, axe_source, "practice page, a mistake named")
    answer_and_check({"c": RIGHT["c"]})
    check(section.find_elements(By.CSS_SELECTOR, "iframe.solution"),
          "no worked solution after full marks")
    audit(driver, axe_source, "practice page, full marks and the worked solution")


def main():
    if not require_chromium():
        return SKIPPED
    if not shutil.which("chromedriver"):
        print("chromium-driver is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    if not os.path.exists(AXE_JS):
        print(f"{AXE_JS} is missing (bash scripts/fetch-web-libs.sh fetches axe-core): skipped")
        return SKIPPED
    practice = os.path.exists(RAYGRADE_JS)
    if not practice:
        print(f"{RAYGRADE_JS} is missing (scripts/build-web.sh builds it): "
              "the practice page is not audited")
    with open(AXE_JS, encoding="utf-8") as f:
        axe_source = f.read()
    started = time.time()
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(OUT)
    handout, practice_page, pages = write_pages(OUT, practice)
    print(f"pages written in {time.time() - started:.1f} s")

    options = webdriver.ChromeOptions()
    for flag in FLAGS:
        options.add_argument(flag if flag != "--headless" else "--headless=new")
    profile = tempfile.mkdtemp(prefix="raygrade-axe-")
    options.add_argument(f"--user-data-dir={profile}")
    options.add_argument("--window-size=1200,1600")
    options.binary_location = shutil.which("chromium") or shutil.which("chromium-browser")
    # The browser inherits chromedriver's environment, and with it the time zone.
    service = Service(shutil.which("chromedriver"), env={**os.environ, "TZ": ZONE})
    driver = webdriver.Chrome(service=service, options=options)
    driver.set_script_timeout(300)
    driver.set_page_load_timeout(300)
    try:
        audit_handout(driver, axe_source, handout)
        if practice_page:
            audit_practice(driver, axe_source, practice_page)
        for name, path in pages.items():
            open_page(driver, path)
            audit(driver, axe_source, name)
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    print(f"{len(audited)} pages and states audited with axe-core {', '.join(sorted(versions))} "
          f"in {time.time() - started:.1f} s")
    print(f"FAILED: {len(failures)} problems" if failures else "ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
