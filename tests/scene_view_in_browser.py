#!/usr/bin/env python3
"""The 3D view of every problem of the bank, drawn by headless Chromium (WebGL in software).

Writes the bank's worked solutions (`raygrade solutions`, which puts the view's script beside
the pages), then:
- opens one solution page from file:// and finds its view drawn by the script loaded from
  scene_view.js;
- gathers the view data of every page into one page and draws them one after the other: each
  canvas must show several distinct colours besides its background (not blank), and no object
  may be of a type the viewer does not know. By default it draws one view of each sort (the
  same object types, camera, lights, given arrows and answer marks: about 50 of the bank's
  views); with RAYGRADE_LONG=1 (or --every) it draws every problem's;
- draws five chosen problems from their fixed initial camera and compares each image with its
  reference in tests/data/scene_view/ (REFERENCE_TOLERANCE below), writing the images and a
  picture of the differences to OUT;
- writes the handout page of the example assignment and checks that no view on it holds an
  answer: no hit point or normal of the student's answers, no answer data at all.

Usage: scene_view_in_browser.py RAYGRADE SOURCE_ROOT OUT [--update-references] [--every]
Exits 77 (skipped) without Chromium, Selenium or the viewer's script.
"""
import base64
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, failures  # noqa: E402
from chromium import FLAGS, SKIPPED, require_chromium  # noqa: E402

