# server.py of a PrairieLearn question written by `raygrade export prairielearn`.
# generate() draws this variant's numbers with raygrade and keeps the reference answer as a
# student types it; parse() turns the inputs into a raygrade answer; grade() grades it with
# raygrade; test() makes the correct, incorrect and invalid submissions of PrairieLearn's question
# tester. Every question of the export has this same file; what differs (the assignment, the
# problem, its inputs) is in raygrade.json beside it.
# raygrade itself and the assignment are in serverFilesCourse/raygrade/ (docs/assignments.md).
#
# Whatever a student types and whatever shape PrairieLearn's data has, parse() and grade() never
# raise: parse() reports what it cannot read as format errors, grade() gives a score of 0 with
# the reason in the feedback; test() never raises either. generate() raises only when the
# question itself cannot run (its files or raygrade missing), since a variant without a statement
# is no question at all.
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
# The key of data["correct_answers"] under which generate() keeps the option of each choice
# until prepare() puts it under the choice's own name: pl-multiple-choice's prepare() runs in
# between and refuses a correct answer already there. No answers-name holds a colon.
CHOICES = "raygrade:choices"
# An input's "type" is the value it takes, in the words of raygrade's table of field types
# (kinds/fields/field_type.h, field_value_word), or "names" for a ray tree's blockers. The
# inputs answered with a pl-multiple-choice:
CHOICE_TYPES = ("one-of", "flag")
THREE_NUMBERS = "typed-three"
SOME_OF = "some-of"


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


# Every input type this server reads; anything else is a raygrade.json of another raygrade.
INPUT_TYPES = CHOICE_TYPES + (THREE_NUMBERS, SOME_OF, "typed-number", "typed-formula", "names")


def _question(data):
    path = os.path.join(_option(data, "question_path"), "raygrade.json")
    with open(path, encoding="utf-8") as f:
        q = json.load(f)
    for inp in q.get("inputs", []):
        if not isinstance(inp, dict) or inp.get("type") not in INPUT_TYPES:
            raise ValueError("this question was exported by another version of raygrade than "
                             "its server.py reads; export the assignment again")
    return q


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
    _set_correct_answers(data, q, s.get("answer"))


def prepare(data):
    """Puts each choice's reference option under the choice's name in correct_answers, as
    pl-multiple-choice lists it (its "key" is what a student picks); None when the reference
    picks no option, as pl-multiple-choice itself sets."""
    correct = data.get("correct_answers")
    if not isinstance(correct, dict) or not isinstance(correct.get(CHOICES), dict):
        return
    for name, index in correct.pop(CHOICES).items():
        correct[name] = _reference_option(data, name, index)


# The reference answer as typed into the inputs: the text a student types into each text input,
# the option of each choice. It is in data["correct_answers"] for PrairieLearn's question tester
# alone: info.json keeps the correct answer panel off, and grade() grades with raygrade.


def _typed(value):
    """A value of raygrade's answer as a student types it: a number with all its digits, text
    as it is, a list (a vector, a set of terms) as its items separated by commas, nothing as
    blank."""
    if value is None:
        return ""
    if isinstance(value, list):
        return ", ".join(_typed(v) for v in value)
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return repr(value)
    return str(value)


def _get(answer, path):
    """The value at `path` in raygrade's answer (as _put() writes it); None when absent."""
    at = answer
    for step in path:
        if isinstance(at, dict) and isinstance(step, str):
            at = at.get(step)
        elif isinstance(at, list) and isinstance(step, int) and 0 <= step < len(at):
            at = at[step]
        else:
            return None
    return at


def _typed_column(q, inp, answer):
    """A column of the hits (t, point ...) as typed: one value per hit, separated by "; ";
    when there is no hit, the input's word for it (none, contained), else blank."""
    hits = answer.get(q.get("hits_key"))
    if not isinstance(hits, list):
        return ""
    if hits:
        return "; ".join(_typed(h.get(inp["column"]) if isinstance(h, dict) else None)
                         for h in hits)
    outcome = "contained" if answer.get("contained") is True else "none"
    words = [w for w, value in inp.get("words", {}).items() if value == outcome]
    return words[0] if words else ""


def _typed_input(q, inp, answer):
    """What a student types into text input `inp` for raygrade's answer `answer`."""
    if inp.get("list"):
        return _typed_column(q, inp, answer)
    return _typed(_get(answer, inp["path"]))


