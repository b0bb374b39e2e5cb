#!/usr/bin/env python3
"""The SCORM package of an assignment (raygrade export scorm) run as an LMS runs it: unpacked
into a folder served over HTTP on 127.0.0.1, launched in an iframe of a small LMS page whose
API object is scorm-again's (Scorm12API as window.API; Scorm2004API as window.API_1484_11),
in headless Chromium driven by Selenium.

The assignment is two problems of the bank with one set of numbers for everyone (a plane's hit
and the cylinder's quadratic, 2 points each). A student types the answers `raygrade solve`
gives, presses each Check, and the LMS holds score 100 and "passed" (SCORM 1.2), or scaled 1,
"passed" and "completed" (2004); with the plane's t wrong it holds 50 and "incomplete" (2004:
success "unknown"). The LMS's data (scorm-again's renderCommitCMI) loaded into a fresh LMS
page brings the answers and attempts back, with the browser's own storage cleared first
(resume from cmi.suspend_data). Stored data the page never wrote (null where answers go, a
prototype key, text that is not JSON) is ignored: the page still grades and sends the score.
The page opened from file://, with no LMS, still grades.
imsmanifest.xml is checked with xmllint: well-formed always; against the SCORM 1.2 and 2004
schemas when RAYGRADE_SCHEMAS (default ../shared/schemas beside the repository) holds them
(scorm12/, scorm2004/), saying which ran.

Usage: scorm_in_browser.py RAYGRADE RAYGRADE_JS REPOSITORY SCORM_AGAIN_DIST OUT
"""
import functools
import http.server
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import zipfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, failures  # noqa: E402
from chromium import SKIPPED, click, require_chromium, selenium_chromium, wait_for  # noqa: E402

try:
    from selenium.webdriver.common.by import By
except ImportError:
    print("python3-selenium is not installed (scripts/install-deps.sh installs it): skipped")
    sys.exit(SKIPPED)

RAYGRADE, RAYGRADE_JS, REPOSITORY, SCORM_AGAIN, OUT = sys.argv[1:6]
PROBLEMS = [("variant-plane", 2), ("seed000-cylinder-derive-origin", 2)]


def export(assignment, out, version):
    """`raygrade export scorm`; returns the zip unpacked into out/unpacked, as an LMS does."""
    args = [RAYGRADE, "export", "scorm", assignment, "--grader-js", RAYGRADE_JS, "--out", out]
    if version != "1.2":
        args += ["--scorm", version]
    r = subprocess.run(args, capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, f"export scorm --scorm {version} failed: {r.stderr}")
    print(r.stderr.strip())
    unpacked = os.path.join(out, "unpacked")
    with zipfile.ZipFile(os.path.join(out, "scorm-check-scorm.zip")) as z:
        names = sorted(z.namelist())
        check(names == ["imsmanifest.xml", "index.html"], f"the zip holds {names}")
        z.extractall(unpacked)
    return unpacked


