#!/usr/bin/env python3
"""A discovered mistake promoted to the bank, and `raygrade regrade` on the example assignment.

Eight students answer the example assignment with their right answers, except that three of
them reflect with the sign of the normal term flipped: for the floor's normal (0, 1, 0), the
right r = (r_x, r_y, 0) becomes (r_x, −3·r_y, 0) (d = (r_x, −r_y, 0); d + 2(d·n)n). The report
must group exactly those three under one discovered change of the step r (or one that gives
the same numbers, such as the sign of d·n); that change is then
added to a copy of the bank as a named mistake of variant-reflect, and `raygrade regrade` with
the copy must list exactly those three students, for variant-reflect alone, and write nothing.

usage: regrade_example.py RAYGRADE_BINARY REPOSITORY OUTPUT_FOLDER
"""
import json
import os
import shutil
import subprocess
import sys

STUDENTS = [f"s{i:03}" for i in range(1, 9)]
PLANTED = {"s002", "s005", "s007"}


def main():
    binary, repo, out = sys.argv[1:4]
    shutil.rmtree(out, ignore_errors=True)
    subs = os.path.join(out, "class")
    os.makedirs(subs)
    assignment = os.path.join(repo, "assignments", "homework-rays.json")
    for s in STUDENTS:
        solved = subprocess.run([binary, "solve", assignment, "--student", s, "--format", "json"],
                                check=True, capture_output=True, text=True).stdout
        answers = {x["id"]: x["answer"] for x in json.loads(solved)["solutions"]}
        if s in PLANTED:
            rx, ry, _ = answers["variant-reflect"]["direction"]
            answers["variant-reflect"] = {"direction": [rx, -3 * ry, 0]}
        with open(os.path.join(subs, s + ".json"), "w", encoding="utf-8") as f:
            json.dump({"student": {"id": s}, "answers": answers}, f)
    faults = []
    subprocess.run([binary, "report", "--assignment", assignment, subs, "--out",
                    os.path.join(out, "report")], check=True, capture_output=True)
    with open(os.path.join(out, "report", "report.json"), encoding="utf-8") as f:
        report = json.load(f)
    reflect = next(p for p in report["problems"] if p["id"] == "variant-reflect")
    groups = [g for g in reflect["groups"] if g["discovered"]]
    if len(groups) != 1 or set(groups[0]["students"]) != PLANTED:
        print("the report does not group the planted students under one change:",
              json.dumps(reflect["groups"]))
        return 1
    change = groups[0]["discovered"]["change"]
    found = groups[0]["discovered"]
    if found["step"] != "r" and not any(e.startswith("r = ") for e in found["equivalent"]):
        faults.append(f"neither the change nor an equivalent one is in the step r: {found}")
    # The bank with the discovered change named.
    bank = os.path.join(out, "problems")
    shutil.copytree(os.path.join(repo, "problems"), bank)
    path = os.path.join(bank, "variants.json")
    with open(path, encoding="utf-8") as f:
        variants = json.load(f)
    for p in variants["problems"]:
        if p["id"] == "variant-reflect":
            p["mistakes"] = [{"id": "normal-term-sign",
                              "message": "The normal part is subtracted twice: r = d − 2(d·n)n.",
                              "change": change}]
    with open(path, "w", encoding="utf-8") as f:
        json.dump(variants, f, ensure_ascii=False, indent=1)
    before = sorted(os.listdir(subs))
    run = subprocess.run([binary, "regrade", "--assignment", assignment, "--bank", bank, subs],
                         capture_output=True, text=True)
    if run.returncode != 0:
        faults.append(f"regrade exited {run.returncode}: {run.stderr}")
    rows = [line.split("\t") for line in run.stdout.splitlines() if line]
    listed = {r[0] for r in rows}
    if listed != PLANTED:
        faults.append(f"regrade lists {sorted(listed)}, not {sorted(PLANTED)}")
    for r in rows:
        if r[1] != "variant-reflect" or "normal-term-sign" not in r[2]:
            faults.append(f"unexpected change: {r}")
    if sorted(os.listdir(subs)) != before:
        faults.append("regrade wrote into the submissions")
    for f in faults:
        print(f)
    print(run.stdout, end="")
    print(f"regrade listed {len(listed)} students for the change {change}")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
