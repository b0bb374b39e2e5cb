#!/usr/bin/env python3
"""Attacks on `raygrade serve`'s launch and submission, each refused with a 4xx page saying why
and nothing stored (no session, user or submission row in the SQLite database of DIR):
forged or unsigned id_tokens, keys named in the token, stale or future times, the wrong
audience, issuer or deployment, nonces replayed or not issued for that login, a state without
its cookie, missing claims, one student's login response, launch or CSRF token used in another
browser. And the cookies' attributes that make a launch work across two sites.

Usage: test_attacks.py [unittest options]   ($RAYGRADE names the binary)"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import re
import unittest

import requests  # noqa: E402

import ltitest  # noqa: E402
from ltitest import ASSIGNMENT, LTI, Flow, browser, launch, row_counts  # noqa: E402


class AttackCase(ltitest.LtiCase):
    def setUp(self):
        super().setUp()
        self.reg = self.register()
        r = requests.post(f"{self.platform}/test/link", json={
            "title": "Homework", "custom": {"assignment": ASSIGNMENT}, "scoreMaximum": 21},
            timeout=30)
        r.raise_for_status()
        self.link = r.json()["id"]

    def refused(self, r, what, statuses=(400, 401, 403)):
        """`r` is a refusal (4xx, an HTML page) and nothing was stored since `self.before`."""
        self.assertIn(r.status_code, statuses, f"{what}: {r.status_code} {r.text[:300]}")
        self.assertNotIn("raygrade-launch", r.text, what)
        self.assertNotIn("raygrade_session", r.headers.get("Set-Cookie", ""), what)
        self.assertEqual(row_counts(self.data), self.before, f"{what}: rows were stored")

    def mark(self):
        self.before = row_counts(self.data)

    def forged(self, options, what, statuses=(400, 401, 403)):
        """A launch through the real login (the tool's own state and nonce) whose id_token the
        platform alters as `options` say; refused."""
        self.mark()
        s = browser()
        flow = Flow(self.platform, s, options, user="mallory", role="Learner", link=self.link)
        r = flow.login()
        self.assertIn(r.status_code, (302, 303), r.text[:300])
        r = flow.authorize()
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.refused(flow.launch(), what, statuses)


class ForgedTokenTest(AttackCase):
    def test_signatures_and_keys(self):
        cases = {
            "a signature by a key the platform never published": {"key": "other"},
            "alg none": {"key": "none"},
            "HS256 keyed with the platform's public key": {"key": "hs256-public"},
            "an unknown kid": {"key": "unknown-kid"},
            "the key in the token's jwk header": {"key": "other", "header": {"jwk": "other"}},
            "a jku header naming the attacker's key set": {
                "key": "other", "header": {"jku": f"{self.platform}/test/other-jwks",
                                           "kid": "not-published"}},
        }
        for what, options in cases.items():
            with self.subTest(what):
                self.forged(options, what)
        # The same flow unaltered is accepted (the refusals above are the alterations').
        r, data = launch(self.platform, browser(), user="mallory", role="Learner", link=self.link)
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.assertIsNotNone(data)

    def test_times_audiences_issuer_deployment(self):
        cases = {
            "an expired token": {"exp_offset": -1000, "iat_offset": -1300},
            "an iat an hour ahead": {"iat_offset": 3600, "exp_offset": 3600},
            "a wrong aud": {"aud": "someone-else"},
            "several audiences without azp": {"aud": None, "claims": {"azp": None}},
            "several audiences, azp another client": {"aud": None, "claims": {"azp": "someone-else"}},
            "a wrong iss": {"claims": {"iss": "http://127.0.0.1:9/evil"}},
            "an unknown deployment": {"claims": {LTI + "deployment_id": "deployment-unknown"}},
        }
        for what, options in cases.items():
            if options.get("aud", 1) is None:
                options["aud"] = [self.reg["client_id"], "another-client"]
            with self.subTest(what):
                self.forged(options, what)

    def test_missing_and_wrong_claims(self):
        required = ["sub", "nonce", "exp", "iat", LTI + "message_type", LTI + "version",
                    LTI + "deployment_id", LTI + "roles", LTI + "resource_link"]
        for claim in required:
            with self.subTest(f"without {claim}"):
                self.forged({"claims": {claim: None}}, f"no {claim}")
        wrong = {LTI + "version": "1.1.0", LTI + "message_type": "LtiSomethingElse",
                 LTI + "resource_link": {"title": "no id"}}
        for claim, value in wrong.items():
            with self.subTest(f"{claim} = {value}"):
                self.forged({"claims": {claim: value}}, f"{claim} = {value}")

    def test_empty_identity_claims(self):
        # An empty field never identifies anyone: LTI Core requires sub, the deployment id and
        # the resource link's id to be present and non-empty (at most 255 characters); an empty
        # string signed by the platform is refused as if it were missing.
        empty = {"sub": "", LTI + "deployment_id": "", LTI + "resource_link": {"id": ""}}
        for claim, value in empty.items():
            with self.subTest(f"{claim} = {value!r}"):
                self.forged({"claims": {claim: value}}, f"{claim} = {value!r}")


class NonceStateTest(AttackCase):
    def test_replayed_nonce(self):
        s = browser()
        flow = Flow(self.platform, s, user="ada", role="Learner", link=self.link)
        flow.login()
        flow.authorize()
        r = flow.launch()
        self.assertEqual(r.status_code, 200, r.text[:300])
        self.mark()
        # The same id_token and state again, in the same browser.
        self.refused(flow.launch(), "the same login response posted twice")
        # The old id_token with the state (and cookie) of a fresh login of the same browser.
        fresh = Flow(self.platform, s, user="ada", role="Learner", link=self.link)
        fresh.login()
        fresh.authorize()
        self.refused(fresh.launch(id_token=flow.fields["id_token"]),
                     "an old id_token with a new login's state")

    def test_nonce_not_issued_for_this_login(self):
        self.forged({"claims": {"nonce": "a-nonce-the-tool-never-issued"}}, "a made-up nonce")
        # Two logins in one browser: the id_token of the first posted with the second's state.
        s = browser()
        one = Flow(self.platform, s, user="ada", role="Learner", link=self.link)
        one.login()
        one.authorize()
        two = Flow(self.platform, s, user="ada", role="Learner", link=self.link)
        two.login()
        two.authorize()
        self.mark()
        self.refused(two.launch(id_token=one.fields["id_token"]), "the other login's nonce")

    def test_state_bound_to_the_browser(self):
        s = browser()
        flow = Flow(self.platform, s, user="ada", role="Learner", link=self.link)
        flow.login()
        flow.authorize()
        self.mark()
        self.refused(flow.launch(state="a-state-the-tool-never-issued"), "a made-up state")
        # The login response posted from a browser without the state cookie.
        self.refused(flow.launch(s=browser()), "the login response in another browser")
        # The state cookie of one login with the state of another browser's login.
        other = browser()
        theirs = Flow(self.platform, other, user="alan", role="Learner", link=self.link)
        theirs.login()
        theirs.authorize()
        self.refused(flow.launch(state=theirs.fields["state"]), "another browser's state")


class AnotherBrowserTest(AttackCase):
    def test_login_response_replayed_elsewhere(self):
        """Ada's login response (id_token and state) in Alan's browser, which has its own
        login under way: refused, and Alan is never logged in as Ada."""
        ada, alan = browser(), browser()
        hers = Flow(self.platform, ada, user="ada", role="Learner", link=self.link)
        hers.login()
        hers.authorize()
        his = Flow(self.platform, alan, user="alan", role="Learner", link=self.link)
        his.login()
        his.authorize()
        self.mark()
        self.refused(hers.launch(s=alan), "Ada's response in Alan's browser")
        self.refused(his.launch(id_token=hers.fields["id_token"]),
                     "Ada's id_token with Alan's state")

    def test_launch_and_csrf_tokens_elsewhere(self):
        ada, alan = browser(), browser()
        r, hers = launch(self.platform, ada, user="ada", role="Learner", link=self.link)
        self.assertEqual(r.status_code, 200)
        r, his = launch(self.platform, alan, user="alan", role="Learner", link=self.link)
        self.assertEqual(r.status_code, 200)
        answers = {}
        self.mark()
        attempts = {
            "Ada's launch and CSRF token with Alan's cookie": (alan, hers["launch"], hers["csrf"]),
            "Alan's launch with Ada's CSRF token": (alan, his["launch"], hers["csrf"]),
            "Ada's CSRF token with Alan's launch, in Ada's browser": (ada, his["launch"],
                                                                       hers["csrf"]),
            "Ada's launch and token without any cookie": (browser(), hers["launch"],
                                                          hers["csrf"]),
            "no CSRF token": (ada, hers["launch"], ""),
        }
        for what, (s, launch_id, csrf) in attempts.items():
            with self.subTest(what):
                r = s.post(hers["submit"], json={"launch": launch_id, "csrf": csrf,
                                                  "answers": answers}, timeout=30)
                self.assertIn(r.status_code, (400, 401, 403), f"{what}: {r.text[:200]}")
                self.assertEqual(row_counts(self.data), self.before, f"{what}: rows stored")
        r = ada.post(hers["submit"], json={"launch": hers["launch"], "csrf": hers["csrf"],
                                           "answers": answers}, timeout=30)
        self.assertEqual(r.status_code, 200, r.text[:300])


def cookie_attributes(header, name):
    """{attribute (lower case): value} of the Set-Cookie of `name` in a raw header."""
    m = re.search(rf"(?:^|,\s*){name}=[^;,]*((?:;[^;,]*)*)", header)
    if not m:
        return None
    attrs = {}
    for part in m[1].split(";")[1:]:
        k, _, v = part.strip().partition("=")
        attrs[k.lower()] = v
    return attrs


class CookieTest(AttackCase):
    def check_cookie(self, header, name):
        attrs = cookie_attributes(header, name)
        self.assertIsNotNone(attrs, f"no {name} cookie in {header!r}")
        self.assertIn("httponly", attrs)
        self.assertEqual(attrs.get("path"), "/lti")
        self.assertEqual(attrs.get("samesite", "").lower(), "none")
        self.assertIn("secure", attrs)

    def test_cookie_attributes(self):
        flow = Flow(self.platform, browser(), user="ada", role="Learner", link=self.link)
        r = flow.login()
        self.check_cookie(r.headers.get("Set-Cookie", ""), "raygrade_state")
        flow.authorize()
        r = flow.launch()
        self.assertEqual(r.status_code, 200)
        self.check_cookie(r.headers.get("Set-Cookie", ""), "raygrade_session")


class CrossSiteTest(AttackCase):
    """The platform at http://localhost:P, the tool at http://127.0.0.1:T: two sites."""
    public_host = "localhost"

    def test_launch_across_sites(self):
        self.assertTrue(self.platform.startswith("http://localhost:"))
        s = browser()
        r, data = launch(self.platform, s, user="ada", role="Learner", link=self.link)
        self.assertEqual(r.status_code, 200, r.text[:300])
        r = self.submit(s, data, {})
        self.assertEqual(r.status_code, 200, r.text[:300])


if __name__ == "__main__":
    unittest.main()
