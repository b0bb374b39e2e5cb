#!/usr/bin/env python3
"""PrairieLearn's question tester (a question's "Test" button), run on the exported questions
without PrairieLearn.

`raygrade export prairielearn` writes the example assignment's questions into a temporary folder,
and one more question, the ray tree, answered point by point (the example has none).
For every question, three variant seeds and each test type (correct, incorrect, invalid), this
does what PrairieLearn does:
1. generate(), then the elements' prepare() and prepare(): the variant;
2. the elements' test(), then test(): the raw answers of a test submission and what test()
   expects of it (format errors, partial scores, score);
3. the raw answers submitted: the elements' parse() and parse(), then, when there is no format
   error, the elements' grade() and grade();
4. the comparison PrairieLearn makes: gradable, the keys of the format errors, and for a
   gradable submission the partial scores and the score, exactly.
The input elements play their part as PrairieLearn's pl-string-input and pl-multiple-choice
do (their own prepare, test, parse and grade, for the attributes question.html uses), and the
score is recomputed from the partial scores after the elements of grade and test, as
PrairieLearn does before server.py runs. Each data dictionary crosses to server.py as JSON and is
checked as PrairieLearn checks it: the keys of its phase, of their types, changed only where
the phase may change them.

Beyond what PrairieLearn compares: a correct submission scores 1, an incorrect one below 1, an
invalid one has a format error and no grade; after prepare() every input has a correct answer;
the answer panel stays off; test() raises nothing on odd data.

Usage: prairielearn_tester.py RAYGRADE ASSIGNMENT
With the environment variable RAYGRADE_PL_SERVER set to a server.py, that file replaces the
exported server.py of every question (to test a server.py without exporting it again).
The last line is `N passed, M failed`; the exit status is 1 when M > 0.
"""
import copy
import html.parser
import json
import math
import random
import sys

from pl_course import Tally, load_server, run_on_courses

SEEDS = [7, 1234567, 2**31 - 1]
TEST_TYPES = ["correct", "incorrect", "invalid"]
# The key of correct_answers that holds the choices' answers between generate() and prepare().
CHOICES = "raygrade:choices"

# PrairieLearn's rules for the data of each phase (its check_data): a key's type, the phases
# it is present in, and the phases that may change it.
ALL = {"generate", "prepare", "parse", "grade", "test"}
EDITED = {"generate", "prepare", "parse", "grade"}
PROPS = {
    "params": (dict, ALL, EDITED),
    "correct_answers": (dict, ALL, EDITED),
    "variant_seed": (int, ALL, set()),
    "options": (dict, ALL, set()),
    "submitted_answers": (dict, {"parse", "grade"}, {"parse", "grade"}),
    "format_errors": (dict, {"parse", "grade", "test"}, {"parse", "grade", "test"}),
    "raw_submitted_answers": (dict, {"parse", "grade", "test"}, {"test"}),
    "partial_scores": (dict, {"grade", "test"}, {"grade", "test"}),
    "score": (float, {"grade", "test"}, {"grade", "test"}),
    "feedback": (dict, {"parse", "grade", "test"}, {"parse", "grade", "test"}),
    "gradable": (bool, {"parse", "grade", "test"}, set()),
    "test_type": (str, {"test"}, set()),
    "answers_names": (dict, {"prepare"}, {"prepare"}),
}

TALLY = Tally()
check = TALLY.check


def short(value, most=300):
    text = value if isinstance(value, str) else json.dumps(value, ensure_ascii=False)
    return text if len(text) <= most else text[:most] + "..."


# The question's input elements, as question.html writes them.


class Element:
    def __init__(self, tag, attrs):
        self.tag, self.name = tag, attrs["answers-name"]
        self.attrs = attrs
        self.options = []  # of a pl-multiple-choice: (text, marked correct)

    def flag(self, name, default=False):
        value = self.attrs.get(name)
        return default if value is None else value.lower() in ("true", "1", "")


