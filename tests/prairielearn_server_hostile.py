#!/usr/bin/env python3
"""The server.py of the PrairieLearn questions against hostile data: whatever a student submits
and whatever shape PrairieLearn's data has, parse() and grade() raise nothing, and generate()
still draws a variant when the seed is odd.

`raygrade export prairielearn` writes the example assignment's questions into a temporary
folder, and one more question, the ray tree, answered point by point. For
every question, its server.py is imported and called with:
- text inputs nested 1,000 brackets deep and of 100 kB: a format error on that input;
- other odd text, and lists, dictionaries, numbers and booleans as submitted values;
- variant seeds that are None, lists, text (digits or not), huge integers, floats, or missing;
- data without (or with a non-dictionary) feedback, partial_scores, format_errors, params or
  submitted_answers;
- options that name no question or no course, and a raygrade that crashes or prints what it
  never prints (so that grade() meets an exception it does not expect).
Each time: no exception escapes; parse() gives a format error or grade() a score of 0; no
message names the temporary folder (the server's folders stand for it).

Usage: prairielearn_server_hostile.py RAYGRADE ASSIGNMENT
With the environment variable RAYGRADE_PL_SERVER set to a server.py, that file replaces the
exported server.py of every question (to test a server.py without exporting it again).
The last line is `N passed, M failed`; the exit status is 1 when M > 0.
"""
import copy
import json
import shutil
import sys
import tempfile

from pl_course import Tally, load_server, run_on_courses, short

# The seed of the ordinary variant that hostile answers are submitted to.
SEED = 7
# Stands for a key left out of the data.
MISSING = object()

# Text each text input must refuse with a format error: too deeply nested, or too long.
REFUSED_TEXT = {
    "1,000 [": "[" * 1000,
    "1,000 (": "(" * 1000,
    "1,000 {": "{" * 1000,
    "100 kB": "1" * (100 * 1024),
    "100 kB of [": "[" * (100 * 1024),
}
# Other values a text or choice input may hold: a format error or a score of 0.
ODD_VALUES = {
    "a list": [1, 2],
    "a dictionary": {"a": 1},
    "an integer": 987654321,
    "a float": -2.5e300,
    "true": True,
    "a lone surrogate": "\ud800",
    "a NUL": "1\x00",
    "JSON NaN": '{"t": NaN}',
    "JSON 1e400": '{"t": 1e400}',
    "unclosed": "(1, 2",
    "closing first": ")]}",
}
# Variant seeds PrairieLearn does not send (it sends an integer).
BAD_SEEDS = {
    "missing": MISSING,
    "None": None,
    "a list": [1, 2],
    "a dictionary": {"seed": 1},
    "text": "abc",
    "empty text": "",
    "decimal text": "123",
    "huge decimal text": "9" * 5000,
    "a huge integer": 10**5000,
    "2**64": 2**64,
    "a negative integer": -5,
    "a float": 1.5,
    "true": True,
}
# Keys of the data that may be missing, or not dictionaries.
DATA_KEYS = ["feedback", "partial_scores", "format_errors", "params", "submitted_answers"]
ODD_CONTAINERS = {"missing": MISSING, "None": None, "a list": ["x"]}

# A stand-in raygrade that misbehaves as its folder's file `mode` says, so that grade() meets
# exceptions it does not expect. Its messages name its folder, a server path.
FAKE_RAYGRADE = r'''
import json, os, sys
here = os.path.dirname(os.path.abspath(__file__))
mode = open(os.path.join(here, "mode")).read().strip()
problem = "?"
if os.path.exists("answers.json"):
    problem = next(iter(json.load(open("answers.json"))["answers"]))
if mode == "crash":
    sys.stderr.write("raygrade: cannot open %s/assignment.json\n" % here)
    sys.exit(134)
out = {
    "not-json": "raygrade: %s is not JSON" % here,
    "no-submissions": {"submissions": []},
    "odd-parts": {"submissions": [{"gradable": True, "problems": [
        {"problem": problem, "parts": 5, "score": 1, "max_score": 1}]}]},
    "null-score": {"submissions": [{"gradable": True, "problems": [
        {"problem": problem, "parts": [], "score": None, "max_score": 1}]}]},
    "path-fault": {"submissions": [{"gradable": False, "fault": {
        "message": "cannot read %s/answers.json" % here}}]},
}[mode]
print(out if isinstance(out, str) else json.dumps(out))
'''
FAKE_MODES = ["crash", "not-json", "no-submissions", "odd-parts", "null-score", "path-fault"]

