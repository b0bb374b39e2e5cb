#!/usr/bin/env python3
"""A practice page (raygrade handout --practice) as a student uses it, in headless Chromium
driven by Selenium, opened from disk (file://).

On the derive problem of the example assignment the student first writes c with r where r²
belongs, presses Check and sees that mistake named, with no full marks and no worked solution
yet; then types the right c, presses Check and sees full marks (2 / 2, the points the
assignment gives) and the worked solution. Attempts are counted, and a reload keeps them. The
formulas are the textbook's (a = v_x² + v_y², b = 2(p_x v_x + p_y v_y), c = p_x² + p_y² − r²
for x² + y² = r²). Then the generic page (no student) of an assignment of that problem whose
numbers are everyone's, its bank named by an absolute path, grades the right answers to full
marks. Prints the grader's load time and the time of each Check (not asserted).
Screenshots land in OUT.

Usage: practice_in_browser.py RAYGRADE RAYGRADE_JS ASSIGNMENT OUT
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

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

RAYGRADE, RAYGRADE_JS, ASSIGNMENT, OUT = sys.argv[1:5]
PROBLEM = "seed000-cylinder-derive-origin"
RIGHT = {"a": "v_x^2 + v_y^2", "b": "2(p_x v_x + p_y v_y)", "c": "p_x^2 + p_y^2 - r^2"}


def problem_section(driver):
    """The section of PROBLEM on the page, and its inputs' names by the form's keys."""
    data = json.loads(driver.find_element(By.ID, "handout-data").get_attribute("textContent"))
    problem = next(p for p in data["problems"] if p["id"] == PROBLEM)
    section = driver.find_element(By.ID, f"problem-{problem['index']}")
    return section, {f["key"]: f"{PROBLEM}.{i}" for i, f in enumerate(problem["form"]["fields"])}


def type_into(driver, names, answers):
    for key, text in answers.items():
        box = driver.find_element(By.NAME, names[key])
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", box)
        box.clear()
        box.send_keys(text)


def press_check_of(driver, section):
    """Presses the section's Check; returns the time the grading took in the page."""
    button = section.find_element(By.CSS_SELECTOR, "button.check")
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", button)
    button.click()
    return driver.execute_script("return window.raygradePractice.timing.lastCheckMs")


def generic_page(driver):
    """The generic page (no --student) of an assignment whose numbers are everyone's, with its
    bank named by an absolute path: the page names no student, and a Check grades the answers
    against the generic set."""
    with open(ASSIGNMENT) as f:
        bank = json.load(f)["bank"]
    folder = os.path.dirname(os.path.abspath(ASSIGNMENT))
    banks = [os.path.normpath(os.path.join(folder, b))
             for b in ([bank] if isinstance(bank, str) else bank)]
    work = os.path.join(OUT, "generic")
    os.makedirs(work)
    same = os.path.join(work, "same.json")
    with open(same, "w") as f:
        json.dump({"assignment": "same", "bank": banks, "variants": {"per_student": False},
                   "problems": [{"id": PROBLEM, "points": 2}]}, f)
    page = os.path.join(work, "page")
    r = subprocess.run([RAYGRADE, "handout", same, "--out", page, "--practice",
                        "--grader-js", RAYGRADE_JS], capture_output=True, text=True, timeout=300)
    if not check(r.returncode == 0, f"handout --practice of the generic page failed: {r.stderr}"):
        return
    driver.get("file://" + os.path.abspath(os.path.join(page, "index.html")))
    if not check(wait_for(driver, "window.raygradePractice && window.raygradePractice.ready"),
                 "the generic page's grader never became ready"):
        return
    data = json.loads(driver.find_element(By.ID, "handout-data").get_attribute("textContent"))
    check(data["student"]["identity"] is None and "stand_in" not in data["practice"],
          f"the generic page names a student: {data['student']}, {sorted(data['practice'])}")
    section, names = problem_section(driver)
    type_into(driver, names, RIGHT)
    press_check_of(driver, section)
    scores = section.find_elements(By.CSS_SELECTOR, ".score")
    check(scores and scores[0].text == "Score: 2 / 2",
          f"the generic page's Check does not grade the right answers: {section.text}")
    driver.save_screenshot(os.path.join(OUT, "practice-generic.png"))