def validate_manifest(folder, version):
    """xmllint on imsmanifest.xml: well-formed, and valid against the schemas when present."""
    manifest = os.path.join(folder, "imsmanifest.xml")
    if not shutil.which("xmllint"):
        check(False, "xmllint is missing (scripts/install-deps.sh installs libxml2-utils)")
        return
    r = subprocess.run(["xmllint", "--noout", manifest], capture_output=True, text=True)
    check(r.returncode == 0, f"SCORM {version}: imsmanifest.xml is not well-formed: {r.stderr}")
    print(f"SCORM {version}: imsmanifest.xml is well-formed (xmllint --noout)")
    with open(manifest, encoding="utf-8") as f:
        text = f.read()
    check('href="index.html"' in text and "<file href=\"index.html\"" in text,
          "the resource does not list index.html")
    wanted = ('adlcp:scormtype="sco"', "<schemaversion>1.2</schemaversion>") if version == "1.2" \
        else ('adlcp:scormType="sco"', "<schemaversion>2004 4th Edition</schemaversion>")
    for w in wanted:
        check(w in text, f"SCORM {version}: imsmanifest.xml lacks {w}")

    schemas = os.environ.get("RAYGRADE_SCHEMAS",
                             os.path.join(REPOSITORY, "..", "shared", "schemas"))
    if version == "1.2":
        folder_name, files = "scorm12", {"http://www.imsproject.org/xsd/imscp_rootv1p1p2":
                                         "imscp_rootv1p1p2.xsd",
                                         "http://www.adlnet.org/xsd/adlcp_rootv1p2":
                                         "adlcp_rootv1p2.xsd"}
    else:
        folder_name, files = "scorm2004", {"http://www.imsglobal.org/xsd/imscp_v1p1":
                                           "imscp_v1p1.xsd",
                                           "http://www.adlnet.org/xsd/adlcp_v1p3":
                                           "adlcp_v1p3.xsd"}
    source = os.path.abspath(os.path.join(schemas, folder_name))
    if not all(os.path.exists(os.path.join(source, f)) for f in files.values()):
        print(f"SCORM {version}: no schemas in {source}: validated for well-formedness only")
        return
    # The schemas side by side in a scratch folder, with one schema importing both namespaces
    # (xmllint takes one). A schema that imports the W3C's xml.xsd from the web (the published
    # imscp_v1p1.xsd does) reads SCORM 1.2's ims_xml.xsd (the same xml:lang and xml:base)
    # instead, so that nothing is fetched.
    scratch = os.path.join(os.path.dirname(folder), "schemas")
    shutil.rmtree(scratch, ignore_errors=True)
    shutil.copytree(source, scratch)
    xml_xsd = os.path.join(source, "..", "scorm12", "ims_xml.xsd")
    for name in os.listdir(scratch):
        path = os.path.join(scratch, name)
        if not name.endswith(".xsd") or not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8-sig") as f:
            schema = f.read()
        local = schema.replace('"http://www.w3.org/2001/xml.xsd"', '"ims_xml.xsd"')
        if local != schema:
            shutil.copy(xml_xsd, os.path.join(scratch, "ims_xml.xsd"))
        with open(path, "w", encoding="utf-8") as f:
            f.write(local)
    imports = "".join(f'<xsd:import namespace="{ns}" schemaLocation="{f}"/>'
                      for ns, f in files.items())
    both = os.path.join(scratch, "both.xsd")
    with open(both, "w", encoding="utf-8") as f:
        f.write('<?xml version="1.0"?>\n<xsd:schema xmlns:xsd="http://www.w3.org/2001/XMLSchema" '
                f'targetNamespace="urn:raygrade:scorm-check">{imports}</xsd:schema>\n')
    r = subprocess.run(["xmllint", "--noout", "--nonet", "--schema", both, manifest],
                       capture_output=True, text=True)
    check(r.returncode == 0, f"SCORM {version}: imsmanifest.xml is not valid: {r.stderr}")
    print(f"SCORM {version}: imsmanifest.xml is valid against {', '.join(files.values())} "
          f"({source})" if r.returncode == 0 else r.stderr)


def serve(folder):
    """An HTTP server on 127.0.0.1 (a free port) serving `folder`; returns its base URL."""
    handler = functools.partial(QuietHandler, directory=folder)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}/"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


# The LMS: scorm-again's API object on the window, the package's launch file in an iframe. The
# test starts it with start(version, cmi), cmi being the data the LMS kept (or null).
HARNESS = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>LMS</title>
<script src="scorm12.min.js"></script><script src="scorm2004.min.js"></script>
<script>
function start(version, cmi) {
  const settings = {logLevel: 5, autocommit: false};
  const api = version === "1.2" ? new Scorm12API(settings) : new Scorm2004API(settings);
  if (version === "1.2") {
    api.cmi.core.student_id = "s042";
    api.cmi.core.student_name = "Student, Test";
  } else {
    api.cmi.learner_id = "s042";
    api.cmi.learner_name = "Student, Test";
  }
  if (cmi) api.loadFromJSON(cmi);
  window[version === "1.2" ? "API" : "API_1484_11"] = api;
  const frame = document.createElement("iframe");
  frame.id = "sco";
  frame.title = "The activity";
  frame.style = "width: 1150px; height: 1400px";
  frame.src = "index.html";
  document.body.appendChild(frame);
}
</script></head><body></body></html>
"""


class Lms:
    """The harness page in the browser, for one package served at `base`."""

    def __init__(self, driver, base, version):
        self.driver, self.base, self.version = driver, base, version
        self.api = "window.API" if version == "1.2" else "window.API_1484_11"

    def launch(self, cmi=None, clear_browser=True):
        d = self.driver
        d.switch_to.default_content()
        d.get(self.base + "harness.html")
        if clear_browser:
            # Only the LMS's copy can bring answers back.
            d.execute_script("localStorage.clear()")
        d.execute_script("start(arguments[0], arguments[1])", self.version, cmi)
        d.switch_to.frame(d.find_element(By.ID, "sco"))
        ready = wait_for(d, "window.raygradePractice && window.raygradePractice.ready")
        check(ready, f"SCORM {self.version}: the grader never became ready")

    def value(self, element):
        """A value of the LMS's data model ("cmi.core.score.raw"), as the LMS holds it."""
        v = self.kept()
        for key in element.split(".")[1:]:
            v = v[key]
        return v

    def kept(self):
        """What the LMS keeps of the attempt: its data model as JSON (renderCommitCMI)."""
        d = self.driver
        d.switch_to.default_content()
        cmi = d.execute_script(f"return {self.api}.renderCommitCMI(true).cmi")
        d.switch_to.frame(d.find_element(By.ID, "sco"))
        return cmi


