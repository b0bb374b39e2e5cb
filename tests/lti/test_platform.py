#!/usr/bin/env python3
"""The test platform checked on its own, with this file playing the tool (its key served from
a small HTTP server): it registers only with its registration token, sends the id_token only to
a registered redirect_uri and only for the user logged in to the browser, signs it with the key
of its JWKS, issues tokens only for a client assertion that verifies (once per jti), records
only well-formed scores within their maximum, and accepts only a deep linking response the
tool signed. So the tests of `raygrade serve` rest on a platform that checks what it should.

Usage: test_platform.py [unittest options]"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/lti holds platform.py, a name of the standard library: look there last.
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != HERE] + [HERE]

import json
import shutil
import tempfile
import time
import unittest
import uuid

import requests  # noqa: E402
from jwcrypto import jwk, jwt  # noqa: E402

import ltitest  # noqa: E402
from ltitest import LTI, browser, parse  # noqa: E402

DL = "https://purl.imsglobal.org/spec/lti-dl/claim/"
SCORE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
LINEITEM = "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem"
TOOL_CONFIG = "https://purl.imsglobal.org/spec/lti-tool-configuration"


class FakeTool:
    """A tool's key and JWKS endpoint, nothing else."""

    def __init__(self):
        self.key = jwk.JWK.generate(kty="RSA", size=2048, kid="tool-1")
        public = {"keys": [json.loads(self.key.export_public())]}

        self.keys = ltitest.JsonServer(lambda: public)
        self.url = self.keys.url

    def sign(self, claims, key=None):
        token = jwt.JWT(header={"alg": "RS256", "kid": "tool-1", "typ": "JWT"}, claims=claims)
        token.make_signed_token(key or self.key)
        return token.serialize()


class PlatformTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="raygrade-platform-")
        self.proc, self.p = ltitest.start_platform(self.tmp)
        self.tool = FakeTool()
        self.addCleanup(lambda: self.proc.stop())
        self.addCleanup(self.tool.keys.close)
        self.addCleanup(shutil.rmtree, self.tmp, True)

    def registration(self, token):
        return {
            "application_type": "web", "response_types": ["id_token"],
            "grant_types": ["implicit", "client_credentials"],
            "initiate_login_uri": f"{self.tool.url}/lti/login",
            "redirect_uris": [f"{self.tool.url}/lti/launch"],
            "client_name": "tool", "jwks_uri": f"{self.tool.url}/lti/jwks",
            "token_endpoint_auth_method": "private_key_jwt", "scope": f"{SCORE} {LINEITEM}",
            TOOL_CONFIG: {"domain": "127.0.0.1", "target_link_uri": f"{self.tool.url}/lti/launch",
                          "claims": ["iss", "sub"],
                          "messages": [{"type": "LtiDeepLinkingRequest"}]}}

    def register(self):
        config = requests.get(f"{self.p}/.well-known/openid-configuration", timeout=10).json()
        self.assertEqual(config["issuer"], self.p)
        t = requests.post(f"{self.p}/test/registration-token", timeout=10).json()
        body = self.registration(t["token"])
        r = requests.post(config["registration_endpoint"], json=body,
                          headers={"Authorization": "Bearer wrong"}, timeout=10)
        self.assertEqual(r.status_code, 401)
        r = requests.post(config["registration_endpoint"], json=body,
                          headers={"Authorization": f"Bearer {t['token']}"}, timeout=10)
        self.assertEqual(r.status_code, 200, r.text)
        answer = r.json()
        # The token is spent.
        r = requests.post(config["registration_endpoint"], json=body,
                          headers={"Authorization": f"Bearer {t['token']}"}, timeout=10)
        self.assertEqual(r.status_code, 401)
        self.client_id = answer["client_id"]
        self.deployment_id = answer[TOOL_CONFIG]["deployment_id"]
        return answer

    def id_token(self, s, message="resource", user="ada", link="link-x", redirect=None):
        """The platform's login initiation and auth answer; returns the verified claims."""
        r = s.post(f"{self.p}/test/launch", params={"user": user, "message": message,
                                                     "link": link}, timeout=10)
        login = parse(r.text).forms[0]
        self.assertEqual(login["action"], f"{self.tool.url}/lti/login")
        f = login["fields"]
        self.assertEqual(f["iss"], self.p)
        self.assertEqual(f["lti_deployment_id"], self.deployment_id)
        q = {"scope": "openid", "response_type": "id_token", "response_mode": "form_post",
             "prompt": "none", "client_id": f["client_id"], "login_hint": f["login_hint"],
             "lti_message_hint": f["lti_message_hint"], "state": "st-1", "nonce": "n-1",
             "redirect_uri": redirect or f"{self.tool.url}/lti/launch"}
        r = s.get(f"{self.p}/auth", params=q, timeout=10)
        if r.status_code != 200:
            return r
        form = parse(r.text).forms[0]
        self.assertEqual(form["action"], q["redirect_uri"])
        self.assertEqual(form["fields"]["state"], "st-1")
        keys = jwk.JWKSet.from_json(requests.get(f"{self.p}/jwks", timeout=10).text)
        claims = json.loads(jwt.JWT(jwt=form["fields"]["id_token"], key=keys,
                                    algs=["RS256"]).claims)
        self.assertEqual(claims["nonce"], "n-1")
        return claims

    def test_registration_and_launch(self):
        self.register()
        s = browser()
        c = self.id_token(s)
        self.assertEqual(c["iss"], self.p)
        self.assertEqual(c["aud"], self.client_id)
        self.assertEqual(c["sub"], "ada")
        self.assertEqual(c[LTI + "deployment_id"], self.deployment_id)
        self.assertEqual(c[LTI + "message_type"], "LtiResourceLinkRequest")
        self.assertEqual(c[LTI + "version"], "1.3.0")
        self.assertEqual(c[LTI + "resource_link"]["id"], "link-x")
        # A redirect_uri the tool did not register.
        r = self.id_token(browser(), redirect="http://127.0.0.1:9/steal")
        self.assertEqual(r.status_code, 400)
        # The auth request of Ada's launch from a browser where Ada is not logged in.
        r = s.post(f"{self.p}/test/launch", params={"user": "ada"}, timeout=10)
        f = parse(r.text).forms[0]["fields"]
        q = {"scope": "openid", "response_type": "id_token", "response_mode": "form_post",
             "prompt": "none", "client_id": f["client_id"], "login_hint": "ada",
             "lti_message_hint": f["lti_message_hint"], "state": "s", "nonce": "n",
             "redirect_uri": f"{self.tool.url}/lti/launch"}
        self.assertEqual(requests.get(f"{self.p}/auth", params=q, timeout=10).status_code, 403)
        self.assertEqual(s.get(f"{self.p}/auth", params=dict(q, login_hint="alan"),
                               timeout=10).status_code, 403)

    def assertion(self, **change):
        now = int(time.time())
        claims = {"iss": self.client_id, "sub": self.client_id, "aud": f"{self.p}/token",
                  "iat": now, "exp": now + 60, "jti": str(uuid.uuid4())}
        claims.update(change)
        return claims

    def token(self, claims, key=None, scope=SCORE):
        return requests.post(f"{self.p}/token", data={
            "grant_type": "client_credentials",
            "client_assertion_type": "urn:ietf:params:oauth:client-assertion-type:jwt-bearer",
            "client_assertion": self.tool.sign(claims, key), "scope": scope}, timeout=10)

    def test_token_and_scores(self):
        self.register()
        s = browser()
        link = s.post(f"{self.p}/test/link", json={"title": "hw", "scoreMaximum": 21}, timeout=10).json()
        self.id_token(s, user="ada", link=link["id"])
        good = self.assertion()
        r = self.token(good)
        self.assertEqual(r.status_code, 200, r.text)
        bearer = r.json()["access_token"]
        self.assertEqual(self.token(good).status_code, 401)  # the same jti again
        self.assertEqual(self.token(self.assertion(aud="http://elsewhere/token")).status_code, 401)
        self.assertEqual(self.token(self.assertion(exp=int(time.time()) - 100)).status_code, 401)
        other = jwk.JWK.generate(kty="RSA", size=2048, kid="tool-1")
        self.assertEqual(self.token(self.assertion(), key=other).status_code, 401)
        lineitem_only = self.token(self.assertion(), scope=LINEITEM).json()["access_token"]

        score = {"userId": "ada", "scoreGiven": 17, "scoreMaximum": 21,
                 "activityProgress": "Completed", "gradingProgress": "FullyGraded",
                 "timestamp": "2026-12-07T10:00:00.123Z"}
        kind = "application/vnd.ims.lis.v1.score+json"

        def post(body, token=bearer, ctype=kind):
            return requests.post(f"{link['lineitem']}/scores", data=json.dumps(body),
                                 headers={"Authorization": f"Bearer {token}",
                                          "Content-Type": ctype}, timeout=10)
        self.assertEqual(post(score, ctype="application/json").status_code, 415)
        self.assertEqual(post(score, token="nope").status_code, 401)
        self.assertEqual(post(score, token=lineitem_only).status_code, 403)
        self.assertEqual(post(dict(score, scoreGiven=22)).status_code, 400)
        self.assertEqual(post(dict(score, userId="mallory")).status_code, 400)
        self.assertEqual(post(score).status_code, 200)
        recorded = requests.get(f"{self.p}/test/scores", timeout=10).json()
        self.assertEqual([x["body"] for x in recorded], [score])
        requests.post(f"{self.p}/test/fail", json={"endpoint": "scores", "times": 1}, timeout=10)
        self.assertEqual(post(score).status_code, 503)
        self.assertEqual(post(score).status_code, 200)
        # Kept across a restart of the platform.
        port = int(self.p.rsplit(":", 1)[1])
        self.proc.stop()
        self.proc, self.p = ltitest.start_platform(self.tmp, port=port)
        self.assertEqual(len(requests.get(f"{self.p}/test/scores", timeout=10).json()), 2)

    def test_deep_linking_response(self):
        self.register()
        s = browser()
        c = self.id_token(s, message="deeplink", user="teacher", link="")
        self.assertEqual(c[LTI + "message_type"], "LtiDeepLinkingRequest")
        settings = c[DL + "deep_linking_settings"]
        now = int(time.time())
        answer = {"iss": self.client_id, "aud": self.p, "iat": now, "exp": now + 60,
                  "nonce": str(uuid.uuid4()), LTI + "deployment_id": self.deployment_id,
                  LTI + "message_type": "LtiDeepLinkingResponse", LTI + "version": "1.3.0",
                  DL + "data": settings["data"],
                  DL + "content_items": [{"type": "ltiResourceLink", "title": "Homework",
                                          "url": f"{self.tool.url}/lti/launch",
                                          "custom": {"assignment": "homework-rays.json"},
                                          "lineItem": {"scoreMaximum": 21, "label": "Homework",
                                                       "tag": "raygrade"}}]}
        url = settings["deep_link_return_url"]
        other = jwk.JWK.generate(kty="RSA", size=2048, kid="tool-1")
        self.assertEqual(s.post(url, data={"JWT": self.tool.sign(answer, other)},
                                timeout=10).status_code, 401)
        wrong_aud = dict(answer, aud="http://elsewhere", nonce="x1")
        self.assertEqual(s.post(url, data={"JWT": self.tool.sign(wrong_aud)},
                                timeout=10).status_code, 401)
        r = s.post(url, data={"JWT": self.tool.sign(answer)}, timeout=10)
        self.assertEqual(r.status_code, 200, r.text)
        self.assertEqual(s.post(url, data={"JWT": self.tool.sign(answer)},
                                timeout=10).status_code, 401)  # the nonce again
        state = requests.get(f"{self.p}/test/state", timeout=10).json()
        (link,) = state["links"].values()
        self.assertEqual(link["custom"], {"assignment": "homework-rays.json"})
        (item,) = state["lineitems"].values()
        self.assertEqual(item["scoreMaximum"], 21)
        self.assertEqual(item["resourceLinkId"], link["id"])

    def test_attack_tokens_are_what_they_say(self):
        """The forged tokens the attack tests send: alg none has no signature, the HS256 one
        is an HMAC keyed with the platform's public key, the jwk header carries a key."""
        import base64
        import hashlib
        import hmac

        def parts(token):
            h, b, sig = token.split(".")
            return json.loads(base64.urlsafe_b64decode(h + "==")), sig
        mint = lambda **k: requests.post(f"{self.p}/test/mint", json=dict(k, claims={"a": 1}),
                                         timeout=10).json()["id_token"]
        head, sig = parts(mint(key="none"))
        self.assertEqual((head["alg"], sig), ("none", ""))
        token = mint(key="hs256-public")
        head, sig = parts(token)
        self.assertEqual(head["alg"], "HS256")
        keys = jwk.JWKSet.from_json(requests.get(f"{self.p}/jwks", timeout=10).text)
        pem = list(keys["keys"])[0].export_to_pem(private_key=False)
        mac = hmac.new(pem, token.rsplit(".", 1)[0].encode(), hashlib.sha256).digest()
        self.assertEqual(base64.urlsafe_b64encode(mac).rstrip(b"=").decode(), sig)
        head, _ = parts(mint(key="other", header={"jwk": "other"}))
        self.assertEqual(head["jwk"]["kty"], "RSA")
        self.assertNotIn("d", head["jwk"])


if __name__ == "__main__":
    unittest.main()
