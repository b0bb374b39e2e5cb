# server.py of a PrairieLearn question written by `raygrade export prairielearn`.
# generate() draws this variant's numbers with raygrade; parse() turns the inputs into a raygrade
# answer; grade() grades it with raygrade. Every question of the export has this same file; what
# differs (the assignment, the problem, its inputs) is in raygrade.json beside it.
# raygrade itself and the assignment are in serverFilesCourse/raygrade/ (docs/assignments.md).
#
# Whatever a student types and whatever shape PrairieLearn's data has, parse() and grade() never
# raise: parse() reports what it cannot read as format errors, grade() gives a score of 0 with
# the reason in the feedback. generate() raises only when the question itself cannot run (its
# files or raygrade missing), since a variant without a statement is no question at all.
# No message shown to students names a folder of the server.
import copy
import json
import math
import os
import re
import subprocess
import tempfile

# Seconds raygrade may take to draw or grade one variant (it takes a few milliseconds).
TIMEOUT = 20
# The longest text an input may hold, in characters, and the deepest nesting of brackets and
# braces in it: longer or deeper text is a format error, given to neither Python's json (which
# recurses once per bracket) nor raygrade.
MAX_TEXT = 100_000
MAX_DEPTH = 64
# The student of every variant whose seed is neither an integer nor decimal digits (PrairieLearn
# always gives an integer): such variants all have the same numbers.
INVALID_SEED_STUDENT = "prairielearn-invalid-seed"
# Seeds are reduced modulo this, so that a seed of any size is a short student key.
SEED_MODULUS = 2**63
# The format error under which parse() reports a failure that is no one input's.
GENERAL_ERROR = "raygrade"
# The longest error message shown, in characters (raygrade's standard error may be long).
MAX_MESSAGE = 400


def _dict(data, key):
    """data[key], made an empty dictionary first when it is missing or not a dictionary."""
    if not isinstance(data.get(key), dict):
        data[key] = {}
    return data[key]


def _option(data, key):
    options = data.get("options")
    value = options.get(key) if isinstance(options, dict) else None
    if not isinstance(value, str) or not value:
        raise RuntimeError("PrairieLearn gave no options.%s" % key)
    return value


def _question(data):
    path = os.path.join(_option(data, "question_path"), "raygrade.json")
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _raygrade(data, q, args, cwd=None):
    """Runs raygrade with `args` in folder `cwd`, ASSIGNMENT standing for the question's
    assignment; its standard output as JSON, or raises. Exit code 2 (some input rejected) still
    gives the JSON report, whose fault says what is wrong."""
    root = os.path.abspath(os.path.join(_option(data, "server_files_course_path"), "raygrade"))
    binary = os.path.join(root, "raygrade")
    assignment = os.path.join(root, q["assignment"], "assignment.json")
    args = [assignment if a == "ASSIGNMENT" else a for a in args]
    proc = subprocess.run([binary] + args, capture_output=True, text=True, timeout=TIMEOUT,
                          check=False, cwd=cwd)
    if proc.returncode not in (0, 1, 2) or not proc.stdout:
        raise RuntimeError("raygrade exited with status %d: %s" % (proc.returncode, proc.stderr))
    return json.loads(proc.stdout)


# Messages: no folder of the server in what students read.

# An absolute path of two or more parts (not a fraction such as 1/2, nor a/b/c).
_PATH = re.compile(r"(?<![\w./])(?:/[^\s'\"/:;,()\[\]{}<>]+){2,}/?")


def _folders(data):
    """The server's folders a message may name: PrairieLearn's paths, the course's folder, and
    the temporary folder, each also as its real path; the longest first."""
    found = {tempfile.gettempdir()}
    options = data.get("options")
    if isinstance(options, dict):
        paths = [v for v in options.values() if isinstance(v, str) and os.path.isabs(v)]
        found.update(paths + [os.path.dirname(p.rstrip("/")) for p in paths])
    found.update([os.path.realpath(f) for f in found])
    return sorted((f.rstrip("/") for f in found if len(f.rstrip("/")) > 1), key=len, reverse=True)


def _without_folders(text, data):
    """`text` with each server folder, and the path below it, replaced by the path's last part."""
    for folder in _folders(data):
        below = re.compile(re.escape(folder) + r"(?:/[^\s'\"]*)?")
        text = below.sub(lambda m: os.path.basename(m.group().rstrip("/")), text)
    return text