try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
except ImportError:
    print("python3-selenium is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(SKIPPED)

RAYGRADE, ROOT, OUT = sys.argv[1:4]
RAYGRADE, ROOT, OUT = os.path.abspath(RAYGRADE), os.path.abspath(ROOT), os.path.abspath(OUT)
UPDATE = "--update-references" in sys.argv[4:]
# Every problem of the bank with RAYGRADE_LONG=1 (about 2 minutes); otherwise one of each sort.
EVERY = os.environ.get("RAYGRADE_LONG") == "1" or "--every" in sys.argv[4:]
REFERENCES = os.path.join(ROOT, "tests", "data", "scene_view")
# The chosen problems: a sphere, a transformed box, a cone, a ray tree and a camera.
CHOSEN = ["seed000-sphere-1", "transform-rotated-box", "cone-side", "seed001-ray-tree",
          "seed004-camera-ray"]
# Software rendering is the same from run to run on one machine, but not bit for bit across
# versions of Chromium's SwiftShader (antialiasing, rounding of edges): an image passes when the
# mean absolute difference per channel is at most 2 (of 255) and at most 1% of its pixels
# differ by more than 48 in some channel.
MEAN_LIMIT = 2.0
PIXEL_LIMIT = 48
SHARE_LIMIT = 0.01
# A drawn canvas holds at least this many colours (quantized to 32 levels per channel) that
# each cover 0.02% of it (28 pixels of 480 by 288), besides its background.
MIN_COLOURS = 3
# WebGL in software: Chromium's flags for SwiftShader without a GPU.
WEBGL_FLAGS = ["--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
               "--ignore-gpu-blocklist", "--force-device-scale-factor=1"]


def run(*args):
    return subprocess.run([RAYGRADE, *args], capture_output=True, text=True, cwd=ROOT)


# Draws one view into a fixed 480-pixel container, measures it, and returns what it found
# (colours, the image as a PNG data URL when asked) before freeing its WebGL context.
DRAW = r"""
const [data, keepImage, reference] = arguments;
const box = document.createElement('div');
box.style.width = '480px';
document.body.appendChild(box);
const view = window.raygradeSceneView.mount(box, data);
const gl = view.renderer.getContext();
const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
const pixels = new Uint8Array(w * h * 4);
gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
const counts = new Map();
for (let i = 0; i < pixels.length; i += 4) {
  const key = (pixels[i] >> 3) << 10 | (pixels[i + 1] >> 3) << 5 | pixels[i + 2] >> 3;
  counts.set(key, (counts.get(key) || 0) + 1);
}
const sorted = [...counts.values()].sort((a, b) => b - a);
const colours = sorted.slice(1).filter((n) => n >= w * h * 0.0002).length;
const out = {ready: box.dataset.ready, colours, width: w, height: h,
             covered: 1 - sorted[0] / (w * h)};
if (keepImage) out.image = view.renderer.domElement.toDataURL('image/png');
view.renderer.dispose();
view.renderer.forceContextLoss();
box.remove();
return out;
"""

# Compares a PNG (data URL) with the reference (data URL); returns the statistics and a picture
# of the differences.
COMPARE = r"""
const [shot, reference, limit] = arguments;
const done = arguments[arguments.length - 1];
const load = (src) => new Promise((ok, fail) => {
  const img = new Image(); img.onload = () => ok(img); img.onerror = fail; img.src = src; });
Promise.all([load(shot), load(reference)]).then(([a, b]) => {
  if (a.width !== b.width || a.height !== b.height) {
    done({size: [a.width, a.height, b.width, b.height]}); return; }
  const pixels = (img) => { const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height; const g = c.getContext('2d');
    g.drawImage(img, 0, 0); return g.getImageData(0, 0, c.width, c.height); };
  const p = pixels(a), q = pixels(b);
  const c = document.createElement('canvas'); c.width = a.width; c.height = a.height;
  const g = c.getContext('2d'); const diff = g.createImageData(a.width, a.height);
  let sum = 0, off = 0;
  for (let i = 0; i < p.data.length; i += 4) {
    let worst = 0;
    for (let k = 0; k < 3; ++k) { const d = Math.abs(p.data[i + k] - q.data[i + k]);
      sum += d; worst = Math.max(worst, d); }
    if (worst > limit) ++off;
    diff.data[i] = worst > limit ? 255 : worst * 4; diff.data[i + 1] = 0; diff.data[i + 2] = 0;
    diff.data[i + 3] = 255;
  }
  g.putImageData(diff, 0, 0);
  const n = p.data.length / 4;
  done({mean: sum / (n * 3), share: off / n, diff: c.toDataURL('image/png')});
}, (e) => done({error: String(e)}));
"""


def data_url(path):
    with open(path, "rb") as f:
        return "data:image/png;base64," + base64.b64encode(f.read()).decode()


def save(url, path):
    with open(path, "wb") as f:
        f.write(base64.b64decode(url.split(",", 1)[1]))


def sort_of_view(data):
    """What a view is made of: its objects' types, and whether it has a camera, lights, a
    given ray or arrows, answer hits and answer rays. Views of one sort are drawn alike."""
    answers = data.get("answers", {})
    return (tuple(sorted({o["shape"]["type"] for o in data.get("objects", [])})),
            "camera" in data, bool(data.get("lights")), "ray" in data, bool(data.get("arrows")),
            bool(answers.get("hits")), tuple(sorted({s["role"] for s in answers.get("segments", [])})))


def sample(views):
    """The chosen views and the first view of every other sort."""
    out, seen = {}, set()
    for base, data in views.items():
        key = sort_of_view(data)
        if base in CHOSEN or key not in seen:
            out[base] = data
            seen.add(key)
    return out


def view_data(html):
    """The JSON of every view on a page, by its element's id."""
    return {m.group(1): json.loads(m.group(2)) for m in re.finditer(
        r'<script type="application/json" id="(scene-[^"]*-data)">(.*?)</script>', html, re.S)}


def vectors(value, out):
    """Every list of three numbers in a JSON value."""
    if isinstance(value, list):
        if len(value) == 3 and all(isinstance(x, (int, float)) for x in value):
            out.append(value)
        for v in value:
            vectors(v, out)
    elif isinstance(value, dict):
        for v in value.values():
            vectors(v, out)
    return out


def near(a, b):
    return all(abs(x - y) <= 1e-9 * max(1, abs(x), abs(y)) for x, y in zip(a, b))


def check_handout():
    """The handout page's views hold the givens only: no answer, no hit point, no normal."""
    work = tempfile.mkdtemp(prefix="raygrade-scene-handout-")
    try:
        roster = os.path.join(work, "roster.csv")
        with open(roster, "w") as f:
            f.write("id,name,email\ns001,Ada Lovelace,ada@example.org\n")
        assignment = os.path.join(ROOT, "assignments", "homework-rays.json")
        r = run("handout", assignment, "--roster", roster, "--out", os.path.join(work, "h"))
        if not check(r.returncode == 0, f"handout exited {r.returncode}: {r.stderr}"):
            return
        with open(os.path.join(work, "h", "s001", "index.html"), encoding="utf-8") as f:
            views = view_data(f.read())
        check(views, "the handout page has no 3D view")
        r = run("solve", assignment, "--student", "s001", "--format", "json")
        solutions = {s["id"]: s["answer"] for s in json.loads(r.stdout)["solutions"]}
        found = 0
        for key, data in views.items():
            check("answers" not in data, f"handout view {key} holds answers")
            # Where the pixel lies tells the camera ray a camera kind asks for.
            check("pixel" not in data.get("camera", {}), f"handout view {key} shows the pixel")
            given = vectors(data, [])
            index = int(key.split("-")[1])
            # The page lists problems in order; the view's number is its index.
            answer = list(solutions.values())[index] if index < len(solutions) else {}
            for hit in answer.get("hits", []):
                for name in ("point", "normal"):
                    v = hit.get(name)
                    if v and any(near(v, g) for g in given):
                        # A normal may equal a given direction by chance; a point may not.
                        check(name == "normal", f"handout view {key} holds the hit {name} {v}")
                    found += name == "point"
        check(found > 0, "no hit point of the student's answers was looked for")
        print(f"handout: {len(views)} views, {found} hit points looked for, none found")
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main():
    browser = require_chromium()
    if not browser:
        return SKIPPED
    if not shutil.which("chromedriver"):
        print("chromedriver is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    start = time.time()
    shots = os.path.join(OUT, "screenshots")
    pages = os.path.join(OUT, "pages")
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(shots)
    r = run("solutions", os.path.join(ROOT, "problems"), "--out", pages, "--format", "html")
    if r.returncode != 0:
        print(f"solutions exited {r.returncode}: {r.stderr}")
        return 1
    script = os.path.join(pages, "scene_view.js")
    if not os.path.exists(script):
        print("raygrade solutions wrote no scene_view.js (a build without the viewer?): skipped")
        return SKIPPED
    views = {}
    for name in sorted(os.listdir(pages)):
        if name.endswith(".html"):
            with open(os.path.join(pages, name), encoding="utf-8") as f:
                for data in view_data(f.read()).values():
                    views[name[:-5]] = data
    # One page that loads the viewer and nothing else; the test draws each view on it.
    harness = os.path.join(pages, "all-views.html")
    with open(harness, "w") as f:
        f.write('<!DOCTYPE html><html><head><meta charset="utf-8"><title>views</title></head>'
                '<body style="margin:0"><script src="scene_view.js"></script></body></html>\n')

    options = webdriver.ChromeOptions()
    for flag in FLAGS:
        if flag != "--disable-gpu":
            options.add_argument(flag if flag != "--headless" else "--headless=new")
    for flag in WEBGL_FLAGS:
        options.add_argument(flag)
    profile = tempfile.mkdtemp(prefix="raygrade-scene-view-")
    options.add_argument(f"--user-data-dir={profile}")
    options.add_argument("--window-size=1000,800")
    options.binary_location = browser
    driver = webdriver.Chrome(service=Service(shutil.which("chromedriver")), options=options)
    driver.set_script_timeout(120)
    try:
        # A real page: its view is drawn by the script it loads from beside it.
        page = os.path.join(pages, "seed000-sphere-1.html")
        driver.get("file://" + page)
        # Views are drawn once the page has loaded and the browser is idle.
        ready = None
        for _ in range(100):
            ready = driver.execute_script(
                "const v = document.querySelector('.scene-view'); return v && v.dataset.ready;")
            if ready:
                break
            time.sleep(0.1)
        check(ready == "drawn", f"seed000-sphere-1.html: the view is {ready!r}, not drawn")

        driver.get("file://" + harness)
        check(driver.execute_script("return !!window.raygradeSceneView"),
              "the viewer's script did not load")
        blank = []
        drawn = views if EVERY else sample(views)
        for base, data in drawn.items():
            got = driver.execute_script(DRAW, data, False, None)
            ok = got["ready"] == "drawn" and got["colours"] >= MIN_COLOURS
            if not ok:
                blank.append(f"{base} ({got['ready']}, {got['colours']} colours)")
        check(not blank, f"{len(blank)} view(s) not drawn: {', '.join(blank)}")
        print(f"drawn: {len(drawn) - len(blank)} of {len(drawn)} problems' views"
              + ("" if EVERY else f" (one of each sort, of {len(views)}; RAYGRADE_LONG=1 draws "
                                  "every one)"))

        for base in CHOSEN:
            if not check(base in views, f"{base}: no such problem with a view"):
                continue
            got = driver.execute_script(DRAW, views[base], True, None)
            shot = os.path.join(shots, base + ".png")
            save(got["image"], shot)
            reference = os.path.join(REFERENCES, base + ".png")
            if UPDATE:
                os.makedirs(REFERENCES, exist_ok=True)
                shutil.copyfile(shot, reference)
                print(f"{base}: reference written")
                continue
            if not check(os.path.exists(reference), f"{base}: no reference {reference}"):
                continue
            cmp = driver.execute_async_script(COMPARE, got["image"], data_url(reference),
                                              PIXEL_LIMIT)
            if "diff" in cmp:
                save(cmp["diff"], os.path.join(shots, base + "-diff.png"))
            if check("mean" in cmp, f"{base}: cannot compare: {cmp}"):
                print(f"{base}: mean difference {cmp['mean']:.3f}, "
                      f"{100 * cmp['share']:.3f}% of pixels off")
                check(cmp["mean"] <= MEAN_LIMIT and cmp["share"] <= SHARE_LIMIT,
                      f"{base}: differs from its reference (mean {cmp['mean']:.2f} > "
                      f"{MEAN_LIMIT} or {100 * cmp['share']:.2f}% > {100 * SHARE_LIMIT}% off)")
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    check_handout()
    print(f"screenshots and differences in {shots}; {time.time() - start:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