def _option_index(inp, answer):
    """The index of the option of choice `inp` whose value the answer holds (the "none"
    option for an absent value); None when no option has it."""
    value = _get(answer, inp["path"])
    for i, option in enumerate(inp["options"]):
        if option.get("value") == value and type(option.get("value")) is type(value):
            return i
    return None


# The ray tree's inputs (question.html's points I1, I2 ...) hold their choices under TREE until
# _answer() turns them into the answer's nodes.
TREE = "raygrade:tree"
NOTHING = "raygrade:nothing"
TERMS = ("ambient", "diffuse", "specular")
LIGHT_STATUS = {"visible": "lit", "transmitted": "lit", "blocked": "shadow", "behind": "away"}


def _tree_rows(answer):
    """The reference tree as the points of the form: row k is the k-th point of the tree that
    meets an object, its ray from the eye or from another row, each light's shadow ray and its
    blockers, and its terms."""
    # not a part: a node's own key, whether its ray meets an object
    nodes = [n for n in answer.get("nodes", []) if isinstance(n, dict) and n.get("hit", True)]
    row_of = {n.get("label"): str(k + 1) for k, n in enumerate(nodes)}
    rows = {}
    for k, n in enumerate(nodes):
        row = {}
        parent = n.get("parent")
        if parent is None:
            row["from"] = "eye"
        elif parent in row_of:
            row["from"] = ("R:" if n.get("ray") == "reflection" else "T:") + row_of[parent]
        row["object"] = n.get("object")
        for i, light in enumerate(n.get("lights") or []):
            status = LIGHT_STATUS.get(light.get("status"))
            row["light%d" % i] = status
            if status == "shadow":
                row["blockers%d" % i] = list(light.get("blocked_by") or [])
        if isinstance(n.get("terms"), list):
            row["terms"] = [t for t in TERMS if t in n["terms"]]
        rows[str(k + 1)] = row
    return rows


def _tree_nodes(rows):
    """The answer's nodes from the points of the form (labels I1, I2 ... by row); a point whose
    ray comes from nowhere is left out."""
    nodes = []
    for key in sorted(rows, key=lambda r: int(r)):
        row = rows[key]
        origin = row.get("from")
        if not origin:
            continue
        node = {"label": "I" + key}
        if origin == "eye":
            node.update(parent=None, ray="primary")
        else:
            node.update(parent="I" + origin[2:],
                        ray="reflection" if origin[0] == "R" else "refraction")
        if row.get("object") == NOTHING:
            node["object"] = None
        elif row.get("object"):
            node["object"] = row["object"]
        lights = sorted(int(k[5:]) for k in row if k.startswith("light") and row[k])
        statuses = [row["light%d" % i] for i in lights]
        if statuses:
            node["in_shadow"] = "lit" not in statuses and "shadow" in statuses
            if node["in_shadow"]:
                by = []
                for i in lights:
                    if row["light%d" % i] == "shadow":
                        by += [b for b in row.get("blockers%d" % i) or [] if b not in by]
                if by:
                    node["shadowed_by"] = by
        if row.get("terms"):
            node["terms"] = list(row["terms"])
        nodes.append(node)
    return nodes


def _set_correct_answers(data, q, answer):
    """data["correct_answers"][NAME]: the text of each text input for the reference answer;
    the option index of each choice under CHOICES, for prepare(). An input whose reference
    cannot be typed gets none: a variant still works without it."""
    if not isinstance(answer, dict):
        return
    if q.get("tree"):
        answer = {**answer, TREE: _tree_rows(answer)}
    correct = _dict(data, "correct_answers")
    choices = {}
    for inp in q["inputs"]:
        try:
            if inp["type"] in CHOICE_TYPES:
                choices[inp["name"]] = _option_index(inp, answer)
            else:
                correct[inp["name"]] = _typed_input(q, inp, answer)
        except Exception:  # a reference of a shape no input takes: that input has none
            continue
    if choices:
        correct[CHOICES] = choices


def _shown_options(data, name):
    """PrairieLearn's list of the options of choice `name` as shown, or None."""
    params = data.get("params")
    shown = params.get(name) if isinstance(params, dict) else None
    return shown if isinstance(shown, list) else None


def _reference_option(data, name, index):
    """Option `index` of choice `name` as pl-multiple-choice lists it in params, or as
    {"key": a, b, c ...} when PrairieLearn lists none; None for no index."""
    if not isinstance(index, int) or isinstance(index, bool) or index < 0:
        return None
    shown = _shown_options(data, name)
    if shown is None:
        return {"key": chr(ord("a") + index)}
    if index < len(shown) and isinstance(shown[index], dict):
        return dict(shown[index])
    return None


