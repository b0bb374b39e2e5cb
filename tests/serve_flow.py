#!/usr/bin/env python3
"""raygrade serve over HTTP, against a stand-in platform of this file (its JWKS, token, scores
and registration endpoints), without a browser: a manual and a dynamic registration, three
students whose own reference answers (`raygrade solve --student`) score full marks and whose
scores reach the platform, the refusals of a forged token, a wrong browser and a missing CSRF
token (nothing stored), the instructor's report and gradebook, and a deep-linking response
verified with the tool's published key.

Usage: serve_flow.py RAYGRADE SOURCE_DIR WORK_DIR
RAYGRADE_TEST_DATABASE=postgresql runs the tool on a throwaway PostgreSQL cluster
(tests/lti/pgcluster.py) rather than SQLite: skipped (77) without PostgreSQL's programs.
"""
import atexit
import json
import os
import re
import shutil
import sqlite3
import subprocess
import sys
import threading
import time
import urllib.parse
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import requests
from jwcrypto import jwk, jwt

RAYGRADE, SOURCE, WORK = sys.argv[1:4]
BACKEND = os.environ.get("RAYGRADE_TEST_DATABASE", "sqlite")
DATABASE = []  # on PostgreSQL: ["--database", its URL], given to every `raygrade serve`
CLUSTER = None
SKIPPED = 77
DATA = os.path.join(WORK, "data")
C = "https://purl.imsglobal.org/spec/lti/claim/"
LEARNER = ["http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"]
INSTRUCTOR = ["http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"]
KEY = jwk.JWK.generate(kty="RSA", size=2048, kid="platform-1")
SCORES, REGISTRATIONS, LINE_ITEMS = [], [], []
SESSIONS = {}  # student: (the last submission's body, the session cookie)
# Answers of 503 still to give, by endpoint; "down": every score refused.
FAILURES = {"token": 1, "scores": 2, "down": False}


class Platform(BaseHTTPRequestHandler):
    def log_message(self, *args):
        pass

    def answer(self, status, body=None):
        data = json.dumps(body).encode() if body is not None else b""
        self.send_response(status)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    def do_GET(self):
        if self.path == "/.well-known/openid-configuration":
            self.answer(200, {"issuer": ISS, "authorization_endpoint": ISS + "/auth",
                              "token_endpoint": ISS + "/token", "jwks_uri": ISS + "/jwks",
                              "registration_endpoint": ISS + "/register"})
        elif self.path == "/jwks":
            self.answer(200, {"keys": [json.loads(KEY.export_public())]})
        elif self.path.startswith("/ags/course-2/lineitems"):
            self.answer(200, LINE_ITEMS)
        else:
            self.answer(404)

    def do_POST(self):
        body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
        if self.path == "/token" and FAILURES["token"] > 0:
            FAILURES["token"] -= 1
            self.answer(503)
        elif self.path.endswith("/scores") and (FAILURES["down"] or FAILURES["scores"] > 0):
            FAILURES["scores"] -= 1
            self.answer(503)
        elif self.path == "/ags/course-2/lineitems":
            item = dict(json.loads(body), id=ISS + "/ags/course-2/lineitems/%d" % (len(LINE_ITEMS) + 1))
            LINE_ITEMS.append(item)
            self.answer(201, item)
        elif self.path == "/token":
            form = urllib.parse.parse_qs(body.decode())
            assertion = jwt.JWT(jwt=form["client_assertion"][0], key=TOOL_KEYS[0], algs=["RS256"])
            claims = json.loads(assertion.claims)
            assert claims["iss"] == claims["sub"] and claims["aud"] == ISS + "/token", claims
            self.answer(200, {"access_token": "T-" + claims["iss"], "expires_in": 3600})
        elif self.path == "/register":
            REGISTRATIONS.append((self.headers.get("Authorization"), json.loads(body)))
            self.answer(200, {"client_id": "client-2",
                              "https://purl.imsglobal.org/spec/lti-tool-configuration":
                                  {"deployment_id": "dep-2"}})
        elif self.path.endswith("/scores"):
            SCORES.append((self.path, self.headers.get("Content-Type"),
                           self.headers.get("Authorization"), json.loads(body)))
            self.answer(200, {})
        else:
            self.answer(404)


def check(condition, what):
    if not condition:
        sys.exit("serve_flow: FAILED: " + what)


def cookie_of(response, name):
    m = re.search(name + r"=([^;]+)", response.headers.get("Set-Cookie", ""))
    return m.group(1) if m else None


