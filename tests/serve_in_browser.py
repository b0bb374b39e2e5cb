#!/usr/bin/env python3
"""A student in headless Chromium: the platform's login redirect, the id_token posted back to
raygrade serve, the student page of their own numbers; a typed answer sent with the page's
Submit button and the feedback shown (the page's own policy lets it connect to the tool, and
the cookies set with SameSite=None; Secure are sent over http on loopback).

Usage: serve_in_browser.py RAYGRADE SOURCE_DIR WORK_DIR
RAYGRADE_TEST_DATABASE=postgresql runs the tool on a throwaway PostgreSQL cluster
(tests/lti/pgcluster.py) rather than SQLite: skipped (77) without PostgreSQL's programs.
"""
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from chromium import SKIPPED, require_chromium, selenium_chromium  # noqa: E402

from jwcrypto import jwk, jwt  # noqa: E402

RAYGRADE, SOURCE, WORK = sys.argv[1:4]
KEY = jwk.JWK.generate(kty="RSA", size=2048, kid="platform-1")
C = "https://purl.imsglobal.org/spec/lti/claim/"


class Platform(BaseHTTPRequestHandler):
    """The platform's JWKS, and its authorization endpoint answering every login with a
    student's launch (an auto-submitting form, as the OIDC form_post response mode asks)."""

    def log_message(self, *args):
        pass

    def do_GET(self):
        url = urllib.parse.urlparse(self.path)
        q = urllib.parse.parse_qs(url.query)
        if url.path == "/jwks":
            body, kind = json.dumps({"keys": [json.loads(KEY.export_public())]}), "application/json"
        elif url.path == "/auth":
            now = int(time.time())
            claims = {"iss": ISS, "aud": "client-1", "sub": q["login_hint"][0], "exp": now + 300,
                      "iat": now, "nonce": q["nonce"][0], C + "deployment_id": "dep-1",
                      C + "message_type": "LtiResourceLinkRequest", C + "version": "1.3.0",
                      C + "roles": ["http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"],
                      C + "resource_link": {"id": "link-1"},
                      C + "target_link_uri": q["redirect_uri"][0],
                      C + "custom": {"assignment": "homework-rays.json"}}
            token = jwt.JWT(header={"alg": "RS256", "kid": "platform-1"}, claims=claims)
            token.make_signed_token(KEY)
            body = (f'<form id="f" method="post" action="{html.escape(q["redirect_uri"][0])}">'
                    f'<input type="hidden" name="id_token" value="{token.serialize()}">'
                    f'<input type="hidden" name="state" value="{html.escape(q["state"][0])}">'
                    '</form><script>document.getElementById("f").submit()</script>')
            kind = "text/html"
        else:
            self.send_response(404)
            self.end_headers()
            return
        data = body.encode()
        self.send_response(200)
        self.send_header("Content-Type", kind)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)


def database():
    """On PostgreSQL: (a throwaway cluster, started, and the URL of a database), else None."""
    if os.environ.get("RAYGRADE_TEST_DATABASE", "sqlite") != "postgresql":
        return None
    sys.path.append(os.path.join(SOURCE, "tests", "lti"))
    import pgcluster
    try:
        cluster = pgcluster.Cluster()
    except FileNotFoundError as e:
        print(f"serve_in_browser: skipped: {e}")
        return None
    cluster.start()
    return cluster, cluster.new_database("browser")


def main():
    if not require_chromium() or not shutil.which("chromedriver"):
        return SKIPPED
    on_pg = os.environ.get("RAYGRADE_TEST_DATABASE", "sqlite") == "postgresql"
    pg = database()
    if on_pg and not pg:
        return SKIPPED
    try:
        return run(pg)
    finally:
        if pg:
            pg[0].stop()


def run(pg):
    global ISS
    shutil.rmtree(WORK, ignore_errors=True)
    data = os.path.join(WORK, "data")
    db = ["--database", pg[1]] if pg else []
    platform = ThreadingHTTPServer(("127.0.0.1", 0), Platform)
    threading.Thread(target=platform.serve_forever, daemon=True).start()
    ISS = f"http://127.0.0.1:{platform.server_port}"
    subprocess.run([RAYGRADE, "serve", "register", "--data", data, "--issuer", ISS,
                    "--client-id", "client-1", "--deployment-id", "dep-1", "--auth-url",
                    ISS + "/auth", "--token-url", ISS + "/token", "--jwks-url", ISS + "/jwks"] + db,
                   check=True, capture_output=True)
    server = subprocess.Popen([RAYGRADE, "serve", "--data", data, "--assignments",
                               os.path.join(SOURCE, "assignments")] + db, stdout=subprocess.PIPE,
                              text=True)
    profile = tempfile.mkdtemp(prefix="raygrade-chromium-")
    driver = None
    try:
        tool = re.search(r"listening on (http://\S+)$", server.stdout.readline()).group(1)
        driver = selenium_chromium(profile)
        driver.get(tool + "/lti/login?" + urllib.parse.urlencode(
            {"iss": ISS, "login_hint": "alice", "client_id": "client-1"}))
        deadline = time.time() + 30
        while not driver.find_elements("id", "raygrade-submit") and time.time() < deadline:
            time.sleep(0.1)
        launch = json.loads(driver.find_element("id", "raygrade-launch").get_attribute(
            "textContent"))
        if launch["student"] != ISS + " alice":
            sys.exit(f"serve_in_browser: FAILED: the page is not alice's: {launch}")
        # variant-sphere's first input (t of its first hit): a value no hit has.
        box = driver.find_element("css selector", "input[name^='variant-sphere']")
        box.send_keys("-1")
        button = driver.find_element("id", "raygrade-submit")
        driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", button)
        button.click()
        result = ""
        while "received" not in result and time.time() < deadline:
            time.sleep(0.1)
            result = driver.find_element("id", "raygrade-result").text
        if not re.search(r"Submission \d+ received: 0 / 21", result):
            sys.exit(f"serve_in_browser: FAILED: no feedback shown: {result[:300]!r}")
        if "A ray along z meets a sphere: 0 / 3" not in result:
            sys.exit(f"serve_in_browser: FAILED: the sphere's feedback: {result[:300]!r}")
    finally:
        if driver:
            driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
        server.terminate()
        server.wait(timeout=20)
    if pg:
        stored = pg[0].query(pg[1], "SELECT COUNT(*) FROM submissions")[0][0]
        if stored != "1" or os.path.exists(os.path.join(data, "raygrade.sqlite")):
            sys.exit(f"serve_in_browser: FAILED: not stored on PostgreSQL ({stored} submissions)")
    print(f"serve_in_browser: passed{' (postgresql)' if pg else ''}")
    return 0


sys.exit(main())
