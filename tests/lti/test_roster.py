#!/usr/bin/env python3
"""The class list from the platform (Names and Role Provisioning Services 2.0): the instructor's
report and gradebook name every enrolled learner, those who never submitted among them, from
the membership container the test platform serves (tests/lti/platform.py), paged or not, with
hostile names, inactive and deleted members, and a platform whose service fails.

Usage: test_roster.py [unittest options]   ($RAYGRADE names the binary;
RAYGRADE_TEST_DATABASE=postgresql runs the tool on PostgreSQL)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import csv  # noqa: E402
import html  # noqa: E402
import io  # noqa: E402
import re  # noqa: E402
import unittest  # noqa: E402

import requests  # noqa: E402

import ltitest  # noqa: E402
from ltitest import assignment_points, browser, launch, solve, student_key  # noqa: E402

LEARNER = "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"
INSTRUCTOR = "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"


def member(user_id, name, role=LEARNER, status="Active"):
    return {"user_id": user_id, "name": name, "email": f"{user_id}@example.edu",
            "roles": [role], "status": status}


def absent_items(report):
    """The text of each item of the report's "No submission" list."""
    m = re.search(r'<section id="no-submission">(.*?)</section>', report, re.S)
    if not m:
        return []
    return [html.unescape(x) for x in re.findall(r"<li>(.*?)</li>", m[1], re.S)]


class RosterCase(ltitest.LtiCase):
    def setUp(self):
        super().setUp()
        self.register()
        self.link = self.deep_link()  # the teacher's deep link places the assignment

    def set_members(self, members):
        r = requests.post(f"{self.platform}/test/members",
                          json={"context": self.link["context"], "members": members}, timeout=30)
        r.raise_for_status()

    def submit_right(self, user):
        """`user` launches the link and hands in the right answers: the score."""
        s = browser()
        r, data = launch(self.platform, s, user=user, role="Learner", link=self.link["id"])
        self.assertEqual(r.status_code, 200, r.text[:300])
        r = self.submit(s, data, solve(student_key(data)))
        self.assertEqual(r.status_code, 200, r.text[:300])
        return r.json()["score"]

    def instructor_views(self):
        """The teacher's launch of the link: (report page, gradebook rows)."""
        s = browser()
        r, data = launch(self.platform, s, user="teacher", role="Instructor",
                         link=self.link["id"])
        self.assertEqual(r.status_code, 200, r.text[:300])
        report = s.get(f"{self.tool}/lti/report", params={"launch": data["launch"]}, timeout=60)
        self.assertEqual(report.status_code, 200, report.text[:300])
        book = s.get(f"{self.tool}/lti/gradebook.csv", params={"launch": data["launch"]},
                     timeout=60)
        self.assertEqual(book.status_code, 200, book.text[:300])
        return report.text, list(csv.DictReader(io.StringIO(book.text)))

    def nrps_calls(self):
        return requests.get(f"{self.platform}/test/calls", timeout=30).json()["calls"]["nrps"]


