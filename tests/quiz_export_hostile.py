#!/usr/bin/env python3
"""The Canvas and Moodle quiz exports of a hostile bank, read with the platforms' own rules.

Usage: quiz_export_hostile.py RAYGRADE

The bank's one problem (a plane y = h met by a ray from (x0, 0, 1) along (0, dy, 0), so
t = h/dy, worked by hand) names its parameters `answer` (h), `e1` (dy) and `s1` (x0): the names
raygrade gives the reference answer, the statement's expressions and the worked solution's
steps. Its statement holds the platforms' own delimiters as text (`[answer]` and `[e1]` for
Canvas; `{answer}`, `{s1}` and `{=1+1}` for Moodle, written `{{...}}` in raygrade's template),
and a second problem misses in some sets (ox = 6), so some questions lack a set. The assignment
is exported as written, and again with characters XML 1.0 forbids (U+0001, BEL, U+FFFF) and a
bidi override in its title and the problem's. Each export is written for 8 sets, then:

- every file is well-formed XML, by xmllint (libxml2) and by Python's parser;
- the export says on standard error that characters were dropped or replaced (only the second),
  and how many sets of `sometimes` have no hit (QuizProblem::lost, shown with the other notes);
- no two variables of a question (Canvas: vars/var, and the vars of each var_set; Moodle:
  dataset_definitions) share a name;
- the question text of each set, with the platform's substitution applied as the platform
  applies it, reads as the statement with that set's numbers and the delimiters as written:
  * Canvas (Quizzes::Quiz#generate_submission_question in instructure/canvas-lms): for each
    variable of the set, every "[name]" of the stored HTML replaced by the value;
  * Moodle (qtype_calculated_variable_substituter::replace_expressions_in_text in
    moodle/moodle): every "{=...}" evaluated, then every "{name}" of a dataset replaced by the
    item's value; the text is then shown as HTML (entities decoded);
- the question's formula (Canvas: formulas/formula; Moodle: the answer's text, one wildcard) is
  a variable whose value in each set is h/dy of that set's numbers as the statement shows them.
"""
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, failures  # noqa: E402

QTI = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"

BANK = {"problems": [{
    "id": "clash",
    "title": "Names and delimiters",
    "statement": "Literal [answer], [e1] and {{answer}}, {{s1}}, {{=1+1}}. A ray starts at "
                 "({s1}, 0, 1) with direction (0, {e1}, 0). Where does it meet the plane "
                 "y = {answer}? Twice the height is {2*answer}.",
    "parameters": {"answer": {"integer": [2, 9], "default": 5},
                   "e1": {"choices": [1, 2, 4], "default": 2},
                   "s1": {"integer": [-3, 3], "default": 1}},
    "ray": {"origin": ["=s1", 0, 1], "direction": [0, "=e1", 0]},
    "object": {"type": "plane", "point": [0, "=answer", 0], "normal": [0, 1, 0]}},
    # The ray from (ox, 0, 0) along +z meets the sphere of radius 5 at (0, 0, 10) where
    # ox = 0 or 3, and misses it where ox = 6: a set without the hits' numbers.
    {"id": "sometimes",
     "statement": "A ray starts at ({ox}, 0, 0) with direction (0, 0, 1). Where does it meet the "
                  "sphere of radius 5 centred at (0, 0, 10)?",
     "parameters": {"ox": {"choices": [0, 3, 6], "default": 0}},
     "ray": {"origin": ["=ox", 0, 0], "direction": [0, 0, 1]},
     "object": {"type": "sphere", "center": [0, 0, 10], "radius": 5}}]}
ASSIGNMENT = {"assignment": "hostile", "title": "Names and delimiters", "bank": "bank.json",
              "variants": {"per_student": True, "seed": 7}, "problems": ["clash", "sometimes"]}
# The same with characters XML 1.0 forbids in the titles (U+0001, BEL, U+FFFF) and a bidi
# override: exported once more, and checked the same way.
CONTROLS = {"title": "Names\u0001 and\u0007 delimiters \uffff \u202eevil",
            "assignment": "Bell\u0007 and \u0001 title"}

# What the statement reads as with a set's numbers x0, dy, h (the delimiters as text).
STATEMENT = re.compile(
    r"^Literal \[answer\], \[e1\] and \{answer\}, \{s1\}, \{=1\+1\}\. A ray starts at "
    r"\((-?[0-9.]+), 0, 1\) with direction \(0, (-?[0-9.]+), 0\)\. Where does it meet the plane "
    r"y = (-?[0-9.]+)\? Twice the height is (-?[0-9.]+)\.$")


