#!/usr/bin/env python3
"""Conformance: raygrade's answers against answers computed in 100-digit arithmetic.

Usage: conformance.py RAYGRADE DATA_DIR [--rtol R]

Runs `RAYGRADE solve DATA_DIR/problems.json --format json` and compares every answer with
DATA_DIR/expected.json: the same number of hits; t, point, normal and barycentric within a
relative error of R (1e-9 by default; absolute below magnitude 1); for first-hit problems the
same object unless the expected answer marks a tie; "contained": true where expected.
Prints one line per failure and a summary; exits 1 if anything failed.
"""
import json
import subprocess
import sys


def near(got, want, rtol):
    return abs(float(got) - float(want)) <= rtol * max(1.0, abs(float(want)))


def mismatch(got, want, rtol):
    """Why `got` differs from `want`, or None."""
    if want.get("contained", False) != got.get("contained", False):
        return f"contained = {got.get('contained', False)}, expected {want.get('contained', False)}"
    got_hits, want_hits = got.get("hits", []), want.get("hits", [])
    if len(got_hits) != len(want_hits):
        return f"{len(got_hits)} hits, expected {len(want_hits)}"
    for i, (g, w) in enumerate(zip(got_hits, want_hits)):
        if not near(g["t"], w["t"], rtol):
            return f"hit {i}: t = {g['t']}, expected {w['t']}"
        for key in ("point", "normal", "barycentric"):
            if key not in w:
                continue
            if key not in g:
                return f"hit {i}: no {key}"
            if len(g[key]) != len(w[key]) or not all(
                    near(a, b, rtol) for a, b in zip(g[key], w[key])):
                return f"hit {i}: {key} = {g[key]}, expected {w[key]}"
    if "object" in want and not want.get("tie") and got.get("object") != want["object"]:
        return f"object {got.get('object')!r}, expected {want['object']!r}"
    return None


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    binary, data = argv[1], argv[2]
    rtol = float(argv[argv.index("--rtol") + 1]) if "--rtol" in argv else 1e-9
    run = subprocess.run([binary, "solve", f"{data}/problems.json", "--format", "json"],
                         capture_output=True, text=True, check=False)
    if run.returncode != 0:
        print(f"raygrade exited with {run.returncode}:\n{run.stderr}")
        return 1
    got = {s["id"]: s["answer"] for s in json.loads(run.stdout)["solutions"]}
    with open(f"{data}/expected.json", encoding="utf-8") as f:
        expected = json.load(f)["solutions"]
    failed = 0
    for e in expected:
        why = "not solved" if e["id"] not in got else mismatch(got[e["id"]], e["answer"], rtol)
        if why:
            failed += 1
            print(f"FAIL {e['id']}: {why}")
    print(f"{len(expected) - failed} passed, {failed} failed")
    return 1 if failed or not expected else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
