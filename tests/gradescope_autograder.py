#!/usr/bin/env python3
"""The Gradescope export, run as Gradescope runs it: `raygrade export gradescope` writes the
autograder; its zip is unpacked into source/ of a temporary AUTOGRADER_ROOT, setup.sh runs once,
and run_autograder runs for each upload with submission/ and submission_metadata.json laid out
as Gradescope's documentation describes
(https://gradescope-autograders.readthedocs.io/en/latest/specs/ and
.../submission_metadata/). Each results/results.json must use documented fields only, its test
scores must add up to its score, and right answers must get the assignment's full points.

Usage: gradescope_autograder.py RAYGRADE ASSIGNMENT [STATIC_RAYGRADE]
Without STATIC_RAYGRADE, RAYGRADE itself is shipped (--binary), which runs on this machine.
"""
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile
import zipfile

from checks import check, failures

# Gradescope's autograder specification: the keys of results.json and of each test.
TOP_KEYS = {"score", "execution_time", "output", "output_format", "test_output_format",
            "test_name_format", "visibility", "stdout_visibility", "extra_data", "tests",
            "leaderboard"}
TEST_KEYS = {"score", "max_score", "status", "name", "name_format", "number", "output",
             "output_format", "tags", "visibility", "extra_data"}
VISIBILITY = {"hidden", "after_due_date", "after_published", "visible"}

# homework-rays.json: the points of its ten problems, as the file states them.
POINTS = {"variant-sphere": 3, "variant-plane": 2, "variant-triangle": 3,
          "variant-first-hit": 2, "variant-camera-ray": 2, "variant-reflect": 1,
          "variant-refract": 2, "variant-shade": 3, "scene-first-hit-only": 1,
          "seed000-cylinder-derive-origin": 2}
STUDENT = {"id": "s1042", "name": "Ada Lovelace", "email": "ada@example.edu"}
OTHER = {"id": "s002", "name": "Grace Hopper", "email": "grace@example.edu"}
# The roster the handouts were written from; the autograder ties each account to its id by it.
ROSTER = ("id,name,email\n"
          f"{STUDENT['id']},{STUDENT['name']},{STUDENT['email']}\n"
          f"{OTHER['id']},{OTHER['name']},{OTHER['email']}\n"
          "s003,Alan Turing,alan@example.edu\n")


def metadata(email, name, due="2026-12-04T23:59:00.000000+00:00", extension=None):
    """Gradescope's submission_metadata.json for an upload on 2026-11-30 by one account;
    `extension` is that account's own due date, when it has one."""
    user = {"email": email, "id": 1234, "name": name}
    if extension:
        user["assignment"] = {"due_date": extension}
    return {
        "id": 123456,
        "created_at": "2026-11-30T14:22:32.365935-08:00",
        "assignment": {"due_date": due, "group_size": None,
                       "group_submission": False, "id": 25828,
                       "late_due_date": None, "outline": [],
                       "release_date": "2026-11-01T00:00:00.000000+00:00",
                       "title": "Homework: rays", "total_points": "21.0"},
        "submission_method": "upload",
        "users": [user],
        "previous_submissions": [],
    }


# When the uploads are graded: after the submission (2026-11-30, 14:22 in California), before
# the due date (2026-12-04) unless a test says otherwise.
GRADED_AT = "2026-11-30T22:30:00Z"
AFTER_DUE = "2026-12-05T12:00:00Z"


def run_upload(root, files, meta, now=GRADED_AT):
    """One run of run_autograder in a fresh submission/ and results/, graded at the time `now`
    (RAYGRADE_NOW); returns results.json."""
    for d in ("submission", "results"):
        shutil.rmtree(root / d, ignore_errors=True)
        (root / d).mkdir()
    for name, text in files.items():
        (root / "submission" / name).parent.mkdir(parents=True, exist_ok=True)
        (root / "submission" / name).write_text(text, encoding="utf-8")
    (root / "submission_metadata.json").write_text(json.dumps(meta), encoding="utf-8")
    proc = subprocess.run([str(root / "run_autograder")], cwd=root, capture_output=True,
                          text=True, env={"AUTOGRADER_ROOT": str(root), "PATH": "/usr/bin:/bin",
                                         "RAYGRADE_NOW": now},
                          timeout=120)
    check(proc.returncode == 0, f"run_autograder exited with {proc.returncode}: {proc.stderr}")
    return json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))


