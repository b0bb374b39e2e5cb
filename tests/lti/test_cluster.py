#!/usr/bin/env python3
"""Two `raygrade serve` processes on one PostgreSQL database, as behind a load balancer: each
student's login, launch and submission go to the servers in turn, so that the state a login
stored on one server is checked by the other, and the session a launch opened on one is used
on the other. One server is killed with SIGKILL halfway through the submissions. No
acknowledged submission is lost, and each stored submission's score reaches the platform once,
whichever server sent it (the outbox's rows are claimed with FOR UPDATE SKIP LOCKED and a lease
that the survivor takes over).

Always on PostgreSQL (a throwaway cluster, pgcluster.py).
Usage: test_cluster.py [unittest options]   ($RAYGRADE names the binary)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]
os.environ["RAYGRADE_TEST_DATABASE"] = "postgresql"

import concurrent.futures  # noqa: E402
import itertools  # noqa: E402
import shutil  # noqa: E402
import socket  # noqa: E402
import tempfile  # noqa: E402
import threading  # noqa: E402
import time  # noqa: E402
import unittest  # noqa: E402
import urllib.parse  # noqa: E402
from collections import Counter  # noqa: E402

import requests  # noqa: E402

import ltitest  # noqa: E402
from ltitest import ASSIGNMENT, browser, parse, solve  # noqa: E402

STUDENTS = 30
# A killed server's claimed scores go to the other after 2 s rather than 5 minutes.
TOOL_ENV = {"RAYGRADE_OUTBOX_BASE_MS": "50", "RAYGRADE_OUTBOX_LEASE_MS": "2000"}


class LoadBalancer:
    """A TCP proxy on a free loopback port: each connection goes to the next server in turn
    that accepts it, as a load balancer with health checks would. The tool's public URL, so
    the platform reaches the tool's JWKS (for the outbox's token requests) while one server
    is dead."""

    def __init__(self, ports):
        self.ports = ports
        self.turn = itertools.count()
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(64)
        self.port = self.sock.getsockname()[1]
        threading.Thread(target=self.serve, daemon=True).start()

    def serve(self):
        while True:
            try:
                client, _ = self.sock.accept()
            except OSError:
                return
            threading.Thread(target=self.handle, args=(client,), daemon=True).start()

    def handle(self, client):
        first = next(self.turn)
        upstream = None
        for i in range(len(self.ports)):
            try:
                upstream = socket.create_connection(
                    ("127.0.0.1", self.ports[(first + i) % len(self.ports)]), timeout=5)
                break
            except OSError:
                continue
        if upstream is None:
            client.close()
            return
        upstream.settimeout(None)

        def pump(src, dst):
            try:
                while True:
                    data = src.recv(65536)
                    if not data:
                        break
                    dst.sendall(data)
            except OSError:
                pass
            finally:
                try:
                    dst.shutdown(socket.SHUT_WR)
                except OSError:
                    pass

        back = threading.Thread(target=pump, args=(upstream, client), daemon=True)
        back.start()
        pump(client, upstream)
        back.join(30)
        client.close()
        upstream.close()

    def close(self):
        self.sock.close()


def on(server, url):
    """`url` sent to one server rather than through the load balancer."""
    parts = urllib.parse.urlsplit(url)
    return urllib.parse.urlunsplit(parts._replace(netloc=urllib.parse.urlsplit(server).netloc))


class TwoServersTest(ltitest.LtiCase):
    def setUp(self):
        if not os.path.exists(ltitest.RAYGRADE):
            self.skipTest(f"{ltitest.RAYGRADE} is not built")
        self.tmp = tempfile.mkdtemp(prefix="raygrade-cluster-")
        self.addCleanup(self.cleanup)
        self.pstate = os.path.join(self.tmp, "platform")
        os.makedirs(self.pstate)
        self.pproc, self.platform = ltitest.start_platform(self.pstate)
        ports = [ltitest.free_port(), ltitest.free_port()]
        self.balancer = LoadBalancer(ports)
        self.addCleanup(self.balancer.close)
        self.tool = f"http://127.0.0.1:{self.balancer.port}"
        self.database = ltitest.cluster().new_database()
        self.servers, self.procs = [], []
        for i, port in enumerate(ports):
            proc, _ = ltitest.start_tool(os.path.join(self.tmp, f"data-{i}"), port=port,
                                         env=TOOL_ENV, public_url=self.tool,
                                         database=self.database)
            self.procs.append(proc)
            self.servers.append(f"http://127.0.0.1:{port}")

    def cleanup(self):
        ltitest.close_browsers()
        for proc in self.procs + [self.pproc]:
            proc.stop()
        shutil.rmtree(self.tmp, ignore_errors=True)

    def rows(self, sql):
        return ltitest.cluster().query(self.database, sql)

    def launch_across(self, user, link, login_on, launch_on):
        """A student's login on one server and the launch on the other; (session, launch)."""
        s = browser()
        flow = ltitest.Flow(self.platform, s, user=user, role="Learner", link=link)
        form = parse(flow.login_page).forms[0]
        flow.login_response = s.post(on(self.servers[login_on], form["action"]),
                                     data=form["fields"], allow_redirects=False, timeout=30)
        self.assertIn(flow.login_response.status_code, (302, 303), flow.login_response.text)
        self.assertEqual(flow.authorize().status_code, 200)
        flow.launch_url = on(self.servers[launch_on], flow.launch_url)
        r = flow.launch()
        self.assertEqual(r.status_code, 200, r.text[:300])
        data = ltitest.launch_json(r.text)
        s.close()  # no idle connection holds a worker
        return s, data

    def test_launches_and_submissions_alternate_and_one_server_dies(self):
        self.register()
        r = requests.post(f"{self.platform}/test/link", json={
            "title": "Homework", "custom": {"assignment": ASSIGNMENT}, "scoreMaximum": 21},
            timeout=30)
        r.raise_for_status()
        link = r.json()["id"]
        # Each score answered 0.2 s late: a server is still sending some of its claimed scores
        # while the other looks for due ones, and a server's batch outlasts half its lease.
        requests.post(f"{self.platform}/test/slow", json={"seconds": 0.2},
                      timeout=30).raise_for_status()
        people = []
        for i in range(STUDENTS):
            s, data = self.launch_across(f"student-{i:02d}", link, i % 2, (i + 1) % 2)
            people.append((f"student-{i:02d}", s, data, i % 2))
        answers = solve("student-00")
        acknowledged = {}
        lock = threading.Lock()

        def hand_in(person):
            user, s, data, server = person
            try:
                r = s.post(on(self.servers[server], data["submit"]),
                           json={"launch": data["launch"], "csrf": data["csrf"],
                                 "answers": answers}, timeout=60)
            except requests.RequestException:
                return
            finally:
                s.close()
            if r.status_code == 200:
                with lock:
                    acknowledged[user] = r.json()

        # Submissions to the server that did not launch the student. The first half one after
        # another; then a second during which both servers send the backlog of slow scores;
        # then the second server is killed (SIGKILL) while the other half hand in.
        victim = self.procs[1]
        half = STUDENTS // 2
        for p in people[:half]:
            hand_in(p)
        time.sleep(1.0)
        with concurrent.futures.ThreadPoolExecutor(4) as pool:
            futures = [pool.submit(hand_in, p) for p in people[half:]]
            victim.kill()
            for f in concurrent.futures.as_completed(futures):
                f.result()
        victim.wait()
        self.assertLess(len(acknowledged), STUDENTS, "the kill came after every submission")
        self.assertGreaterEqual(len(acknowledged), half)

        stored = {r[0]: r[1] for r in self.rows("SELECT id, sub FROM submissions")}
        for user, answer in acknowledged.items():
            self.assertEqual(stored.get(str(answer["submission"])), user,
                             f"{user}'s acknowledged submission lost")
        # The others hand in again on the server left, with the sessions they had.
        for user, s, data, _ in people:
            if user not in acknowledged:
                r = s.post(on(self.servers[0], data["submit"]),
                           json={"launch": data["launch"], "csrf": data["csrf"],
                                 "answers": answers}, timeout=60)
                self.assertEqual(r.status_code, 200, f"{user}: {r.text[:200]}")
        count = len(self.rows("SELECT id FROM submissions"))
        self.assertGreaterEqual(count, STUDENTS)

        # Every score once: the killed server's claims pass to the survivor when their lease
        # runs out. A score whose POST the kill cut between the platform's answer and the
        # outbox's note of it is sent again, identical (same user, timestamp and values), which
        # an AGS platform counts once; the platform of tests/ marks it as a repeat.
        end = time.time() + 90
        while time.time() < end and self.rows("SELECT id FROM outbox WHERE delivered = 0"):
            time.sleep(0.2)
        self.assertEqual(self.rows("SELECT id FROM outbox WHERE delivered = 0"), [])
        time.sleep(0.5)
        scores = self.scores()
        kept = [x for x in scores if not x["repeat"]]
        print(f"{len(acknowledged)} acknowledged at the first try, {count} stored, "
              f"{len(kept)} scores, {len(scores) - len(kept)} sent again identical, calls "
              f"{requests.get(self.platform + '/test/calls', timeout=30).json()}")
        # One score at most was on its way from the killed server (each sends one at a time).
        self.assertLessEqual(len(scores) - len(kept), 1)
        self.assertEqual(len(kept), count, "not every stored submission's score came once")
        per_user = Counter(x["body"]["userId"] for x in kept)
        stored_per_user = Counter(r[0] for r in self.rows("SELECT sub FROM submissions"))
        self.assertEqual(per_user, stored_per_user)


if __name__ == "__main__":
    unittest.main()