def main():
    if not require_chromium() or not shutil.which("chromedriver"):
        print("chromium-driver is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    if not os.path.exists(RAYGRADE_JS):
        print(f"{RAYGRADE_JS} is missing (scripts/build-web.sh builds it)")
        return 1
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(OUT)
    handouts = os.path.join(OUT, "handouts")
    r = subprocess.run([RAYGRADE, "handout", ASSIGNMENT, "--student", "s001", "--out", handouts,
                        "--practice", "--grader-js", RAYGRADE_JS],
                       capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, f"handout --practice failed: {r.stderr}")
    page = os.path.abspath(os.path.join(handouts, "s001", "index.html"))
    size = os.path.getsize(page)
    print(f"practice page: {size / 1e6:.2f} MB (raygrade.js {os.path.getsize(RAYGRADE_JS) / 1e6:.2f} MB)")

    options = webdriver.ChromeOptions()
    for flag in FLAGS:
        options.add_argument(flag if flag != "--headless" else "--headless=new")
    profile = tempfile.mkdtemp(prefix="raygrade-practice-")
    options.add_argument(f"--user-data-dir={profile}")
    options.add_argument("--window-size=1200,1600")
    options.binary_location = shutil.which("chromium") or shutil.which("chromium-browser")
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    # Generous: on a loaded machine a step may wait long for the processor; nothing is timed.
    driver.set_script_timeout(300)
    driver.set_page_load_timeout(300)
    try:
        # A student's browser is running when they open the page: an empty page first starts
        # the browser's processes, so that the page's own load is what is measured (a fresh
        # profile: nothing of the page is cached).
        driver.get("about:blank")
        start = time.time()
        driver.get("file://" + page)
        ready = wait_for(driver, "window.raygradePractice && window.raygradePractice.ready")
        check(ready, "the grader never became ready: " +
              str(driver.execute_script("return document.getElementById('grader-status').textContent")))
        timing = driver.execute_script("return window.raygradePractice.timing")
        print(f"ready {time.time() - start:.2f} s after navigation (as the test sees it); in the "
              f"page {timing['readyAfterNavigationMs']:.0f} ms after navigation began, "
              f"{timing['readyMs']:.0f} ms after its script started the grader")
        warm = wait_for(driver, "window.raygradePractice.timing.warmUpMs")
        print(f"assignment read and variants drawn (after ready, before the first Check): {warm:.0f} ms")
        section, names = problem_section(driver)

        def type_answers(answers):
            type_into(driver, names, answers)

        def press_check():
            return press_check_of(driver, section)

        # A wrong c: r where r² belongs.
        type_answers({**RIGHT, "c": "p_x^2 + p_y^2 - r"})
        ms = press_check()
        print(f"Check (wrong answer): {ms:.1f} ms")
        mistakes = section.find_elements(By.CSS_SELECTOR, ".mistake[data-mistake='r-not-squared']")
        check(len(mistakes) == 1 and "r where r² belongs" in mistakes[0].text,
              f"the named mistake is not shown: {section.text}")
        score = section.find_element(By.CSS_SELECTOR, ".score").text
        check(score.startswith("Score: 1.33") and score.endswith(" / 2"),
              f"a wrong c scores {score!r}, not 4/3 of 2 (two of three parts)")
        check(not section.find_elements(By.CSS_SELECTOR, "iframe.solution"),
              "the worked solution shows after one wrong attempt")
        check("Attempts: 1" in section.text, f"the attempt is not counted: {section.text}")
        driver.execute_script("arguments[0].scrollIntoView({block: 'start'})", section)
        driver.save_screenshot(os.path.join(OUT, "practice-wrong.png"))

        # The right c.
        type_answers({"c": RIGHT["c"]})
        ms = press_check()
        print(f"Check (right answer): {ms:.1f} ms")
        score = section.find_element(By.CSS_SELECTOR, ".score").text
        check(score == "Score: 2 / 2", f"the right answers score {score!r}, not 2 / 2")
        check(not section.find_elements(By.CSS_SELECTOR, ".mistake"), "a mistake is still named")
        check("Attempts: 2 — full marks" in section.text, f"attempts: {section.text}")
        frames = section.find_elements(By.CSS_SELECTOR, "iframe.solution")
        check(len(frames) == 1, "no worked solution after full marks")
        if frames:
            srcdoc = frames[0].get_attribute("srcdoc")
            check("r²" in srcdoc or "r<sup>2</sup>" in srcdoc or "<msup>" in srcdoc,
                  "the worked solution does not show the quadratic's coefficients")
            driver.execute_script("arguments[0].scrollIntoView({block: 'start'})", section)
        driver.save_screenshot(os.path.join(OUT, "practice-right.png"))

        # A reload keeps the attempts and the unlocked solution.
        driver.refresh()
        wait_for(driver, "window.raygradePractice && window.raygradePractice.ready")
        section, _ = problem_section(driver)
        check("Attempts: 2 — full marks" in section.text, "the attempts are lost on reload")
        check(len(section.find_elements(By.CSS_SELECTOR, "iframe.solution")) == 1,
              "the worked solution is locked again after a reload")

        generic_page(driver)
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    print("FAILED" if failures else "ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