def total_shown(r):
    """Whether a student sees their total score in `r`, as Gradescope's specification says
    (docs/specs.md, "Controlling Test Case Visibility"): not while any test waits for a later
    time (after_due_date, after_published); hidden tests, which carry no points, do not count;
    nor when the whole result waits."""
    if r.get("visibility", "visible") != "visible":
        return False
    return not [t for t in r.get("tests", [])
                if t.get("visibility", r.get("visibility", "visible")) in
                ("after_due_date", "after_published")]


def check_results(r, what):
    check(set(r) <= TOP_KEYS, f"{what}: undocumented keys {set(r) - TOP_KEYS}")
    check(r.get("output_format") == "text", f"{what}: output_format is not text")
    check(r.get("visibility") in VISIBILITY, f"{what}: visibility {r.get('visibility')}")
    check(total_shown(r), f"{what}: the student cannot see their total score")
    total = 0.0
    for t in r.get("tests", []):
        check(set(t) <= TEST_KEYS, f"{what}: test with undocumented keys {set(t) - TEST_KEYS}")
        check(t.get("output_format") == "text", f"{what}: test {t.get('name')} not text")
        check(t.get("visibility") in VISIBILITY, f"{what}: test visibility {t.get('visibility')}")
        check("score" in t and "max_score" in t, f"{what}: {t.get('name')} has no points")
        if "score" in t:
            check(0 <= t["score"] <= t["max_score"], f"{what}: {t['name']} score out of range")
            check(t["status"] == ("passed" if t["score"] >= t["max_score"] else "failed"),
                  f"{what}: {t['name']} status {t['status']}")
            total += t["score"]
    check(abs(total - r["score"]) < 1e-9, f"{what}: tests add up to {total}, score {r['score']}")


def scored(r):
    return {t["name"].split(":")[0]: t for t in r["tests"] if "score" in t}


def install(raygrade, assignment, static, tmp, name):
    """Exports the autograder of `assignment` with the roster and lays it out as Gradescope
    does in tmp/name; returns that AUTOGRADER_ROOT."""
    (tmp / "roster.csv").write_text(ROSTER, encoding="utf-8")
    export = tmp / (name + "-export")
    proc = subprocess.run([raygrade, "export", "gradescope", assignment, "--out", str(export),
                           "--binary", static or raygrade, "--roster", str(tmp / "roster.csv")],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"export failed ({proc.returncode}): {proc.stderr}")
    root = tmp / name
    with zipfile.ZipFile(export / "autograder.zip") as z:
        names = set(z.namelist())
        for f in ("setup.sh", "run_autograder", "raygrade", "assignment.json", "roster.csv"):
            check(f in names, f"autograder.zip lacks {f} at its root")
        z.extractall(root / "source")
    # zipfile drops permissions; Gradescope's unzip keeps them, and setup.sh sets them.
    for f in ("setup.sh", "run_autograder", "raygrade"):
        info = zipfile.ZipFile(export / "autograder.zip").getinfo(f)
        check((info.external_attr >> 16) & 0o111, f"{f} is not executable in the zip")
        (root / "source" / f).chmod(0o755)
    unpacked = sorted(p.relative_to(export / "autograder").as_posix()
                      for p in (export / "autograder").rglob("*") if p.is_file())
    check(unpacked == sorted(names), "the folder and the zip differ")
    proc = subprocess.run(["bash", str(root / "source" / "setup.sh")], capture_output=True,
                          text=True)
    check(proc.returncode == 0, f"setup.sh failed: {proc.stderr}")
    shutil.copy(root / "source" / "run_autograder", root / "run_autograder")
    return root


def solve(raygrade, assignment, student):
    solved = subprocess.run([raygrade, "solve", assignment, "--student", student,
                             "--format", "json"], capture_output=True, text=True, check=True)
    return {s["id"]: s["answer"] for s in json.loads(solved.stdout)["solutions"]}


