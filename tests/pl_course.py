"""What the PrairieLearn tests share: an exported course of the example assignment and of a
one-problem assignment answered through the ray tree's inputs, and each question's server.py loaded as a module.

With the environment variable RAYGRADE_PL_SERVER set to a server.py, that file replaces the
exported one in every question (to run the tests against another version of it)."""
import importlib.util
import json
import os
import pathlib
import shutil
import subprocess
import tempfile

# The problem of the example's bank answered as a ray tree, point by point.
TREE_PROBLEM = "seed001-ray-tree"


def short(value, most=200):
    text = repr(value) if not isinstance(value, str) else value
    return text if len(text) <= most else text[:most] + "..."


def export(raygrade, assignment, out):
    """Exports `assignment` into the course folder `out`; raygrade's complaint, or None."""
    proc = subprocess.run([raygrade, "export", "prairielearn", str(assignment), "--out",
                           str(out), "--binary", raygrade], capture_output=True, text=True)
    return None if proc.returncode == 0 else f"export of {assignment} failed: {short(proc.stderr)}"


def tree_assignment(assignment, folder, name):
    """An assignment named `name` of the example's bank with the one ray tree problem,
    written into `folder`."""
    spec = json.loads(pathlib.Path(assignment).read_text(encoding="utf-8"))
    spec.pop("$schema", None)
    spec["assignment"] = name
    spec["bank"] = str((pathlib.Path(assignment).parent / spec["bank"]).resolve())
    spec["problems"] = [{"id": TREE_PROBLEM, "points": 1}]
    path = folder / f"{name}.json"
    path.write_text(json.dumps(spec), encoding="utf-8")
    return path


def export_courses(raygrade, assignment, tmp, name):
    """The two courses (the example, and the ray tree one) in `tmp`; their folders and
    the first complaint of the exports (None when both went through)."""
    courses = [tmp / "course", tmp / "course-tree"]
    fault = export(raygrade, assignment, courses[0]) or \
        export(raygrade, tree_assignment(assignment, tmp, name), courses[1])
    return courses, fault


def load_server(qdir, module_name):
    """The question's server.py (or RAYGRADE_PL_SERVER's file in its place) as a module."""
    replacement = os.environ.get("RAYGRADE_PL_SERVER")
    if replacement:
        shutil.copyfile(replacement, qdir / "server.py")
    spec = importlib.util.spec_from_file_location(module_name, qdir / "server.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class Tally:
    """Checks passed and failed, and the run's report: `N passed, M failed`."""

    def __init__(self):
        self.passed = 0
        self.failures = []

    def check(self, ok, what):
        if ok:
            self.passed += 1
        else:
            self.failures.append(what)
        return ok

    def report(self):
        """Prints every failure and the count; the exit status (1 when any failed)."""
        for f in self.failures:
            print("FAIL:", f)
        print(f"{self.passed} passed, {len(self.failures)} failed")
        return 1 if self.failures else 0


def run_on_courses(raygrade, assignment, name, tally, body):
    """Exports both courses into a temporary folder and calls body(raygrade, courses, tmp) when
    the exports went through (a failed export is a failure); the exit status."""
    raygrade = str(pathlib.Path(raygrade).resolve())
    with tempfile.TemporaryDirectory() as folder:
        tmp = pathlib.Path(folder)
        courses, fault = export_courses(raygrade, assignment, tmp, name)
        if tally.check(fault is None, fault):
            body(raygrade, courses, tmp)
    return tally.report()
