#!/usr/bin/env python3
"""Seed 001's ray tree answered through the handout's form, in headless Chromium driven by
Selenium, with no JSON typed anywhere; then the same choices through the PrairieLearn question.

The answers are the seed document's own: the ray from (0, 1, 0) along +x meets the glass sphere
(I1), its reflection the mirror ceiling (I2) and that one's reflection the floor (I3); the
refraction leaves the sphere (I4) and meets the back wall (I5). I1 to I3 see the light and need
all three Phong terms; I4 and I5 are in shadow (the sphere blocks I4's shadow ray) and need the
ambient term alone.
1. The student adds the five points with "Add a point", picks where each ray comes from, what it
   meets, its shadow ray toward L and its terms, and downloads answers.json: `raygrade grade
   --assignment` gives 3 of 3.
2. In a fresh browser: I3 (the floor) is left out, and the refraction point's shadow ray is
   marked lit with all three terms. The grade names the missing reflection and the mistake
   diffuse-in-shadow, in the form's own words: the points as the form numbered them, and "its
   shadow ray toward L".
3. The PrairieLearn question of the same assignment, given the same choices as its inputs,
   grades both submissions to the same scores.
The outline of the tree drawn while building is checked too. Screenshots land in OUT.

Usage: tree_form_in_browser.py RAYGRADE ASSIGNMENT OUT
"""
import importlib.util
import json
import os
import pathlib
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

RAYGRADE, ASSIGNMENT, OUT = (os.path.abspath(a) for a in sys.argv[1:4])
PROBLEM = "seed001-ray-tree"
ROSTER = "id,name,email\ns001,Ada Lovelace,ada@example.edu\n"

# The seed's tree, point by point, as the form asks for it: where the ray comes from (the eye,
# or ("R" or "T", the number of an earlier point)), the object it meets, the shadow ray toward
# the one light L (and its blockers when in shadow), and the terms.
ALL = "ambient, diffuse and specular"
RIGHT = [
    {"from": "eye", "object": "glass sphere", "light": "lit", "terms": ALL},
    {"from": ("R", 1), "object": "mirror ceiling", "light": "lit", "terms": ALL},
    {"from": ("R", 2), "object": "floor", "light": "lit", "terms": ALL},
    {"from": ("T", 1), "object": "glass sphere", "light": "shadow", "blockers": ["glass sphere"],
     "terms": "ambient only"},
    {"from": ("T", 4), "object": "back wall", "light": "shadow", "terms": "ambient only"},
]
# Without the floor (the points after it move up one), and the refraction point (now I3)
# said to be lit, with all three terms.
WRONG = [
    RIGHT[0], RIGHT[1],
    {"from": ("T", 1), "object": "glass sphere", "light": "lit", "terms": ALL},
    {"from": ("T", 3), "object": "back wall", "light": "shadow", "terms": "ambient only"},
]
FROM_TEXT = {"R": "the reflection at I{}", "T": "the refraction at I{}"}
LIGHT_TEXT = {"lit": "reaches the light (lit)", "shadow": "is blocked (in shadow)",
              "away": "the surface faces away"}


def run(*args, cwd=None):
    return subprocess.run([RAYGRADE, *args], capture_output=True, text=True, timeout=300, cwd=cwd)


def from_text(point):
    origin = point["from"]
    return "the eye (the primary ray)" if origin == "eye" else FROM_TEXT[origin[0]].format(origin[1])




def choose(driver, el, text):
    driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", el)
    Select(el).select_by_visible_text(text)


def build_tree(driver, points):
    """Adds the points through the form, as a student does, one control at a time."""
    form = driver.find_element(By.CSS_SELECTOR, f"section[data-problem='{PROBLEM}'] .form")
    check(not form.find_elements(By.TAG_NAME, "textarea"), "the ray tree's form has a textarea")
    for k, point in enumerate(points):
        click(driver, form.find_element(By.CSS_SELECTOR, "button.tree-add"))
        row = form.find_elements(By.CSS_SELECTOR, "li.tree-point")[k]
        check(f"I{k + 1}" in row.text, f"the new point is not named I{k + 1}: {row.text[:60]!r}")
        choose(driver, row.find_element(By.CSS_SELECTOR, "select.tree-from"), from_text(point))
        choose(driver, row.find_element(By.CSS_SELECTOR, "select.tree-object"), point["object"])
        choose(driver, row.find_element(By.CSS_SELECTOR, "select.tree-light"), LIGHT_TEXT[point["light"]])
        for name in point.get("blockers", []):
            click(driver, row.find_element(By.CSS_SELECTOR, f"input.tree-blocker[value='{name}']"))
        choose(driver, row.find_element(By.CSS_SELECTOR, "select.tree-terms"), point["terms"])
    return form



