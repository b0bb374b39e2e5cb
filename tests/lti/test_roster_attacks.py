#!/usr/bin/env python3
"""The class list from the platform (NRPS 2.0) attacked: next links to another origin, in a
loop or without end, answers that are not membership containers, huge or never finished,
user_ids that differ only in case or Unicode normalisation, the same user_id in two courses and
two platforms, hostile text in names. The instructor's report and gradebook must come, show
only the course's own members, and the tool's bearer token must go nowhere but the membership
service's origin.

Usage: test_roster_attacks.py [unittest options]   ($RAYGRADE names the binary;
RAYGRADE_TEST_DATABASE=postgresql runs the tool on PostgreSQL)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import base64  # noqa: E402
import json  # noqa: E402
import time  # noqa: E402
import unicodedata  # noqa: E402
import unittest  # noqa: E402

import requests  # noqa: E402

import ltitest  # noqa: E402
from ltitest import browser, launch  # noqa: E402
from test_roster import INSTRUCTOR, RosterCase, absent_items, member  # noqa: E402

# The most seconds an instructor waits for a report whose roster cannot be read: the tool's
# whole read of a roster is bounded (kRosterSeconds of grader/serve/roster.h, 30 s), and
# the page is built after it.
REPORT_WAIT = 60
# A container's start up to its one member's name.
NAMED = b'{"members": [{"user_id": "a", "roles": ["Learner"], "name": "'


def foreign_origin():
    """An HTTP server of another origin that records what comes to it: where a token must not
    go."""
    return ltitest.JsonServer(lambda: {"members": [member("stolen", "Stolen Roster")]})


class AttackCase(RosterCase):
    def hostile(self, **how):
        requests.post(f"{self.platform}/test/nrps", json=how, timeout=30).raise_for_status()

    def report(self):
        """The teacher's report page, and the seconds it took."""
        s = browser()
        r, data = launch(self.platform, s, user="teacher", role="Instructor",
                         link=self.link["id"])
        self.assertEqual(r.status_code, 200, r.text[:300])
        start = time.monotonic()
        report = s.get(f"{self.tool}/lti/report", params={"launch": data["launch"]},
                       timeout=REPORT_WAIT + 30)
        took = time.monotonic() - start
        self.assertEqual(report.status_code, 200, report.text[:300])
        return report.text, took


class NextLinkTest(AttackCase):
    def test_a_next_link_to_another_origin_gets_no_token(self):
        """A page whose next link is on another host (or port), or another scheme, or a
        scheme-relative //host: the tool asks no other origin for anything, with or without
        its token, and says the roster could not be read."""
        foreign = foreign_origin()
        self.addCleanup(foreign.close)
        port = self.platform.rsplit(":", 1)[1]
        self.set_members([member("ada", "Ada Lovelace")])
        for target in (f"{foreign.url}/nrps/course-1",
                       f"https://127.0.0.1:{port}/nrps/course-1",
                       f"http://localhost:{port}/nrps/course-1",
                       f"//127.0.0.1:{foreign.url.rsplit(':', 1)[1]}/nrps/course-1"):
            self.hostile(next=target)
            report, _ = self.report()
            self.assertTrue("could not be read" in report, target)
            self.assertTrue("Stolen Roster" not in report, target)
        self.assertEqual(foreign.seen, [])
        tokens = [a for a in self.nrps_calls()["authorization"]]
        self.assertTrue(all(a and a.startswith("Bearer ") for a in tokens), tokens)

    def test_a_next_link_back_to_the_first_page(self):
        """The second page links back to the first: read twice at most, and said."""
        self.set_members([member("ada", "Ada Lovelace")])
        first = f"{self.platform}/nrps/{self.link['context']}"
        for target in (first, first + "?offset=0"):
            before = self.nrps_calls()["ok"]
            self.hostile(next=target)
            report, _ = self.report()
            self.assertTrue("could not be read" in report, "no note")
            self.assertLessEqual(self.nrps_calls()["ok"] - before, 3)

    def test_pages_without_end(self):
        """Every page links to one more: the read stops (at kMaxRosterPages pages, or its
        time), the report comes and says so."""
        self.set_members([member("ada", "Ada Lovelace")])
        self.hostile(endless=True)
        report, took = self.report()
        self.assertTrue("could not be read" in report, "no note")
        self.assertLessEqual(self.nrps_calls()["ok"], 1000)
        print(f"\n  endless pages: {self.nrps_calls()['ok']} read in {took:.1f} s",
              file=sys.stderr)