# Reading the inputs: every input is text (or a choice's key), read as raygrade reads answers.


def _split(text, sep, strip=True):
    """Splits at `sep` outside parentheses and brackets; the pieces stripped, or as typed."""
    pieces, depth, start = [], 0, 0
    for i, c in enumerate(text):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == sep and depth == 0:
            pieces.append(text[start:i])
            start = i + 1
    pieces.append(text[start:])
    return [p.strip() for p in pieces] if strip else pieces


# The spaces raygrade itself skips around a typed number; any other character (a no-break
# space, a byte-order mark, a line break) is left for raygrade to refuse, as the page refuses it.
SPACES = " \t"


def _vector(text):
    """The three numbers of a vector typed into one input, each as typed: raygrade reads them
    (the grader's reader decides what each means; nothing is cleaned here)."""
    text = text.strip(SPACES)
    if not text:
        return ["", "", ""]
    if text[0] + text[-1] in ("()", "[]") and len(_split(text[1:-1], ",", False)) == 3:
        text = text[1:-1]
    parts = _split(text, ",", False)
    if len(parts) != 3 or not all(p.strip(SPACES) for p in parts):
        raise ValueError("a vector is three numbers separated by commas, like (1, 0, -2.5)")
    return parts


def _submitted(data):
    answers = data.get("submitted_answers")
    return answers if isinstance(answers, dict) else {}


def _depth(text):
    """The deepest nesting of (), [] and {} in `text`."""
    depth = deepest = 0
    for c in text:
        if c in "([{":
            depth += 1
            deepest = max(deepest, depth)
        elif c in ")]}":
            depth -= 1
    return deepest


def _text(data, name):
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
    if _depth(value) > MAX_DEPTH:
        raise ValueError("brackets are nested more than %d deep" % MAX_DEPTH)
    # Blank is no answer; anything else goes to raygrade as typed, as the handout page saves it.
    return value if value.strip() else ""


def _choice(data, inp):
    """The value of the option chosen, or None when nothing is chosen."""
    key = _submitted(data).get(inp["name"])
    if key is None or key == "":
        return None
    if not isinstance(key, str):
        raise ValueError("not one of the options")
    shown = _shown_options(data, inp["name"])
    if shown is not None:  # PrairieLearn's own list of the options as shown
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
    if kind in CHOICE_TYPES:
        chosen = _choice(data, inp)
        if chosen is not None:
            _put(answer, inp["path"], chosen["value"])
        return
    text = _text(data, name)
    if inp.get("list"):
        items = [] if not text else _split(text, ";", False)
        word = items[0].strip().lower() if len(items) == 1 else None
        if word in inp.get("words", {}):
            hits["word"] = inp["words"][word]
            return
        if any(not item.strip(SPACES) for item in items):
            raise ValueError("an empty value between two semicolons")
        hits[inp["column"]] = [_vector(i) if kind == THREE_NUMBERS else i for i in items]
        blanks[inp["column"]] = ["", "", ""] if kind == THREE_NUMBERS else ""
    elif kind == THREE_NUMBERS:
        _put(answer, inp["path"], _vector(text))
    elif kind == SOME_OF:
        if text:
            _put(answer, inp["path"], [w.strip().lower() for w in _split(text, ",")])
    elif kind == "names":  # object names, as they are written
        if text:
            _put(answer, inp["path"], [w for w in _split(text, ",") if w])
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
    rows = answer.pop(TREE, None)
    if isinstance(rows, dict):
        nodes = _tree_nodes(rows)
        if nodes:
            answer["nodes"] = nodes
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
        # not a part: the file's mode
        with open(os.path.join(folder, "answers.json"), "w", encoding="utf-8") as f:
            json.dump(submission, f)
        out = _raygrade(data, q, ["grade", "--assignment", "ASSIGNMENT", "--format", "json",
                                  "answers.json"], cwd=folder)
    g = out["submissions"][0]
    if not g.get("gradable", False):
        raise RuntimeError(g.get("fault", {}).get("message", "raygrade could not read the answer"))
    return next(p for p in g["problems"] if p["problem"] == q["problem"])


