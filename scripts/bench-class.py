#!/usr/bin/env python3
"""Benchmarks of a class's batch and of hostile submissions (docs/hardening.md quotes them).

1. `raygrade grade --assignment` on N distinct students (N = 1,000, 2,000 and 5,000 by default),
   each handing in one file: peak memory (the child's maximum resident set) and wall time. Memory
   must stay flat in N and time grow linearly.
2. One submission with K answers to problems the assignment does not have, and one whose ray
   tree has K nodes (K = 2,500, 5,000 and 10,000): time per K, which must grow linearly.

Usage: scripts/bench-class.py RAYGRADE [--students 1000,2000,5000] [--sizes 2500,5000,10000]
It prints a Markdown table of each and exits 0; it asserts no time (a benchmark, not a test).
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
ASSIGNMENT = ROOT / "assignments" / "homework-rays.json"


def measured(args, cwd):
    """Runs raygrade from a child Python, so that its RUSAGE_CHILDREN holds this run alone:
    the wall time in seconds and the peak resident memory in MB."""
    code = ("import json,sys,resource,subprocess,time;"
            "s=time.perf_counter();"
            "p=subprocess.run(sys.argv[1:],stdout=subprocess.DEVNULL,stderr=subprocess.PIPE);"
            "t=time.perf_counter()-s;"
            "print(json.dumps([t,resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss/1024,"
            "p.returncode]))")
    out = subprocess.run([sys.executable, "-c", code] + args, cwd=cwd, capture_output=True,
                         text=True, check=True)
    seconds, mb, status = json.loads(out.stdout)
    if status not in (0, 1, 2):
        sys.exit(f"raygrade exited with {status}")
    return seconds, mb


def class_of(n, folder):
    """N submissions of N distinct students, each answering the sphere (a wrong t)."""
    folder.mkdir(parents=True, exist_ok=True)
    for i in range(n):
        (folder / f"s{i:05d}.json").write_text(json.dumps({
            "student": {"id": f"s{i:05d}"},
            "answers": {"variant-sphere": {"hits": [{"t": 1.5}]}}}), encoding="utf-8")


def unknown_ids(k, path):
    path.write_text(json.dumps({"student": {"id": "s00001"}, "answers": {
        f"no-such-problem-{i}": {"hits": []} for i in range(k)}}), encoding="utf-8")


def tree_nodes(k, path):
    nodes = [{"label": "I1", "parent": None, "ray": "primary", "object": "glass sphere",
              "in_shadow": False}]
    for i in range(2, k + 1):
        nodes.append({"label": f"I{i}", "parent": f"I{i - 1}", "ray": "reflection",
                      "object": "floor", "in_shadow": False})
    path.write_text(json.dumps({"student": "tree", "answers": {
        "seed001-ray-tree": {"nodes": nodes}}}), encoding="utf-8")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("raygrade")
    ap.add_argument("--students", default="1000,2000,5000")
    ap.add_argument("--sizes", default="2500,5000,10000")
    a = ap.parse_args()
    raygrade = os.path.abspath(a.raygrade)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        print("| students | wall s | s per 1,000 students | peak MB |")
        print("| ---: | ---: | ---: | ---: |")
        for n in (int(x) for x in a.students.split(",")):
            subs = tmp / f"class-{n}"
            class_of(n, subs)
            seconds, mb = measured([raygrade, "grade", "--assignment", str(ASSIGNMENT), str(subs),
                                    "--format", "csv", "--now", "2026-12-01T00:00:00Z"], tmp)
            print(f"| {n:,} | {seconds:.1f} | {seconds / n * 1000:.2f} | {mb:.0f} |")
        print()
        print("| items in one submission | unknown ids: s | ray-tree nodes: s |")
        print("| ---: | ---: | ---: |")
        for k in (int(x) for x in a.sizes.split(",")):
            unknown_ids(k, tmp / "unknown.json")
            tree_nodes(k, tmp / "tree.json")
            t_unknown, _ = measured([raygrade, "grade", "--assignment", str(ASSIGNMENT),
                                     str(tmp / "unknown.json"), "--format", "json",
                                     "--now", "2026-12-01T00:00:00Z"], tmp)
            t_tree, _ = measured([raygrade, "grade", "--problems", str(ROOT / "problems"),
                                  "--answered-only", str(tmp / "tree.json"), "--format", "json"],
                                 tmp)
            print(f"| {k:,} | {t_unknown:.2f} | {t_tree:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