class Page(html.parser.HTMLParser):
    """The input elements of a question.html, in the page's order."""

    def __init__(self, text):
        super().__init__()
        self.elements, self.answer = [], None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag in ("pl-string-input", "pl-multiple-choice"):
            self.elements.append(Element(tag, attrs))
        elif tag == "pl-answer":
            self.answer = ["", (attrs.get("correct") or "").lower() == "true"]

    def handle_data(self, data):
        if self.answer is not None:
            self.answer[0] += data

    def handle_endtag(self, tag):
        if tag == "pl-answer" and self.answer is not None:
            self.elements[-1].options.append((self.answer[0].strip(), self.answer[1]))
            self.answer = None


# What PrairieLearn's input elements do in each phase, before server.py.


def keys_of(data, element):
    return [o["key"] for o in data["params"][element.name]]


def elements_prepare(page, data):
    """pl-multiple-choice lists its options in params (keys a, b, c in the fixed order) and
    sets its correct answer, refusing one already there."""
    for e in page.elements:
        if e.name in data["answers_names"]:
            raise ValueError(f'Duplicate "answers-name" attribute: "{e.name}"')
        data["answers_names"][e.name] = True
        if e.tag != "pl-multiple-choice":
            continue
        if e.name in data["params"]:
            raise ValueError(f"Duplicate params variable name: {e.name}")
        if e.name in data["correct_answers"]:
            raise ValueError(f"Duplicate correct_answers variable name: {e.name}")
        shown = [{"key": chr(ord("a") + i), "html": text, "feedback": None, "score": None}
                 for i, (text, _) in enumerate(e.options)]
        data["params"][e.name] = shown
        right = [o for o, (_, correct) in zip(shown, e.options) if correct]
        data["correct_answers"][e.name] = right[0] if right else None


def elements_test(page, data, rng):
    """pl-string-input submits its correct answer (plus a number when incorrect; a blank,
    which allow-blank makes correct, when invalid); pl-multiple-choice without builtin grading
    a random option, or the key "0" when invalid."""
    kind = data["test_type"]
    for e in page.elements:
        if e.tag == "pl-multiple-choice" and not e.flag("builtin-grading", True):
            if kind == "invalid":
                data["raw_submitted_answers"][e.name] = "0"
                data["format_errors"][e.name] = "INVALID choice"
            else:
                data["raw_submitted_answers"][e.name] = rng.choice(keys_of(data, e))
            continue
        if e.tag != "pl-string-input":
            continue
        result, right = kind, ""
        if result in ("correct", "incorrect"):
            if e.name not in data["correct_answers"]:
                continue
            right = str(data["correct_answers"][e.name])
        if result == "invalid" and e.flag("allow-blank"):
            result = "correct"
        if result == "correct":
            data["raw_submitted_answers"][e.name] = right
            data["partial_scores"][e.name] = {"score": 1, "weight": 1}
        elif result == "incorrect":
            data["raw_submitted_answers"][e.name] = right + str(
                rng.randint(1, 11) * rng.choice([-1, 1]))
            data["partial_scores"][e.name] = {"score": 0, "weight": 1}
        else:
            data["raw_submitted_answers"][e.name] = ""
            data["format_errors"][e.name] = "invalid"


def elements_parse(page, data):
    """pl-string-input keeps the text (its ends removed) or reports it missing or blank;
    pl-multiple-choice reports a key it does not list."""
    submitted, errors = data["submitted_answers"], data["format_errors"]
    for e in page.elements:
        if e.tag == "pl-string-input":
            text = submitted.get(e.name)
            if text is None:
                errors[e.name] = "No submitted answer."
                submitted[e.name] = None
                continue
            if e.flag("remove-leading-trailing") or e.flag("multiline"):
                text = text.strip()
            text = text.replace("\r\n", "\n")
            if not text and not e.flag("allow-blank"):
                errors[e.name] = "Invalid format. The submitted answer was left blank."
                submitted[e.name] = None
            else:
                submitted[e.name] = text
        else:
            key = submitted.get(e.name, "") or ""
            if key == "" and not e.flag("allow-blank"):
                errors[e.name] = "No answer was submitted."
            elif key != "" and key not in keys_of(data, e):
                errors[e.name] = f"Invalid choice: {key}"


