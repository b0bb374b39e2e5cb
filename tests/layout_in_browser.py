#!/usr/bin/env python3
"""Measures the layout of the HTML worked solutions in headless Chromium at a 1200-pixel window.

Every worked solution of the bank is rendered as HTML on one page (`solve --format html`), and
the pages of three long ones on their own (`solutions --format html`); each gets a small script
(in a copy made for the test, never in the output of raygrade) that measures, after layout:

- the document: its scrollWidth against its clientWidth (more means a horizontal scrollbar);
- every formula: whether it reaches past the right edge of its article, or scrolls inside
  itself (scrollWidth over clientWidth);
- every label of every sketch: its box on the page (the browser's own text metrics, with the
  transform that puts a second view beside the first), and whether any two boxes of one sketch
  overlap.

The measurements are read back from the dumped DOM. Screenshots of three long worked solutions
(the triangle's edge tests e_ab, the camera ray's d_r, the refracted direction t) are saved at
1200 pixels with the scrollbars shown, in OUTPUT_FOLDER/screenshots. Exit 77 (skipped) when
Chromium is not installed.

usage: layout_in_browser.py RAYGRADE_BINARY BANK_FOLDER OUTPUT_FOLDER
"""
import json
import os
import re
import subprocess
import sys

from chromium import SKIPPED, require_chromium, run_browser, write_solution_pages

WIDTH, HEIGHT = 1200, 900

# Long worked solutions of the bank, shown in screenshots.
LONG = ["seed004-triangle", "camera-ray-corner", "optics-refract-water"]

MEASURE = r"""<script>
(function () {
  const root = document.documentElement;
  const out = {scrollWidth: root.scrollWidth, clientWidth: root.clientWidth,
               overflowing: [], overlaps: [], labels: 0};
  for (const m of document.querySelectorAll("math")) {
    const article = m.closest("article");
    if (!article) continue;
    const edge = article.getBoundingClientRect().right;
    const box = m.getBoundingClientRect();
    const inner = m.scrollWidth > m.clientWidth + 1 && m.clientWidth > 0;
    if (box.right > edge + 0.5 || inner) {
      out.overflowing.push({text: m.textContent.slice(0, 120), right: box.right, edge: edge});
    }
  }
  for (const svg of document.querySelectorAll("svg")) {
    const boxes = [];
    for (const t of svg.querySelectorAll("text")) {
      // On the page, transforms applied: a sketch of two views moves the second one aside.
      const b = t.getBoundingClientRect();
      boxes.push({text: t.textContent, x: b.x, y: b.y, w: b.width, h: b.height});
    }
    out.labels += boxes.length;
    for (let i = 0; i < boxes.length; ++i) {
      for (let j = i + 1; j < boxes.length; ++j) {
        const a = boxes[i], b = boxes[j];
        const dx = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
        const dy = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
        if (dx > 0 && dy > 0) out.overlaps.push([a, b]);
      }
    }
  }
  const pre = document.createElement("pre");
  pre.id = "layout-measure";
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>
"""


def measure(browser, page, work):
    """The measurements of `page`, from a copy of it with the measuring script."""
    with open(page, encoding="utf-8") as f:
        source = f.read()
    probe = os.path.join(work, "probe-" + os.path.basename(page))
    with open(probe, "w", encoding="utf-8") as f:
        f.write(source.replace("</body>", MEASURE + "</body>"))
    dom = run_browser(browser, [f"--window-size={WIDTH},{HEIGHT}", "--dump-dom"], probe).stdout
    found = re.search(r'<pre id="layout-measure">(.*?)</pre>', dom, re.S)
    if not found:
        return None
    text = found.group(1).replace("&quot;", '"').replace("&lt;", "<").replace("&gt;", ">")
    return json.loads(text.replace("&amp;", "&"))


def main():
    binary, bank, out = sys.argv[1:4]
    browser = require_chromium()
    if not browser:
        return SKIPPED
    pages, shots = write_solution_pages(binary, bank, out, "html")
    work = os.path.join(out, "probes")
    os.makedirs(work, exist_ok=True)
    # Every worked solution of the bank on one page (as `solve --format html` prints them),
    # measured in one run of the browser; the pages of the long ones measured on their own too.
    everything = os.path.abspath(os.path.join(work, "all.html"))
    with open(everything, "w", encoding="utf-8") as f:
        f.write(subprocess.run([binary, "solve", bank, "--format", "html"], check=True,
                               capture_output=True, text=True).stdout)
    failures = []
    labels = 0
    measured = [everything] + [os.path.abspath(os.path.join(pages, b + ".html")) for b in LONG]
    for page in measured:
        name = os.path.basename(page)
        if not os.path.exists(page):
            failures.append(f"{name}: not written")
            continue
        m = measure(browser, page, os.path.abspath(work))
        if m is None:
            failures.append(f"{name}: no measurement in the DOM")
            continue
        labels += m["labels"]
        if m["scrollWidth"] > m["clientWidth"]:
            failures.append(f"{name}: document {m['scrollWidth']} px wide in a "
                            f"{m['clientWidth']} px window: a horizontal scrollbar")
        for f in m["overflowing"]:
            failures.append(f"{name}: formula past the edge ({f['right']:.0f} > "
                            f"{f['edge']:.0f} px): {f['text']}")
        for a, b in m["overlaps"]:
            failures.append(f"{name}: labels overlap: {a['text']!r} and {b['text']!r}")
    for base in LONG:
        page = os.path.abspath(os.path.join(pages, base + ".html"))
        shot = os.path.join(shots, base + "-1200px.png")
        if not os.path.exists(page):
            failures.append(f"{base}.html: not written")
            continue
        # Tall enough to show the long formulas; the scrollbars are shown, not hidden.
        run_browser(browser, [f"--window-size={WIDTH},3000", f"--screenshot={shot}"], page)
        if not os.path.exists(shot) or os.path.getsize(shot) < 1000:
            failures.append(f"{base}: no screenshot")
    for f in failures:
        print("FAIL", f)
    print(f"every worked solution of {bank} measured at {WIDTH} px ({labels} sketch labels); "
          f"{len(failures)} problems; screenshots in {shots}")
    return 1 if failures or labels == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
