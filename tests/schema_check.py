#!/usr/bin/env python3
"""The problem schema: it is a valid draft 2020-12 schema, every file of the bank conforms to
it, and it rejects typical mistakes.

Usage: schema_check.py SCHEMA BANK_DIR
"""
import copy
import json
import pathlib
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("schema_check: the python3 module jsonschema is missing "
             "(Debian package python3-jsonschema; run scripts/install-deps.sh)")

GOOD = {
    "id": "good",
    "ray": {"origin": [0, 0, 0], "direction": [0, 0, 1]},
    "object": {"type": "sphere", "center": [0, 0, 5], "radius": 2},
}


def variant(change):
    problem = copy.deepcopy(GOOD)
    change(problem)
    return problem


# Each broken example: what is wrong, and the problem.
BROKEN = [
    ("zero radius", variant(lambda p: p["object"].update(radius=0))),
    ("negative radius", variant(lambda p: p["object"].update(radius=-1))),
    ("misspelt key", variant(lambda p: p["object"].update(raduis=2))),
    ("zero direction", variant(lambda p: p["ray"].update(direction=[0, 0, 0]))),
    ("two coordinates", variant(lambda p: p["ray"].update(origin=[0, 0]))),
    ("missing ray", variant(lambda p: p.pop("ray"))),
    ("missing id", variant(lambda p: p.pop("id"))),
    ("unknown problem key", variant(lambda p: p.update(stament="typo"))),
    ("unknown type", variant(lambda p: p["object"].update(type="torus"))),
    ("unknown kind", variant(lambda p: p.update(kind="intersekt"))),
    ("derive without find", variant(lambda p: p.update(kind="derive"))),
    ("derive with an empty find", variant(lambda p: p.update(kind="derive", find=[]))),
    ("a key of another kind", variant(lambda p: p.update(find=["t1"]))),
    ("plane with neither point nor d",
     variant(lambda p: p.update(object={"type": "plane", "normal": [0, 0, 1]}))),
    ("plane with both point and d",
     variant(lambda p: p.update(
         object={"type": "plane", "normal": [0, 0, 1], "point": [0, 0, 0], "d": 1}))),
    ("caps without height",
     variant(lambda p: p.update(
         object={"type": "cylinder", "base": [0, 0, 0], "radius": 1, "capped": True}))),
    ("triangle with four vertices",
     variant(lambda p: p.update(
         object={"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]}))),
    ("first-hit object without a name",
     variant(lambda p: p.update(kind="first-hit", objects=[p.pop("object")]))),
    ("camera-ray with an unknown convention",
     {"id": "c", "kind": "camera-ray", "pixel": [0, 0], "convention": "middle",
      "camera": {"eye": [0, 0, 0], "direction": [0, 0, -1], "up": [0, 1, 0],
                 "focal_length": 1, "resolution": [4, 4]}}),
    ("wrapper with an unknown key", {"problems": [GOOD], "problem": []}),
    ("ray-tree with an unknown ask",
     {"id": "t", "kind": "ray-tree", "ask": "everything", "ray": GOOD["ray"],
      "scene": {"objects": [GOOD["object"]]}}),
    ("transparent material without its refractive index",
     {"id": "t", "kind": "ray-tree", "ray": GOOD["ray"],
      "scene": {"objects": [dict(GOOD["object"], material={"transparency": 0.5})]}}),
]


# Problems the schema must accept beside the bank's: keys every kind takes, kinds the bank has
# few of.
ALSO_GOOD = [
    ("conventions", variant(lambda p: p.update(conventions={"contained": "line"}))),
    ("a derive problem", variant(lambda p: p.update(kind="derive", find=["b", "c"]))),
]


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    schema = json.loads(pathlib.Path(argv[1]).read_text(encoding="utf-8"))
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = 0
    files = sorted(pathlib.Path(argv[2]).rglob("*.json"))
    for path in files:
        for error in validator.iter_errors(json.loads(path.read_text(encoding="utf-8"))):
            failures += 1
            where = "/" + "/".join(str(p) for p in error.absolute_path)
            print(f"FAIL {path}: {where}: {error.message}")
    if not list(validator.iter_errors(GOOD)) == []:
        failures += 1
        print("FAIL the good example is rejected")
    for what, problem in ALSO_GOOD:
        for error in validator.iter_errors(problem):
            failures += 1
            print(f"FAIL the schema rejects {what}: {error.message}")
    for what, problem in BROKEN:
        if validator.is_valid(problem):
            failures += 1
            print(f"FAIL the schema accepts a problem with {what}")
    print(f"{len(files)} bank files and {len(BROKEN)} broken examples checked, {failures} failures")
    return 1 if failures or not files else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
