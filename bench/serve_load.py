#!/usr/bin/env python3
"""Load on raygrade serve (docs/lti.md, "Load"): N students launched one after another, then
all submitting their own answers at once; the time from sending a submission to its graded
answer (median, 99th percentile, slowest) and the server's peak memory. Bounded: it stops by
itself. A benchmark, not a test: nothing is asserted but that every submission is graded.

Usage: serve_load.py RAYGRADE SOURCE_DIR WORK_DIR [STUDENTS]
"""
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import threading
import time
import urllib.parse
from concurrent.futures import ThreadPoolExecutor
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import requests
from jwcrypto import jwk, jwt

RAYGRADE, SOURCE, WORK = sys.argv[1:4]
STUDENTS = int(sys.argv[4]) if len(sys.argv) > 4 else 200
KEY = jwk.JWK.generate(kty="RSA", size=2048, kid="platform-1")
C = "https://purl.imsglobal.org/spec/lti/claim/"


class Platform(BaseHTTPRequestHandler):
    def log_message(self, *args):
        pass

    def do_GET(self):
        data = json.dumps({"keys": [json.loads(KEY.export_public())]}).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)


def launch(tool, iss, sub):
    r = requests.get(tool + "/lti/login", allow_redirects=False,
                     params={"iss": iss, "login_hint": sub, "client_id": "client-1"})
    q = urllib.parse.parse_qs(urllib.parse.urlparse(r.headers["Location"]).query)
    state_cookie = re.search(r"raygrade_state=([^;]+)", r.headers["Set-Cookie"]).group(1)
    now = int(time.time())
    claims = {"iss": iss, "aud": "client-1", "sub": sub, "exp": now + 3600, "iat": now,
              "nonce": q["nonce"][0], C + "deployment_id": "dep-1",
              C + "message_type": "LtiResourceLinkRequest", C + "version": "1.3.0",
              C + "roles": ["http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"],
              C + "resource_link": {"id": "link-1"}, C + "target_link_uri": tool + "/lti/launch",
              C + "custom": {"assignment": "homework-rays.json"}}
    token = jwt.JWT(header={"alg": "RS256", "kid": "platform-1"}, claims=claims)
    token.make_signed_token(KEY)
    r = requests.post(tool + "/lti/launch", data={"id_token": token.serialize(),
                                                  "state": q["state"][0]},
                      headers={"Cookie": "raygrade_state=" + state_cookie})
    session = re.search(r"raygrade_session=([^;]+)", r.headers["Set-Cookie"]).group(1)
    page = json.loads(re.search(r'id="raygrade-launch">(.*?)</script>', r.text).group(1))
    out = subprocess.run([RAYGRADE, "solve", os.path.join(SOURCE, "assignments/homework-rays.json"),
                          "--student", page["student"], "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    answers = {s["id"]: s["answer"] for s in json.loads(out)["solutions"]}
    return page, session, answers


def peak_memory_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        return int(re.search(r"VmHWM:\s+(\d+)", f.read()).group(1))


def main():
    shutil.rmtree(WORK, ignore_errors=True)
    data = os.path.join(WORK, "data")
    platform = ThreadingHTTPServer(("127.0.0.1", 0), Platform)
    threading.Thread(target=platform.serve_forever, daemon=True).start()
    iss = f"http://127.0.0.1:{platform.server_port}"
    subprocess.run([RAYGRADE, "serve", "register", "--data", data, "--issuer", iss,
                    "--client-id", "client-1", "--deployment-id", "dep-1", "--auth-url",
                    iss + "/auth", "--token-url", iss + "/token", "--jwks-url", iss + "/jwks"],
                   check=True, capture_output=True)
    server = subprocess.Popen([RAYGRADE, "serve", "--data", data, "--assignments",
                               os.path.join(SOURCE, "assignments")], stdout=subprocess.PIPE,
                              text=True)
    try:
        tool = re.search(r"listening on (http://\S+)$", server.stdout.readline()).group(1)
        started = time.time()
        students = [launch(tool, iss, f"student-{i}") for i in range(STUDENTS)]
        launched = time.time() - started
        barrier = threading.Barrier(STUDENTS)

        def submit(student):
            page, session, answers = student
            body = {"launch": page["launch"], "csrf": page["csrf"], "answers": answers}
            barrier.wait(timeout=60)
            t0 = time.perf_counter()
            try:
                r = requests.post(page["submit"], json=body,
                                  headers={"Cookie": "raygrade_session=" + session}, timeout=120)
            except requests.ConnectionError as e:
                return time.perf_counter() - t0, str(e)[:80], None
            took = time.perf_counter() - t0
            return took, r.status_code, r.json().get("score")

        with ThreadPoolExecutor(max_workers=STUDENTS) as pool:
            results = list(pool.map(submit, students))
        times = sorted(t for t, _, _ in results)
        graded = sum(1 for _, code, score in results if code == 200 and score == 21)
        for _, code, _ in results:
            if code != 200:
                print("not graded:", code)
        p99 = times[min(len(times) - 1, int(0.99 * len(times)))]
        print(f"students: {STUDENTS}; launches (one after another): {launched:.1f} s")
        print(f"graded at full marks: {graded} of {STUDENTS}")
        print(f"time to a graded answer, all at once: median {statistics.median(times):.2f} s, "
              f"99th percentile {p99:.2f} s, slowest {times[-1]:.2f} s")
        print(f"server's peak memory: {peak_memory_kib(server.pid) / 1024:.0f} MiB")
        return 0 if graded == STUDENTS else 1
    finally:
        server.terminate()
        server.wait(timeout=30)


sys.exit(main())