def _outcome(data, q, answer):
    """What grade() sets for the readable answer `answer`: the partial scores (one per part
    raygrade grades), the score and the feedback. raygrade failing or timing out, or giving
    what it never gives, is no points and the reason."""
    try:
        result = _grade_with_raygrade(data, q, answer)
        partial, parts = {}, []
        for part in result["parts"]:
            most = part["max_points"]
            text = _without_folders(" ".join(part["feedback"]), data)
            status = part["status"]
            if most > 0:
                partial[part["name"]] = {"score": part["points"] / most, "feedback": text}
            else:
                # A part that carries no points was not asked: no score badge, no verdict.
                status = "not counted"
            parts.append({"name": part["name"], "status": status, "feedback": text})
        most = result["max_score"]
        score = result["score"] / most if most > 0 else 0.0
        mistakes = ["%s: %s" % (m["id"], m["message"]) for m in result.get("mistakes", [])]
        lines = [_without_folders(line, data) for line in mistakes + result.get("notes", [])]
        return partial, score, {"parts": parts, "lines": lines}
    except Exception as e:
        return {}, 0.0, {"lines": ["The answer could not be graded: %s" % _message(e, data)]}


def grade(data):
    try:
        q = _question(data)
        answer, errors = _answer(data, q)
        if errors:
            # parse() has set them already when PrairieLearn called it; a grade without it
            # still says what could not be read, and gives no points.
            format_errors = _dict(data, "format_errors")
            for name, message in errors.items():
                format_errors.setdefault(name, message)
            partial, score, feedback = {}, 0.0, None
        else:
            partial, score, feedback = _outcome(data, q, answer)
    except Exception as e:
        # The question cannot be read, or the data is not what PrairieLearn sends: no points,
        # and the reason.
        partial, score = {}, 0.0
        feedback = {"lines": ["The answer could not be graded: %s" % _message(e, data)]}
    # raygrade's parts alone: pl-string-input has already scored each input against
    # correct_answers by its exact text ("2" against "2.0"), which is no grade of ours.
    data["partial_scores"] = partial
    data["score"] = score
    if feedback is not None:
        _dict(data, "feedback")["raygrade"] = feedback


# PrairieLearn's question tester: test() gives the raw answers of a submission of
# data["test_type"] ("correct", "incorrect" or "invalid") and what parse() and grade() must then
# give (the format errors, the partial scores and the score); PrairieLearn submits the raw
# answers and compares.

# Text that parse() refuses, by the kind of input: a vector of two numbers, an empty value between
# two semicolons, and for any other text brackets nested deeper than MAX_DEPTH.
UNREADABLE_VECTOR = "1, 2"
UNREADABLE_LIST = "1;;2"
UNREADABLE_TEXT = "(" * (MAX_DEPTH + 1) + "1" + ")" * (MAX_DEPTH + 1)
# A key no choice has, as pl-multiple-choice's own test() submits.
UNREADABLE_CHOICE = "0"


def test(data):
    try:
        raw, errors, partial, score = _test(data)
    except Exception as e:
        # No submission can be made (the question cannot be read): parse() reports the one
        # general error, and nothing is graded.
        raw, partial, score = {}, {}, 0.0
        errors = {GENERAL_ERROR: "The answer could not be read: %s" % _message(e, data)}
    data["raw_submitted_answers"] = raw
    data["format_errors"] = errors
    data["partial_scores"] = partial
    data["score"] = score


def _test(data):
    """The raw answers of the test submission, and its format errors, partial scores and
    score as predicted. Any test type other than incorrect and invalid is a correct one."""
    q = _question(data)
    correct = _correct_inputs(data, q)
    kind = data.get("test_type")
    if kind == "invalid":
        made = _invalid(q, correct)
        if made is not None:
            raw, name = made
            _, errors = _answer(_submitting(data, raw), q)
            return raw, {name: errors.get(name, "Could not read this.")}, {}, 0.0
        kind = "correct"  # no input at all: no submission is invalid
    if kind == "incorrect":
        found = _incorrect(data, q, correct)
        if found is not None:
            raw, partial, score = found
            return raw, {}, partial, score
    # The reference answer earns full points on every part raygrade grades (the parts and
    # their feedback are the ones raygrade gives it).
    partial, _ = _predicted(data, q, correct) or ({}, 0.0)
    return correct, {}, {name: {**p, "score": 1.0} for name, p in partial.items()}, 1.0


def _submitting(data, raw):
    """The data as parse() sees a submission of the raw answers `raw` (every input element
    passes the text on, its ends removed)."""
    submitted = {name: v.strip() if isinstance(v, str) else v for name, v in raw.items()}
    return {**data, "submitted_answers": submitted}