def id_token(claims, header=None):
    t = jwt.JWT(header=header or {"alg": "RS256", "kid": "platform-1"}, claims=claims)
    t.make_signed_token(KEY)
    return t.serialize()


def login(client_id):
    """The login's redirect: (state, nonce, the raygrade_state cookie)."""
    r = requests.get(TOOL + "/lti/login", allow_redirects=False,
                     params={"iss": ISS, "login_hint": "x", "client_id": client_id})
    check(r.status_code == 302, f"login answers 302 (got {r.status_code})")
    q = urllib.parse.parse_qs(urllib.parse.urlparse(r.headers["Location"]).query)
    check(q["redirect_uri"][0] == TOOL + "/lti/launch" and q["response_mode"][0] == "form_post",
          "the authentication request's redirect and mode")
    # requests sends no Secure cookie over plain http (browsers do, on loopback): by hand.
    return q["state"][0], q["nonce"][0], cookie_of(r, "raygrade_state")


def launch_claims(sub, roles, nonce, client_id="client-1", deployment="dep-1", ags=None):
    now = int(time.time())
    return {"iss": ISS, "aud": client_id, "sub": sub, "exp": now + 300, "iat": now,
            "nonce": nonce, "name": "Student " + sub, C + "deployment_id": deployment,
            C + "message_type": "LtiResourceLinkRequest", C + "version": "1.3.0",
            C + "roles": roles, C + "resource_link": {"id": "link-1"},
            C + "target_link_uri": TOOL + "/lti/launch",
            C + "custom": {"assignment": "homework-rays.json"},
            "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint":
                ags or {"lineitem": ISS + "/ags/course-1/lineitems/7"}}


def post_launch(token, state, state_cookie):
    return requests.post(TOOL + "/lti/launch", data={"id_token": token, "state": state},
                         headers={"Cookie": "raygrade_state=" + (state_cookie or "")})


def launch_json(page):
    m = re.search(r'<script type="application/json" id="raygrade-launch">(.*?)</script>', page)
    return json.loads(m.group(1))


def stored(table):
    if CLUSTER:
        return int(CLUSTER.query(DATABASE[1], f"SELECT COUNT(*) FROM {table}")[0][0])
    with sqlite3.connect(os.path.join(DATA, "raygrade.sqlite")) as db:
        return db.execute(f"SELECT COUNT(*) FROM {table}").fetchone()[0]


def start_database():
    """On PostgreSQL: a throwaway cluster and a database, named to each `raygrade serve`."""
    global CLUSTER
    if BACKEND != "postgresql":
        return
    sys.path.append(os.path.join(SOURCE, "tests", "lti"))
    import pgcluster
    try:
        CLUSTER = pgcluster.Cluster()
    except FileNotFoundError as e:
        print(f"serve_flow: skipped: {e}")
        sys.exit(SKIPPED)
    CLUSTER.start()
    atexit.register(CLUSTER.stop)
    DATABASE.extend(["--database", CLUSTER.new_database("flow")])


