#!/usr/bin/env python3
"""The PrairieLearn export, driven as PrairieLearn drives a question: `raygrade export
prairielearn` writes the course fragment into a temporary folder; every info.json must validate
against PrairieLearn's question schema (tests/data/prairielearn-infoQuestion.schema.json, its
source in tests/data/README.md); every server.py is imported and its generate(), parse() and
grade() are called with data dictionaries shaped as PrairieLearn's server.py documentation
describes (params, correct_answers, submitted_answers, raw_submitted_answers, format_errors,
partial_scores, score, feedback, variant_seed, options), for a right, a wrong and a blank or
malformed answer to every problem of the assignment.

The right answers are `raygrade solve ASSIGNMENT --student prairielearn-SEED`, typed into the
inputs as a student types them; the sphere's t values and the camera ray's direction are also
checked against values worked by hand from the numbers the statement shows.

Usage: prairielearn_export.py RAYGRADE ASSIGNMENT [STATIC_RAYGRADE]
Without STATIC_RAYGRADE, RAYGRADE itself is shipped (--binary), which runs on this machine.
"""
import copy
import html.parser
import importlib.util
import json
import math
import pathlib
import re
import subprocess
import sys
import tempfile
import uuid

try:
    import jsonschema
except ImportError:
    sys.exit("prairielearn_export: the python3 module jsonschema is missing "
             "(Debian package python3-jsonschema; run scripts/install-deps.sh)")

from checks import check, failures  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
SCHEMA = HERE / "data" / "prairielearn-infoQuestion.schema.json"
SEEDS = [7, 1234567, 2**31 - 1]

# What generate() may change, and what parse() and grade() may (PrairieLearn's check_data).
GENERATE_KEYS = {"params", "correct_answers"}
PARSE_KEYS = {"params", "correct_answers", "submitted_answers", "format_errors", "feedback"}
GRADE_KEYS = PARSE_KEYS | {"partial_scores", "score"}


class Elements(html.parser.HTMLParser):
    """The answer elements of a question.html: name -> (tag, options of a multiple choice)."""

    def __init__(self):
        super().__init__()
        self.inputs, self.current, self.text = {}, None, None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag in ("pl-string-input", "pl-multiple-choice"):
            self.inputs[attrs["answers-name"]] = (tag, [])
            self.current = attrs["answers-name"] if tag == "pl-multiple-choice" else None
        elif tag == "pl-answer":
            self.text = ""

    def handle_data(self, data):
        if self.text is not None:
            self.text += data

    def handle_endtag(self, tag):
        if tag == "pl-answer" and self.current:
            self.inputs[self.current][1].append(self.text.strip())
            self.text = None


def fnv1a(pieces):
    """64-bit FNV-1a over each piece's UTF-8 bytes followed by the byte 0xFF."""
    h = 0xcbf29ce484222325
    for piece in pieces:
        for byte in piece.encode("utf-8") + b"\xff":
            h = ((h ^ byte) * 0x100000001b3) % 2**64
    return h


def expected_uuid(assignment, problem):
    """docs/assignments.md: two variant seeds, version 8 and the RFC 9562 variant bits."""
    hi, lo = (fnv1a(["raygrade variant", assignment, "0", f"prairielearn-uuid-{k}", problem])
              for k in (1, 2))
    hi = (hi & ~0xf000) | 0x8000
    lo = (lo & ~(0xc << 60)) | (0x8 << 60)
    h = f"{hi:016x}{lo:016x}"
    return f"{h[:8]}-{h[8:12]}-{h[12:16]}-{h[16:20]}-{h[20:]}"