def elements_grade(page, data):
    """pl-string-input scores its text against correct_answers, exactly (its ends removed);
    pl-multiple-choice without builtin grading scores nothing."""
    for e in page.elements:
        right = data["correct_answers"].get(e.name)
        if e.tag != "pl-string-input" or right is None:
            continue
        data["partial_scores"][e.name] = {"score": 0.0, "weight": 1}
        if e.name in data["submitted_answers"]:
            same = str(data["submitted_answers"][e.name]).strip() == str(right).strip()
            data["partial_scores"][e.name]["score"] = 1.0 if same else 0.0


def rescore(data, partial_credit):
    """The score from the partial scores, as PrairieLearn sets it after the elements."""
    values = [v if isinstance(v, dict) else {} for v in data["partial_scores"].values()]
    scores = [(v.get("score", 0), v.get("weight", 1)) for v in values]
    if partial_credit:
        total = sum(w for _, w in scores)
        data["score"] = sum(s * w for s, w in scores) / (total or 1)
    else:
        data["score"] = 1 if scores and all(s >= 1 for s, _ in scores) else 0


# server.py, called as PrairieLearn calls it.


def check_data(before, after, phase):
    """What PrairieLearn finds wrong with the data a server.py function returns; None."""
    extra = set(after) - set(PROPS)
    if extra:
        return f"data has extra keys {sorted(extra)}"
    missing = set(before) - set(after)
    if missing:
        return f"data lost the keys {sorted(missing)}"
    for key, (kind, present, edited) in PROPS.items():
        if phase not in present:
            continue
        value = after.get(key)
        if kind is float:
            ok = isinstance(value, (int, float)) and not isinstance(value, bool) \
                and math.isfinite(value)
        else:
            ok = isinstance(value, kind) and not (kind is int and isinstance(value, bool))
        if not ok:
            return f"data[{key!r}] is not a {kind.__name__}: {short(repr(value))}"
        if phase not in edited and value != before.get(key):
            return f"data[{key!r}] has been illegally modified"
    try:
        json.dumps(after, allow_nan=False)
    except (TypeError, ValueError) as e:
        return f"data is not JSON: {e}"
    return None


def call(label, server, phase, data):
    """server.py's `phase`(data) on the data as JSON, as PrairieLearn passes it; the data after
    (unchanged when server.py has no such function, as in PrairieLearn), or None when it raises
    or leaves data PrairieLearn refuses."""
    data = json.loads(json.dumps(data, allow_nan=False))
    function = getattr(server, phase, None)
    if function is None:
        return data
    before = copy.deepcopy(data)
    try:
        function(data)
    except Exception as e:  # RecursionError too
        check(False, f"{label}: {phase}() raised {type(e).__name__}: {short(str(e))}")
        return None
    fault = check_data(before, data, phase)
    return data if check(fault is None, f"{label}: after {phase}(): {fault}") else None


