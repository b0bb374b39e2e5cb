# server.py of a PrairieLearn question written by `raygrade export prairielearn`.
# generate() draws this variant's numbers with raygrade; parse() turns the inputs into a raygrade
# answer; grade() grades it with raygrade. Every question of the export has this same file; what
# differs (the assignment, the problem, its inputs) is in raygrade.json beside it.
# raygrade itself and the assignment are in serverFilesCourse/raygrade/ (docs/assignments.md).
import copy
import json
import os
import subprocess
import tempfile

# Seconds raygrade may take to draw or grade one variant (it takes a few milliseconds).
TIMEOUT = 20


def _question(data):
    path = os.path.join(data["options"]["question_path"], "raygrade.json")
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _raygrade(data, q, args, cwd=None):
    """Runs raygrade with `args` in folder `cwd`, ASSIGNMENT standing for the question's
    assignment; its standard output as JSON, or raises. Exit code 2 (some input rejected) still
    gives the JSON report, whose fault says what is wrong."""
    root = os.path.abspath(os.path.join(data["options"]["server_files_course_path"], "raygrade"))
    binary = os.path.join(root, "raygrade")
    assignment = os.path.join(root, q["assignment"], "assignment.json")
    args = [assignment if a == "ASSIGNMENT" else a for a in args]
    proc = subprocess.run([binary] + args, capture_output=True, text=True, timeout=TIMEOUT,
                          check=False, cwd=cwd)
    if proc.returncode not in (0, 1, 2) or not proc.stdout:
        raise RuntimeError("raygrade exited with status %d: %s" % (proc.returncode, proc.stderr))
    return json.loads(proc.stdout)


def _student(data):
    # PrairieLearn's variant seed stands for the student: the same seed, the same numbers.
    return "prairielearn-%d" % int(data["variant_seed"])


def generate(data):
    q = _question(data)
    out = _raygrade(data, q, ["solve", "ASSIGNMENT", "--student", _student(data), "--format", "json"])
    found = [s for s in out.get("solutions", []) if s.get("id") == q["problem"]]
    if not found:
        raise RuntimeError("raygrade gave no variant of %s: %s" % (q["problem"], out))
    s = found[0]
    data["params"]["title"] = s["title"]
    data["params"]["statement"] = s["statement"]
    data["params"]["values"] = s.get("parameters", {})


# Reading the inputs: every input is text (or a choice's key), read as raygrade reads answers.


def _split(text, sep):
    """Splits at `sep` outside parentheses and brackets; stripped pieces."""
    pieces, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == sep and depth == 0:
            pieces.append(text[start:i].strip())
            start = i + 1
    pieces.append(text[start:].strip())
    return pieces


def _vector(text):
    text = text.strip()
    if not text:
        return ["", "", ""]
    if text[0] + text[-1] in ("()", "[]") and len(_split(text[1:-1], ",")) == 3:
        text = text[1:-1]
    parts = _split(text, ",")
    if len(parts) != 3 or not all(parts):
        raise ValueError("a vector is three numbers separated by commas, like (1, 0, -2.5)")
    return parts


def _text(data, name):
    value = data["submitted_answers"].get(name)
    return "" if value is None else str(value).strip()


def _choice(data, inp):
    """The value of the option chosen, or None when nothing is chosen."""
    key = data["submitted_answers"].get(inp["name"])
    if key is None or key == "":
        return None
    shown = data["params"].get(inp["name"])
    if isinstance(shown, list):  # PrairieLearn's own list of the options as shown
        for i, option in enumerate(shown):
            if isinstance(option, dict) and option.get("key") == key:
                key = chr(ord("a") + i)
    index = ord(str(key)[:1] or "?") - ord("a")
    if len(str(key)) != 1 or not 0 <= index < len(inp["options"]):
        raise ValueError("not one of the options")
    return {"value": inp["options"][index]["value"]}


def _put(answer, path, value):
    at = answer
    for step in path[:-1]:
        at = at.setdefault(step, {}) if isinstance(step, str) else at[step]
    at[path[-1]] = value


