#!/usr/bin/env python3
"""Measures the class report's search on the misconception classes (README.md).

Writes the classes with make_classes.py, runs `raygrade report` on each kind's class and
reports, per kind and per slip:
  own     the share of the slip's students in one explained group that holds only them
          (the explained group holding most of them; 0 when it holds anyone else);
  random  the share of random answers in any explained group;
  right   how many right answers are in an explained group.
A group is explained when it names a mistake of the catalogue or a discovered change.

  measure.py RAYGRADE [--work DIR] [--json FILE] [--check] [--kind KIND]...

--check exits 1 unless the search reaches what it must: every slip at least 90% in a group of
its own, at most 2% of random answers and no right answer explained. Whatever the
options, it exits 2 when the classes themselves are faulty: a right answer that is not
graded full marks, or a planted slip that is (the class would not test what it says).
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import make_classes  # noqa: E402

OWN_MIN = 0.90
RANDOM_MAX = 0.02


def explained(group):
    return group.get("mistake") is not None or group.get("discovered") is not None


def label(group):
    if group.get("mistake") is not None:
        return f"mistake {group['mistake']}"
    d = group.get("discovered")
    if d is not None:
        return f"{d.get('kind')}: {d.get('change')}"
    return "unexplained"


def measure_kind(raygrade, kdir, students, jobs):
    out = kdir / "report"
    run = subprocess.run(
        [raygrade, "report", "--problems", str(kdir / "problems.json"),
         str(kdir / "submissions"), "--out", str(out), "-j", str(jobs)],
        capture_output=True, text=True)
    if run.returncode not in (0, 1):
        raise SystemExit(f"raygrade report failed on {kdir} ({run.returncode}):\n{run.stderr}")
    report = json.loads((out / "report.json").read_text())
    group_of = {}  # student -> (problem id, group index)
    groups = {}
    for p in report["problems"]:
        for i, g in enumerate(p["groups"]):
            groups[(p["id"], i)] = g
            for s in g["students"]:
                group_of[s] = (p["id"], i)

    faults = []
    slips = {}  # slip -> {planted, own, where}
    rnd = {"total": 0, "explained": 0}
    right = {"total": 0, "explained": 0}
    by_slip = {}
    for sid, role in students.items():
        if role["role"] == "slip":
            by_slip.setdefault((role["problem"], role["slip"]), []).append(sid)
        elif role["role"] == "random":
            rnd["total"] += 1
            g = group_of.get(sid)
            if g is not None and explained(groups[g]):
                rnd["explained"] += 1
        else:
            right["total"] += 1
            g = group_of.get(sid)
            if g is not None:
                faults.append(f"{sid} ({role['problem']}): a right answer graded below full "
                              f"marks")
                if explained(groups[g]):
                    right["explained"] += 1
    for (pid, slip), sids in sorted(by_slip.items()):
        graded_right = [s for s in sids if s not in group_of]
        if graded_right:
            faults.append(f"{pid} {slip}: {len(graded_right)} planted answers graded full marks")
        counts = {}
        for s in sids:
            g = group_of.get(s)
            if g is not None and explained(groups[g]):
                counts[g] = counts.get(g, 0) + 1
        own, where = 0, "not explained"
        if counts:
            best = max(counts, key=lambda g: counts[g])
            members = set(groups[best]["students"])
            where = label(groups[best])
            if members <= set(sids):
                own = counts[best]
            else:
                where += f" (shared with {len(members - set(sids))} others)"
        entry = slips.setdefault(slip, {"planted": 0, "own": 0, "where": []})
        entry["planted"] += len(sids)
        entry["own"] += own
        entry["where"].append(f"{pid}: {where}")
    return {"slips": slips, "random": rnd, "right": right}, faults


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("raygrade")
    ap.add_argument("--work", help="folder for the classes and reports (default: a temporary one)")
    ap.add_argument("--json", help="write the figures here")
    ap.add_argument("--check", action="store_true", help="assert what the search must reach")
    ap.add_argument("--kind", action="append", help="only these kinds")
    ap.add_argument("--seed", type=int, default=48)
    ap.add_argument("-j", "--jobs", type=int, default=2)
    args = ap.parse_args()
    tmp = None
    if args.work:
        work = pathlib.Path(args.work)
    else:
        tmp = tempfile.TemporaryDirectory(prefix="misconceptions-")
        work = pathlib.Path(tmp.name)
    faults = make_classes.build(work, args.seed)
    manifest = json.loads((work / "manifest.json").read_text())

    figures = {}
    for kind, entry in manifest["kinds"].items():
        if args.kind and kind not in args.kind:
            continue
        fig, kfaults = measure_kind(args.raygrade, work / kind, entry["students"], args.jobs)
        figures[kind] = fig
        faults += kfaults

    ok = True
    print(f"{'kind / slip':44} {'own group':>12}  where")
    for kind, fig in figures.items():
        planted = sum(s["planted"] for s in fig["slips"].values())
        own = sum(s["own"] for s in fig["slips"].values())
        rnd, right = fig["random"], fig["right"]
        kind_ok = (all(s["own"] >= OWN_MIN * s["planted"] for s in fig["slips"].values())
                   and rnd["explained"] <= RANDOM_MAX * rnd["total"] and right["explained"] == 0)
        ok &= kind_ok
        print(f"{kind:44} {own:5}/{planted:<5}  random {rnd['explained']}/{rnd['total']}, "
              f"right {right['explained']}/{right['total']}"
              f"{'' if kind_ok else '  (below acceptance)'}")
        for slip, s in sorted(fig["slips"].items()):
            share = s["own"] / s["planted"]
            print(f"  {slip:42} {s['own']:5}/{s['planted']:<5} {share:4.0%}  "
                  f"{'; '.join(s['where'])[:110]}")
    planted = sum(s["planted"] for f in figures.values() for s in f["slips"].values())
    own = sum(s["own"] for f in figures.values() for s in f["slips"].values())
    rnd = sum(f["random"]["explained"] for f in figures.values())
    rnd_total = sum(f["random"]["total"] for f in figures.values())
    right = sum(f["right"]["explained"] for f in figures.values())
    print(f"all: {own} of {planted} planted answers in a group of their own slip; "
          f"{rnd} of {rnd_total} random answers and {right} right answers explained")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(
            {"figures": figures, "faults": faults, "accepted": ok}, indent=1) + "\n")
    for f in faults:
        print(f"fault in the classes: {f}", file=sys.stderr)
    if faults:
        return 2
    if args.check and not ok:
        print("below what the search must reach (>= 90% of each slip in a group of its own, "
              "<= 2% of random answers and no right answer explained)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