class Question:
    """One exported question: its folder, page, inputs, server.py and course."""

    def __init__(self, qdir, course, index):
        self.qdir, self.course = qdir, course
        self.name = f"{qdir.parent.name}/{qdir.name}"
        self.spec = json.loads((qdir / "raygrade.json").read_text(encoding="utf-8"))
        self.info = json.loads((qdir / "info.json").read_text(encoding="utf-8"))
        self.page = Page((qdir / "question.html").read_text(encoding="utf-8"))
        self.server = load_server(qdir, f"pl_tester_{index}")
        self.variants = {}

    def options(self):
        return {"question_path": str(self.qdir),
                "server_files_course_path": str(self.course / "serverFilesCourse"),
                "client_files_question_path": str(self.qdir / "clientFilesQuestion")}

    def variant(self, seed):
        """generate() and prepare(): (params, correct_answers), or None; made once a seed."""
        if seed not in self.variants:
            self.variants[seed] = self.make_variant(seed)
        return self.variants[seed]

    def make_variant(self, seed):
        label = f"{self.name} seed {seed}"
        data = {"params": {}, "correct_answers": {}, "variant_seed": seed,
                "options": self.options()}
        data = call(label, self.server, "generate", data)
        if data is None:
            return None
        check_generated(label, self.spec, data["correct_answers"])
        data["answers_names"] = {}
        try:
            elements_prepare(self.page, data)
        except ValueError as e:
            check(False, f"{label}: an element's prepare() refused the variant: {e}")
            return None
        data = call(label, self.server, "prepare", data)
        if data is None:
            return None
        check_prepared(label, self.spec, data)
        return data["params"], data["correct_answers"]

    def expected(self, label, variant, kind, seed):
        """The elements' test() and test(): the data of the expected submission, or None."""
        params, correct = variant
        data = {"params": params, "correct_answers": correct, "format_errors": {},
                "partial_scores": {}, "score": 0, "feedback": {}, "variant_seed": seed,
                "options": self.options(), "raw_submitted_answers": {}, "gradable": True,
                "test_type": kind}
        elements_test(self.page, data, random.Random(seed))
        rescore(data, self.info.get("partialCredit", False))
        data = call(label, self.server, "test", data)
        if data is not None:
            data["gradable"] = not data["format_errors"]
        return data

    def submitted(self, label, variant, raw, seed):
        """The raw answers submitted: parse(), then grade() when gradable; the submission
        (its score None when it is not graded), or None."""
        params, correct = variant
        data = {"params": params, "correct_answers": correct,
                "submitted_answers": copy.deepcopy(raw), "feedback": {}, "format_errors": {},
                "variant_seed": seed, "options": self.options(),
                "raw_submitted_answers": copy.deepcopy(raw), "gradable": True}
        elements_parse(self.page, data)
        data = call(label, self.server, "parse", data)
        if data is None:
            return None
        if data["format_errors"]:
            return {**data, "gradable": False, "partial_scores": None, "score": None}
        data.update(partial_scores={}, score=0)
        elements_grade(self.page, data)
        rescore(data, self.info.get("partialCredit", False))
        data = call(label, self.server, "grade", data)
        if data is not None:
            data["gradable"] = not data["format_errors"]
        return data


def check_generated(label, spec, correct):
    """generate() types the reference into every text input, and keeps every choice's option
    aside (pl-multiple-choice's prepare() refuses a correct answer set before it)."""
    for inp in spec["inputs"]:
        if inp["type"] in ("one-of", "flag"):
            check(inp["name"] not in correct and inp["name"] in correct.get(CHOICES, {}),
                  f"{label}: generate() did not keep the choice {inp['name']} aside")
        else:
            check(isinstance(correct.get(inp["name"]), str),
                  f"{label}: no correct answer typed for {inp['name']}: {short(correct)}")


def check_prepared(label, spec, data):
    """After prepare() every choice's correct answer is one of the options shown, or None."""
    correct = data["correct_answers"]
    check(CHOICES not in correct, f"{label}: prepare() left {CHOICES} in correct_answers")
    for inp in spec["inputs"]:
        if inp["type"] in ("one-of", "flag"):
            option = correct.get(inp["name"])
            check(option is None or option in data["params"][inp["name"]],
                  f"{label}: the correct answer of {inp['name']} is no option: {short(option)}")


def compare(label, expected, got):
    """PrairieLearn's comparison of test()'s expectation with the submission."""
    check(expected["gradable"] == got["gradable"],
          f"{label}: gradable expected {expected['gradable']}, got {got['gradable']} "
          f"(format errors {short(got['format_errors'])})")
    check(sorted(expected["format_errors"]) == sorted(got["format_errors"]),
          f"{label}: format error keys expected {sorted(expected['format_errors'])}, got "
          f"{sorted(got['format_errors'])}")
    if expected["gradable"] and got["gradable"]:
        check(expected["partial_scores"] == got["partial_scores"],
              f"{label}: partial_scores expected {short(expected['partial_scores'])}, got "
              f"{short(got['partial_scores'])}")
        check(expected["score"] == got["score"],
              f"{label}: score expected {expected['score']}, got {got['score']}")


