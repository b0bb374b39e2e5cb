#!/usr/bin/env python3
"""Opens the HTML worked solution of every kind and method in headless Chromium.

For one problem of each (kind, method) of the bank it renders the page, loads it in Chromium,
checks in the resulting DOM that the formulas are MathML (<math> with <mrow>), that the
sketch is an inline SVG and that nothing refers to a script or the network but the 3D view's
(its data and scene_view.js beside the page), and saves a screenshot. Exit 77 (skipped) when Chromium is not installed.

usage: html_in_browser.py RAYGRADE_BINARY BANK_FOLDER OUTPUT_FOLDER
"""
import json
import os
import re
import sys

from chromium import SKIPPED, PageBrowser, require_chromium, write_solution_pages


def main():
    binary, bank, out = sys.argv[1:4]
    browser = require_chromium()
    if not browser:
        return SKIPPED
    pages, shots = write_solution_pages(binary, bank, out, "html,json")
    # The object's type of each problem, from the bank itself (a triangle and a convex
    # polygon share the method name "edge-tests").
    types = {}
    for root, _, files in os.walk(bank):
        for name in files:
            if name.endswith(".json"):
                with open(os.path.join(root, name), encoding="utf-8") as f:
                    data = json.load(f)
                for p in data.get("problems", [data]) if isinstance(data, dict) else []:
                    if isinstance(p, dict) and isinstance(p.get("object"), dict):
                        types[p.get("id")] = p["object"].get("type", "")
    chosen = {}
    for name in sorted(os.listdir(pages)):
        if not name.endswith(".json"):
            continue
        with open(os.path.join(pages, name), encoding="utf-8") as f:
            solution = json.load(f)
        kind = solution["kind"]
        if solution["id"] in types:
            kind += " " + types[solution["id"]]
        chosen.setdefault((kind, solution["methods"][0]["method"]), name[:-5])
    failures = []
    with PageBrowser() as pages_browser:
        for (kind, method), base in sorted(chosen.items()):
            check_page(pages_browser, pages, shots, kind, method, base, failures)
    print(f"screenshots in {shots}")
    return 1 if failures or not chosen else 0


def check_page(browser, pages, shots, kind, method, base, failures):
    """Loads one worked solution; appends its name to `failures` when a check fails."""
    page = os.path.abspath(os.path.join(pages, base + ".html"))
    with open(page, encoding="utf-8") as f:
        source = f.read()
    dom = browser.dom(page)
    problems = []
    if not re.search(r"<math[^>]*>\s*<mrow>", dom):
        problems.append("no MathML formulas in the DOM")
    if "<svg" not in dom:
        problems.append("no SVG sketch in the DOM")
    # The one script a worked solution may have is the 3D view's: its data and the viewer
    # beside the page (scene_view.js, which `raygrade solutions` writes there).
    rest = re.sub(r'<script type="application/json" id="scene-[^"]*-data">.*?</script>', "",
                  source, flags=re.S)
    rest = rest.replace('<script src="scene_view.js"></script>', "")
    if re.search(r"<script|<link|<img|<iframe|\bsrc=|url\(", rest):
        problems.append("refers to a script or an external resource")
    if re.search(r"https?://(?!www\.w3\.org/2000/svg)", source):
        problems.append("names a network address")
    shot = os.path.join(shots, base + ".png")
    browser.screenshot(page, shot, (1000, 1600))
    if not os.path.exists(shot) or os.path.getsize(shot) < 1000:
        problems.append("no screenshot")
    status = "ok" if not problems else "; ".join(problems)
    print(f"{kind} / {method}: {base}.html: {status}")
    if problems:
        failures.append(base)


if __name__ == "__main__":
    sys.exit(main())
