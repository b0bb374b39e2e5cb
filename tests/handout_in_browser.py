#!/usr/bin/env python3
"""The handout page as a student uses it, in headless Chromium driven by Selenium.

Writes the handouts of two students from a roster, checks that their numbers differ on every
problem with parameters, opens the first student's page from disk, types that student's right
answers into the inputs (some as a student would type them: "2√2", "1/4", "−3"), watches an
unreadable entry being flagged as it is typed, downloads answers.json, and grades the download
with `raygrade grade --assignment`: full marks. The same answers handed in as the second
student earn less. Reloading the page keeps the answers. Screenshots land in OUT.

Usage: handout_in_browser.py RAYGRADE ASSIGNMENT OUT
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, failures  # noqa: E402
from chromium import SKIPPED, click, require_chromium, selenium_chromium, wait_for_file  # noqa: E402

try:
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select
except ImportError:
    print("python3-selenium is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(SKIPPED)

RAYGRADE, ASSIGNMENT, OUT = sys.argv[1:4]
ROSTER = "id,name,email\ns001,Ada Lovelace,ada@example.edu\ns002,Alan Turing,alan@example.edu\n"


def run(*args):
    return subprocess.run([RAYGRADE, *args], capture_output=True, text=True, timeout=300)


def answers_of(student):
    r = run("solve", ASSIGNMENT, "--student", student, "--format", "json")
    assert r.returncode == 0, r.stderr
    return {s["id"]: s["answer"] for s in json.loads(r.stdout)["solutions"]}


def typed(x):
    """A number as a student types it: whole numbers plainly, others to 12 significant digits,
    and a few in the forms the grader reads (a fraction, a square root, a Unicode minus)."""
    if x == int(x):
        v = int(x)
        return f"−{-v}" if v < 0 else str(v)
    for q in (2, 4, 5, 8, 10):
        if abs(x * q - round(x * q)) < 1e-12:
            return f"{round(x * q)}/{q}"
    for k in (2, 3):
        if abs(x / math.sqrt(k) - round(x / math.sqrt(k))) < 1e-12 and round(x / math.sqrt(k)) != 0:
            return f"{round(x / math.sqrt(k))}√{k}"
    return f"{x:.12g}"




def fill(driver, answers):
    """Types every answer into the page, as a student would, field by field."""
    def put(name, value):
        el = driver.find_element(By.NAME, name)
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", el)
        el.clear()
        el.send_keys(value)

    def put_vector(name, v):
        for axis, x in zip("xyz", v):
            put(f"{name}.{axis}", typed(x))

    data = json.loads(driver.find_element(By.ID, "handout-data").get_attribute("textContent"))
    for p in data["problems"]:
        a = answers[p["id"]]
        for i, f in enumerate(p["form"]["fields"]):
            prefix = f"{p['id']}.{i}"
            kind = f["type"]
            if kind == "hits":
                hits = a.get("hits", [])
                if not hits:
                    click(driver, driver.find_element(By.NAME, prefix + ".miss"))
                for n, hit in enumerate(hits):
                    if n > 0:
                        buttons = driver.find_elements(By.CSS_SELECTOR, f"#problem-{p['index']} button.add")
                        click(driver, buttons[0])
                    for c in f["columns"]:
                        if c["key"] not in hit:
                            continue
                        if c["type"] == "vector":
                            put_vector(f"{prefix}.{n}.{c['key']}", hit[c["key"]])
                        else:
                            put(f"{prefix}.{n}.{c['key']}", typed(hit[c["key"]]))
            elif kind == "choice":
                want = a.get(f["key"])
                index = [o["value"] for o in f["options"]].index(want)
                Select(driver.find_element(By.NAME, prefix)).select_by_value(str(index))
            elif kind in ("number", "vector", "yesno", "formula"):
                v = a
                for k in f["key"].split("/"):
                    v = v.get(k) if isinstance(v, dict) else None
                if v is None:
                    continue
                if kind == "vector":
                    put_vector(prefix, v)
                elif kind == "yesno":
                    Select(driver.find_element(By.NAME, prefix)).select_by_value("true" if v else "false")
                elif kind == "formula":
                    put(prefix, v)
                else:
                    put(prefix, typed(v))
            elif kind == "rows":
                for r, row in enumerate(f["rows"]):
                    mine = next(x for x in a[f["key"]] if all(x.get(k) == w for k, w in row["fixed"].items()))
                    for c in f["columns"]:
                        name = f"{prefix}.{r}.{c['key']}"
                        if c["type"] == "yesno":
                            Select(driver.find_element(By.NAME, name)).select_by_value("true" if mine[c["key"]] else "false")
                        else:
                            put(name, typed(mine[c["key"]]))
            elif kind == "set":
                for option in a.get(f["key"], []):
                    click(driver, driver.find_element(By.NAME, f"{prefix}.{option}"))
            elif kind == "json":
                put(prefix, json.dumps({k: v for k, v in a.items()}))



def with_unknown_field(page, work):
    """A copy of `page` whose first problem's form starts with fields of types the page does not
    know: "slider", and names of a JavaScript object's own properties."""
    with open(page, encoding="utf-8") as f:
        html = f.read()
    start = html.index('<script type="application/json" id="handout-data">')
    start = html.index(">", start) + 1
    end = html.index("</script>", start)
    data = json.loads(html[start:end])
    # A name of no type, and names every JavaScript object answers to.
    for name in ["slider", "constructor", "__proto__", "toString"]:
        data["problems"][0]["form"]["fields"].insert(0, {"type": name, "key": name, "label": name})
    text = json.dumps(data).replace("</", "<\\/")
    out = os.path.join(work, "unknown-field.html")
    with open(out, "w", encoding="utf-8") as f:
        f.write(html[:start] + text + html[end:])
    return out