def _message(error, data):
    """An error as students may read it: without paths of the server (a file named by its base
    name), short, and never empty."""
    text = _without_folders(str(error), data)
    text = _PATH.sub(lambda m: os.path.basename(m.group().rstrip("/")), text).strip()
    if len(text) > MAX_MESSAGE:
        text = text[:MAX_MESSAGE] + "..."
    return text or type(error).__name__


# The variant.


def _student(data):
    """The student key of the variant: PrairieLearn's variant seed stands for the student (the
    same seed, the same numbers). An integer (not a bool), or a string of decimal digits,
    reduced modulo SEED_MODULUS (a seed PrairieLearn gives is below it, so it stays as it is);
    any other seed (missing, None, a float, a list, other text) gives INVALID_SEED_STUDENT."""
    seed = data.get("variant_seed")
    if isinstance(seed, str):
        seed = _digits_modulo(seed.strip())
    if isinstance(seed, int) and not isinstance(seed, bool):
        return "prairielearn-%d" % (seed % SEED_MODULUS)
    return INVALID_SEED_STUDENT


def _digits_modulo(text):
    """The number that the decimal digits `text` write, modulo SEED_MODULUS; None for other
    text. Read a chunk at a time: int() refuses more than 4,300 digits at once."""
    if not text or not (text.isascii() and text.isdigit()):
        return None
    number = 0
    for start in range(0, len(text), 1000):
        chunk = text[start:start + 1000]
        number = (number * 10 ** len(chunk) + int(chunk)) % SEED_MODULUS
    return number


def generate(data):
    q = _question(data)
    out = _raygrade(data, q, ["solve", "ASSIGNMENT", "--student", _student(data), "--format", "json"])
    found = [s for s in out.get("solutions", []) if s.get("id") == q["problem"]]
    if not found:
        raise RuntimeError("raygrade gave no variant of %s: %s" % (q["problem"], out))
    s = found[0]
    params = _dict(data, "params")
    params["title"] = s["title"]
    params["statement"] = s["statement"]
    params["values"] = s.get("parameters", {})


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


def _submitted(data):
    answers = data.get("submitted_answers")
    return answers if isinstance(answers, dict) else {}


def _depth(text, json_strings):
    """The deepest nesting of (), [] and {} in `text`; with `json_strings`, brackets inside a
    JSON string do not count."""
    depth = deepest = 0
    in_string = escaped = False
    for c in text:
        if in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
        elif c == '"' and json_strings:
            in_string = True
        elif c in "([{":
            depth += 1
            deepest = max(deepest, depth)
        elif c in ")]}":
            depth -= 1
    return deepest


def _text(data, name, json_strings=False):
    """The text typed into input `name` (a number PrairieLearn has read already as its text);
    ValueError when it is not text, or too long or too deeply nested to read safely."""
    value = _submitted(data).get(name)
    if value is None:
        return ""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = str(value)
    if not isinstance(value, str):
        raise ValueError("the answer is text typed into the box")
    if len(value) > MAX_TEXT:
        raise ValueError("the answer is longer than %d characters" % MAX_TEXT)
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise ValueError("the answer holds a character that is not text") from None
    if _depth(value, json_strings) > MAX_DEPTH:
        raise ValueError("brackets are nested more than %d deep" % MAX_DEPTH)
    return value.strip()


def _json_constant(name):
    raise ValueError("%s is not a number an answer may hold" % name)


def _json_number(text):
    value = float(text)
    if not math.isfinite(value):
        raise ValueError("a number is too large")
    return value


def _json_integer(text):
    if len(text) > 300:  # beyond any double, and int() refuses over 4,300 digits
        raise ValueError("a number is too large")
    return int(text)


def _json_object(text):
    """The JSON object `text` holds, its numbers finite."""
    try:
        value = json.loads(text, parse_constant=_json_constant, parse_float=_json_number,
                           parse_int=_json_integer)
    except json.JSONDecodeError as e:
        raise ValueError("this is not JSON (%s at line %d, column %d)"
                         % (e.msg, e.lineno, e.colno)) from None
    if not isinstance(value, dict):
        raise ValueError("the answer is a JSON object, {...}")
    return value