def reference_answers(student):
    out = subprocess.run([RAYGRADE, "solve", os.path.join(SOURCE, "assignments/homework-rays.json"),
                          "--student", student, "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    return {s["id"]: s["answer"] for s in json.loads(out)["solutions"]}


def submit_as(sub, ags=None, change=None):
    """A launch and a submission of the student's own answers (`change` may alter them); the
    submission's answer."""
    state, nonce, cookie = login("client-1")
    r = post_launch(id_token(launch_claims(sub, LEARNER, nonce, ags=ags)), state, cookie)
    check(r.status_code == 200, f"{sub}'s launch answers 200 (got {r.status_code})")
    launch = launch_json(r.text)
    body = {"launch": launch["launch"], "csrf": launch["csrf"],
            "answers": reference_answers(launch["student"])}
    if change:
        change(body["answers"])
    session = cookie_of(r, "raygrade_session")
    r = requests.post(launch["submit"], json=body, headers={"Cookie": "raygrade_session=" + session})
    check(r.status_code == 200, f"{sub}'s submission answers 200 ({r.text[:200]})")
    SESSIONS[sub] = (body, session)
    return r.json()


def wait_for_scores(count, seconds=20):
    deadline = time.time() + seconds
    while len(SCORES) < count and time.time() < deadline:
        time.sleep(0.05)
    time.sleep(0.3)  # a score sent twice would come now


def students_flow():
    answers = {}
    for sub in ["s1", "s2", "s3"]:
        state, nonce, cookie = login("client-1")
        r = post_launch(id_token(launch_claims(sub, LEARNER, nonce)), state, cookie)
        check(r.status_code == 200, f"{sub}'s launch answers 200 (got {r.status_code})")
        session = cookie_of(r, "raygrade_session")
        launch = launch_json(r.text)
        check(launch["student"] == ISS + " " + sub, "the variant key is issuer and sub")
        answers[sub] = reference_answers(launch["student"])
        body = {"launch": launch["launch"], "csrf": launch["csrf"], "answers": answers[sub]}
        r = requests.post(launch["submit"], json=body)
        check(r.status_code == 403, "a submission without the session cookie is refused")
        r = requests.post(launch["submit"], json=dict(body, csrf="forged"),
                          headers={"Cookie": "raygrade_session=" + session})
        check(r.status_code == 403, "a submission with another CSRF token is refused")
        r = requests.post(launch["submit"], json=body,
                          headers={"Cookie": "raygrade_session=" + session})
        check(r.status_code == 200, f"{sub}'s submission answers 200 ({r.text[:200]})")
        # assignments/homework-rays.json: 21 points, and these are the student's own answers.
        check(r.json()["score"] == 21 and r.json()["max"] == 21, f"{sub} scores 21 of 21")
    check(len({json.dumps(a, sort_keys=True) for a in answers.values()}) == 3,
          "three students, three sets of numbers")
    state, nonce, cookie = login("client-1")
    r = post_launch(id_token(launch_claims("s1", LEARNER, nonce)), state, cookie)
    last = launch_json(r.text).get("last", {})
    check(last.get("score") == 21 and last.get("max") == 21, f"a new launch shows the last score: {last}")
    state, nonce, cookie = login("client-1")
    r = post_launch(id_token(launch_claims("s9", LEARNER, nonce)), state, cookie)
    check("last" not in launch_json(r.text), "a student who has not submitted has no last score")
    return answers


def attacks():
    launches, states = stored("launches"), stored("login_states")
    state, nonce, cookie = login("client-1")
    claims = launch_claims("mallory", LEARNER, nonce)
    signed = id_token(claims).split(".")
    forged = {
        "alg none": jwk.base64url_encode(json.dumps({"alg": "none", "kid": "platform-1"})) +
                    "." + signed[1] + ".",
        "bad signature": signed[0] + "." + signed[1] + "." + signed[2][::-1],
        "unknown kid": id_token(claims, {"alg": "RS256", "kid": "platform-9"}),
        "jku in the header": id_token(claims, {"alg": "RS256", "kid": "platform-1",
                                               "jku": "http://127.0.0.1:9/keys"}),
        "another nonce": id_token(dict(claims, nonce="not-issued")),
        "expired": id_token(dict(claims, exp=int(time.time()) - 120)),
        "unknown deployment": id_token(dict(claims, **{C + "deployment_id": "dep-9"})),
    }
    for what, token in forged.items():
        r = post_launch(token, state, cookie)
        check(r.status_code == 401, f"{what}: refused with 401 (got {r.status_code})")
        check('id="reason"' in r.text, f"{what}: the page says why")
    r = post_launch(id_token(claims), state, "another-browser")
    check(r.status_code == 403, "a state presented by another browser is refused with 403")
    check(stored("launches") == launches, "the refusals stored no launch")
    r = post_launch(id_token(claims), state, cookie)
    check(r.status_code == 200, "the same login, untouched, is accepted")
    r = post_launch(id_token(claims), state, cookie)
    check(r.status_code == 400, "a state used once is refused the second time")
    check(stored("login_states") == states + 1, "one login state per login")


def instructor_flow():
    state, nonce, cookie = login("client-1")
    r = post_launch(id_token(launch_claims("teacher", INSTRUCTOR, nonce)), state, cookie)
    check(r.status_code == 200, "the instructor's launch")
    launch, session = launch_json(r.text), cookie_of(r, "raygrade_session")
    check(launch.get("role") == "instructor", "the instructor's page")
    headers = {"Cookie": "raygrade_session=" + session}
    r = requests.get(TOOL + "/lti/gradebook.csv", params={"launch": launch["launch"]},
                     headers=headers)
    rows = [line for line in r.text.splitlines() if line.startswith(ISS)]
    check(r.status_code == 200 and len(rows) == 3, "a gradebook row per student")
    r = requests.get(TOOL + "/lti/report", params={"launch": launch["launch"]}, headers=headers)
    check(r.status_code == 200 and "<html" in r.text, "the class report")
    r = requests.get(TOOL + "/lti/report", params={"launch": launch["launch"]})
    check(r.status_code == 403, "the report without the instructor's session is refused")


def registration_and_deep_link():
    r = requests.get(TOOL + "/lti/register", params={
        "openid_configuration": ISS + "/.well-known/openid-configuration",
        "registration_token": "reg-token"})
    check(r.status_code == 200 and "org.imsglobal.lti.close" in r.text, "dynamic registration")
    auth, asked = REGISTRATIONS[-1]
    check(auth == "Bearer reg-token", "the registration token is sent as a bearer token")
    check(asked["jwks_uri"] == TOOL + "/lti/jwks" and
          asked["token_endpoint_auth_method"] == "private_key_jwt", "what the tool asks for")
    state, nonce, cookie = login("client-2")
    claims = launch_claims("teacher", INSTRUCTOR, nonce, "client-2", "dep-2")
    claims[C + "message_type"] = "LtiDeepLinkingRequest"
    claims["https://purl.imsglobal.org/spec/lti-dl/claim/deep_linking_settings"] = {
        "deep_link_return_url": ISS + "/deep-link-return", "data": "opaque-1"}
    r = post_launch(id_token(claims), state, cookie)
    check(r.status_code == 200, "the deep-linking launch")
    form = re.search(r'name="launch" value="([^"]+)".*?name="csrf" value="([^"]+)"', r.text)
    r = requests.post(TOOL + "/lti/deep-link", headers={
        "Cookie": "raygrade_session=" + cookie_of(r, "raygrade_session")}, data={
        "launch": form.group(1), "csrf": form.group(2), "assignment": "homework-rays.json"})
    token = re.search(r'name="JWT" value="([^"]+)"', r.text).group(1)
    response = json.loads(jwt.JWT(jwt=token, key=TOOL_KEYS[0], algs=["RS256"]).claims)
    item = response["https://purl.imsglobal.org/spec/lti-dl/claim/content_items"][0]
    check(response["aud"] == ISS and response["iss"] == "client-2", "the response's iss and aud")
    check(response["https://purl.imsglobal.org/spec/lti-dl/claim/data"] == "opaque-1",
          "the request's data returned")
    check(item["lineItem"]["scoreMaximum"] == 21 and
          item["custom"]["assignment"] == "homework-rays.json", "the link and its line item")


def start_server():
    server = subprocess.Popen([RAYGRADE, "serve", "--data", DATA, "--listen", "127.0.0.1:0",
                               "--assignments", os.path.join(SOURCE, "assignments")] + DATABASE,
                              stdout=subprocess.PIPE, text=True,
                              env=dict(os.environ, RAYGRADE_OUTBOX_BASE_MS="50",
                                       RAYGRADE_OUTBOX_LEASE_MS="2000"))
    lines = [server.stdout.readline().strip() for _ in range(5)]
    tool = re.match(r"raygrade serve: listening on (http://127\.0\.0\.1:\d+)$", lines[0])[1]
    check(lines[1:] == [f"registration URL: {tool}/lti/register",
                        f"login URL: {tool}/lti/login", f"launch URL: {tool}/lti/launch",
                        f"JWKS URL: {tool}/lti/jwks"], f"the printed URLs: {lines}")
    return server, tool


def outbox_flow():
    wait_for_scores(3)
    got = {(s[3]["userId"], s[3]["scoreGiven"], s[3]["scoreMaximum"]) for s in SCORES}
    # The token endpoint failed once and the scores twice: each score still arrives, once.
    check(got == {("s1", 21, 21), ("s2", 21, 21), ("s3", 21, 21)} and len(SCORES) == 3,
          f"each score reaches the platform once: {SCORES}")
    path, kind, auth, score = SCORES[0]
    check(path == "/ags/course-1/lineitems/7/scores" and
          kind == "application/vnd.ims.lis.v1.score+json" and auth == "Bearer T-client-1",
          "the score's URL, type and token")
    check(re.fullmatch(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z", score["timestamp"]) and
          score["activityProgress"] == "Completed" and
          score["gradingProgress"] == "FullyGraded", "the score's fields")
    # A link with the context's line items only: the tool makes the link's line item.
    submit_as("s4", {"lineitems": ISS + "/ags/course-2/lineitems"})
    wait_for_scores(4)
    check(len(LINE_ITEMS) == 1 and LINE_ITEMS[0]["resourceLinkId"] == "link-1" and
          LINE_ITEMS[0]["scoreMaximum"] == 21, f"one line item made: {LINE_ITEMS}")
    check(SCORES[3][0] == "/ags/course-2/lineitems/1/scores", "the score goes to the new item")


def regrade_flow():
    """A student's t of the sphere off by 0.5; a bank whose sphere takes t within 1: the
    regrade finds that student's score changed, and sends the new one."""
    def nudge(answers):
        answers["variant-sphere"]["hits"][0]["t"] += 0.5
    before = submit_as("s6", change=nudge)
    check(before["score"] < 21, f"an answer off by 0.5 loses points ({before['score']})")
    wait_for_scores(5)
    state, nonce, cookie = login("client-1")
    r = post_launch(id_token(launch_claims("teacher", INSTRUCTOR, nonce)), state, cookie)
    launch, session = launch_json(r.text), cookie_of(r, "raygrade_session")
    files = []
    for folder, _, names in os.walk(os.path.join(SOURCE, "problems")):
        for name in sorted(names):
            path = os.path.join(folder, name)
            text = open(path).read()
            if name == "variants.json":
                bank = json.loads(text)
                for p in bank["problems"]:
                    if p["id"] == "variant-sphere":
                        p["tolerance"] = {"atol": 1, "rtol": 0}
                text = json.dumps(bank)
            rel = os.path.relpath(path, os.path.join(SOURCE, "problems")).replace("/", "-")
            files.append(("bank", (rel, text, "application/json")))
    r = requests.post(TOOL + "/lti/regrade", files=files + [
        ("launch", (None, launch["launch"])), ("csrf", (None, launch["csrf"]))],
        headers={"Cookie": "raygrade_session=" + session})
    check(r.status_code == 200 and "1 students" in r.text, f"one score changes: {r.text[-400:]}")
    wait_for_scores(6)
    check(len(SCORES) == 6 and SCORES[5][3]["userId"] == "s6" and
          SCORES[5][3]["scoreGiven"] == 21, f"the changed score is sent: {SCORES[4:]}")


def main():
    global ISS, TOOL, TOOL_KEYS
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    start_database()
    platform = ThreadingHTTPServer(("127.0.0.1", 0), Platform)
    threading.Thread(target=platform.serve_forever, daemon=True).start()
    ISS = f"http://127.0.0.1:{platform.server_port}"
    subprocess.run([RAYGRADE, "serve", "register", "--data", DATA, "--issuer", ISS,
                    "--client-id", "client-1", "--deployment-id", "dep-1", "--auth-url",
                    ISS + "/auth", "--token-url", ISS + "/token", "--jwks-url", ISS + "/jwks"] +
                   DATABASE, check=True)
    server, TOOL = start_server()
    try:
        TOOL_KEYS = [jwk.JWKSet.from_json(requests.get(TOOL + "/lti/jwks").text)]
        students_flow()
        attacks()
        instructor_flow()
        registration_and_deep_link()
        outbox_flow()
        regrade_flow()
        # The platform down: a score acknowledged, then the server killed; after a restart
        # the score is delivered, once, and the tool's key is the same.
        FAILURES["down"] = True
        submit_as("s5")
        server.kill()
        server.wait()
        FAILURES["down"] = False
        server, TOOL = start_server()
        check(jwk.JWKSet.from_json(requests.get(TOOL + "/lti/jwks").text).export() ==
              TOOL_KEYS[0].export(), "the tool's key survives a restart")
        wait_for_scores(7)
        check(len(SCORES) == 7 and SCORES[6][3]["userId"] == "s5",
              "a score left in the outbox by a killed server is delivered after a restart")
        # The session survives the restart: s5 submits again from the same page.
        body, session = SESSIONS["s5"]
        r = requests.post(TOOL + "/lti/submit", json=body,
                          headers={"Cookie": "raygrade_session=" + session})
        check(r.status_code == 200 and r.json()["score"] == 21, "a session kept over a restart")
        acknowledged = stored("submissions")  # s1-s6, s5 twice
        check(acknowledged == 7, f"every acknowledged submission is stored ({acknowledged})")
    finally:
        server.terminate()
        code = server.wait(timeout=20)
    check(code == 0, f"the server stops on SIGTERM with 0 (got {code})")
    check(not CLUSTER or not os.path.exists(os.path.join(DATA, "raygrade.sqlite")),
          "on PostgreSQL, no SQLite database beside")
    print(f"serve_flow: passed ({BACKEND})")


main()
