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

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def metadata(email, name):
    return {
        "id": 123456,
        "created_at": "2026-11-30T14:22:32.365935-08:00",
        "assignment": {"due_date": "2026-12-04T23:59:00.000000+00:00", "group_size": None,
                       "group_submission": False, "id": 25828,
                       "late_due_date": None, "outline": [],
                       "release_date": "2026-11-01T00:00:00.000000+00:00",
                       "title": "Homework: rays", "total_points": "21.0"},
        "submission_method": "upload",
        "users": [{"email": email, "id": 1234, "name": name}],
        "previous_submissions": [],
    }


def run_upload(root, files, meta):
    """One run of run_autograder in a fresh submission/ and results/; returns results.json."""
    for d in ("submission", "results"):
        shutil.rmtree(root / d, ignore_errors=True)
        (root / d).mkdir()
    for name, text in files.items():
        (root / "submission" / name).write_text(text, encoding="utf-8")
    (root / "submission_metadata.json").write_text(json.dumps(meta), encoding="utf-8")
    proc = subprocess.run([str(root / "run_autograder")], cwd=root, capture_output=True,
                          text=True, env={"AUTOGRADER_ROOT": str(root), "PATH": "/usr/bin:/bin"},
                          timeout=120)
    check(proc.returncode == 0, f"run_autograder exited with {proc.returncode}: {proc.stderr}")
    return json.loads((root / "results" / "results.json").read_text(encoding="utf-8"))


def check_results(r, what):
    check(set(r) <= TOP_KEYS, f"{what}: undocumented keys {set(r) - TOP_KEYS}")
    check(r.get("output_format") == "text", f"{what}: output_format is not text")
    check(r.get("visibility") in VISIBILITY, f"{what}: visibility {r.get('visibility')}")
    total = 0.0
    for t in r.get("tests", []):
        check(set(t) <= TEST_KEYS, f"{what}: test with undocumented keys {set(t) - TEST_KEYS}")
        check(t.get("output_format") == "text", f"{what}: test {t.get('name')} not text")
        check(t.get("visibility") in VISIBILITY, f"{what}: test visibility {t.get('visibility')}")
        if "score" in t:
            check(0 <= t["score"] <= t["max_score"], f"{what}: {t['name']} score out of range")
            check(t["status"] == ("passed" if t["score"] >= t["max_score"] else "failed"),
                  f"{what}: {t['name']} status {t['status']}")
            total += t["score"]
        else:
            # A test without points is the worked feedback, shown after the due date.
            check(t.get("visibility") == "after_due_date", f"{what}: {t['name']} unscored")
    check(abs(total - r["score"]) < 1e-9, f"{what}: tests add up to {total}, score {r['score']}")


def scored(r):
    return {t["name"].split(":")[0]: t for t in r["tests"] if "score" in t}


def main(raygrade, assignment, static=None):
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        proc = subprocess.run([raygrade, "export", "gradescope", assignment, "--out",
                               str(tmp / "export"), "--binary", static or raygrade],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            sys.exit(f"export failed ({proc.returncode}): {proc.stderr}")
        root = tmp / "autograder"
        with zipfile.ZipFile(tmp / "export" / "autograder.zip") as z:
            names = set(z.namelist())
            for f in ("setup.sh", "run_autograder", "raygrade", "assignment.json"):
                check(f in names, f"autograder.zip lacks {f} at its root")
            z.extractall(root / "source")
        # zipfile drops permissions; Gradescope's unzip keeps them, and setup.sh sets them.
        for f in ("setup.sh", "run_autograder", "raygrade"):
            info = zipfile.ZipFile(tmp / "export" / "autograder.zip").getinfo(f)
            check((info.external_attr >> 16) & 0o111, f"{f} is not executable in the zip")
            (root / "source" / f).chmod(0o755)
        unpacked = sorted(p.relative_to(tmp / "export" / "autograder").as_posix()
                          for p in (tmp / "export" / "autograder").rglob("*") if p.is_file())
        check(unpacked == sorted(names), "the folder and the zip differ")
        proc = subprocess.run(["bash", str(root / "source" / "setup.sh")], capture_output=True,
                              text=True)
        check(proc.returncode == 0, f"setup.sh failed: {proc.stderr}")
        shutil.copy(root / "source" / "run_autograder", root / "run_autograder")

        solved = subprocess.run([raygrade, "solve", assignment, "--student", STUDENT["id"],
                                 "--format", "json"], capture_output=True, text=True, check=True)
        answers = {s["id"]: s["answer"] for s in json.loads(solved.stdout)["solutions"]}
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
        # Before the due date the reflection's full feedback waits for it; a right problem
        # has none to wait for.
        worked = {t["name"].split(":")[0] for t in wrong["tests"] if "score" not in t}
        check(worked <= {"variant-plane", "variant-reflect"}, f"wrong: worked tests {worked}")

        cases = {
            "broken JSON": ({"answers.json": '{"student": '}, meta, "answers.json"),
            "no .json": ({"answers.txt": "t = 3"}, meta, "one file ending in .json"),
            "two .json": ({"a.json": "{}", "b.json": "{}"}, meta, "Upload one"),
            "someone else's": ({"answers.json": json.dumps(
                {"student": STUDENT, "answers": answers})},
                metadata("grace@example.edu", "Grace Hopper"), "not the account"),
            "html in the name": ({"answers.json": json.dumps(
                {"student": {"name": "<b>x</b>", "email": "ada@example.edu"},
                 "answers": {"nope": 1}})}, meta, ""),
        }
        for what, (files, m, says) in cases.items():
            r = run_upload(root, files, m)
            check_results(r, what)
            check(r["score"] == 0, f"{what}: score {r['score']}")
            check(says in r.get("output", ""), f"{what}: output {r.get('output')!r} lacks {says!r}")
    for f in failures:
        print("FAIL:", f)
    print(f"gradescope_autograder: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