def _choice(data, inp):
    """The value of the option chosen, or None when nothing is chosen."""
    key = _submitted(data).get(inp["name"])
    if key is None or key == "":
        return None
    if not isinstance(key, str):
        raise ValueError("not one of the options")
    params = data.get("params")
    shown = params.get(inp["name"]) if isinstance(params, dict) else None
    if isinstance(shown, list):  # PrairieLearn's own list of the options as shown
        for i, option in enumerate(shown):
            if isinstance(option, dict) and option.get("key") == key:
                key = chr(ord("a") + i)
    index = ord(key[:1]) - ord("a")
    if len(key) != 1 or not 0 <= index < len(inp["options"]):
        raise ValueError("not one of the options")
    return {"value": inp["options"][index]["value"]}


def _put(answer, path, value):
    at = answer
    for step in path[:-1]:
        at = at.setdefault(step, {}) if isinstance(step, str) else at[step]
    at[path[-1]] = value


def _read_input(data, inp, answer, hits, blanks):
    """Puts input `inp`'s value into the answer, or for a column of hits into `hits` (and its
    blank into `blanks`); ValueError when it cannot be read."""
    name, kind = inp["name"], inp["type"]
    if kind in ("choice", "yesno"):
        chosen = _choice(data, inp)
        if chosen is not None:
            _put(answer, inp["path"], chosen["value"])
        return
    text = _text(data, name, json_strings=kind == "json")
    if inp.get("list"):
        items = [] if not text else _split(text, ";")
        if len(items) == 1 and items[0].lower() in inp.get("words", {}):
            hits["word"] = inp["words"][items[0].lower()]
            return
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
            answer.update(_json_object(text))
    else:
        _put(answer, inp["path"], text)


def _answer(data, q):
    """The raygrade answer of the inputs, and the format errors by input name."""
    answer = copy.deepcopy(q["blank"])
    errors = {}
    hits = {}  # column -> its values, one per hit; "word": none or contained
    blanks = {}  # column -> its blank, for a hit whose column has fewer values
    for inp in q["inputs"]:
        try:
            _read_input(data, inp, answer, hits, blanks)
        except ValueError as e:
            errors[inp["name"]] = "Could not read this: %s." % _message(e, data)
        except RecursionError:
            errors[inp["name"]] = "Could not read this: it is nested too deeply."
        except Exception as e:  # whatever else the input does: still a format error
            errors[inp["name"]] = "Could not read this (%s)." % _message(e, data)
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
    try:
        _, errors = _answer(data, _question(data))
    except Exception as e:
        # A question that cannot be read, or data PrairieLearn does not send: one general error,
        # so that PrairieLearn grades nothing.
        errors = {GENERAL_ERROR: "The answer could not be read: %s" % _message(e, data)}
    format_errors = _dict(data, "format_errors")
    for name, message in errors.items():
        format_errors.setdefault(name, message)


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
    try:
        _grade(data)
    except Exception as e:
        # raygrade failed or timed out, or the data is not what PrairieLearn sends: no points,
        # and the reason.
        data["score"] = 0.0
        _dict(data, "feedback")["raygrade"] = {
            "lines": ["The answer could not be graded: %s" % _message(e, data)]}


def _grade(data):
    q = _question(data)
    answer, errors = _answer(data, q)
    if errors:
        # parse() has set them already when PrairieLearn called it; a grade without it still
        # says what could not be read, and gives no points.
        format_errors = _dict(data, "format_errors")
        for name, message in errors.items():
            format_errors.setdefault(name, message)
        data["score"] = 0.0
        return
    result = _grade_with_raygrade(data, q, answer)
    # Everything is read before data changes, so that a failure leaves no half-set scores.
    partial, parts = {}, []
    for part in result["parts"]:
        most = part["max_points"]
        score = part["points"] / most if most > 0 else (1.0 if part["status"] == "right" else 0.0)
        text = _without_folders(" ".join(part["feedback"]), data)
        partial[part["name"]] = {"score": score, "feedback": text}
        parts.append({"name": part["name"], "status": part["status"], "feedback": text})
    most = result["max_score"]
    score = result["score"] / most if most > 0 else 0.0
    mistakes = ["%s: %s" % (m["id"], m["message"]) for m in result.get("mistakes", [])]
    lines = [_without_folders(line, data) for line in mistakes + result.get("notes", [])]
    _dict(data, "partial_scores").update(partial)
    data["score"] = score
    _dict(data, "feedback")["raygrade"] = {"parts": parts, "lines": lines}