def page_data(driver):
    return json.loads(driver.find_element(By.ID, "handout-data").get_attribute("textContent"))


def input_texts(driver, answers):
    """The inputs' names and the text to type in each, from the page's forms and the answers
    `raygrade solve` gives: one hit's t, point and normal, and formulas."""
    texts = {}
    for p in page_data(driver)["problems"]:
        answer = answers[p["id"]]
        for i, f in enumerate(p["form"]["fields"]):
            prefix = f"{p['id']}.{i}"
            if f["type"] == "hits":
                for c in f["columns"]:
                    value = answer["hits"][0][c["key"]]
                    if c["type"] == "vector":
                        for axis, x in zip("xyz", value):
                            texts[f"{prefix}.0.{c['key']}.{axis}"] = f"{x:g}"
                    else:
                        texts[f"{prefix}.0.{c['key']}"] = f"{value:g}"
            else:
                texts[prefix] = str(answer[f["key"]])
    return texts


def type_and_check(driver, texts):
    """Types every answer as a student does, then presses each problem's Check."""
    for name, text in texts.items():
        box = driver.find_element(By.NAME, name)
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", box)
        box.clear()
        box.send_keys(text)
    for button in driver.find_elements(By.CSS_SELECTOR, "button.check"):
        # A Check counts an attempt: its line under the button changes when the grading is done.
        attempts = button.find_element(By.XPATH, "following-sibling::span[@class='attempts muted']")
        before = attempts.text
        click(driver, button)
        end = time.time() + 30
        while attempts.text == before and time.time() < end:
            time.sleep(0.05)


def feedback(driver):
    """What the page says under each problem, for a failure's message."""
    return [e.text for e in driver.find_elements(By.CSS_SELECTOR, ".practice")]


def scores(driver):
    return [e.text for e in driver.find_elements(By.CSS_SELECTOR, ".practice-feedback .score")]


def run_version(driver, unpacked, version, answers):
    """A right attempt, a resumed one, and a wrong one through the LMS of `version`."""
    with open(os.path.join(unpacked, "harness.html"), "w", encoding="utf-8") as f:
        f.write(HARNESS)
    for name in ("scorm12.min.js", "scorm2004.min.js"):
        shutil.copy(os.path.join(SCORM_AGAIN, name), unpacked)
    server, base = serve(unpacked)
    try:
        lms = Lms(driver, base, version)
        v12 = version == "1.2"
        raw = "cmi.core.score.raw" if v12 else "cmi.score.raw"
        status = "cmi.core.lesson_status" if v12 else "cmi.success_status"

        # Every answer right: full marks for the whole assignment.
        lms.launch()
        texts = input_texts(driver, answers)
        type_and_check(driver, texts)
        check(scores(driver) == ["Score: 2 / 2"] * 2,
              f"the page scores {scores(driver)}: {feedback(driver)}")
        got = (lms.value(raw), lms.value(status))
        check(got == ("100", "passed"),
              f"SCORM {version}: right answers sent {got}, not 100, passed")
        if v12:
            got = (lms.value("cmi.core.score.min"), lms.value("cmi.core.score.max"),
                   lms.value("cmi.core.exit"))
            check(got == ("0", "100", "suspend"), f"SCORM 1.2: min, max, exit are {got}")
        else:
            got = (lms.value("cmi.score.scaled"), lms.value("cmi.completion_status"),
                   lms.value("cmi.exit"))
            check(got == ("1", "completed", "suspend"),
                  f"SCORM 2004: scaled, completion, exit are {got}")
        suspend = lms.value("cmi.suspend_data")
        print(f"SCORM {version}: right answers: score {lms.value(raw)}, {lms.value(status)}; "
              f"suspend_data {len(suspend)} characters")
        check(0 < len(suspend) <= 4096, f"suspend_data is {len(suspend)} characters")

        # The next launch: a fresh LMS page with the data the LMS kept, the browser's copy gone.
        cmi = lms.kept()
        if v12:
            cmi["core"]["entry"] = "resume"
        else:
            cmi["entry"] = "resume"
        lms.launch(cmi)
        shown = {n: driver.find_element(By.NAME, n).get_attribute("value") for n in texts}
        check(shown == texts, f"SCORM {version}: resumed inputs are {shown}, not {texts}")
        check("Attempts: 1 — full marks" in driver.find_element(By.TAG_NAME, "main").text,
              f"SCORM {version}: the attempts are not resumed")
        print(f"SCORM {version}: resumed {len(shown)} answers from cmi.suspend_data")

        # One answer wrong (the plane's t): half the points, not passed.
        wrong = dict(texts)
        t_name = next(n for n in texts if n.endswith(".t"))
        wrong[t_name] = "7"
        lms.launch()
        type_and_check(driver, wrong)
        got = (lms.value(raw), lms.value(status))
        # The plane's hit is not found at t = 7 (0 of 2 points), the cylinder earns 2 of 2.
        want = ("50", "incomplete" if v12 else "unknown")
        check(got == want, f"SCORM {version}: one wrong t sent {got}, not {want}")
        print(f"SCORM {version}: one wrong answer: score {got[0]}, {got[1]} "
              f"(the page: {', '.join(scores(driver))})")

        # Stored data this page never wrote (an older page's, or anyone's who can set
        # cmi.suspend_data): the page still opens, grades and reports the score. The first threw
        # inside the LMS script, and no score was ever sent again (issue 47).
        for hostile in ('{"v":1,"i":{"x":null}}', '{"v":1,"i":{},"p":{"p":null},"r":"x"}',
                        '{"v":1,"i":{"":{"__proto__":{"polluted":"1"}}}}', "not JSON"):
            cmi = lms.kept()
            cmi["suspend_data"] = hostile
            if v12:
                cmi["core"]["entry"] = "resume"
            else:
                cmi["entry"] = "resume"
            lms.launch(cmi)
            linked = driver.execute_script("return !!window.raygradeLms")
            check(linked, f"SCORM {version}: suspend_data {hostile!r} cut the page from the LMS")
            type_and_check(driver, texts)
            got = lms.value(raw)
            check(got == "100", f"SCORM {version}: with suspend_data {hostile!r} the right answers "
                  f"sent {got}, not 100: {feedback(driver)}")
        print(f"SCORM {version}: hostile suspend_data ignored, the score still sent")
    finally:
        driver.switch_to.default_content()
        server.shutdown()