def check_kind(label, kind, got):
    """What each test type must give, whatever test() predicted."""
    if kind == "correct":
        check(got["gradable"] and got["score"] == 1,
              f"{label}: the correct answers scored {got['score']} "
              f"(format errors {short(got['format_errors'])}, feedback {short(got['feedback'])})")
    elif kind == "incorrect":
        check(got["gradable"] and got["score"] is not None and got["score"] < 1,
              f"{label}: the incorrect answers scored {got['score']} "
              f"(format errors {short(got['format_errors'])})")
    else:
        check(not got["gradable"] and got["format_errors"] and not got["score"],
              f"{label}: the invalid answers gave no format error (score {got['score']})")


def run_tests(q):
    check(q.info.get("showCorrectAnswer") is False, f"{q.name}: the answer panel is on")
    for seed in SEEDS:
        variant = q.variant(seed)
        if variant is None:
            continue
        for kind in TEST_TYPES:
            label = f"{q.name} seed {seed} {kind}"
            expected = q.expected(label, variant, kind, seed)
            if expected is None:
                continue
            got = q.submitted(label, variant, expected["raw_submitted_answers"], seed)
            if got is None:
                continue
            compare(label, expected, got)
            check_kind(label, kind, got)


def odd_tests(q, tmp):
    """test() on data PrairieLearn does not send raises nothing and leaves data of the right
    types."""
    variant = q.variant(SEEDS[0])
    if variant is None:
        return
    params, correct = variant
    nowhere = str(tmp / "no-such-folder")
    cases = {
        "test_type missing": {"test_type": None},
        "test_type bogus": {"test_type": "bogus"},
        "no correct answers": {"correct_answers": {}},
        "correct answers of other types": {
            "correct_answers": {i["name"]: [1] for i in q.spec["inputs"]}},
        "no params": {"params": {}},
        "options None": {"options": None},
        "no question folder": {"options": {**q.options(), "question_path": nowhere}},
        "no course folder": {"options": {**q.options(), "server_files_course_path": nowhere}},
    }
    for what, changes in cases.items():
        for kind in (["correct"] if "test_type" in changes else TEST_TYPES):
            data = {"params": copy.deepcopy(params), "correct_answers": copy.deepcopy(correct),
                    "format_errors": {}, "partial_scores": {}, "score": 0, "feedback": {},
                    "variant_seed": SEEDS[0], "options": q.options(),
                    "raw_submitted_answers": {}, "gradable": True, "test_type": kind}
            data.update(changes)
            if data["test_type"] is None:
                del data["test_type"]
            label = f"{q.name} test() with {what}, {data.get('test_type')}"
            try:
                q.server.test(data)
            except Exception as e:
                check(False, f"{label}: raised {type(e).__name__}: {short(str(e))}")
                continue
            types = {"raw_submitted_answers": dict, "format_errors": dict,
                     "partial_scores": dict, "score": (int, float)}
            check(all(isinstance(data.get(k), t) for k, t in types.items()),
                  f"{label}: {short({k: repr(data.get(k)) for k in types})}")


def on_courses(raygrade, courses, tmp):
    folders = [q for c in courses for q in sorted(c.glob("questions/*/*"))]
    check(len(folders) > 1, f"no questions exported: {folders}")
    for index, qdir in enumerate(folders):
        q = Question(qdir, qdir.parent.parent.parent, index)
        run_tests(q)
        odd_tests(q, tmp)


def main(raygrade, assignment):
    return run_on_courses(raygrade, assignment, "tester-tree", TALLY, on_courses)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(*sys.argv[1:]))
