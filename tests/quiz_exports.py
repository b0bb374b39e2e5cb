#!/usr/bin/env python3
"""The Canvas and Moodle quiz exports, checked as the platforms read them.

Usage: quiz_exports.py RAYGRADE REPO

Exports assignments/homework-rays.json for the three students of assignments/roster.csv, then:
- validates the Canvas QTI files against the IMS QTI 1.2 ASI and IMS Content Packaging 1.1
  schemas with xmllint, where the schemas are (RAYGRADE_SCHEMAS, default REPO/../shared/schemas;
  without them, the files are only checked for well-formedness, and the test says so);
- reads each question the way Canvas's QTI importer and Moodle's XML importer do (the elements
  they read, by name) and, for every variable set or dataset item, checks that
  * the statement with the set's values put in is the statement `raygrade solve --student`
    gives that student (so the numbers shown are the numbers solved),
  * the answer is that student's reference answer (to 1e-12, relative),
  * the tolerance is the problem's: raygrade's default relative 0.1% for a number of its own,
    and the absolute 1e-6 + 0.1% of the vector's length for a component (the same in every
    set, as for unit normals, or the strictest of the sets);
- checks the Moodle file's worked solution (general feedback) uses only datasets it defines;
- checks that each export's summary names what the questions cannot carry.
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zipfile

from checks import check, failures

QTI = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True)


def parameter_text(v):
    # What a statement prints for a value: 2, 0.25, -1.5 (raygrade's parameter_text).
    if float(v).is_integer():
        return str(int(v))
    return repr(float(v))


def fill(template, values, brackets):
    open_, close = brackets
    return re.sub(re.escape(open_) + r"([A-Za-z_][A-Za-z0-9_]*)" + re.escape(close),
                  lambda m: parameter_text(values[m.group(1)]), template)


def statement_of(html):
    # The first paragraph is the statement, HTML-escaped.
    first = html.split("</p>")[0].removeprefix("<p>")
    return first.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", '"') \
        .replace("&#39;", "'").replace("&amp;", "&")


def expected_tolerance(problem, pointer, answers):
    """The problem's tolerance, from the bank's JSON and raygrade's documented rules
    (docs/grading.md): a problem with "precision" k and no "tolerance" is graded to k decimal
    places (half a unit of the last one, with a 2% margin); otherwise relative 0.1% plus 1e-6
    absolute, a vector's components relative to the vector's length."""
    if "tolerance" in problem:
        raise SystemExit(f"{problem['id']}: a tolerance of its own, which this test does not read")
    if "precision" in problem:
        return ("absolute", 0.51 * 10.0 ** -problem["precision"])
    parts = pointer.strip("/").split("/")
    if parts[-1].isdigit():
        lengths = [math.sqrt(sum(c * c for c in v)) for v in answers["vectors"]]
        allowed = [1e-6 + 1e-3 * n for n in lengths]
        return ("absolute", min(allowed))
    return ("relative", 1e-3)


def at_pointer(doc, pointer):
    for key in pointer.strip("/").split("/"):
        if isinstance(doc, list):
            key = int(key)
            if key >= len(doc):
                return None
        elif key not in doc:
            return None
        doc = doc[key]
    return doc


def main():
    raygrade, repo = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    assignment = os.path.join(repo, "assignments", "homework-rays.json")
    roster = os.path.join(repo, "assignments", "roster.csv")
    schemas = os.environ.get("RAYGRADE_SCHEMAS", os.path.join(repo, "..", "shared", "schemas"))
    work = tempfile.mkdtemp(prefix="raygrade-quiz-")
    try:
        exports = [run(raygrade, "export", platform, assignment, "--roster", roster, "--out",
                       f"{work}/{platform}") for platform in ("canvas", "moodle")]
        # The summary on standard error names what the questions cannot carry, each once, with
        # the problems it concerns.
        for r in exports:
            summary = r.stderr
            for lost in ["not carried: named-mistake feedback: the platform grades each number "
                         "alone (every problem asked)",
                         "not carried: raygrade takes the hits in any order, the quiz asks them "
                         "in order of t (variant-sphere"]:
                check(summary.count(lost) == 1, f"{r.args[2]}'s summary does not say once "
                      f"{lost!r}:\n{summary}")

        bank = {}
        for root, _, files in os.walk(os.path.join(repo, "problems")):
            for name in files:
                if name.endswith(".json"):
                    with open(os.path.join(root, name)) as f:
                        doc = json.load(f)
                    for p in doc.get("problems", [doc]) if isinstance(doc, dict) else []:
                        if isinstance(p, dict) and "id" in p:
                            bank[p["id"]] = p
        solved = {}
        with open(roster, newline="") as f:
            students = [row["id"] for row in csv.DictReader(f)]
        check(len(students) == 3, f"the roster has {len(students)} students, not 3")
        for s in students:
            out = run(raygrade, "solve", assignment, "--student", s, "--format", "json").stdout
            solved[s] = {p["id"]: p for p in json.loads(out)["solutions"]}

        # Canvas: unpack the zip as Canvas's importer does, and validate.
        unpacked = work + "/canvas-unpacked"
        with zipfile.ZipFile(work + "/canvas/homework-rays-canvas-qti.zip") as z:
            z.extractall(unpacked)
        manifest = os.path.join(unpacked, "imsmanifest.xml")
        tree = ET.parse(manifest)
        hrefs = [r.get("href") for r in tree.iter("{http://www.imsglobal.org/xsd/imscp_v1p1}resource")
                 if r.get("type") == "imsqti_xmlv1p2"]
        check(len(hrefs) == 1, f"the manifest lists {len(hrefs)} QTI resources")
        qti = os.path.join(unpacked, hrefs[0])
        validations = [(os.path.join(schemas, "imscp", "imscp_v1p1.xsd"), manifest),
                       (os.path.join(schemas, "qti12", "ims_qtiasiv1p2p1_local.xsd"), qti)]
        for xsd, doc in validations:
            if os.path.exists(xsd):
                r = subprocess.run(["xmllint", "--noout", "--nonet", "--schema", xsd, doc],
                                   capture_output=True, text=True)
                print(f"xmllint --schema {os.path.relpath(xsd, schemas)} {os.path.basename(doc)}:",
                      r.stderr.strip())
                check(r.returncode == 0, f"{doc} does not validate against {xsd}")
            else:
                print(f"NOTE: {xsd} not found: {os.path.basename(doc)} checked for "
                      "well-formedness only (set RAYGRADE_SCHEMAS to the schemas' folder)")
                r = subprocess.run(["xmllint", "--noout", doc], capture_output=True, text=True)
                check(r.returncode == 0, f"{doc} is not well-formed: {r.stderr}")

        sets = {}
        with open(work + "/canvas/sets.csv", newline="") as f:
            for row in csv.DictReader(f):
                sets[(row["problem"], row["set"])] = row["variant"]

        checked = 0
        items = list(ET.parse(qti).iter(QTI + "item"))
        check(len(items) > 20, f"only {len(items)} Canvas questions")
        for item in items:
            meta = {f.findtext(QTI + "fieldlabel"): f.findtext(QTI + "fieldentry")
                    for f in item.iter(QTI + "qtimetadatafield")}
            check(meta.get("question_type") == "calculated_question", f"{item.get('ident')}: type")
            html = item.find(f"{QTI}presentation/{QTI}material/{QTI}mattext").text
            calc = item.find(f"{QTI}itemproc_extension/{QTI}calculated")
            tolerance = calc.findtext(QTI + "answer_tolerance")
            check(calc.find(f"{QTI}formulas/{QTI}formula").text == "answer",
                  f"{item.get('ident')}: the formula is not the answer variable")
            problem, pointer = None, None
            for pid in solved[students[0]]:
                if item.get("ident").startswith(pid + "_"):
                    problem = pid
                    pointer = "/" + item.get("ident")[len(pid) + 1:].replace("_", "/")
            check(problem is not None, f"{item.get('ident')}: no problem of the assignment")
            vectors, answers = [], []
            for vs in calc.iter(QTI + "var_set"):
                values = {v.get("name"): float(v.text) for v in vs.findall(QTI + "var")}
                answer = float(vs.findtext(QTI + "answer"))
                student = sets[(problem, vs.get("ident"))]
                ref = solved[student][problem]
                want = at_pointer(ref["answer"], pointer)
                check(want is not None and abs(answer - want) <= 1e-12 * max(1, abs(want)),
                      f"Canvas {item.get('ident')} {vs.get('ident')}: answer {answer}, "
                      f"{student}'s reference {want}")
                check(values["answer"] == answer, f"{item.get('ident')}: answer variable")
                shown = fill(statement_of(html), values, "[]")
                check(shown == ref["statement"],
                      f"Canvas {item.get('ident')} {vs.get('ident')}: the statement shown is\n"
                      f"  {shown}\nbut {student}'s is\n  {ref['statement']}")
                if pointer.split("/")[-1].isdigit():
                    vectors.append(at_pointer(ref["answer"], pointer.rsplit("/", 1)[0]))
                answers.append(want)
                checked += 1
            kind, value = expected_tolerance(bank[problem], pointer,
                                             {"vectors": vectors, "answers": answers})
            if kind == "relative":
                check(tolerance == f"{value * 100:g}%",
                      f"Canvas {item.get('ident')}: tolerance {tolerance}, want {value * 100:g}%")
            else:
                # Written to 12 figures, never above the error raygrade accepts.
                check(not tolerance.endswith("%") and
                      value * (1 - 1e-10) <= float(tolerance) <= value,
                      f"Canvas {item.get('ident')}: tolerance {tolerance}, want {value}")
        print(f"Canvas: {len(items)} questions, {checked} variable sets checked")

        # Moodle: the elements Moodle's XML importer reads of a calculated question.
        moodle = ET.parse(work + "/moodle/homework-rays-moodle.xml").getroot()
        check(moodle.tag == "quiz", "Moodle's root is not <quiz>")
        questions = [q for q in moodle.findall("question") if q.get("type") == "calculated"]
        check(len(questions) == len(items), f"{len(questions)} Moodle and {len(items)} Canvas questions")
        checked = 0
        for q in questions:
            ident = q.findtext("idnumber")
            for path in ["name/text", "questiontext/text", "generalfeedback/text", "defaultgrade",
                         "synchronize", "single", "answernumbering", "shuffleanswers",
                         "answer/text", "answer/tolerance", "answer/tolerancetype",
                         "answer/correctanswerformat", "answer/correctanswerlength",
                         "dataset_definitions/dataset_definition"]:
                check(q.find(path) is not None, f"Moodle {ident}: no {path}")
            check(q.find("answer").get("fraction") == "100", f"Moodle {ident}: answer fraction")
            check(q.findtext("answer/text") == "{answer}", f"Moodle {ident}: the answer formula")
            datasets = {}
            for d in q.iter("dataset_definition"):
                for path in ["status/text", "name/text", "type", "distribution/text",
                             "minimum/text", "maximum/text", "decimals/text", "itemcount"]:
                    check(d.find(path) is not None, f"Moodle {ident}: a dataset has no {path}")
                items_ = {int(i.findtext("number")): float(i.findtext("value"))
                          for i in d.iter("dataset_item")}
                check(int(d.findtext("itemcount")) == len(items_) <= 100,
                      f"Moodle {ident}: itemcount")
                datasets[d.findtext("name/text")] = items_
            counts = {len(v) for v in datasets.values()}
            check(len(counts) == 1, f"Moodle {ident}: datasets of different sizes")
            feedback = q.findtext("generalfeedback/text")
            for name in re.findall(r"\{([A-Za-z_][A-Za-z0-9_]*)\}", feedback):
                check(name in datasets, f"Moodle {ident}: the feedback's {{{name}}} has no dataset")
            problem = next(p for p in solved[students[0]] if ident.startswith(p + "_"))
            pointer = "/" + ident[len(problem) + 1:].replace("_", "/")
            text = statement_of(q.findtext("questiontext/text"))
            tolerance = float(q.findtext("answer/tolerance"))
            tolerance_type = q.findtext("answer/tolerancetype")
            vectors = []
            for n in sorted(datasets["answer"]):
                values = {name: items_[n] for name, items_ in datasets.items()}
                student = sets[(problem, f"set-{n}")] if (problem, f"set-{n}") in sets else None
                # Moodle's items are numbered 1..N over the sets this question offers, which
                # are all the sets unless a variant lacks the number; this assignment's do not.
                ref = solved[student][problem]
                want = at_pointer(ref["answer"], pointer)
                got = values["answer"]
                check(abs(got - want) <= 1e-12 * max(1, abs(want)),
                      f"Moodle {ident} item {n}: answer {got}, {student}'s reference {want}")
                shown = fill(text, values, "{}")
                check(shown == ref["statement"], f"Moodle {ident} item {n}: statement {shown}")
                if pointer.split("/")[-1].isdigit():
                    vectors.append(at_pointer(ref["answer"], pointer.rsplit("/", 1)[0]))
                checked += 1
            kind, value = expected_tolerance(bank[problem], pointer, {"vectors": vectors})
            check(tolerance_type == ("1" if kind == "relative" else "2"),
                  f"Moodle {ident}: tolerance type {tolerance_type}")
            check(value * (1 - 1e-10) <= tolerance <= value, f"Moodle {ident}: tolerance {tolerance}, want {value}")
        print(f"Moodle: {len(questions)} questions, {checked} dataset items checked")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        print(f"{len(failures)} failures")
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