TALLY = Tally()
check = TALLY.check


def fake_course(folder, mode):
    """A course folder whose raygrade is FAKE_RAYGRADE in `mode`."""
    tools = folder / f"fake-{mode}" / "serverFilesCourse" / "raygrade"
    tools.mkdir(parents=True)
    (tools / "mode").write_text(mode)
    binary = tools / "raygrade"
    binary.write_text(f"#!{sys.executable}\n{FAKE_RAYGRADE}")
    binary.chmod(0o755)
    return tools.parent


class Question:
    """One exported question: its folder, course, server.py module and inputs."""

    def __init__(self, qdir, course, index):
        self.qdir, self.course = qdir, course
        self.name = f"{qdir.parent.name}/{qdir.name}"
        spec = json.loads((qdir / "raygrade.json").read_text(encoding="utf-8"))
        self.inputs = {i["name"]: i["type"] for i in spec["inputs"]}
        self.text_inputs = [n for n, t in self.inputs.items() if t not in ("one-of", "flag")]
        self.server = load_server(qdir, f"pl_hostile_{index}")
        self.params = {}

    def options(self, course=None):
        return {"question_path": str(self.qdir),
                "server_files_course_path": str((course or self.course) / "serverFilesCourse"),
                "client_files_question_path": str(self.qdir / "clientFilesQuestion")}

    def data(self, answers, **changes):
        """The data of a submission of `answers` to the ordinary variant, with `changes`
        (MISSING removes a key)."""
        d = {"params": copy.deepcopy(self.params), "correct_answers": {},
             "submitted_answers": copy.deepcopy(answers),
             "raw_submitted_answers": copy.deepcopy(answers), "format_errors": {},
             "partial_scores": {}, "score": 0.0, "feedback": {}, "gradable": True,
             "variant_seed": SEED, "options": self.options()}
        for key, value in changes.items():
            if value is MISSING:
                d.pop(key, None)
            else:
                d[key] = value
        return d

    def blank(self):
        return {}

    def malformed(self):
        return {n: ("(1" if n in self.text_inputs else "z") for n in self.inputs}


def call(label, function, data):
    """function(data); checks that it raises nothing."""
    try:
        function(data)
    except Exception as e:  # RecursionError too
        return check(False, f"{label}: {function.__name__}() raised {type(e).__name__}: "
                            f"{short(str(e))}")
    return check(True, label)


def strings(value):
    """Every string in `value`, recursively."""
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for v in value.values():
            yield from strings(v)
    elif isinstance(value, list):
        for v in value:
            yield from strings(v)


def check_messages(label, data):
    """What students read names no temporary folder; format errors are short."""
    shown = list(strings([data.get("format_errors"), data.get("feedback"),
                          data.get("partial_scores")]))
    leaked = [s for s in shown if tempfile.gettempdir() in s]
    check(not leaked, f"{label}: a server path shown: {short(leaked)}")
    errors = data.get("format_errors")
    long = [m for m in strings(errors) if len(m) > 500]
    check(not long, f"{label}: a format error of {len(long[0]) if long else 0} characters")


def submit(q, label, answers, must_refuse=None, **changes):
    """parse() on one copy of the data, grade() on another (PrairieLearn may call grade without
    parse): no exception; input `must_refuse`, if any, has a format error; grade scores 0 (every
    answer submitted here is blank or wrong); no path shown."""
    parsed, graded = q.data(answers, **changes), q.data(answers, **changes)
    call(f"{q.name} {label}", q.server.parse, parsed)
    call(f"{q.name} {label}", q.server.grade, graded)
    if must_refuse:
        errors = parsed.get("format_errors")
        check(isinstance(errors, dict) and must_refuse in errors,
              f"{q.name} {label}: no format error on {must_refuse}: {short(errors)}")
    check(graded.get("score") == 0, f"{q.name} {label}: grade() scored {graded.get('score')}")
    check_messages(f"{q.name} {label} (parse)", parsed)
    check_messages(f"{q.name} {label} (grade)", graded)


def draw(q, label, **changes):
    """generate() draws a variant: no exception, a statement."""
    data = {"params": {}, "correct_answers": {}, "variant_seed": SEED, "options": q.options()}
    for key, value in changes.items():
        if value is MISSING:
            data.pop(key, None)
        else:
            data[key] = value
    if call(f"{q.name} generate {label}", q.server.generate, data):
        params = data.get("params")
        check(isinstance(params, dict) and params.get("statement"),
              f"{q.name} generate {label}: no statement")
        return params
    return None