def load_server(path, index):
    spec = importlib.util.spec_from_file_location(f"pl_server_{index}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def base_data(qdir, course, seed):
    return {"params": {}, "correct_answers": {}, "variant_seed": seed,
            "options": {"question_path": str(qdir),
                        "server_files_course_path": str(course / "serverFilesCourse"),
                        "client_files_question_path": str(qdir / "clientFilesQuestion")}}


def changed(before, after):
    return {k for k in set(before) | set(after) if before.get(k) != after.get(k)}


def typed(v):
    """A number or a vector as a student types it."""
    if isinstance(v, list):
        return ", ".join(typed(x) for x in v)
    if isinstance(v, bool):
        return "yes" if v else "no"
    return v if isinstance(v, str) else repr(v)


def choose(options, text):
    """The key PrairieLearn gives an option of a multiple choice in fixed order: a, b, c..."""
    return chr(ord("a") + options.index(text))


def type_answer(answer, elements):
    """The inputs a student fills in for `answer`, by answers-name."""
    out = {}
    hits = answer.get("hits")
    for name, (tag, options) in elements.items():
        m = re.fullmatch(r"lights_(\d+)_(.+)", name)
        if m:
            value = answer["lights"][int(m[1])].get(m[2])
        elif name.startswith("ray_"):
            value = answer["ray"][name[4:]]
        elif hits is not None and name in ("t", "point", "normal", "barycentric"):
            value = "; ".join(typed(h[name]) for h in hits) if hits else "none"
        elif name == "terms":
            value = ", ".join(answer.get("terms", []))
        else:
            value = answer.get(name)
        if tag == "pl-multiple-choice":
            if name == "object":
                text = value if value is not None else "none (the ray hits nothing)"
            else:
                text = "yes" if value else "no"
            out[name] = choose(options, text)
        else:
            out[name] = "" if value is None else typed(value)
    return out


def submit(server, qdir, course, seed, params, inputs):
    """parse() then grade(), as PrairieLearn runs them; the data after each."""
    data = base_data(qdir, course, seed)
    data.update({"params": copy.deepcopy(params), "submitted_answers": dict(inputs),
                 "raw_submitted_answers": dict(inputs), "format_errors": {}, "feedback": {},
                 "partial_scores": {}, "score": 0.0, "gradable": True})
    before = copy.deepcopy(data)
    server.parse(data)
    check(changed(before, data) <= PARSE_KEYS, f"parse changed {changed(before, data)}")
    if data["format_errors"]:
        return data  # PrairieLearn grades no submission with format errors
    before = copy.deepcopy(data)
    server.grade(data)
    check(changed(before, data) <= GRADE_KEYS, f"grade changed {changed(before, data)}")
    # What students read names no folder of the server (the file raygrade grades is a
    # temporary one).
    check(tempfile.gettempdir() not in feedback_text(data), f"a path shown: {feedback_text(data)}")
    return data


def feedback_text(data):
    """The feedback as question.html shows it: each part with its status, then the lines."""
    fb = data["feedback"].get("raygrade", {})
    parts = [f"{p['name']} ({p['status']}): {p['feedback']}" for p in fb.get("parts", [])]
    return " ".join(parts + fb.get("lines", []))


def shifted(vectors, by):
    return "; ".join(typed([x + by for x in v]) for v in vectors)


def flipped(vectors):
    return "; ".join(typed([-x for x in v]) for v in vectors)


# Inputs that also answer another part: "yes" to total internal reflection says there is no
# refracted direction; a ray tree's first hit is one part, its object and t.
ALSO_ANSWERS = {"total_internal_reflection": "direction", "object": "hit", "t": "hit"}


def wrong_answer(pid, inputs, answer, statement):
    """A wrong answer to each problem, made as students make them, and what the feedback must
    then say: the id of the named mistake where raygrade's catalogue has one for the kind,
    else the status of the wrong part."""
    w = dict(inputs)
    hits = answer.get("hits", [])
    if pid in ("variant-sphere", "variant-first-hit", "variant-triangle"):
        # The point a little off (the normal carries no points here, so it is not asked).
        w.update(point=shifted([h["point"] for h in hits], 0.5))
        return w, "point (wrong)"
    if pid == "variant-plane":
        # t measured along the unit direction: t·|D|.
        d = [float(x) for x in re.search(r"direction \(([^)]*)\)", statement)[1].split(",")]
        w["t"] = typed(hits[0]["t"] * math.sqrt(sum(x * x for x in d)))
        return w, "unit-direction-t"
    if pid == "variant-camera-ray":
        # The pixel's corner, x - resX/2, instead of its centre (d × u = (1, 0, 0) here).
        m = re.search(r"focal length (\S+) and an image of (\d+) × (\d+) pixels.*pixel "
                      r"\((\d+), (\d+)\)", statement)
        f, res_x, res_y, x, y = (float(g) for g in m.groups())
        w["ray_direction"] = typed([x - res_x / 2, y - res_y / 2, -f])
        return w, "pixel-corner"
    if pid == "seed000-cylinder-derive-origin":
        return {**w, "b": "2*vx + 2*vy"}, "cylinder-b-no-origin"
    if pid == "variant-reflect":
        d = answer["direction"]
        return {**w, "direction": typed([d[0], -d[1], d[2]])}, "direction (wrong)"
    if pid == "variant-refract":
        d = answer["direction"]
        return {**w, "direction": typed([d[0], -d[1], d[2]])}, "direction (wrong)"
    if pid == "variant-shade":
        return {**w, "intensity": typed(answer["ambient"])}, "intensity (wrong)"
    if pid == "scene-first-hit-only":
        return {**w, "t": typed(hits[0]["t"] + 1)}, "hit (partial)"
    raise KeyError(pid)


def main(raygrade, assignment, static=None):
    validator = jsonschema.Draft7Validator(json.loads(SCHEMA.read_text(encoding="utf-8")))
    with tempfile.TemporaryDirectory() as tmp:
        course = pathlib.Path(tmp) / "course"
        proc = subprocess.run([raygrade, "export", "prairielearn", assignment, "--out",
                               str(course), "--binary", static or raygrade],
                              capture_output=True, text=True)
        if proc.returncode != 0:
            sys.exit(f"export failed ({proc.returncode}): {proc.stderr}")
        spec = json.loads(pathlib.Path(assignment).read_text(encoding="utf-8"))
        aid = spec["assignment"]
        ids = [p if isinstance(p, str) else p["id"] for p in spec["problems"]]
        shipped = course / "serverFilesCourse" / "raygrade"
        check((shipped / "raygrade").stat().st_mode & 0o111, "raygrade is not executable")
        check((shipped / aid / "assignment.json").is_file(), "no assignment.json")
        folders = sorted(p.name for p in (course / "questions" / aid).iterdir())
        check(folders == sorted(ids), f"question folders {folders}")

        # The reference: raygrade's own solution of each seed's variant.
        def solve(seed):
            out = subprocess.run([raygrade, "solve", assignment, "--student",
                                  f"prairielearn-{seed}", "--format", "json"],
                                 capture_output=True, text=True, check=True)
            return {s["id"]: s for s in json.loads(out.stdout)["solutions"]}
        reference = {seed: solve(seed) for seed in SEEDS}

        uuids = set()
        for index, pid in enumerate(ids):
            qdir = course / "questions" / aid / pid
            info = json.loads((qdir / "info.json").read_text(encoding="utf-8"))
            errors = sorted(e.message for e in validator.iter_errors(info))
            check(not errors, f"{pid}/info.json: {errors}")
            check(info["type"] == "v3", f"{pid}: type {info['type']}")
            uuids.add(info["uuid"])
            parsed = uuid.UUID(info["uuid"])
            check(parsed.version == 8 and parsed.variant == uuid.RFC_4122,
                  f"{pid}: uuid {info['uuid']} is not a version 8 RFC 9562 uuid")
            check(info["uuid"] == expected_uuid(aid, pid),
                  f"{pid}: uuid {info['uuid']}, documented {expected_uuid(aid, pid)}")
            has_parameters = "parameters" in reference[SEEDS[0]][pid]
            check(info["singleVariant"] == (not has_parameters), f"{pid}: singleVariant")
            elements = Elements()
            elements.feed((qdir / "question.html").read_text(encoding="utf-8"))
            check(elements.inputs, f"{pid}: question.html has no inputs")
            server = load_server(qdir / "server.py", index)

            drawn = {}
            for seed in SEEDS:
                data = base_data(qdir, course, seed)
                before = copy.deepcopy(data)
                server.generate(data)
                check(changed(before, data) <= GENERATE_KEYS,
                      f"{pid}: generate changed {changed(before, data)}")
                ref = reference[seed][pid]
                check(data["params"]["statement"] == ref["statement"], f"{pid}: statement")
                check(data["params"]["values"] == ref.get("parameters", {}), f"{pid}: values")
                again = base_data(qdir, course, seed)
                server.generate(again)
                check(again["params"] == data["params"], f"{pid}: seed {seed} drew twice")
                drawn[seed] = data["params"]
                params = data["params"]
                inputs = type_answer(ref["answer"], elements.inputs)
                check(set(inputs) == set(elements.inputs), f"{pid}: inputs {sorted(inputs)}")

                right = submit(server, qdir, course, seed, params, inputs)
                check(not right["format_errors"], f"{pid}/{seed} right: {right['format_errors']}")
                check(math.isclose(right.get("score", 0), 1.0),
                      f"{pid}/{seed} right: score {right.get('score')}: {feedback_text(right)}")
                check(right["partial_scores"] and all(
                    math.isclose(p["score"], 1.0) for p in right["partial_scores"].values()),
                    f"{pid}/{seed} right: partial scores {right['partial_scores']}")
                # Every input asks for a part that carries points (a scored part); a part
                # worth 0 points has no input.
                for name in elements.inputs:
                    part = re.sub(r"^(ray|lights)_.*", r"\1", name)
                    scored = set(right["partial_scores"])
                    check(part in scored or ALSO_ANSWERS.get(part) in scored,
                          f"{pid}: input {name} asks for a part worth no points ({sorted(scored)})")

                wrong_inputs, says = wrong_answer(pid, inputs, ref["answer"], ref["statement"])
                wrong = submit(server, qdir, course, seed, params, wrong_inputs)
                check(not wrong["format_errors"], f"{pid}/{seed} wrong: {wrong['format_errors']}")
                check(wrong.get("score", 1) < 1, f"{pid}/{seed} wrong: score {wrong.get('score')}")
                check(says in feedback_text(wrong),
                      f"{pid}/{seed} wrong: {says!r} not in {feedback_text(wrong)!r}")

                blank = submit(server, qdir, course, seed, params,
                               {name: "" for name in elements.inputs
                                if elements.inputs[name][0] == "pl-string-input"})
                check(blank.get("score") == 0, f"{pid}/{seed} blank: score {blank.get('score')}")
                check(feedback_text(blank), f"{pid}/{seed} blank: no message")

                # Malformed: a vector of two numbers is a format error (PrairieLearn then asks
                # again without using an attempt); a number raygrade cannot read is feedback.
                vector = next((n for n in elements.inputs if n in
                               ("point", "direction", "ray_direction")), None)
                if vector:
                    bad = submit(server, qdir, course, seed, params, {**inputs, vector: "1, 2"})
                    check(vector in bad["format_errors"], f"{pid}/{seed}: {vector} '1, 2' read")
                number = next((n for n in ("t", "intensity", "a")
                               if n in elements.inputs), None)
                if number:
                    bad = submit(server, qdir, course, seed, params, {**inputs, number: "7.2.7"})
                    check(bad.get("score", 1) < 1 and "7.2.7" in feedback_text(bad),
                          f"{pid}/{seed}: '7.2.7' gave {feedback_text(bad)!r}")
                # grade() called without parse() never raises either.
                data = base_data(qdir, course, seed)
                data.update({"params": params, "submitted_answers": {vector or "x": "(1"},
                             "format_errors": {}, "feedback": {}, "partial_scores": {},
                             "score": 0.0})
                server.grade(data)
                check(data["score"] == 0, f"{pid}/{seed}: grade without parse scored")
                # An answer raygrade rejects (here a key no answer has): the reason is what is
                # wrong with it, without the server's temporary folder.
                try:
                    server._grade_with_raygrade(data, server._question(data), {"bogus": 1})
                    check(False, f"{pid}/{seed}: an answer with an unknown key was graded")
                except RuntimeError as e:
                    check("unknown key 'bogus'" in str(e) and tempfile.gettempdir() not in str(e),
                          f"{pid}/{seed}: {e}")
            if has_parameters:
                values = [json.dumps(drawn[s]["values"], sort_keys=True) for s in SEEDS]
                check(len(set(values)) > 1, f"{pid}: every seed drew {values[0]}")

        check(len(uuids) == len(ids), "two questions share a uuid")
        # The same export again gives the same uuids.
        again = pathlib.Path(tmp) / "again"
        subprocess.run([raygrade, "export", "prairielearn", assignment, "--out", str(again),
                        "--binary", static or raygrade], capture_output=True, check=True)
        for pid in ids:
            a = json.loads((course / "questions" / aid / pid / "info.json").read_text())
            b = json.loads((again / "questions" / aid / pid / "info.json").read_text())
            check(a["uuid"] == b["uuid"], f"{pid}: uuid changed between exports")

        # By hand: the sphere of radius 5 at (0, 0, cz), the ray from (ox, 0, 0) along
        # (0, 0, dz): x = ox on the sphere gives z = cz ± sqrt(25 - ox²), t = z/dz.
        for seed in SEEDS:
            v = reference[seed]["variant-sphere"]["parameters"]
            ox, cz, dz = v["ox"], v["cz"], v["dz"]
            want = [(cz - math.sqrt(25 - ox * ox)) / dz, (cz + math.sqrt(25 - ox * ox)) / dz]
            got = [h["t"] for h in reference[seed]["variant-sphere"]["answer"]["hits"]]
            check(len(got) == 2 and all(math.isclose(a, b) for a, b in zip(got, want)),
                  f"sphere seed {seed}: t {got}, by hand {want}")
            statement = reference[seed]["variant-sphere"]["statement"]
            check(f"({ox}, 0, 0)" in statement and f"(0, 0, {cz})" in statement,
                  f"sphere seed {seed}: the statement does not show ox={ox}, cz={cz}")
            # The camera looks along d = (0, 0, -1) with up u = (0, 1, 0), so d × u = (1, 0, 0)
            # and the ray through the centre of pixel (x, y) of a W × H image at focal length
            # f runs along (x + 0.5 - W/2, y + 0.5 - H/2, -f).
            camera = reference[seed]["variant-camera-ray"]
            m = re.search(r"focal length (\S+) and an image of (\d+) × (\d+) pixels.*pixel "
                          r"\((\d+), (\d+)\)", camera["statement"])
            f, res_x, res_y, x, y = (float(g) for g in m.groups())
            want = [x + 0.5 - res_x / 2, y + 0.5 - res_y / 2, -f]
            got = camera["answer"]["ray"]["direction"]
            check(all(math.isclose(a, b, abs_tol=1e-12) for a, b in zip(got, want)),
                  f"camera seed {seed}: direction {got}, by hand {want}")
    print(f"prairielearn_export: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