class AnswerTest(AttackCase):
    def raw(self, body):
        self.hostile(raw=base64.b64encode(body if isinstance(body, bytes) else
                                          json.dumps(body).encode()).decode())

    def test_answers_that_are_not_membership_containers(self):
        """Not JSON, JSON without members, members not a list, a name of bytes that are not
        UTF-8 or of a lone surrogate's escape (RFC 8259 asks for UTF-8): the report comes and
        says the roster could not be read."""
        self.set_members([member("ada", "Ada Lovelace")])
        for body in (b"<html>Service unavailable</html>", b"", b"\xff\xfe\x00{",
                     NAMED + b'\xff\xc0"}]}', NAMED + b'\\udc80"}]}',
                     {"id": "x"}, {"members": {"user_id": "a"}}, [member("a", "A")],
                     {"members": None}):
            self.raw(body)
            report, _ = self.report()
            self.assertTrue("could not be read" in report, body)

    def test_members_that_are_not_objects_or_have_no_string_user_id(self):
        """Members that are strings, numbers, or objects whose user_id is a number, null, a
        list or empty: left out; the good ones read."""
        good = member("ada", "Ada Lovelace")
        self.set_members([good])
        bad = ["ada", 7, None, [good], dict(good, user_id=7, name="Number Id"),
               dict(good, user_id=None, name="Null Id"), dict(good, user_id=["x"], name="List"),
               dict(good, user_id="", name="Empty Id"), dict(good, name=["x"]),
               dict(good, user_id="grace", name={"a": 1}, roles="Learner")]
        self.raw({"members": bad + [good, member("alan", "Alan Turing")]})
        report, _ = self.report()
        self.assertTrue("could not be read" not in report, "a note")
        absent = absent_items(report)
        self.assertEqual(len(absent), 2, absent)
        for name in ("Number Id", "Null Id", "List", "Empty Id"):
            self.assertTrue(name not in report, name)

    def test_a_huge_answer_is_not_read_whole(self):
        """A page of 200 MB (one name that long): the tool stops reading it (the roster could
        not be read) and its memory stays far below the page's size."""
        self.set_members([member("ada", "Ada Lovelace")])
        self.hostile(huge=200 << 20)
        report, _ = self.report()
        self.assertTrue("could not be read" in report, "no note")
        with open(f"/proc/{self.tproc.pid}/status") as f:
            peak = [int(x.split()[1]) for x in f if x.startswith("VmHWM:")][0]  # kB
        self.assertLess(peak, 120 << 10, f"the tool's peak memory {peak} kB")

    def test_a_page_of_many_tiny_members(self):
        """700,000 members of a few bytes each in one page of 26 MiB (below the page's bound):
        more than kMaxRosterMembers (100,000), so the roster is not read, and the tool's memory
        stays far below what a tree of 700,000 JSON objects takes (some 700 MB)."""
        self.set_members([member("ada", "Ada Lovelace")])
        self.raw(b'{"members": [' + b",".join(b'{"user_id":"u%06d","roles":["Learner"]}' % i
                                              for i in range(700_000)) + b"]}")
        report, _ = self.report()
        self.assertTrue("could not be read" in report and "100000" in report, "no note")
        with open(f"/proc/{self.tproc.pid}/status") as f:
            peak = [int(x.split()[1]) for x in f if x.startswith("VmHWM:")][0]  # kB
        self.assertLess(peak, 150 << 10, f"the tool's peak memory {peak} kB")

    def test_a_hanging_or_dripping_service(self):
        """A service that answers nothing for two minutes, and one that sends a byte a second
        of a 1 MB body: the report comes within REPORT_WAIT seconds and says why."""
        self.set_members([member("ada", "Ada Lovelace")])
        for how in ({"hang": 120}, {"drip": 1}):
            self.hostile(**how)
            report, took = self.report()
            self.assertTrue("could not be read" in report, how)
            self.assertLess(took, REPORT_WAIT, how)


