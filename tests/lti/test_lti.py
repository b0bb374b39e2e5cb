#!/usr/bin/env python3
"""The whole LTI 1.3 flow of `raygrade serve` against the test platform (tests/lti/platform.py):
dynamic registration, an instructor's deep link verified by the platform, three students with
their own numbers, submissions graded as `raygrade grade` grades the same answers, and the
scores the platform receives by AGS, each once.

Usage: test_lti.py [unittest options]   ($RAYGRADE names the binary)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import copy
import unittest

import ltitest  # noqa: E402
from ltitest import (ASSIGNMENT, LTI, assignment_points, browser, cli_grade, launch,  # noqa: E402
                     solve, student_key)

SCORE_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"


def spoil(answers):
    """The answers with two problems left blank and the first hit's t of a third made wrong."""
    out = copy.deepcopy(answers)
    del out["variant-sphere"], out["variant-plane"]
    out["variant-triangle"]["hits"][0]["t"] += 1000
    return out


class RegistrationTest(ltitest.LtiCase):
    def test_dynamic_registration(self):
        reg = self.register()
        asked = reg["request"]
        self.assertEqual(asked["initiate_login_uri"], f"{self.tool}/lti/login")
        self.assertEqual(asked["redirect_uris"], [f"{self.tool}/lti/launch"])
        self.assertEqual(asked["jwks_uri"], f"{self.tool}/lti/jwks")
        self.assertEqual(asked["token_endpoint_auth_method"], "private_key_jwt")
        self.assertIn(SCORE_SCOPE, asked["scope"].split())
        config = asked["https://purl.imsglobal.org/spec/lti-tool-configuration"]
        self.assertEqual(config["target_link_uri"], f"{self.tool}/lti/launch")
        types = {m["type"] for m in config.get("messages", [])}
        self.assertEqual(types, {"LtiResourceLinkRequest", "LtiDeepLinkingRequest"})

    def test_registration_token_is_checked(self):
        """A registration token the platform never issued: the platform refuses, the tool says
        so with a 4xx and stores no registration."""
        s = browser()
        r = s.get(f"{self.tool}/lti/register", params={
            "openid_configuration": f"{self.platform}/.well-known/openid-configuration",
            "registration_token": "made-up"}, timeout=60)
        self.assertGreaterEqual(r.status_code, 400)
        self.assertLess(r.status_code, 600)
        self.assertEqual(self.state()["registrations"], {})