class RosterTest(RosterCase):
    def test_learners_who_never_submitted_are_listed(self):
        """Three learners and an instructor on the platform's roster, one learner submits: the
        report lists the two others as without a submission, the gradebook has a row for each
        of the three learners (none for the instructor), the roster kept in the database."""
        self.set_members([member("ada", "Ada Lovelace"), member("alan", "Alan Turing"),
                          member("grace", "Grace Hopper"),
                          member("teacher", "Tess Teacher", INSTRUCTOR)])
        score = self.submit_right("ada")
        self.assertAlmostEqual(score, assignment_points(), places=9)  # 21: every answer right
        report, rows = self.instructor_views()
        absent = absent_items(report)
        self.assertEqual(len(absent), 2, absent)
        self.assertTrue(any("Alan Turing" in a for a in absent), absent)
        self.assertTrue(any("Grace Hopper" in a for a in absent), absent)
        self.assertFalse(any("Ada" in a or "Tess" in a for a in absent), absent)
        by_name = {r["student"]: r for r in rows}
        self.assertEqual(sorted(by_name), ["Ada Lovelace", "Alan Turing", "Grace Hopper"])
        self.assertEqual(by_name["Alan Turing"]["email"], "alan@example.edu")
        self.assertAlmostEqual(float(by_name["Ada Lovelace"]["total"]), 21, places=9)
        for name in ("Alan Turing", "Grace Hopper"):
            self.assertEqual(float(by_name[name]["total"]), 0)
            self.assertEqual(by_name[name]["status"], "no submission")
        self.assertEqual(float(by_name["Alan Turing"]["max"]), 21)
        self.assertGreaterEqual(self.nrps_calls()["ok"], 1)
        # Kept: four members of the context (the teacher among them).
        stored = ltitest.query(self.data, "SELECT user_id FROM members ORDER BY user_id")
        self.assertEqual([r[0] for r in stored], ["ada", "alan", "grace", "teacher"])

    def test_a_paged_roster_is_read_to_its_last_page(self):
        """The platform answers two members a page, with Link rel="next": the tool follows
        the links, and every one of the five learners has a row."""
        requests.post(f"{self.platform}/test/nrps", json={"page_size": 2}, timeout=30)
        names = ["Ada Lovelace", "Alan Turing", "Grace Hopper", "Edsger Dijkstra",
                 "Barbara Liskov"]
        self.set_members([member(f"u{i}", n) for i, n in enumerate(names)])
        self.submit_right("u3")
        report, rows = self.instructor_views()
        self.assertEqual(sorted(r["student"] for r in rows), sorted(names))
        self.assertEqual(len(absent_items(report)), 4)
        # The teacher (of the deep link) and five learners: three pages of two.
        self.assertEqual(self.nrps_calls()["ok"] % 3, 0)

    def test_hostile_names_are_text(self):
        """Names made to be markup, to reorder a line, to be a spreadsheet formula, or very
        long: the report shows them as text, the gradebook's cells as data; a member with an
        empty user_id is nobody."""
        script = '<script>alert("roster")</script>'
        formula = '=HYPERLINK("http://evil.example","x")'
        long_name = "L" * 20000
        self.set_members([member("m1", script), member("m2", "abc\u202egnp.exe"),
                          member("m3", formula), member("m4", long_name),
                          member("", "Nobody Atall")])
        report, rows = self.instructor_views()
        # (assertTrue, not assertIn: a failure would print the whole page of 20 000 L's)
        self.assertTrue("<script>alert" not in report, "markup of a name in the report")
        self.assertTrue("&lt;script&gt;" in report, "the name shown as text")
        self.assertTrue("\u202e" not in report, "a bidi override in the report")
        self.assertTrue("Nobody Atall" not in report, "a member of no user_id in the report")
        self.assertEqual(len(rows), 4, [r["student"][:40] for r in rows])
        cells = {r["id"].rsplit(" ", 1)[1]: r["student"] for r in rows}
        self.assertEqual(cells["m1"], script)
        self.assertEqual(cells["m3"], "'" + formula)
        self.assertNotIn("\u202e", cells["m2"])
        self.assertTrue(cells["m4"].startswith("LLLL"))

    def test_inactive_members_are_marked_and_deleted_ones_left_out(self):
        self.set_members([member("ada", "Ada Lovelace"),
                          member("alan", "Alan Turing", status="Inactive"),
                          member("grace", "Grace Hopper", status="Deleted")])
        report, rows = self.instructor_views()
        absent = absent_items(report)
        self.assertEqual(len(absent), 2, absent)
        alan = [a for a in absent if "Alan Turing" in a]
        self.assertEqual(len(alan), 1)
        self.assertIn("inactive", alan[0])
        by_name = {r["student"]: r for r in rows}
        self.assertEqual(sorted(by_name), ["Ada Lovelace", "Alan Turing"])
        self.assertIn("inactive", by_name["Alan Turing"]["status"])

    def test_a_roster_that_cannot_be_read(self):
        """The platform's service fails: the report and the gradebook still come, the report
        says the class list could not be read; the list read before is the one shown."""
        self.set_members([member("ada", "Ada Lovelace"), member("alan", "Alan Turing")])
        self.submit_right("ada")
        requests.post(f"{self.platform}/test/fail", json={"endpoint": "nrps", "times": 100},
                      timeout=30)
        report, rows = self.instructor_views()
        self.assertIn("could not be read", report)
        self.assertEqual(absent_items(report), [])
        self.assertEqual(len(rows), 1)  # the one who submitted
        # Read once it works again, then kept when it fails again.
        requests.post(f"{self.platform}/test/fail", json={"endpoint": "nrps", "times": 0},
                      timeout=30)
        report, rows = self.instructor_views()
        self.assertNotIn("could not be read", report)
        self.assertEqual(len(rows), 2)
        requests.post(f"{self.platform}/test/fail", json={"endpoint": "nrps", "times": 100},
                      timeout=30)
        report, rows = self.instructor_views()
        self.assertIn("could not be read", report)
        self.assertEqual(len(absent_items(report)), 1)
        self.assertEqual(sorted(r["student"] for r in rows), ["Ada Lovelace", "Alan Turing"])


if __name__ == "__main__":
    unittest.main()
