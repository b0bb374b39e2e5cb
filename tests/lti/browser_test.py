#!/usr/bin/env python3
"""One launch in headless Chromium, across two sites: the test platform at http://localhost:P,
`raygrade serve` at http://127.0.0.1:T, so the tool's cookies must be SameSite=None; Secure to
come back on the platform's cross-site form posts. The student launches through the platform,
types the right answers of some problems into the page's form, submits, and sees feedback;
the platform receives the score, and it is the score `raygrade grade` gives the same answers.
Screenshots land in OUT.

Usage: browser_test.py [OUT]   ($RAYGRADE names the binary; exits 77 without Chromium)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import json
import time

sys.path.append(os.path.dirname(HERE))
import requests  # noqa: E402

import ltitest  # noqa: E402
from chromium import SKIPPED, require_chromium  # noqa: E402
from ltitest import ASSIGNMENT, cli_grade, solve, student_key  # noqa: E402

OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ltitest.ROOT, "build", "lti-browser")


def typed(x):
    if isinstance(x, bool):
        return "true" if x else "false"
    return str(int(x)) if x == int(x) else f"{x:.15g}"


def fill(driver, form, right):
    """Types the right answers of the problems whose inputs are plain numbers, vectors or a
    single hit; returns {problem: answer} of what was typed."""
    from selenium.webdriver.common.by import By

    def put(name, value):
        found = driver.find_elements(By.NAME, name)
        if not found:
            raise LookupError(name)
        el = found[0]
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", el)
        el.clear()
        el.send_keys(value)

    # The launch data's form: {problem id: answer form} (or a list of {"id", "form"}).
    if isinstance(form, dict) and "problems" in form:
        problems = form["problems"]
    elif isinstance(form, dict):
        problems = [{"id": pid, "form": f} for pid, f in form.items()]
    else:
        problems = form
    done = {}
    for p in problems:
        pid = p["id"]
        a = right.get(pid)
        fields = p["form"]["fields"]
        kinds = {f["type"] for f in fields}
        if a is None or not kinds <= {"number", "vector", "hits"}:
            continue
        if "hits" in kinds and len(a.get("hits", [])) != 1:
            continue
        try:
            for i, f in enumerate(fields):
                prefix = f"{pid}.{i}"
                if f["type"] == "hits":
                    hit = a["hits"][0]
                    for c in f["columns"]:
                        if c["key"] not in hit:
                            continue
                        if c["type"] == "vector":
                            for axis, x in zip("xyz", hit[c["key"]]):
                                put(f"{prefix}.0.{c['key']}.{axis}", typed(x))
                        else:
                            put(f"{prefix}.0.{c['key']}", typed(hit[c["key"]]))
                    continue
                v = a
                for k in f["key"].split("/"):
                    v = v.get(k) if isinstance(v, dict) else None
                if v is None:
                    continue
                if f["type"] == "vector":
                    for axis, x in zip("xyz", v):
                        put(f"{prefix}.{axis}", typed(x))
                else:
                    put(prefix, typed(v))
        except LookupError as e:
            print(f"{pid}: no input named {e}: left blank")
            continue
        done[pid] = a
    return done


def main():
    if not require_chromium():
        return SKIPPED
    try:
        from selenium.webdriver.common.by import By
    except ImportError:
        print("python3-selenium is not installed: skipped")
        return SKIPPED
    from chromium import selenium_chromium
    os.makedirs(OUT, exist_ok=True)

    class Case(ltitest.LtiCase):
        public_host = "localhost"

        def runTest(self):
            pass

    case = Case()
    case.setUp()
    failures = []
    try:
        case.register()
        link = requests.post(f"{case.platform}/test/link", json={
            "title": "Homework", "custom": {"assignment": ASSIGNMENT}, "scoreMaximum": 21},
            timeout=30).json()
        driver = selenium_chromium(os.path.join(case.tmp, "profile"))
        try:
            driver.get(f"{case.platform}/test/launch?user=ada&role=Learner&link={link['id']}")
            end = time.time() + 30
            while time.time() < end and not driver.find_elements(By.ID, "raygrade-launch"):
                time.sleep(0.1)
            driver.save_screenshot(os.path.join(OUT, "student-page.png"))
            found = driver.find_elements(By.ID, "raygrade-launch")
            if not found:
                print(f"no student page at {driver.current_url}: {driver.page_source[:500]}")
                return 1
            data = json.loads(found[0].get_attribute("textContent"))
            key = student_key(data)
            typed_answers = fill(driver, data["form"], solve(key))
            if not typed_answers:
                failures.append("no problem's inputs could be filled")
            buttons = driver.find_elements(By.CSS_SELECTOR, "#raygrade-submit")
            if not buttons:
                failures.append("no submit button")
            else:
                driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", buttons[0])
                buttons[0].click()
            scores = case.wait_scores(1, 30)
            time.sleep(0.5)
            for shown in driver.find_elements(By.ID, "raygrade-result"):
                driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", shown)
            driver.save_screenshot(os.path.join(OUT, "student-feedback.png"))
            if len(scores) != 1:
                failures.append(f"the platform has {len(scores)} scores, not 1")
            else:
                body = scores[0]["body"]
                want, top = cli_grade(key, typed_answers, case.tmp)
                if body["userId"] != "ada":
                    failures.append(f"score of {body['userId']}, not ada")
                if abs(body["scoreGiven"] / body["scoreMaximum"] - want / top) > 1e-9:
                    failures.append(f"platform has {body['scoreGiven']}/{body['scoreMaximum']},"
                                    f" raygrade grade gives {want}/{top}")
                if want <= 0:
                    failures.append("the typed answers earned nothing")
                text = driver.find_element(By.TAG_NAME, "body").text
                shown = {f"{want:g}", f"{want:.1f}", f"{want:.2f}", str(want)}
                if not any(s in text for s in shown):
                    failures.append(f"the page does not show the score {want:g}: {text[-400:]!r}")
        finally:
            driver.quit()
    finally:
        case.cleanup()
    for f in failures:
        print("FAIL:", f)
    print("ok" if not failures else f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