class FlowTest(ltitest.LtiCase):
    def test_deep_link_students_and_scores(self):
        self.register()
        link = self.deep_link()
        points = assignment_points()
        self.assertEqual(points, 21)  # 3+2+3+2+2+1+2+3+1+2 in assignments/homework-rays.json
        # The platform verified the tool's signed response (by the tool's JWKS) and made the
        # link and its line item from it.
        self.assertEqual(link["custom"], {"assignment": ASSIGNMENT})
        self.assertEqual(link["url"], f"{self.tool}/lti/launch")
        item = self.state()["lineitems"][link["lineitem"].rsplit("/", 1)[1]]
        self.assertEqual(item["scoreMaximum"], points)
        self.assertEqual(item["tag"], "raygrade")
        self.assertEqual(item["resourceLinkId"], link["id"])

        students = {}
        for user in ("ada", "alan", "grace"):
            s = browser()
            r, data = launch(self.platform, s, user=user, role="Learner", link=link["id"])
            self.assertEqual(r.status_code, 200, r.text[:500])
            self.assertIsNotNone(data, "the student page has no raygrade-launch data")
            self.assertIn(data["assignment"], ("homework-rays", ASSIGNMENT))
            self.assertEqual(data["submit"], f"{self.tool}/lti/submit")
            self.assertNotEqual(data.get("role"), "instructor")
            students[user] = (s, data, student_key(data))
        keys = {k for _, _, k in students.values()}
        self.assertEqual(len(keys), 3, "two students share a variant key")
        right = {u: solve(k) for u, (_, _, k) in students.items()}
        # Each student's numbers as a whole: one problem drawn from a few values may coincide
        # by chance (the key holds the platform's address, whose port changes from run to run),
        # all of them together do not.
        self.assertNotEqual(right["ada"], right["alan"])
        self.assertNotEqual(right["alan"], right["grace"])
        self.assertNotEqual(right["ada"], right["grace"])

        # Ada answers everything right, Alan leaves two problems blank and gets the t of a
        # third wrong, Grace hands in Ada's answers (right for Ada's numbers, not for hers).
        handed = {"ada": right["ada"], "alan": spoil(right["alan"]),
                  "grace": right["ada"]}
        got = {}
        for user, (s, data, key) in students.items():
            r = self.submit(s, data, handed[user])
            self.assertEqual(r.status_code, 200, r.text[:500])
            answer = r.json()
            want = cli_grade(key, handed[user], self.tmp)
            self.assertAlmostEqual(answer["score"], want[0], places=9, msg=user)
            self.assertAlmostEqual(answer["max"], want[1], places=9, msg=user)
            self.assertIn("feedback", answer)
            got[user] = answer
        self.assertAlmostEqual(got["ada"]["score"], points, places=9)
        # Alan: less than full marks less the 3 + 2 points of the blank problems.
        self.assertLess(got["alan"]["score"], points - 5)
        self.assertLess(got["grace"]["score"], points)

        # Each score reaches the platform once, with the student's sub and the right values.
        scores = self.wait_scores(3)
        self.assertEqual(len(scores), 3, scores)
        by_user = {s["body"]["userId"]: s for s in scores}
        self.assertEqual(set(by_user), {"ada", "alan", "grace"})
        for user, answer in got.items():
            body = by_user[user]["body"]
            self.assertEqual(by_user[user]["lineitem"], link["lineitem"])
            self.assertAlmostEqual(body["scoreGiven"] / body["scoreMaximum"],
                                   answer["score"] / answer["max"], places=9)
            self.assertAlmostEqual(body["scoreMaximum"], points, places=9)
            self.assertEqual(body["activityProgress"], "Completed")
            self.assertEqual(body["gradingProgress"], "FullyGraded")
            self.assertRegex(body["timestamp"], r"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$")

        # A second launch of the same student gives the same numbers (the key is stable).
        s = browser()
        r, again = launch(self.platform, s, user="ada", role="Learner", link=link["id"])
        self.assertEqual(r.status_code, 200)
        self.assertEqual(student_key(again), students["ada"][2])
        self.assertNotEqual(again["launch"], students["ada"][1]["launch"])

    def test_line_item_made_by_the_tool(self):
        """A link placed without a line item (the launch carries lineitems, not lineitem): the
        tool creates the line item of the resource link by AGS, once, and scores go there."""
        import requests
        self.register()
        link = requests.post(f"{self.platform}/test/link", json={
            "title": "Homework", "custom": {"assignment": ASSIGNMENT}}, timeout=30).json()
        self.assertIsNone(link["lineitem"])
        for user in ("ada", "alan"):
            s = browser()
            r, data = launch(self.platform, s, user=user, role="Learner", link=link["id"])
            self.assertEqual(r.status_code, 200, r.text[:300])
            r = self.submit(s, data, solve(student_key(data)))
            self.assertEqual(r.status_code, 200, r.text[:300])
        scores = self.wait_scores(2)
        items = list(self.state()["lineitems"].values())
        self.assertEqual(len(items), 1, items)
        self.assertEqual(items[0]["resourceLinkId"], link["id"])
        self.assertAlmostEqual(items[0]["scoreMaximum"], assignment_points(), places=9)
        self.assertEqual({x["lineitem"] for x in scores}, {items[0]["id"]})
        self.assertEqual(sorted(x["body"]["userId"] for x in scores), ["ada", "alan"])
        for x in scores:
            self.assertAlmostEqual(x["body"]["scoreGiven"], x["body"]["scoreMaximum"], places=9)

    def test_instructor_page(self):
        self.register()
        link = self.deep_link()
        s = browser()
        r, data = launch(self.platform, s, user="teacher", role="Instructor", link=link["id"])
        self.assertEqual(r.status_code, 200, r.text[:500])
        self.assertEqual(data.get("role"), "instructor")
        for path in ("/lti/report", "/lti/gradebook.csv", "/lti/regrade"):
            self.assertIn(f"{self.tool}{path}", r.text)
        report = s.get(f"{self.tool}/lti/report", params={"launch": data["launch"]}, timeout=60)
        self.assertEqual(report.status_code, 200, report.text[:300])
        book = s.get(f"{self.tool}/lti/gradebook.csv", params={"launch": data["launch"]},
                     timeout=60)
        self.assertEqual(book.status_code, 200, book.text[:300])
        self.assertTrue(book.headers.get("Content-Type", "").startswith("text/csv"))
        # A student's session cannot read the report.
        student = browser()
        r, sdata = launch(self.platform, student, user="ada", role="Learner", link=link["id"])
        self.assertEqual(r.status_code, 200)
        refused = student.get(f"{self.tool}/lti/report", params={"launch": sdata["launch"]},
                              timeout=60)
        self.assertIn(refused.status_code, (401, 403))
        refused = student.get(f"{self.tool}/lti/report", params={"launch": data["launch"]},
                              timeout=60)
        self.assertIn(refused.status_code, (401, 403))

    def test_deep_link_response_is_signed_by_the_tool(self):
        """The JWT the tool returns verifies with /lti/jwks (checked again here, apart from the
        platform): RS256, a kid of the tool's set, aud the platform, iss the client_id."""
        from jwcrypto import jwk, jwt
        import json
        import requests
        reg = self.register()
        self.deep_link()
        keys = jwk.JWKSet.from_json(requests.get(f"{self.tool}/lti/jwks", timeout=30).text)
        for k in json.loads(keys.export(private_keys=False))["keys"]:
            self.assertEqual(k["kty"], "RSA")
            self.assertNotIn("d", k)
        token = jwt.JWT(jwt=self.dl_jwt, key=keys, algs=["RS256"])
        claims = json.loads(token.claims)
        self.assertEqual(claims["aud"] if isinstance(claims["aud"], str) else claims["aud"][0],
                         self.platform)
        self.assertEqual(claims["iss"], reg["client_id"])
        self.assertEqual(claims[LTI + "message_type"], "LtiDeepLinkingResponse")
        # A tampered response is refused by the platform.
        head, body, sig = self.dl_jwt.split(".")
        forged = f"{head}.{body}.{sig[:-4]}AAAA"
        r = browser().post(f"{self.platform}/deep-link-return", data={"JWT": forged}, timeout=30)
        self.assertEqual(r.status_code, 401)


if __name__ == "__main__":
    unittest.main()