def numbers(answer):
    """The numbers of an answer with a fraction part, as feedback could print them."""
    out = set()
    def walk(x):
        if isinstance(x, bool):
            return
        if isinstance(x, (int, float)):
            if abs(x - round(x)) > 1e-6:
                for d in (2, 3, 4):
                    out.add(f"{x:.{d}f}".rstrip("0"))
            return
        for v in (x.values() if isinstance(x, dict) else x if isinstance(x, list) else []):
            walk(v)
    walk(answer)
    return out


def leaked(r, values):
    """The reference values that any text of results.json shows."""
    import re
    texts = [r.get("output", "")] + [t.get("output", "") for t in r.get("tests", [])]
    found = set()
    for text in texts:
        tokens = set(re.findall(r"-?\d+\.\d+", text))
        found |= {v for v in values if v in tokens}
    return found


def policy_everywhere(raygrade, assignment, static, tmp, policy):
    """The assignment with one feedback policy at all times, as a copy in tmp."""
    a = json.loads(pathlib.Path(assignment).read_text(encoding="utf-8"))
    a["bank"] = str((pathlib.Path(assignment).parent / a["bank"]).resolve())
    a.pop("$schema", None)
    a["feedback"] = policy
    for p in a["problems"]:
        p.pop("feedback", None)
    path = tmp / f"assignment-{policy}.json"
    path.write_text(json.dumps(a), encoding="utf-8")
    return str(path)