def _predicted(data, q, raw):
    """(partial scores, score) that grade() gives raw answers `raw`; None when parse() finds
    a format error in them (PrairieLearn then grades nothing) or raygrade fails on them."""
    answer, errors = _answer(_submitting(data, raw), q)
    if errors:
        return None
    partial, score, feedback = _outcome(data, q, answer)
    return (partial, score) if "parts" in feedback else None


def _correct_inputs(data, q):
    """The raw answer of every input for the reference answer: correct_answers' text, or
    the key of the reference option; blank for an input without a correct answer."""
    correct = data.get("correct_answers")
    correct = correct if isinstance(correct, dict) else {}
    held = correct.get(CHOICES) if isinstance(correct.get(CHOICES), dict) else {}
    raw = {}
    for inp in q["inputs"]:
        name = inp["name"]
        value = correct.get(name)
        if inp["type"] in CHOICE_TYPES:
            if name in held:  # prepare() has not run
                value = _reference_option(data, name, held[name])
            key = value.get("key") if isinstance(value, dict) else None
            raw[name] = key if isinstance(key, str) else ""
        else:
            raw[name] = value if isinstance(value, str) else ""
    return raw


def _invalid(q, correct):
    """The correct raw answers with one input made unreadable, and that input's name: a vector
    if there is one, else a list of hits, JSON, any other text, a choice; None when there is
    no input."""
    def first(wanted):
        return next((i for i in q["inputs"] if wanted(i)), None)
    inp = (first(lambda i: i["type"] == THREE_NUMBERS) or first(lambda i: i.get("list"))
           or first(lambda i: i["type"] not in CHOICE_TYPES) or first(lambda i: True))
    if inp is None:
        return None
    if inp["type"] == THREE_NUMBERS:
        text = UNREADABLE_VECTOR
    elif inp.get("list"):
        text = UNREADABLE_LIST
    elif inp["type"] in CHOICE_TYPES:
        text = UNREADABLE_CHOICE
    else:
        text = UNREADABLE_TEXT
    return {**correct, inp["name"]: text}, inp["name"]


def _incorrect(data, q, correct):
    """The first wrong answer of _wrong_answers() that raygrade grades below full points: its
    raw answers, partial scores and score; None when every one earns them all."""
    for raw in _wrong_answers(data, q, correct):
        predicted = _predicted(data, q, raw)
        if predicted is not None and predicted[1] < 1:
            return (raw, *predicted)
    return None


def _wrong_answers(data, q, correct):
    """The correct raw answers with one input's value changed as a student gets it wrong,
    each input in turn (those whose reference is blank are left as they are)."""
    for inp in q["inputs"]:
        for text in _wrong_values(data, inp, correct[inp["name"]]):
            yield {**correct, inp["name"]: text}


def _wrong_values(data, inp, text):
    """Wrong values of input `inp`, whose right value is `text`: another option; another
    number; a vector turned around; a term left out; the ray tree with an item left out, or
    empty. No value for a text input whose reference is blank."""
    kind = inp["type"]
    if kind in CHOICE_TYPES:
        shown = _shown_options(data, inp["name"])
        keys = ([o.get("key") for o in shown if isinstance(o, dict)] if shown is not None
                else [chr(ord("a") + i) for i in range(len(inp["options"]))])
        return [k for k in keys if isinstance(k, str) and k != text][:1]
    if not text:
        return []
    if inp.get("list"):
        items = _split(text, ";")
        words = inp.get("words", {})
        if len(items) == 1 and items[0].lower() in words:
            return [w for w in words if w != items[0].lower()][:1]
        wrong = _wrong_vector(items[0]) if kind == THREE_NUMBERS else _wrong_number(items[0])
        return ["; ".join([wrong] + items[1:])]
    if kind == THREE_NUMBERS:
        return [_wrong_vector(text)]
    if kind in (SOME_OF, "names"):
        terms = _split(text, ",")
        return [", ".join(terms[1:])] if len(terms) > 1 else []
    return [_wrong_number(text)]


def _wrong_number(text):
    """A number that differs from `text` by at least 1 and by at least its size; an expression
    or a formula, plus 1."""
    try:
        x = float(text)
    except ValueError:
        x = math.nan
    if not math.isfinite(x):
        return "%s + 1" % text
    return repr(x + max(1.0, abs(x)))


def _wrong_vector(text):
    """The vector `text` turned around (1, 1, 1 for the zero vector)."""
    try:
        parts = [float(p) for p in _vector(text)]
    except ValueError:
        return "-(%s)" % text
    if not any(parts):
        return "1, 1, 1"
    return ", ".join(repr(-p) for p in parts)
