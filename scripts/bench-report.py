#!/usr/bin/env python3
"""Benchmark of `raygrade report` (docs/report.md quotes it): a class of N students (200 by
default) on the example assignment's 10 problems, each student's own right answers (from
`raygrade solve --student`) with a third of them made wrong (t doubled, a vector's sign
flipped, every number shifted at random) and a tenth left blank. Prints the wall time of each
run and their median; it asserts no time (a benchmark, not a test).

Usage: scripts/bench-report.py RAYGRADE [--students 200] [--runs 3] [--jobs 2]
"""
import argparse
import json
import pathlib
import random
import statistics
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
ASSIGNMENT = ROOT / "assignments" / "homework-rays.json"


def changed(answer, how, rng):
    """The answer with every number changed one way: doubled t, negated vectors, or shifted."""
    if isinstance(answer, dict):
        return {k: (v * 2 if how == "t" and k == "t" and isinstance(v, (int, float))
                    else changed(v, how, rng)) for k, v in answer.items()}
    if isinstance(answer, list):
        if how == "sign" and len(answer) == 3 and all(isinstance(x, (int, float)) for x in answer):
            return [-x for x in answer]
        return [changed(v, how, rng) for v in answer]
    if how == "noise" and isinstance(answer, (int, float)) and not isinstance(answer, bool):
        return round(answer + rng.uniform(-3, 3), 2)
    return answer


def write_class(binary, n, folder, rng):
    for i in range(1, n + 1):
        student = f"s{i:03}"
        out = subprocess.run([str(binary), "solve", str(ASSIGNMENT), "--student", student,
                              "--format", "json"], check=True, capture_output=True, text=True)
        answers = {s["id"]: s["answer"] for s in json.loads(out.stdout)["solutions"]}
        for problem in list(answers):
            roll = rng.random()
            if roll < 0.1:
                del answers[problem]
            elif roll < 0.43:
                answers[problem] = changed(answers[problem], rng.choice(["t", "sign", "noise"]),
                                           rng)
        (folder / f"{student}.json").write_text(
            json.dumps({"student": {"id": student}, "answers": answers}), encoding="utf-8")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("raygrade")
    ap.add_argument("--students", type=int, default=200)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    rng = random.Random(2026)
    with tempfile.TemporaryDirectory(prefix="raygrade-bench-report-") as tmp:
        folder = pathlib.Path(tmp) / "class"
        folder.mkdir()
        write_class(args.raygrade, args.students, folder, rng)
        times = []
        for run in range(args.runs):
            start = time.perf_counter()
            subprocess.run([args.raygrade, "report", "--assignment", str(ASSIGNMENT), str(folder),
                            "--out", str(pathlib.Path(tmp) / "report"), "-j", str(args.jobs)],
                           check=True, capture_output=True)
            times.append(time.perf_counter() - start)
            print(f"run {run + 1}: {times[-1]:.2f} s")
        report = json.loads((pathlib.Path(tmp) / "report" / "report.json").read_text())
        groups = sum(len(p["groups"]) for p in report["problems"])
        print(f"| students | problems | jobs | median wall time | groups |")
        print(f"| --- | --- | --- | --- | --- |")
        print(f"| {args.students} | {len(report['problems'])} | {args.jobs} | "
              f"{statistics.median(times):.2f} s | {groups} |")


if __name__ == "__main__":
    main()
