#!/usr/bin/env python3
"""A large class list (a benchmark, not a test): a course of N learners (10,000 by default) on
the test platform of tests/lti, S of them submitting (200 by default), then the instructor's
class report and gradebook asked for, the roster served in one page and in pages of 100.
Prints the time of each request and the server's resident memory before and its peak after
(VmRSS and VmHWM of /proc/PID/status). Loopback only; every request has a timeout.
RAYGRADE_TEST_DATABASE=postgresql runs the tool on PostgreSQL (needs Debian's postgresql).

Usage: bench/roster_size.py [--members 10000] [--submitters 200]"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LTI_DIR = os.path.join(ROOT, "tests", "lti")
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != LTI_DIR] + [LTI_DIR]

import argparse  # noqa: E402
import time  # noqa: E402
import unittest  # noqa: E402

import requests  # noqa: E402

from ltitest import browser, launch  # noqa: E402
from test_roster import RosterCase, member  # noqa: E402

ARGS = None


def kb(pid, field):
    with open(f"/proc/{pid}/status") as f:
        return [int(x.split()[1]) for x in f if x.startswith(field + ":")][0]


class RosterSize(RosterCase):
    def test_size(self):
        n, s = ARGS.members, ARGS.submitters
        self.set_members([member(f"learner{i:05d}", f"Learner Number {i}") for i in range(n)])
        start = time.monotonic()
        for i in range(s):
            self.submit_right(f"learner{i * (n // s):05d}")
        print(f"{s} submissions in {time.monotonic() - start:.1f} s", file=sys.stderr)
        for page_size in (None, 100):
            requests.post(f"{self.platform}/test/nrps", json={"page_size": page_size},
                          timeout=30).raise_for_status()
            b = browser()
            r, data = launch(self.platform, b, user="teacher", role="Instructor",
                             link=self.link["id"])
            self.assertEqual(r.status_code, 200)
            for what in ("report", "gradebook.csv"):
                rss = kb(self.tproc.pid, "VmRSS")
                start = time.monotonic()
                got = b.get(f"{self.tool}/lti/{what}", params={"launch": data["launch"]},
                            timeout=600)
                took = time.monotonic() - start
                self.assertEqual(got.status_code, 200, got.text[:300])
                self.assertTrue("could not be read" not in got.text)
                print(f"{n} members, pages of {page_size or 'all'}: {what} in {took:.2f} s, "
                      f"{len(got.content) / 1e6:.1f} MB; server RSS {rss / 1024:.0f} MB before, "
                      f"peak {kb(self.tproc.pid, 'VmHWM') / 1024:.0f} MB", file=sys.stderr)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--members", type=int, default=10000)
    parser.add_argument("--submitters", type=int, default=200)
    ARGS = parser.parse_args()
    unittest.main(argv=[sys.argv[0]], verbosity=0)