def hostile_inputs(q):
    for name in q.text_inputs:
        for what, text in REFUSED_TEXT.items():
            submit(q, f"{name}={what}", {name: text}, must_refuse=name)
    for name in q.inputs:
        for what, value in ODD_VALUES.items():
            submit(q, f"{name}={what}", {name: value})


def hostile_seeds(q):
    ordinary = draw(q, "seed 123", variant_seed=123)
    for what, seed in BAD_SEEDS.items():
        params = draw(q, f"seed {what}", variant_seed=seed)
        if what == "decimal text" and params and ordinary:
            check(params == ordinary, f"{q.name}: seed '123' drew another variant than 123")
        submit(q, f"seed {what}", q.blank(), variant_seed=seed)


def hostile_data(q):
    for key in DATA_KEYS:
        for what, value in ODD_CONTAINERS.items():
            for answers, kind in ((q.blank(), "blank"), (q.malformed(), "malformed")):
                submit(q, f"{kind}, {key} {what}", answers, **{key: value})
    for what, value in ODD_CONTAINERS.items():
        draw(q, f"params {what}", params=value)


def hostile_options(q, tmp):
    """Options naming no question or no course, and raygrades that misbehave."""
    nowhere = tmp / "no-such-folder"
    cases = {"options missing": MISSING, "options None": None,
             "no question folder": {**q.options(), "question_path": str(nowhere)},
             "no course folder": q.options(nowhere)}
    for what, options in cases.items():
        submit(q, f"blank, {what}", q.blank(), options=options)
        submit(q, f"malformed, {what}", q.malformed(), options=options)
    for mode in FAKE_MODES:
        data = q.data(q.blank(), options=q.options(tmp / f"fake-{mode}"))
        label = f"{q.name} raygrade {mode}"
        call(label, q.server.grade, data)
        check(data.get("score") == 0, f"{label}: score {data.get('score')}")
        lines = (data.get("feedback") or {}).get("raygrade", {}).get("lines")
        check(bool(lines), f"{label}: no feedback")
        check_messages(label, data)


# The input types of raygrade.json as raygrade wrote them before they were the words of its table
# of field types: an older export's question, read by today's server.py.
OLDER_TYPES = {"typed-number": "number", "typed-three": "vector", "typed-formula": "formula",
               "flag": "yesno", "one-of": "choice", "some-of": "set"}


def older_export(q, tmp):
    """The question with an older raygrade.json: server.py says the question must be exported
    again, to the student as one general error and in grade()'s feedback, with no points;
    it never reads an input by a word it does not know."""
    old = tmp / "older" / q.qdir.name
    shutil.copytree(q.qdir, old, dirs_exist_ok=True)
    spec = json.loads((q.qdir / "raygrade.json").read_text(encoding="utf-8"))
    for inp in spec["inputs"]:
        inp["type"] = OLDER_TYPES.get(inp["type"], inp["type"])
    (old / "raygrade.json").write_text(json.dumps(spec), encoding="utf-8")
    options = {**q.options(), "question_path": str(old)}
    label = f"{q.name} older raygrade.json"
    parsed, graded = q.data(q.blank(), options=options), q.data(q.blank(), options=options)
    call(label, q.server.parse, parsed)
    call(label, q.server.grade, graded)
    said = " ".join(strings([parsed.get("format_errors")]))
    check("export" in said and "again" in said,
          f"{label}: parse() does not say to export the question again: {short(said)}")
    lines = " ".join(strings([graded.get("feedback")]))
    check(graded.get("score") == 0 and "export" in lines,
          f"{label}: grade() gives {graded.get('score')} and says {short(lines)}")
    check_messages(label, parsed)


def questions_of(course):
    return sorted(p for p in (course / "questions").glob("*/*") if (p / "server.py").is_file())


def on_courses(raygrade, courses, tmp):
    for mode in FAKE_MODES:
        fake_course(tmp, mode)
    folders = [(qdir, course) for course in courses for qdir in questions_of(course)]
    questions = [Question(qdir, course, i) for i, (qdir, course) in enumerate(folders)]
    check(any("names" in q.inputs.values() for q in questions),
          "no question has the ray tree's inputs")
    for q in questions:
        q.params = draw(q, f"seed {SEED}") or {}
        hostile_inputs(q)
        hostile_seeds(q)
        hostile_data(q)
        hostile_options(q, tmp)
        older_export(q, tmp)


def main(raygrade, assignment):
    return run_on_courses(raygrade, assignment, "hostile-tree", TALLY, on_courses)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