def well_formed(path):
    r = subprocess.run(["xmllint", "--noout", path], capture_output=True, text=True, errors="replace")
    check(r.returncode == 0, f"xmllint: {path} is not well-formed: {r.stderr.strip()}")
    try:
        return ET.parse(path)
    except ET.ParseError as e:
        check(False, f"Python's XML parser: {path}: {e}")
        return None


def text_of(fragment):
    """The text a browser shows of an HTML fragment: tags dropped, entities decoded."""
    return html.unescape(re.sub(r"<[^>]*>", "", fragment))


def first_paragraph(fragment):
    return fragment.split("</p>")[0].removeprefix("<p>")


def read_statement(shown, where):
    m = STATEMENT.match(shown)
    if not check(m is not None, f"{where}: the statement reads {shown!r}"):
        return None
    x0, dy, h, twice = (float(g) for g in m.groups())
    check(twice == 2 * h, f"{where}: twice the height is {twice}, h is {h}")
    return x0, dy, h


def unique(names, where):
    check(len(names) == len(set(names)), f"{where}: variables share a name: {sorted(names)}")


def lost_sets(summary, platform):
    """The sets of `sometimes` where the ray misses have no hit: the export says so (a
    QuizProblem's `lost`, shown with its other notes)."""
    m = re.search(r"the nearest hit \(smallest t\)\)?[^;]*: (\d+) of the (\d+) sets have no such "
                  r"number", summary) or re.search(r": (\d+) of the (\d+) sets have no such number",
                                                   summary)
    check(m is not None and 0 < int(m.group(1)) < int(m.group(2)) and "sometimes" in summary,
          f"export {platform} does not say which sets have no hit:\n{summary}")


def export(raygrade, work, assignment, controls, platform):
    """Exports the assignment for the platform (8 sets) and checks the command's exit, whether it
    says characters were dropped, and that it says which sets have no hit; the output folder."""
    out = os.path.join(work, platform + "-" + assignment)
    r = subprocess.run([raygrade, "export", platform, os.path.join(work, assignment), "--sets", "8",
                        "--out", out], capture_output=True, text=True, errors="replace")
    check(r.returncode == 0, f"export {platform}: exit {r.returncode}: {r.stderr}")
    check(("dropped or replaced" in r.stderr) == controls,
          f"export {platform} of {assignment} says wrongly whether characters were dropped:\n{r.stderr}")
    lost_sets(r.stderr, platform)
    return out


def canvas(raygrade, work, assignment, controls):
    out = export(raygrade, work, assignment, controls, "canvas")
    unpacked = os.path.join(work, "canvas-unpacked-" + assignment)
    with zipfile.ZipFile(os.path.join(out, "hostile-canvas-qti.zip")) as z:
        z.extractall(unpacked)
    trees = {}
    for root, _, files in os.walk(unpacked):
        for name in files:
            trees[name] = well_formed(os.path.join(root, name))
    qti = [t for n, t in trees.items() if n != "imsmanifest.xml"]
    if not check(len(qti) == 1 and qti[0] is not None, f"the package holds {sorted(trees)}"):
        return
    items = [i for i in qti[0].iter(QTI + "item") if i.get("ident").startswith("clash")]
    check(len(items) >= 1, "no Canvas item of the problem clash")
    sets_seen = 0
    for item in items:
        ident = item.get("ident")
        title = item.get("title")
        check(all(ord(c) >= 0x20 and c not in "\ufffe\uffff\u202e" for c in title),
              f"{ident}: the title keeps a forbidden character: {title!r}")
        text = item.find(f"{QTI}presentation/{QTI}material/{QTI}mattext").text
        calc = item.find(f"{QTI}itemproc_extension/{QTI}calculated")
        formula = calc.find(f"{QTI}formulas/{QTI}formula").text.strip()
        names = [v.get("name") for v in calc.find(f"{QTI}vars")]
        unique(names, f"Canvas {ident}")
        check(formula in names, f"Canvas {ident}: the formula {formula!r} is no variable")
        for vs in calc.find(f"{QTI}var_sets"):
            values = [(v.get("name"), v.text) for v in vs.findall(f"{QTI}var")]
            unique([n for n, _ in values], f"Canvas {ident} {vs.get('ident')}")
            shown = text
            for name, value in values:
                shown = re.sub(r"\[" + re.escape(name) + r"\]", lambda _: value, shown)
            where = f"Canvas {ident} {vs.get('ident')}"
            got = read_statement(text_of(first_paragraph(shown)), where)
            if got is None or not re.search(r"[-_]t$", ident):
                continue
            sets_seen += 1
            x0, dy, h = got
            answer = float(dict(values)[formula])
            check(abs(answer - h / dy) <= 1e-12 * abs(h / dy),
                  f"{where}: the formula's value {answer}, h/dy = {h}/{dy}")
            check(float(vs.find(f"{QTI}answer").text) == answer, f"{where}: answer differs")
    check(sets_seen > 1, f"only {sets_seen} Canvas sets of t read")