def _answer(data, q):
    """The raygrade answer of the inputs, and the format errors by input name."""
    answer = copy.deepcopy(q["blank"])
    errors = {}
    hits = {}  # column -> its values, one per hit; "word": none or contained
    blanks = {}  # column -> its blank, for a hit whose column has fewer values
    for inp in q["inputs"]:
        name, kind = inp["name"], inp["type"]
        try:
            if kind in ("choice", "yesno"):
                chosen = _choice(data, inp)
                if chosen is not None:
                    _put(answer, inp["path"], chosen["value"])
                continue
            text = _text(data, name)
            if inp.get("list"):
                items = [] if not text else _split(text, ";")
                if len(items) == 1 and items[0].lower() in inp.get("words", {}):
                    hits["word"] = inp["words"][items[0].lower()]
                    continue
                if any(not item for item in items):
                    raise ValueError("an empty value between two semicolons")
                hits[inp["column"]] = [_vector(i) if kind == "vector" else i for i in items]
                blanks[inp["column"]] = ["", "", ""] if kind == "vector" else ""
            elif kind == "vector":
                _put(answer, inp["path"], _vector(text))
            elif kind == "set":
                if text:
                    _put(answer, inp["path"], [w.strip().lower() for w in _split(text, ",")])
            elif kind == "json":
                if text:
                    value = json.loads(text)
                    if not isinstance(value, dict):
                        raise ValueError("the answer is a JSON object, {...}")
                    answer.update(value)
            else:
                _put(answer, inp["path"], text)
        except ValueError as e:
            errors[name] = "Could not read this: %s." % e
    if "hits_key" in q:
        rows = max([len(v) for k, v in hits.items() if k != "word"] + [0])
        word = hits.get("word")
        if word is not None:
            answer[q["hits_key"]] = []
            if word == "contained":
                answer["contained"] = True
        elif rows:
            answer[q["hits_key"]] = [
                {k: (v[i] if i < len(v) else blanks[k]) for k, v in hits.items()}
                for i in range(rows)
            ]
        else:
            answer.pop(q["hits_key"], None)
    return answer, errors


def parse(data):
    q = _question(data)
    _, errors = _answer(data, q)
    for name, message in errors.items():
        data["format_errors"].setdefault(name, message)


def _grade_with_raygrade(data, q, answer):
    submission = {"student": {"id": _student(data)}, "answers": {q["problem"]: answer}}
    with tempfile.TemporaryDirectory() as folder:
        # Run in the folder, so that a message about the file names "answers.json" alone.
        with open(os.path.join(folder, "answers.json"), "w", encoding="utf-8") as f:
            json.dump(submission, f)
        out = _raygrade(data, q, ["grade", "--assignment", "ASSIGNMENT", "--format", "json",
                                  "answers.json"], cwd=folder)
    g = out["submissions"][0]
    if not g.get("gradable", False):
        raise RuntimeError(g.get("fault", {}).get("message", "raygrade could not read the answer"))
    return next(p for p in g["problems"] if p["problem"] == q["problem"])


def grade(data):
    q = _question(data)
    answer, errors = _answer(data, q)
    if errors:
        # parse() has set them already when PrairieLearn called it; a grade without it still
        # says what could not be read, and gives no points.
        for name, message in errors.items():
            data["format_errors"].setdefault(name, message)
        data["score"] = 0.0
        return
    try:
        result = _grade_with_raygrade(data, q, answer)
    except (RuntimeError, OSError, ValueError, KeyError, StopIteration,
            subprocess.TimeoutExpired) as e:
        data["score"] = 0.0
        data["feedback"]["raygrade"] = {"lines": ["The answer could not be graded: %s" % e]}
        return
    parts = []
    for part in result["parts"]:
        most = part["max_points"]
        score = part["points"] / most if most > 0 else (1.0 if part["status"] == "right" else 0.0)
        text = " ".join(part["feedback"])
        data["partial_scores"][part["name"]] = {"score": score, "feedback": text}
        parts.append({"name": part["name"], "status": part["status"], "feedback": text})
    most = result["max_score"]
    data["score"] = result["score"] / most if most > 0 else 0.0
    mistakes = ["%s: %s" % (m["id"], m["message"]) for m in result.get("mistakes", [])]
    data["feedback"]["raygrade"] = {"parts": parts, "lines": mistakes + result.get("notes", [])}