def answer_in_browser(page, work, points, shot):
    """Builds the tree in a fresh browser, downloads answers.json; its path and the outline."""
    downloads = os.path.join(work, shot + "-downloads")
    os.makedirs(downloads)
    driver = selenium_chromium(os.path.join(work, shot + "-profile"), downloads)
    try:
        driver.get("file://" + page)
        form = build_tree(driver, points)
        outline = form.find_element(By.CSS_SELECTOR, ".tree-outline").text
        driver.save_screenshot(os.path.join(OUT, shot + ".png"))
        # The tree is kept in the browser: a reload shows the same points and the same tree.
        driver.refresh()
        form = driver.find_element(By.CSS_SELECTOR, f"section[data-problem='{PROBLEM}'] .form")
        check(len(form.find_elements(By.CSS_SELECTOR, "li.tree-point")) == len(points),
              "the points were not kept after a reload")
        check(form.find_element(By.CSS_SELECTOR, ".tree-outline").text == outline,
              "the tree drawn after a reload differs")
        click(driver, driver.find_element(By.ID, "download"))
        return wait_for_file(downloads, "answers.json"), outline
    finally:
        driver.quit()


def grade(submission, workdir):
    r = run("grade", "--assignment", ASSIGNMENT, "--format", "json", "--feedback", "full",
            "--roster", os.path.join(workdir, "roster.csv"), submission, cwd=workdir)
    check(r.returncode == 0, f"grading {submission} exited {r.returncode}: {r.stderr}")
    out = json.loads(r.stdout)
    return out["submissions"][0]["problems"][0]


def pl_inputs(spec, points):
    """The same choices as the PrairieLearn question's inputs: each choice by the key of its
    option (a, b, c ... in the order of question.html), the blockers as typed text."""
    raw = {}
    inputs = {i["name"]: i for i in spec["inputs"]}

    def pick(name, value):
        options = inputs[name]["options"]
        index = next(i for i, o in enumerate(options) if o["value"] == value)
        raw[name] = chr(ord("a") + index)

    for k, point in enumerate(points, 1):
        origin = point["from"]
        pick(f"tree_{k}_from", "eye" if origin == "eye" else f"{origin[0]}:{origin[1]}")
        pick(f"tree_{k}_object", point["object"])
        pick(f"tree_{k}_light_0", point["light"])
        raw[f"tree_{k}_blockers_0"] = ", ".join(point.get("blockers", []))
        terms = {"ambient only": ["ambient"], ALL: ["ambient", "diffuse", "specular"]}[point["terms"]]
        pick(f"tree_{k}_terms", terms)
    return raw


def grade_in_prairielearn(course, points):
    """The question's server.py, as PrairieLearn calls it: parse(), then grade(); the score."""
    qdirs = sorted(pathlib.Path(course, "questions").glob("*/*"))
    qdir = qdirs[0]
    spec = json.loads((qdir / "raygrade.json").read_text(encoding="utf-8"))
    module_spec = importlib.util.spec_from_file_location("tree_form_server", qdir / "server.py")
    server = importlib.util.module_from_spec(module_spec)
    module_spec.loader.exec_module(server)
    data = {"params": {}, "correct_answers": {}, "submitted_answers": pl_inputs(spec, points),
            "format_errors": {}, "partial_scores": {}, "score": 0.0, "feedback": {},
            "variant_seed": 7,
            "options": {"question_path": str(qdir),
                        "server_files_course_path": str(pathlib.Path(course, "serverFilesCourse"))}}
    server.parse(data)
    check(not data["format_errors"], f"PrairieLearn format errors: {data['format_errors']}")
    server.grade(data)
    return data["score"], data.get("feedback", {}).get("raygrade")