def main():
    if not require_chromium() or not shutil.which("chromedriver"):
        print("chromium-driver is not installed (scripts/install-deps.sh installs it): skipped")
        return SKIPPED
    if not os.path.exists(os.path.join(SCORM_AGAIN, "scorm12.min.js")):
        print(f"scorm-again is missing from {SCORM_AGAIN} (scripts/fetch-web-libs.sh fetches it): "
              "skipped")
        return SKIPPED
    if not os.path.exists(RAYGRADE_JS):
        print(f"{RAYGRADE_JS} is missing (scripts/build-web.sh builds it)")
        return 1
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(OUT)
    with open(os.path.join(REPOSITORY, "assignments", "homework-rays.json"), encoding="utf-8") as f:
        example = json.load(f)
    assignment = os.path.join(OUT, "scorm-check.json")
    with open(assignment, "w", encoding="utf-8") as f:
        json.dump({"assignment": "scorm-check", "title": "SCORM check: a plane and a cylinder",
                   # Relative: the page reads the assignment as written, from its own files.
                   "bank": os.path.relpath(os.path.join(REPOSITORY, "problems"), OUT),
                   "feedback": example["feedback"],
                   "problems": [{"id": p, "points": n} for p, n in PROBLEMS]}, f, indent=2)
    solved = subprocess.run([RAYGRADE, "solve", assignment, "--format", "json"],
                            capture_output=True, text=True, timeout=120)
    check(solved.returncode == 0, f"solve failed: {solved.stderr}")
    answers = {s["id"]: s["answer"] for s in json.loads(solved.stdout)["solutions"]}

    profile = tempfile.mkdtemp(prefix="raygrade-scorm-")
    driver = selenium_chromium(profile, size="1200,1500")
    driver.set_script_timeout(120)
    driver.set_page_load_timeout(120)
    start = time.time()
    try:
        for version in ("1.2", "2004"):
            unpacked = export(assignment, os.path.join(OUT, f"scorm-{version}"), version)
            validate_manifest(unpacked, version)
            run_version(driver, unpacked, version, answers)
            print(f"SCORM {version}: {time.time() - start:.1f} s since the browser started")

        # No LMS: the page from disk grades as any practice page.
        page = os.path.abspath(os.path.join(OUT, "scorm-1.2", "unpacked", "index.html"))
        driver.get("file://" + page)
        wait_for(driver, "window.raygradePractice && window.raygradePractice.ready")
        check(driver.execute_script("return window.raygradeLms") is None,
              "the page found an LMS where there is none")
        type_and_check(driver, input_texts(driver, answers))
        check(scores(driver) == ["Score: 2 / 2"] * 2,
              f"without an LMS the page scores {scores(driver)}: {feedback(driver)}")
        status = driver.find_element(By.ID, "grader-status").text
        check("nothing is sent" in status, f"without an LMS the page says {status!r}")
        print(f"no LMS (file://): {scores(driver)}")
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    print(f"{time.time() - start:.1f} s in the browser")
    print("FAILED" if failures else "ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