def grade(submission, *extra):
    r = run("grade", "--assignment", ASSIGNMENT, "--format", "json", "--feedback", "full", *extra, submission)
    return r.returncode, json.loads(r.stdout) if r.stdout.strip() else None, r.stderr


def main():
    if not require_chromium():
        return SKIPPED
    if not shutil.which("chromedriver"):
        print("chromedriver is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    os.makedirs(OUT, exist_ok=True)
    work = tempfile.mkdtemp(prefix="raygrade-handout-")
    try:
        roster = os.path.join(work, "roster.csv")
        with open(roster, "w") as f:
            f.write(ROSTER)
        handouts = os.path.join(work, "handouts")
        r = run("handout", ASSIGNMENT, "--roster", roster, "--out", handouts)
        check(r.returncode == 0, f"handout exited {r.returncode}: {r.stderr}")
        pages = {s: os.path.join(handouts, s, "index.html") for s in ("s001", "s002")}
        check(all(os.path.exists(p) for p in pages.values()), "a handout page is missing")

        # The numbers differ on every problem with parameters.
        mine, theirs = answers_of("s001"), answers_of("s002")
        with open(ASSIGNMENT) as f:
            spec = json.load(f)
        for entry in spec["problems"]:
            pid = entry if isinstance(entry, str) else entry["id"]
            if pid.startswith("variant-"):
                check(mine[pid] != theirs[pid], f"{pid}: both students got the same numbers")

        downloads = os.path.join(work, "downloads")
        os.makedirs(downloads)
        profile = os.path.join(work, "profile")
        driver = selenium_chromium(profile, downloads)
        try:
            driver.get("file://" + pages["s001"])
            # An unreadable entry is flagged as it is typed, and the flag goes when it is fixed.
            probe = driver.find_element(By.NAME, "variant-sphere.0.0.t")
            probe.send_keys("7.2.7")
            hint = driver.execute_script("return arguments[0].hint.textContent", probe)
            check("second decimal point" in hint, f"no syntax message for 7.2.7: {hint!r}")
            driver.save_screenshot(os.path.join(OUT, "handout-typing-error.png"))
            probe.clear()
            probe.send_keys("30°")
            hint = driver.execute_script("return arguments[0].hint.textContent", probe)
            check("reads as 0.523599" in hint, f"30° not read as 0.523599 (radians): {hint!r}")
            probe.clear()
            probe.send_keys("2√2")
            hint = driver.execute_script("return arguments[0].hint.textContent", probe)
            check("reads as 2.82843" in hint, f"2√2 not read as 2.82843: {hint!r}")
            fill(driver, mine)
            driver.save_screenshot(os.path.join(OUT, "handout-filled.png"))
            bad = driver.find_elements(By.CSS_SELECTOR, "input.bad")
            check(not bad, f"{len(bad)} inputs flagged as unreadable after filling")
            # Progress is kept: reload and the answers are still there.
            driver.refresh()
            kept = driver.find_element(By.NAME, "variant-sphere.0.0.t").get_attribute("value")
            check(kept != "", "the answers were not kept after a reload")
            click(driver, driver.find_element(By.ID, "download"))
            downloaded = wait_for_file(downloads, "answers.json")
            check(downloaded is not None, "answers.json was not downloaded")
            driver.save_screenshot(os.path.join(OUT, "handout-downloaded.png"))
            # A field of a type the page does not know (a page from a newer raygrade, or one
            # edited): said so where it would be, never shown as another type's input, and the
            # fields after it still shown.
            driver.get("file://" + pages["s002"])
            inputs = len(driver.find_elements(By.CSS_SELECTOR, "input, select"))
            unknown = with_unknown_field(pages["s002"], work)
            driver.get("file://" + unknown)
            alerts = [a.text for a in driver.find_elements(By.CSS_SELECTOR, "[role=alert]")]
            for name in ["slider", "constructor", "__proto__", "toString"]:
                check(any(f"\u201c{name}\u201d" in a for a in alerts),
                      f"a field of the unknown type {name} is not said to be one: {alerts}")
            after = len(driver.find_elements(By.CSS_SELECTOR, "input, select"))
            check(after == inputs, f"{after} inputs with the unknown field, {inputs} without: "
                  "the unknown field was shown as an input, or the fields after it were lost")
        finally:
            driver.quit()
        if downloaded:
            shutil.copy(downloaded, os.path.join(OUT, "answers-s001.json"))
            with open(downloaded) as f:
                submission = json.load(f)
            check(submission.get("student", {}).get("id") == "s001", "the download does not name s001")
            code, graded, err = grade(downloaded, "--roster", roster)
            check(code == 0, f"grading the download exited {code}: {err}")
            s = graded["submissions"][0] if graded else {}
            check(s.get("score") == s.get("max_score") and s.get("max_score", 0) > 0,
                  f"the right answers got {s.get('score')} / {s.get('max_score')}: "
                  + json.dumps([p for p in s.get("problems", []) if p["score"] < p["max_score"]])[:2000])
            # The same answers handed in as the other student.
            submission["student"] = {"id": "s002"}
            as_other = os.path.join(work, "as-s002.json")
            with open(as_other, "w") as f:
                json.dump(submission, f)
            code, graded, err = grade(as_other, "--roster", roster)
            t = graded["submissions"][0] if graded else {}
            check(code == 1 or code == 0, f"grading as s002 exited {code}: {err}")
            check(t.get("score", 0) < s.get("score", 0), f"s002 with s001's answers got {t.get('score')}")
            # The other student's right answers, handed in as the first student.
            theirs_as_mine = os.path.join(work, "s002-answers-as-s001.json")
            with open(theirs_as_mine, "w") as f:
                json.dump({"student": {"id": "s001"}, "answers": theirs}, f)
            code, graded, err = grade(theirs_as_mine, "--roster", roster)
            u = graded["submissions"][0] if graded else {}
            check(u.get("score", 0) < s.get("score", 0),
                  f"s001 with s002's right answers got {u.get('score')} of {u.get('max_score')}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"handout_in_browser: {'FAILED' if failures else 'passed'}; screenshots in {OUT}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