def main():
    if not require_chromium():
        return SKIPPED
    if not shutil.which("chromedriver"):
        print("chromedriver is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    os.makedirs(OUT, exist_ok=True)
    work = tempfile.mkdtemp(prefix="raygrade-tree-form-")
    try:
        roster = os.path.join(work, "roster.csv")
        with open(roster, "w") as f:
            f.write(ROSTER)
        handouts = os.path.join(work, "handout")
        r = run("handout", ASSIGNMENT, "--roster", roster, "--out", handouts)
        if not check(r.returncode == 0, f"handout exited {r.returncode}: {r.stderr}"):
            return 1
        page = os.path.join(handouts, "s001", "index.html")
        with open(page, encoding="utf-8") as f:
            html = f.read()
        check("JSON" not in html.split('id="handout-data"')[0],
              "the page asks for JSON before its data")

        # 1. The right tree: full marks.
        right, outline = answer_in_browser(page, work, RIGHT, "tree-form-right")
        if check(right is not None, "answers.json was not downloaded"):
            shutil.copy(right, os.path.join(OUT, "answers-right.json"))
            with open(right) as f:
                nodes = json.load(f)["answers"][PROBLEM]["nodes"]
            check([n["label"] for n in nodes] == ["I1", "I2", "I3", "I4", "I5"],
                  f"labels {[n['label'] for n in nodes]}")
            graded = grade(right, work)
            print(f"right tree: {graded['score']} / {graded['max_score']}")
            check(graded["score"] == 3 and graded["max_score"] == 3,
                  f"the right tree earned {graded['score']} of {graded['max_score']}")
        # The outline shows I2 and I4 under I1, I3 under I2 and I5 under I4.
        lines = [line.strip() for line in outline.splitlines() if line.strip()]
        print("outline:", " | ".join(lines))
        check(any(line.startswith("primary ray → I1: on glass sphere") for line in lines),
              f"the outline has no primary ray to I1: {lines}")
        check(any(line.startswith("refraction → I5: on back wall") for line in lines),
              f"the outline has no refraction to I5: {lines}")

        # 2. The floor left out, the refraction point said to be lit.
        wrong, _ = answer_in_browser(page, work, WRONG, "tree-form-wrong")
        if check(wrong is not None, "the second answers.json was not downloaded"):
            shutil.copy(wrong, os.path.join(OUT, "answers-wrong.json"))
            graded = grade(wrong, work)
            print(f"wrong tree: {graded['score']} / {graded['max_score']}")
            check(graded["score"] < 3, f"the wrong tree earned {graded['score']}")
            feedback = " ".join(line for p in graded["parts"] for line in p.get("feedback", []))
            check("Missing: the point where the reflection ray from I2 meets floor." in feedback,
                  f"the missing floor is not named in the form's words: {feedback}")
            mistakes = {m["id"]: m["message"] for m in graded.get("mistakes", [])}
            check("diffuse-in-shadow" in mistakes, f"no diffuse-in-shadow among {list(mistakes)}")
            said = mistakes.get("diffuse-in-shadow", "")
            check("I3 needs ambient only" in said and "its shadow ray toward L is blocked by glass sphere" in said,
                  f"the mistake does not name the form's I3 and its shadow ray toward L: {said}")
            wrong_score = graded["score"] / graded["max_score"]

        # 3. PrairieLearn: the same choices, the same grades.
        course = os.path.join(work, "course")
        r = run("export", "prairielearn", ASSIGNMENT, "--out", course, "--binary", RAYGRADE)
        if check(r.returncode == 0, f"export prairielearn exited {r.returncode}: {r.stderr}"):
            question = next(pathlib.Path(course, "questions").glob("*/*/question.html")).read_text()
            check("JSON" not in question and "multiline" not in question,
                  "the PrairieLearn question asks for JSON")
            score, _ = grade_in_prairielearn(course, RIGHT)
            print(f"PrairieLearn, right tree: {score}")
            check(score == 1, f"PrairieLearn gives the right tree {score}")
            if wrong is not None:
                score, feedback = grade_in_prairielearn(course, WRONG)
                print(f"PrairieLearn, wrong tree: {score} (raygrade: {wrong_score})")
                check(abs(score - wrong_score) < 1e-9,
                      f"PrairieLearn gives the wrong tree {score}, raygrade {wrong_score}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print(f"{len(failures)} failure(s)")
        return 1
    print("tree_form_in_browser: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