def moodle_substitute(text, items):
    """Moodle's replace_expressions_in_text: {=...} formulas, then {name} wildcards."""
    def formula(m):
        expr = m.group(1)
        for name, value in items.items():
            expr = expr.replace("{" + name + "}", value)
        return "EVALUATED"
    text = re.sub(r"\{=([^{}]*(?:\{[^{}]+}[^{}]*)*)}", formula, text)
    for name, value in items.items():
        text = text.replace("{" + name + "}", value)
    return text


def moodle(raygrade, work, assignment, controls):
    out = export(raygrade, work, assignment, controls, "moodle")
    tree = well_formed(os.path.join(out, "hostile-moodle.xml"))
    if tree is None:
        return
    questions = [q for q in tree.getroot() if q.get("type") == "calculated" and
                 q.find("idnumber").text.startswith("clash")]
    check(len(questions) >= 1, "no Moodle question of the problem clash")
    sets_seen = 0
    for q in questions:
        ident = q.find("idnumber").text
        name = q.find("name/text").text
        check(all(ord(c) >= 0x20 and c not in "\ufffe\uffff\u202e" for c in name),
              f"{ident}: the name keeps a forbidden character: {name!r}")
        datasets = {}
        names = []
        for d in q.find("dataset_definitions"):
            n = d.find("name/text").text
            names.append(n)
            datasets[n] = {i.find("number").text: i.find("value").text
                           for i in d.find("dataset_items")}
        unique(names, f"Moodle {ident}")
        wildcard = q.find("answer/text").text.strip()
        m = re.fullmatch(r"\{([A-Za-z][A-Za-z0-9_]*)\}", wildcard)
        if not check(m and m.group(1) in datasets, f"Moodle {ident}: the answer is {wildcard!r}"):
            continue
        text = q.find("questiontext/text").text
        feedback = q.find("generalfeedback/text").text
        for number in sorted(datasets[m.group(1)], key=int):
            items = {n: d[number] for n, d in datasets.items()}
            where = f"Moodle {ident} item {number}"
            got = read_statement(text_of(first_paragraph(moodle_substitute(text, items))), where)
            shown = moodle_substitute(feedback, items)
            check("{" not in shown.replace("&#123;", ""),
                  f"{where}: the feedback keeps a wildcard: {shown!r}")
            if got is None or not re.search(r"[-_]t$", ident):
                continue
            sets_seen += 1
            x0, dy, h = got
            answer = float(items[m.group(1)])
            check(abs(answer - h / dy) <= 1e-12 * abs(h / dy),
                  f"{where}: the answer's value {answer}, h/dy = {h}/{dy}")
    check(sets_seen > 1, f"only {sets_seen} Moodle items of t read")


def main():
    raygrade = os.path.abspath(sys.argv[1])
    if not shutil.which("xmllint"):
        print("xmllint is missing (libxml2-utils; scripts/install-deps.sh installs it)")
        return 1
    work = tempfile.mkdtemp(prefix="raygrade-quiz-hostile-")
    try:
        with open(os.path.join(work, "bank.json"), "w", encoding="utf-8") as f:
            json.dump(BANK, f)
        with open(os.path.join(work, "a.json"), "w", encoding="utf-8") as f:
            json.dump(ASSIGNMENT, f)
        bank = json.loads(json.dumps(BANK))
        bank["problems"][0]["title"] = CONTROLS["title"]
        with open(os.path.join(work, "controls-bank.json"), "w", encoding="utf-8") as f:
            json.dump(bank, f)
        with open(os.path.join(work, "controls.json"), "w", encoding="utf-8") as f:
            json.dump(dict(ASSIGNMENT, title=CONTROLS["assignment"], bank="controls-bank.json"), f)
        for assignment, controls in (("a.json", False), ("controls.json", True)):
            canvas(raygrade, work, assignment, controls)
            moodle(raygrade, work, assignment, controls)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"{len(failures)} failures" if failures else "quiz exports of a hostile bank: ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
