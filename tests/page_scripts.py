#!/usr/bin/env python3
"""Every script raygrade puts into a page parses: `node --check` on the page scripts (classic
scripts) and on the viewer's and the web build's modules, before any browser test loads a page
whose script would then fail as a whole (a name declared twice, a bracket left open).

Usage: page_scripts.py NODE SOURCE_ROOT
"""
import pathlib
import subprocess
import sys

NODE, ROOT = sys.argv[1], pathlib.Path(sys.argv[2])
CLASSIC = ["grader/assignments/handout_page.js", "grader/assignments/platforms/scorm_page.js"]
MODULES = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "web").glob("**/*.js")
                 if "node_modules" not in p.parts and "vendor" not in p.parts)
failed = 0
for rel in CLASSIC + MODULES:
    text = (ROOT / rel).read_text(encoding="utf-8")
    args = [NODE, "--check"] if rel in CLASSIC else [NODE, "--input-type=module", "--check"]
    r = subprocess.run(args + ([str(ROOT / rel)] if rel in CLASSIC else []),
                       input=None if rel in CLASSIC else text, capture_output=True, text=True,
                       timeout=60)
    if r.returncode != 0:
        failed += 1
        print(f"{rel}: does not parse:\n{r.stderr.strip()}")
print(f"page_scripts: {len(CLASSIC) + len(MODULES)} scripts, {failed} that do not parse")
sys.exit(1 if failed else 0)