def main(raygrade, assignment, static=None):
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        root = install(raygrade, assignment, static, tmp, "autograder")
        answers = solve(raygrade, assignment, STUDENT["id"])
        check(set(answers) == set(POINTS), f"solve gave {sorted(answers)}")
        meta = metadata(STUDENT["email"], STUDENT["name"])

        right = run_upload(root, {"answers.json": json.dumps(
            {"student": STUDENT, "answers": answers})}, meta)
        check_results(right, "right")
        check(all("score" in t for t in right["tests"]), "right: worked tests for right answers")
        check(right["score"] == sum(POINTS.values()), f"right: score {right['score']}")
        tests = scored(right)
        check(set(tests) == set(POINTS), f"right: tests {sorted(tests)}")
        for pid, t in tests.items():
            check(t["max_score"] == POINTS[pid], f"right: {pid} max_score {t['max_score']}")

        wrong_answers = dict(answers)
        del wrong_answers["variant-plane"]
        wrong_answers["variant-reflect"] = {"direction": [1, -1, 0],
                                            "unit_direction": [0.5**0.5, -(0.5**0.5), 0]}
        wrong = run_upload(root, {"my answers.JSON": json.dumps(
            {"student": STUDENT, "answers": wrong_answers})}, meta)
        check_results(wrong, "wrong")
        tests = scored(wrong)
        check(tests["variant-plane"]["score"] == 0, "wrong: the unanswered problem scored")
        check(tests["variant-reflect"]["score"] < 1, "wrong: the wrong reflection got full marks")
        for pid in set(POINTS) - {"variant-plane", "variant-reflect"}:
            check(tests[pid]["score"] == POINTS[pid], f"wrong: {pid}, answered right, lost points")
        # Before the due date the policy (mistakes) shows no reference value; the same upload
        # graded again after it (Regrade All Submissions) gets the after_due policy (full),
        # which does: the check of the policies below can see them.
        wrong_values = set()
        for pid in ("variant-plane", "variant-reflect"):
            wrong_values |= numbers(answers[pid])
        check(not leaked(wrong, wrong_values),
              f"wrong: before the due date, results.json shows {sorted(leaked(wrong, wrong_values))}")
        regraded = run_upload(root, {"my answers.JSON": json.dumps(
            {"student": STUDENT, "answers": wrong_answers})}, meta, now=AFTER_DUE)
        check_results(regraded, "regraded")
        check(regraded["score"] == wrong["score"], "regraded: the score changed")
        check(leaked(regraded, wrong_values), "regraded: the after-due feedback shows no value")

        # A Mac's archive metadata is not an answers file.
        mac = run_upload(root, {"answers.json": json.dumps({"student": STUDENT,
                                                            "answers": answers}),
                                "__MACOSX/._answers.json": "\x00\x05\x16\x07Mac OS X",
                                "._answers.json": "\x00\x05\x16\x07"}, meta)
        check(mac["score"] == sum(POINTS.values()), f"__MACOSX: score {mac['score']}")

        # Another student's answers, under another student's id, uploaded from one's own
        # account: the variant is the account's, so it never scores.
        other = solve(raygrade, assignment, OTHER["id"])
        check(other != answers, "two students got the same numbers")
        cases = {
            "broken JSON": ({"answers.json": '{"student": '}, meta, "answers.json"),
            "no .json": ({"answers.txt": "t = 3"}, meta, "one file ending in .json"),
            "two .json": ({"a.json": "{}", "b.json": "{}"}, meta, "Upload one: the answers.json"),
            "a PDF named .json": ({"answers.json": "%PDF-1.4\n%\xe2\xe3\n"}, meta,
                                  "answers.json"),
            "someone else's": ({"answers.json": json.dumps(
                {"student": STUDENT, "answers": answers})},
                metadata("grace@example.edu", "Grace Hopper"), "not the account"),
            "another's id, one's own email": ({"answers.json": json.dumps(
                {"student": {"id": OTHER["id"], "email": STUDENT["email"]},
                 "answers": other})}, meta, "name different students"),
            "another's id alone": ({"answers.json": json.dumps(
                {"student": {"id": OTHER["id"]}, "answers": other})}, meta, "not the account"),
            "another's whole identity": ({"answers.json": json.dumps(
                {"student": OTHER, "answers": other})}, meta, "not the account"),
            "an account not on the roster": ({"answers.json": json.dumps(
                {"student": STUDENT, "answers": answers})},
                metadata("mallory@example.edu", "Mallory"), "not on the course's roster"),
            "html in the name": ({"answers.json": json.dumps(
                {"student": {"name": "<b>x</b>", "email": "ada@example.edu"},
                 "answers": {"nope": 1}})}, meta, ""),
        }
        for what, (files, m, says) in cases.items():
            r = run_upload(root, files, m)
            check_results(r, what)
            check(r["score"] == 0, f"{what}: score {r['score']}")
            check(says in r.get("output", ""), f"{what}: output {r.get('output')!r} lacks {says!r}")
            check(str(tmp) not in json.dumps(r), f"{what}: results.json shows a server path")

        # No student and no answers file name: the account alone says who it is.
        r = run_upload(root, {"answers.json": json.dumps({"answers": answers})}, meta)
        check(r["score"] == sum(POINTS.values()), f"no student named: score {r['score']}")

        # Gradescope's due date, and a student's extension, decide which policy is in force
        # when the upload is graded (2026-11-30), whatever the assignment file says.
        late = run_upload(root, {"answers.json": json.dumps(
            {"student": STUDENT, "answers": wrong_answers})},
            metadata(STUDENT["email"], STUDENT["name"], due="2026-11-29T23:59:00.000000-08:00"))
        check_results(late, "late")
        check(not [t for t in late["tests"] if t.get("visibility") != "visible"],
              "late: graded after the due date, yet a test waits for it")
        check(leaked(late, wrong_values), "late: the after-due policy (full) shows no value")
        extended = run_upload(root, {"answers.json": json.dumps(
            {"student": STUDENT, "answers": wrong_answers})},
            metadata(STUDENT["email"], STUDENT["name"], due="2026-11-29T23:59:00.000000-08:00",
                     extension="2026-12-10T23:59:00.000000-08:00"))
        check_results(extended, "extended")
        check(not leaked({"tests": [t for t in extended["tests"]
                                    if t.get("visibility") == "visible"]}, wrong_values),
              "extended: reference values shown before the student's own due date")

        # Under a policy that never shows reference values, no output shows one, at any time.
        for policy in ("mistakes", "score"):
            copy = policy_everywhere(raygrade, assignment, static, tmp, policy)
            proot = install(raygrade, copy, static, tmp, "autograder-" + policy)
            r = run_upload(proot, {"answers.json": json.dumps(
                {"student": STUDENT, "answers": wrong_answers})}, meta)
            check_results(r, policy)
            check(not [t for t in r["tests"] if t.get("visibility") != "visible"],
                  f"{policy}: a test shown later")
            check(not leaked(r, wrong_values),
                  f"{policy}: results.json shows {sorted(leaked(r, wrong_values))}")
    print(f"gradescope_autograder: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
