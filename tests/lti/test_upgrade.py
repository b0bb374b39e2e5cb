#!/usr/bin/env python3
"""An upgrade: a database of schema version 2 (and one of version 1), with a course's rows in
it (tests/lti/fixtures: the schema as raygrade made it then, and the rows), opened by this
`raygrade serve`: migrated to the current version once, every row kept, and served: the old
launches' sessions still open the report and take a submission.

Usage: test_upgrade.py [unittest options]   ($RAYGRADE names the binary;
RAYGRADE_TEST_DATABASE=postgresql runs the tool on PostgreSQL)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import csv  # noqa: E402
import io  # noqa: E402
import shutil  # noqa: E402
import sqlite3  # noqa: E402
import tempfile  # noqa: E402
import unittest  # noqa: E402

import requests  # noqa: E402

import ltitest  # noqa: E402
from ltitest import query, solve  # noqa: E402

FIXTURES = os.path.join(HERE, "fixtures")
ISSUER = "https://lms.example"
CURRENT_VERSION = 3  # this raygrade's: the rosters (NRPS) came with version 3


def old_database(data, version):
    """The tool's database in `data` made at schema `version` (1 or 2), with the fixture's
    rows."""
    with open(os.path.join(FIXTURES, f"schema_v2.{ltitest.BACKEND}.sql")) as f:
        schema = f.read()
    if version == 1:
        schema = schema.split("\n-- version 2\n")[0]
    with open(os.path.join(FIXTURES, "rows_v2.sql")) as f:
        rows = f.read()
    os.makedirs(data, exist_ok=True)
    url = ltitest.database_url(data)
    if url:
        ltitest.cluster().query(url, schema + rows)
    else:
        con = sqlite3.connect(os.path.join(data, "raygrade.sqlite"))
        con.executescript(schema + rows)
        con.close()


class UpgradeTest(unittest.TestCase):
    def setUp(self):
        if not os.path.exists(ltitest.RAYGRADE):
            self.skipTest(f"{ltitest.RAYGRADE} is not built")
        self.tmp = tempfile.mkdtemp(prefix="raygrade-upgrade-")
        self.addCleanup(shutil.rmtree, self.tmp, True)

    def upgrade(self, version):
        data = os.path.join(self.tmp, f"data-v{version}")
        old_database(data, version)
        self.assertEqual(query(data, "SELECT MAX(version) FROM schema_version"),
                         [(str(version),)])
        proc, tool = ltitest.start_tool(data)
        self.addCleanup(proc.stop)
        # Migrated once to each version after the old one.
        versions = [int(v) for (v,) in query(data, "SELECT version FROM schema_version")]
        self.assertEqual(sorted(versions), list(range(1, CURRENT_VERSION + 1)))
        # Every row kept.
        for table, count in (("registrations", 1), ("deployments", 1), ("launches", 2),
                             ("submissions", 1), ("outbox", 1), ("line_items", 1),
                             ("members", 0)):
            self.assertEqual(query(data, f"SELECT COUNT(*) FROM {table}"), [(str(count),)], table)
        self.assertEqual(query(data, "SELECT delivered, claimed_until FROM outbox"), [("1", "0")])

        # Served: the teacher's session of before opens the report and the gradebook.
        teacher = {"Cookie": "raygrade_session=session-teacher"}
        r = requests.get(f"{tool}/lti/report", params={"launch": "launch-teacher"},
                         headers=teacher, timeout=60)
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.assertIn("no class list", r.text)  # the old launches carried no roster URL
        r = requests.get(f"{tool}/lti/gradebook.csv", params={"launch": "launch-teacher"},
                         headers=teacher, timeout=60)
        self.assertEqual(r.status_code, 200, r.text[:300])
        (row,) = list(csv.DictReader(io.StringIO(r.text)))
        self.assertEqual(row["id"], f"{ISSUER} ada")
        self.assertEqual((float(row["total"]), float(row["max"])), (0, 21))
        # Ada's session of before hands in her own right answers: full marks, a second row.
        r = requests.post(f"{tool}/lti/submit", headers={"Cookie": "raygrade_session=session-ada"},
                          json={"launch": "launch-ada", "csrf": "csrf-ada",
                                "answers": solve(f"{ISSUER} ada")}, timeout=60)
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.assertAlmostEqual(r.json()["score"], 21, places=9)
        self.assertEqual(query(data, "SELECT COUNT(*) FROM submissions"), [("2",)])
        # Opened again: nothing to migrate.
        proc.stop()
        proc, tool = ltitest.start_tool(data)
        self.addCleanup(proc.stop)
        self.assertEqual(query(data, "SELECT COUNT(*) FROM schema_version"),
                         [(str(CURRENT_VERSION),)])

    def test_version_2_database(self):
        self.upgrade(2)

    def test_version_1_database(self):
        self.upgrade(1)


if __name__ == "__main__":
    unittest.main()