class IdentityTest(AttackCase):
    def test_user_ids_differing_in_case_or_normalisation_are_different_members(self):
        """user_id is an opaque, case-sensitive string: ada, Ada, ADA, é (NFC) and é (NFD) are
        five learners, stored as five, and Ada's submission is hers alone."""
        nfc = unicodedata.normalize("NFC", "\u00e9mile")
        nfd = unicodedata.normalize("NFD", nfc)
        self.assertNotEqual(nfc, nfd)
        ids = {"ada": "Ada One", "Ada": "Ada Two", "ADA": "Ada Three", nfc: "Emile Composed",
               nfd: "Emile Decomposed"}
        self.set_members([member(u, n) for u, n in ids.items()])
        self.submit_right("Ada")
        report, rows = self.instructor_views()
        absent = absent_items(report)
        # Each item is "user_id (name)".
        self.assertEqual(sorted(absent), sorted(["ada (Ada One)", "ADA (Ada Three)",
                                                 f"{nfc} (Emile Composed)",
                                                 f"{nfd} (Emile Decomposed)"]))
        self.assertEqual(len(rows), 5)
        by_name = {r["student"]: r for r in rows}
        self.assertAlmostEqual(float(by_name["Ada Two"]["total"]), 21, places=9)
        for name in ("Ada One", "Ada Three", "Emile Composed", "Emile Decomposed"):
            self.assertEqual(float(by_name[name]["total"]), 0, name)
        self.assertEqual(by_name["Emile Decomposed"]["id"].rsplit(" ", 1)[1], nfd)
        stored = ltitest.query(self.data, "SELECT user_id FROM members")
        self.assertEqual(sorted(r[0] for r in stored), sorted(list(ids) + ["teacher"]))

    def test_a_roster_never_shows_in_another_course(self):
        """Two courses of one platform, ada in both under two names: each course's report and
        gradebook show its own members and submissions only."""
        link2 = self.deep_link(context="course-2")
        self.set_members([member("ada", "Ada In One"), member("alan", "Alan Turing")])
        requests.post(f"{self.platform}/test/members", json={
            "context": "course-2", "members": [member("ada", "Ada In Two"),
                                               member("grace", "Grace Hopper")]},
            timeout=30).raise_for_status()
        self.submit_right("ada")  # in course 1
        report1, rows1 = self.instructor_views()
        self.link = link2
        report2, rows2 = self.instructor_views()
        self.assertEqual(sorted(r["student"] for r in rows1), ["Ada In One", "Alan Turing"])
        self.assertEqual(sorted(r["student"] for r in rows2), ["Ada In Two", "Grace Hopper"])
        self.assertEqual(sorted(absent_items(report2)),
                         ["ada (Ada In Two)", "grace (Grace Hopper)"])
        for r in rows2:
            self.assertEqual(float(r["total"]), 0, r)
        for name in ("Alan Turing", "Ada In One"):
            self.assertTrue(name not in report2, name)
        for name in ("Grace Hopper", "Ada In Two"):
            self.assertTrue(name not in report1, name)

    def test_a_roster_never_shows_under_another_platform(self):
        """A second platform (another issuer) with a course of the same id and the same
        user_ids: ada's submission on the first is not hers on the second, and neither
        platform's report names the other's members."""
        first, first_link = self.platform, self.link
        os.makedirs(os.path.join(self.tmp, "platform2"))
        pproc2, second = ltitest.start_platform(os.path.join(self.tmp, "platform2"))
        self.addCleanup(pproc2.stop)
        self.platform = second
        self.register()
        second_link = self.deep_link()  # course-1 too
        self.set_members([member("ada", "Ada Elsewhere"), member("grace", "Grace Hopper")])
        self.platform, self.link = first, first_link
        self.set_members([member("ada", "Ada Lovelace"), member("alan", "Alan Turing")])
        self.submit_right("ada")
        report1, rows1 = self.instructor_views()
        self.platform, self.link = second, second_link
        report2, rows2 = self.instructor_views()
        self.assertEqual(sorted(r["student"] for r in rows1), ["Ada Lovelace", "Alan Turing"])
        self.assertEqual(sorted(r["student"] for r in rows2), ["Ada Elsewhere", "Grace Hopper"])
        self.assertEqual(sorted(absent_items(report2)),
                         ["ada (Ada Elsewhere)", "grace (Grace Hopper)"])
        for r in rows2:
            self.assertEqual(float(r["total"]), 0, r)
            self.assertTrue(r["id"].startswith(second + " "), r["id"])
        for name in ("Alan Turing", "Ada Lovelace"):
            self.assertTrue(name not in report2, name)
        self.assertTrue("Ada Elsewhere" not in report1, "the other platform's name")


class TextTest(AttackCase):
    def test_control_characters_and_long_text(self):
        """Names and emails with NUL, escape sequences, line breaks, a bidi override, a formula
        and 100 kB of markup; a user_id with a NUL: the report shows text only, the gradebook
        has one row per line, each cell data, and the user_id of a NUL names nobody (no
        database keeps it whole)."""
        big = "<b>x</b>" * (100_000 // 8)
        hostile = [
            dict(member("m1", "Ada\x00Evil"), email="a\r\nb@example.edu"),
            dict(member("m2", "\x1b[31mRed\x1b[0m\u202e"), email="=cmd|'/C calc'!A0"),
            dict(member("m3", big), given_name="<i>g</i>", email="+1@x"),
            member("m4", "\u0007Bell\nNew,line \"quoted\""),
            member("m\x00x", "Nul In Id"),
        ]
        self.set_members(hostile)
        report, rows = self.instructor_views()
        self.assertTrue("could not be read" not in report, "a note")
        self.assertTrue("<b>x</b>" not in report and "&lt;b&gt;x&lt;/b&gt;" in report)
        for bad in ("\x00", "\x1b", "\u202e", "\x07"):
            self.assertTrue(bad not in report, repr(bad))
        self.assertTrue("Nul In Id" not in report, "a user_id with a NUL")
        self.assertEqual(len(rows), 4, [r["student"][:30] for r in rows])
        cells = {r["id"].rsplit(" ", 1)[1]: r for r in rows}
        self.assertEqual(sorted(cells), ["m1", "m2", "m3", "m4"])
        for r in rows:
            for k, v in r.items():
                self.assertFalse(any(c in v for c in "\x00\x1b\x07\u202e\r"), (k, v[:40]))
                self.assertFalse(v[:1] in ("=", "+", "-", "@"), (k, v[:40]))
        self.assertTrue(cells["m3"]["student"].startswith("<b>x</b>"))


if __name__ == "__main__":
    unittest.main()
