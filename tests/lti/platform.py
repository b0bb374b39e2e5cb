#!/usr/bin/env python3
"""A small LTI 1.3 platform (an LMS stand-in) for testing `raygrade serve`.

Written from the 1EdTech specifications: LTI Core 1.3, Security Framework 1.0, Deep Linking 2.0,
Assignment and Grade Services 2.0, Names and Role Provisioning Services 2.0 and Dynamic
Registration 1.0. Standard library HTTP server, Debian's python3-jwcrypto for the keys and
tokens, python3-requests to fetch the tool's keys.

Usage: platform.py --port 0 --state DIR [--host 127.0.0.1] [--public-host NAME]
Prints `platform: http://HOST:PORT` (the issuer) once it listens.

Platform endpoints (as the specifications name them):
  GET  /.well-known/openid-configuration   the platform's OpenID configuration
  GET  /jwks                               its public key (RS256)
  POST /register                           Dynamic Registration (Bearer registration token)
  GET|POST /auth                           the OIDC authorization endpoint (form_post answer)
  POST /token                              client_credentials with a private_key_jwt assertion
  GET|POST /ags/<context>/lineitems        AGS line items; GET|PUT|DELETE .../lineitems/<id>
  POST /ags/<context>/lineitems/<id>/scores, GET .../results
  GET  /nrps/<context>[?limit=N]           NRPS membership container, paged: at most N members
                                           (and the page size below) a page, Link rel="next"
  POST /deep-link-return                   the tool's LtiDeepLinkingResponse (form field JWT)

Test controls (JSON answers unless said otherwise):
  POST /test/registration-token            {"token", "openid_configuration"}: one registration
  GET  /test/state                         registrations, links, line items, contexts
  GET  /test/scores                        every score POST received, in order ("repeat": true
                                           when the same score had come before)
  GET  /test/calls                         how many /token and /scores calls came, by outcome
  POST /test/fail {"endpoint": "token"|"scores"|"nrps", "times": N}   503 to the next N calls
  POST /test/nrps {"page_size": N}         at most N members a membership page (null: all);
       hostile answers, each until set again: "next": URL (every page's Link rel="next"),
       "endless": true (a next link on every page, past the last member), "raw": base64 (the
       body of every page), "hang": S (seconds before the answer), "drip": S (a 1 MB body
       promised, one byte sent every S seconds), "huge": N (a body of N bytes: a container
       whose one member's name is that long)
  POST /test/slow {"seconds": S}           each score POST answered S seconds late (recorded first)
  GET|POST /test/launch?user=U&role=Learner|Instructor&context=C&link=L&message=resource|deeplink
       [&client_id=..][&name=..][&email=..]; a POST JSON body may add "claims" (merged into the
       id_token, a null value removes the claim), "header" (merged into the JOSE header),
       "key": "platform"|"other"|"none"|"hs256-public" (how the id_token is signed),
       "aud" (replaces aud), "iat_offset"/"exp_offset" (seconds added).
       Logs the browser in as U (cookie `platform_user`) and answers the auto-submitting form of
       the third-party initiated login to the tool's initiate_login_uri.
  POST /test/mint {"claims", "header", "key"}  an id_token signed as asked: {"id_token"}
  POST /test/link {"context", "title", "custom", "scoreMaximum"}  a resource link (and its line
       item) made without deep linking: the link as the platform keeps it
  GET  /test/other-jwks                    the unpublished key, for a token naming it by jku
  POST /test/members {"context", "members": [...]}  the NRPS roster of a context
"""
import os
import sys

# This file's name is also the standard library's `platform`, which `uuid` and `requests`
# import: its folder goes to the end of the search path so theirs is found first.
_HERE = os.path.dirname(os.path.abspath(__file__))
sys.path = [d for d in sys.path if os.path.abspath(d or ".") != _HERE] + [_HERE]

import argparse  # noqa: E402
import base64
import hashlib
import hmac
import html
import json
import secrets
import threading
import time
import urllib.parse
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from http.cookies import SimpleCookie

import requests
from jwcrypto import jwk, jws, jwt

LTI = "https://purl.imsglobal.org/spec/lti/claim/"
DL = "https://purl.imsglobal.org/spec/lti-dl/claim/"
AGS_CLAIM = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
NRPS_CLAIM = "https://purl.imsglobal.org/spec/lti-nrps/claim/namesroleservice"
TOOL_CONFIG = "https://purl.imsglobal.org/spec/lti-tool-configuration"
PLATFORM_CONFIG = "https://purl.imsglobal.org/spec/lti-platform-configuration"
SCOPE_LINEITEM = "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem"
SCOPE_LINEITEM_RO = "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem.readonly"
SCOPE_SCORE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
SCOPE_RESULT = "https://purl.imsglobal.org/spec/lti-ags/scope/result.readonly"
SCOPE_NRPS = "https://purl.imsglobal.org/spec/lti-nrps/scope/contextmembership.readonly"
ALL_SCOPES = [SCOPE_LINEITEM, SCOPE_LINEITEM_RO, SCOPE_SCORE, SCOPE_RESULT, SCOPE_NRPS]
ROLE = {"Learner": "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner",
        "Instructor": "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"}
SCORE_TYPE = "application/vnd.ims.lis.v1.score+json"
LINEITEM_TYPE = "application/vnd.ims.lis.v2.lineitem+json"
LINEITEMS_TYPE = "application/vnd.ims.lis.v2.lineitemcontainer+json"
RESULTS_TYPE = "application/vnd.ims.lis.v2.resultcontainer+json"
NRPS_TYPE = "application/vnd.ims.lti-nrps.v2.membershipcontainer+json"
ACTIVITY = {"Initialized", "Started", "InProgress", "Submitted", "Completed"}
GRADING = {"FullyGraded", "Pending", "PendingManual", "Failed", "NotReady"}
ASSERTION_TYPE = "urn:ietf:params:oauth:client-assertion-type:jwt-bearer"
TOKEN_LIFE = 3600


def b64url(data):
    return base64.urlsafe_b64encode(data).rstrip(b"=").decode()


class Refused(Exception):
    """A request the platform answers with `status` and a JSON error."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


class Platform:
    """The platform's state: its key, registrations, launches, line items, scores. What must
    survive a restart (key, registrations, links, line items, scores) is saved in `state_dir`."""

    def __init__(self, state_dir):
        self.dir = state_dir
        os.makedirs(state_dir, exist_ok=True)
        self.lock = threading.RLock()
        self.issuer = None
        self.key = self._load_key("platform-key.json", "platform-1")
        self._other_key = None
        self.data = {"registrations": {}, "links": {}, "lineitems": {}, "contexts": {},
                     "scores": []}
        path = os.path.join(state_dir, "state.json")
        if os.path.exists(path):
            with open(path) as f:
                self.data.update(json.load(f))
        self.registration_tokens = set()
        self.launches = {}      # lti_message_hint -> the launch a test started
        self.users = {}         # platform_user cookie -> user id
        self.tokens = {}        # access token -> {"client_id", "scopes", "exp"}
        self.jtis = set()       # client assertion jti seen
        self.dl_nonces = set()  # deep linking response nonces seen
        self.faults = {"token": 0, "scores": 0, "nrps": 0}
        self.slow_scores = 0.0  # seconds a score's answer waits
        self.nrps_page_size = None  # the most members a membership page holds (None: all)
        self.nrps_hostile = {}  # how membership pages misbehave (POST /test/nrps)
        self.calls = {"token": {"ok": 0, "refused": 0, "failed": 0},
                      "scores": {"ok": 0, "refused": 0, "failed": 0},
                      "nrps": {"ok": 0, "refused": 0, "failed": 0}}

    @property
    def other_key(self):
        """A second key the platform never publishes: tokens signed with it must be refused."""
        with self.lock:
            if self._other_key is None:
                self._other_key = self._load_key("other-key.json", "not-published")
            return self._other_key

    def _load_key(self, name, kid):
        path = os.path.join(self.dir, name)
        if os.path.exists(path):
            with open(path) as f:
                return jwk.JWK.from_json(f.read())
        key = jwk.JWK.generate(kty="RSA", size=2048, kid=kid, alg="RS256", use="sig")
        with open(path + ".tmp", "w") as f:
            f.write(key.export_private())
        os.replace(path + ".tmp", path)
        return key

    def save(self):
        """Writes the durable state at once (a temporary file renamed over the old)."""
        with self.lock:
            path = os.path.join(self.dir, "state.json")
            with open(path + ".tmp", "w") as f:
                json.dump(self.data, f, indent=1)
                f.flush()
                os.fsync(f.fileno())
            os.replace(path + ".tmp", path)

    def jwks(self):
        public = json.loads(self.key.export_public())
        public.update({"alg": "RS256", "use": "sig"})
        return {"keys": [public]}

    def url(self, path):
        return self.issuer + path

    # --- signing -------------------------------------------------------------------------
    def sign(self, claims, header=None, key="platform"):
        """A compact JWS of `claims`: RS256 with the platform's key (kid in the header) unless
        `key` asks for an attack: "other" (an unpublished key under the platform's kid), "none"
        (alg none, no signature), "hs256-public" (HMAC keyed with the platform's public key in
        PEM, the classic confusion), "unknown-kid" (the right key, a kid nobody published)."""
        head = {"typ": "JWT", "alg": "RS256", "kid": self.key.key_id}
        if key == "unknown-kid":
            head["kid"] = "nobody-" + secrets.token_hex(4)
        if key == "none":
            head = {"typ": "JWT", "alg": "none"}
        if key == "hs256-public":
            head = {"typ": "JWT", "alg": "HS256", "kid": self.key.key_id}
        head.update(header or {})
        # A key named in the token itself (the attack the Security Framework forbids honouring):
        # "other" stands for the unpublished key's public half, and the token is signed by it.
        if head.get("jwk") == "other":
            head["jwk"] = json.loads(self.other_key.export_public())
        head = {k: v for k, v in head.items() if v is not None}
        payload = json.dumps(claims, separators=(",", ":")).encode()
        if key == "none":
            return f"{b64url(json.dumps(head).encode())}.{b64url(payload)}."
        if key == "hs256-public":
            signing = f"{b64url(json.dumps(head).encode())}.{b64url(payload)}".encode()
            secret = self.key.export_to_pem(private_key=False)
            return signing.decode() + "." + b64url(hmac.new(secret, signing, hashlib.sha256).digest())
        signer = self.other_key if key == "other" else self.key
        token = jws.JWS(payload)
        token.add_signature(signer, alg="RS256", protected=json.dumps(head))
        return token.serialize(compact=True)

    # --- registration ----------------------------------------------------------------------
    def openid_configuration(self):
        return {
            "issuer": self.issuer,
            "authorization_endpoint": self.url("/auth"),
            "token_endpoint": self.url("/token"),
            "jwks_uri": self.url("/jwks"),
            "registration_endpoint": self.url("/register"),
            "scopes_supported": ["openid"] + ALL_SCOPES,
            "response_types_supported": ["id_token"],
            "subject_types_supported": ["public", "pairwise"],
            "id_token_signing_alg_values_supported": ["RS256"],
            "token_endpoint_auth_methods_supported": ["private_key_jwt"],
            "token_endpoint_auth_signing_alg_values_supported": ["RS256"],
            "claims_supported": ["sub", "iss", "name", "given_name", "family_name", "email"],
            PLATFORM_CONFIG: {
                "product_family_code": "raygrade-test-platform",
                "version": "1.0",
                "messages_supported": [{"type": "LtiResourceLinkRequest"},
                                       {"type": "LtiDeepLinkingRequest"}],
                "variables": [],
            },
        }

    def register(self, bearer, body):
        """Dynamic Registration: checks the one-time registration token and the tool's client
        registration, and issues a client_id and a deployment_id."""
        with self.lock:
            if bearer not in self.registration_tokens:
                raise Refused(401, "no valid registration token")
            self.registration_tokens.discard(bearer)
        need = {"application_type", "response_types", "grant_types", "initiate_login_uri",
                "redirect_uris", "jwks_uri", "token_endpoint_auth_method", TOOL_CONFIG}
        missing = sorted(need - set(body))
        if missing:
            raise Refused(400, f"registration lacks {missing}")
        if "id_token" not in body["response_types"]:
            raise Refused(400, "response_types must include id_token")
        if not {"implicit", "client_credentials"} <= set(body["grant_types"]):
            raise Refused(400, "grant_types must include implicit and client_credentials")
        if body["token_endpoint_auth_method"] != "private_key_jwt":
            raise Refused(400, "token_endpoint_auth_method must be private_key_jwt")
        config = body[TOOL_CONFIG]
        for field in ("domain", "target_link_uri", "claims"):
            if field not in config:
                raise Refused(400, f"{TOOL_CONFIG} lacks {field}")
        if not isinstance(body["redirect_uris"], list) or not body["redirect_uris"]:
            raise Refused(400, "redirect_uris must be a non-empty list")
        client_id = "client-" + secrets.token_hex(6)
        deployment_id = "deployment-" + secrets.token_hex(4)
        scopes = [s for s in body.get("scope", "").split() if s in ALL_SCOPES]
        with self.lock:
            self.data["registrations"][client_id] = {
                "client_id": client_id, "deployment_id": deployment_id,
                "initiate_login_uri": body["initiate_login_uri"],
                "redirect_uris": body["redirect_uris"], "jwks_uri": body["jwks_uri"],
                "target_link_uri": config["target_link_uri"], "scopes": scopes,
                "client_name": body.get("client_name", ""), "registered": time.time(),
                "request": body}
            self.save()
        answer = dict(body)
        answer["client_id"] = client_id
        answer["scope"] = " ".join(scopes)
        answer[TOOL_CONFIG] = dict(config, deployment_id=deployment_id)
        return answer

    def registration(self, client_id=None):
        regs = self.data["registrations"]
        if client_id:
            if client_id not in regs:
                raise Refused(400, f"unknown client_id {client_id}")
            return regs[client_id]
        if not regs:
            raise Refused(400, "no tool is registered")
        return max(regs.values(), key=lambda r: r["registered"])

    def tool_keys(self, reg):
        r = requests.get(reg["jwks_uri"], timeout=10)
        r.raise_for_status()
        return jwk.JWKSet.from_json(r.text)

    # --- launches --------------------------------------------------------------------------
    def context(self, cid):
        with self.lock:
            ctx = self.data["contexts"].setdefault(
                cid, {"id": cid, "title": f"Course {cid}", "members": {}})
            return ctx

    def start_launch(self, params, options, browser_user_cookie):
        """Records a launch for the test's browser and answers (cookie, form to the tool)."""
        user = params.get("user") or "student-1"
        role = params.get("role", "Learner")
        message = params.get("message", "resource")
        reg = self.registration(params.get("client_id"))
        link_id = params.get("link")
        link = self.data["links"].get(link_id) if link_id else None
        if link_id and not link and message == "resource":
            link = {"id": link_id, "context": params.get("context", "course-1"),
                    "title": link_id, "url": reg["target_link_uri"], "custom": {},
                    "lineitem": None}
        cid = link["context"] if link else params.get("context", "course-1")
        ctx = self.context(cid)
        with self.lock:
            ctx["members"].setdefault(user, {
                "user_id": user, "status": "Active", "roles": [ROLE.get(role, role)],
                "name": params.get("name", f"User {user}"),
                "email": params.get("email", f"{user}@example.edu")})
            self.save()
        hint = "launch-" + secrets.token_hex(8)
        session = browser_user_cookie or secrets.token_hex(16)
        launch = {"user": user, "role": role, "message": message, "client_id": reg["client_id"],
                  "context": cid, "link": link, "options": options, "session": session,
                  "name": params.get("name", f"User {user}"),
                  "email": params.get("email", f"{user}@example.edu"), "used": False}
        with self.lock:
            self.users[session] = user
            self.launches[hint] = launch
        target = (link or {}).get("url") or reg["target_link_uri"]
        fields = {"iss": self.issuer, "login_hint": user, "target_link_uri": target,
                  "lti_message_hint": hint, "client_id": reg["client_id"],
                  "lti_deployment_id": reg["deployment_id"]}
        if options.get("login_fields"):
            fields.update(options["login_fields"])
        return session, hint, autopost(reg["initiate_login_uri"], fields)

    def authorize(self, q, user_cookie):
        """The OIDC authentication request of the tool: checked as the Security Framework
        says, then the id_token (form_post to the registered redirect_uri)."""
        for name in ("scope", "response_type", "client_id", "redirect_uri", "login_hint",
                     "state", "response_mode", "nonce", "prompt"):
            if not q.get(name):
                raise Refused(400, f"authentication request lacks {name}")
        if q["scope"] != "openid" or q["response_type"] != "id_token":
            raise Refused(400, "scope must be openid and response_type id_token")
        if q["response_mode"] != "form_post" or q["prompt"] != "none":
            raise Refused(400, "response_mode must be form_post and prompt none")
        reg = self.registration(q["client_id"])
        if q["redirect_uri"] not in reg["redirect_uris"]:
            raise Refused(400, "redirect_uri is not one the tool registered")
        with self.lock:
            launch = self.launches.get(q.get("lti_message_hint", ""))
            if not launch:
                raise Refused(400, "unknown lti_message_hint")
            # The user is the one logged in to the platform in this browser, never the tool's say.
            if self.users.get(user_cookie) != launch["user"] or q["login_hint"] != launch["user"]:
                raise Refused(403, "login_hint is not the user logged in to this browser")
            if launch["client_id"] != q["client_id"]:
                raise Refused(400, "client_id is not the one of this launch")
        token = self.id_token(launch, reg, q["nonce"])
        return autopost(q["redirect_uri"], {"id_token": token, "state": q["state"]})

    def id_token(self, launch, reg, nonce):
        now = int(time.time())
        opt = launch["options"]
        ctx = self.data["contexts"][launch["context"]]
        claims = {
            "iss": self.issuer, "aud": reg["client_id"], "azp": reg["client_id"],
            "sub": launch["user"], "exp": now + 300 + opt.get("exp_offset", 0),
            "iat": now + opt.get("iat_offset", 0), "nonce": nonce,
            "name": launch["name"], "email": launch["email"],
            LTI + "deployment_id": reg["deployment_id"],
            LTI + "version": "1.3.0",
            LTI + "roles": [ROLE.get(launch["role"], launch["role"])],
            LTI + "context": {"id": ctx["id"], "title": ctx["title"],
                              "type": ["http://purl.imsglobal.org/vocab/lis/v2/course#CourseOffering"]},
            LTI + "tool_platform": {"guid": "raygrade-test-platform", "name": "Test platform",
                                    "product_family_code": "raygrade-test-platform"},
            NRPS_CLAIM: {"context_memberships_url": self.url(f"/nrps/{ctx['id']}"),
                         "service_versions": ["2.0"]},
        }
        ags = {"scope": reg["scopes"] and [s for s in reg["scopes"] if "lti-ags" in s] or
               [SCOPE_LINEITEM, SCOPE_SCORE, SCOPE_RESULT],
               "lineitems": self.url(f"/ags/{ctx['id']}/lineitems")}
        if launch["message"] == "deeplink":
            claims[LTI + "message_type"] = "LtiDeepLinkingRequest"
            data = "dl-" + secrets.token_hex(6)
            with self.lock:
                self.data.setdefault("dl_requests", {})[data] = {
                    "context": ctx["id"], "client_id": reg["client_id"]}
                self.save()
            claims[DL + "deep_linking_settings"] = {
                "deep_link_return_url": self.url("/deep-link-return"),
                "accept_types": ["ltiResourceLink"], "accept_presentation_document_targets":
                ["iframe", "window"], "accept_multiple": False, "accept_lineitem": True,
                "auto_create": True, "data": data}
        else:
            link = launch["link"] or {"id": "link-" + launch["context"], "title": "Raygrade"}
            claims[LTI + "message_type"] = "LtiResourceLinkRequest"
            claims[LTI + "target_link_uri"] = link.get("url") or reg["target_link_uri"]
            claims[LTI + "resource_link"] = {"id": link["id"], "title": link.get("title", "")}
            if link.get("custom"):
                claims[LTI + "custom"] = link["custom"]
            if link.get("lineitem"):
                ags["lineitem"] = link["lineitem"]
        claims[AGS_CLAIM] = ags
        claims.update(opt.get("claims", {}))
        if "aud" in opt:
            claims["aud"] = opt["aud"]
        claims = {k: v for k, v in claims.items() if v is not None}
        return self.sign(claims, opt.get("header"), opt.get("key", "platform"))

    # --- deep linking ----------------------------------------------------------------------
    def deep_link_return(self, token):
        """Verifies the tool's LtiDeepLinkingResponse (signed by a key of the tool's JWKS,
        RS256, iss = the client_id, aud = this issuer, fresh nonce, the request's data echoed)
        and creates the resource links and line items it carries."""
        try:
            head = json.loads(base64.urlsafe_b64decode(token.split(".")[0] + "=="))
            unverified = json.loads(base64.urlsafe_b64decode(token.split(".")[1] + "=="))
        except (ValueError, IndexError):
            raise Refused(400, "JWT is not a compact JWS")
        if head.get("alg") != "RS256" or not head.get("kid"):
            raise Refused(400, "the deep linking response must be RS256 with a kid")
        reg = self.registration(unverified.get("iss"))
        keys = self.tool_keys(reg)
        try:
            verified = jwt.JWT(jwt=token, key=keys, algs=["RS256"])
        except Exception as e:  # jwcrypto raises several kinds for a bad signature
            raise Refused(401, f"signature not verified by the tool's JWKS: {e}")
        c = json.loads(verified.claims)
        now = time.time()
        aud = c.get("aud")
        if aud != self.issuer and not (isinstance(aud, list) and self.issuer in aud):
            raise Refused(401, "aud is not this platform's issuer")
        if c.get("iss") != reg["client_id"]:
            raise Refused(401, "iss is not the tool's client_id")
        if not isinstance(c.get("exp"), (int, float)) or c["exp"] < now - 5:
            raise Refused(401, "expired or no exp")
        if not isinstance(c.get("iat"), (int, float)) or c["iat"] > now + 60:
            raise Refused(401, "iat missing or in the future")
        nonce = c.get("nonce")
        with self.lock:
            if not nonce or nonce in self.dl_nonces:
                raise Refused(401, "nonce missing or replayed")
            self.dl_nonces.add(nonce)
        if c.get(LTI + "message_type") != "LtiDeepLinkingResponse":
            raise Refused(400, "message_type is not LtiDeepLinkingResponse")
        if c.get(LTI + "version") != "1.3.0":
            raise Refused(400, "version is not 1.3.0")
        if c.get(LTI + "deployment_id") != reg["deployment_id"]:
            raise Refused(400, "deployment_id is not the tool's")
        request = self.data.get("dl_requests", {}).get(c.get(DL + "data"))
        if not request or request["client_id"] != reg["client_id"]:
            raise Refused(400, "data does not echo a deep linking request of this platform")
        created = []
        for item in c.get(DL + "content_items", []):
            if item.get("type") != "ltiResourceLink":
                raise Refused(400, f"content item type {item.get('type')} was not accepted")
            created.append(self.create_link(request["context"], reg, item))
        with self.lock:
            self.data.setdefault("deep_link_responses", []).append(
                {"claims": c, "header": head, "links": [x["id"] for x in created]})
            self.save()
        return created

    def create_link(self, cid, reg, item):
        link_id = "link-" + secrets.token_hex(5)
        link = {"id": link_id, "context": cid, "title": item.get("title", ""),
                "url": item.get("url") or reg["target_link_uri"],
                "custom": item.get("custom", {}), "lineitem": None, "item": item}
        li = item.get("lineItem")
        if li is not None:
            if not isinstance(li.get("scoreMaximum"), (int, float)) or li["scoreMaximum"] <= 0:
                raise Refused(400, "lineItem.scoreMaximum must be a positive number")
            made = self.new_lineitem(cid, {"scoreMaximum": li["scoreMaximum"],
                                           "label": li.get("label", item.get("title", "")),
                                           "resourceId": li.get("resourceId", ""),
                                           "tag": li.get("tag", ""),
                                           "resourceLinkId": link_id})
            link["lineitem"] = made["id"]
        with self.lock:
            self.data["links"][link_id] = link
            self.save()
        return link

    # --- services --------------------------------------------------------------------------
    def new_lineitem(self, cid, body):
        if not isinstance(body.get("scoreMaximum"), (int, float)) or body["scoreMaximum"] <= 0:
            raise Refused(400, "scoreMaximum must be a positive number")
        if not body.get("label"):
            raise Refused(400, "a line item needs a label")
        with self.lock:
            n = len(self.data["lineitems"]) + 1
            url = self.url(f"/ags/{cid}/lineitems/{n}")
            item = {k: body[k] for k in ("scoreMaximum", "label", "resourceId", "tag",
                                         "resourceLinkId", "startDateTime", "endDateTime")
                    if k in body}
            item["id"] = url
            self.data["lineitems"][str(n)] = dict(item, context=cid)
            self.save()
        return item

    def fault(self, endpoint):
        with self.lock:
            if self.faults[endpoint] > 0:
                self.faults[endpoint] -= 1
                self.calls[endpoint]["failed"] += 1
                return True
        return False

    def issue_token(self, form):
        """client_credentials with a client assertion (RFC 7523) as the Security Framework
        asks: RS256 by a key of the tool's JWKS, iss = sub = client_id, aud = this token URL,
        exp in the future, jti used once."""
        if form.get("grant_type") != "client_credentials":
            raise Refused(400, "unsupported_grant_type")
        if form.get("client_assertion_type") != ASSERTION_TYPE:
            raise Refused(400, "client_assertion_type must be jwt-bearer")
        assertion = form.get("client_assertion", "")
        try:
            head = json.loads(base64.urlsafe_b64decode(assertion.split(".")[0] + "=="))
            unverified = json.loads(base64.urlsafe_b64decode(assertion.split(".")[1] + "=="))
        except (ValueError, IndexError):
            raise Refused(400, "invalid_client: the assertion is not a JWS")
        if head.get("alg") != "RS256":
            raise Refused(401, "invalid_client: the assertion must be RS256")
        reg = self.registration(unverified.get("iss"))
        try:
            verified = jwt.JWT(jwt=assertion, key=self.tool_keys(reg), algs=["RS256"])
        except Exception as e:
            raise Refused(401, f"invalid_client: signature not verified ({e})")
        c = json.loads(verified.claims)
        now = time.time()
        if c.get("iss") != reg["client_id"] or c.get("sub") != reg["client_id"]:
            raise Refused(401, "invalid_client: iss and sub must be the client_id")
        aud = c.get("aud")
        token_url = self.url("/token")
        if aud != token_url and not (isinstance(aud, list) and token_url in aud):
            raise Refused(401, "invalid_client: aud is not the token endpoint")
        if not isinstance(c.get("exp"), (int, float)) or c["exp"] < now - 5:
            raise Refused(401, "invalid_client: the assertion expired")
        if isinstance(c.get("iat"), (int, float)) and c["iat"] > now + 60:
            raise Refused(401, "invalid_client: iat in the future")
        jti = c.get("jti")
        with self.lock:
            if not jti or jti in self.jtis:
                raise Refused(401, "invalid_client: jti missing or used before")
            self.jtis.add(jti)
        asked = form.get("scope", "").split()
        granted = [s for s in asked if s in ALL_SCOPES]
        if not granted:
            raise Refused(400, "invalid_scope")
        token = secrets.token_urlsafe(24)
        with self.lock:
            self.tokens[token] = {"client_id": reg["client_id"], "scopes": granted,
                                  "exp": now + TOKEN_LIFE}
        return {"access_token": token, "token_type": "Bearer", "expires_in": TOKEN_LIFE,
                "scope": " ".join(granted)}

    def bearer(self, header, scopes):
        """The token's grant when `header` carries a live bearer token with one of `scopes`."""
        if not header or not header.startswith("Bearer "):
            raise Refused(401, "no bearer token")
        with self.lock:
            grant = self.tokens.get(header[7:].strip())
        if not grant or grant["exp"] < time.time():
            raise Refused(401, "unknown or expired token")
        if not set(scopes) & set(grant["scopes"]):
            raise Refused(403, f"the token lacks the scope {scopes[0]}")
        return grant

    def record_score(self, cid, n, body):
        item = self.data["lineitems"].get(n)
        if not item or item["context"] != cid:
            raise Refused(404, "no such line item")
        for field in ("userId", "activityProgress", "gradingProgress", "timestamp"):
            if field not in body:
                raise Refused(400, f"score lacks {field}")
        if body["activityProgress"] not in ACTIVITY or body["gradingProgress"] not in GRADING:
            raise Refused(400, "unknown activityProgress or gradingProgress")
        ctx = self.data["contexts"].get(cid, {"members": {}})
        if body["userId"] not in ctx["members"]:
            raise Refused(400, f"userId {body['userId']} is not a member of {cid}")
        if "scoreGiven" in body:
            given, top = body["scoreGiven"], body.get("scoreMaximum")
            if not isinstance(given, (int, float)) or not isinstance(top, (int, float)):
                raise Refused(400, "scoreGiven needs a numeric scoreMaximum")
            if given < 0 or top <= 0 or given > top:
                raise Refused(400, "scoreGiven must be within 0..scoreMaximum")
        if not valid_timestamp(body["timestamp"]):
            raise Refused(400, "timestamp is not ISO 8601 with a time zone")
        with self.lock:
            # The same score sent again (same user, timestamp and values): AGS keeps the result
            # of the latest timestamp, so a repeat changes nothing; recorded, marked as such.
            again = any(s["lineitem"] == item["id"] and s["body"] == body
                        for s in self.data["scores"])
            self.data["scores"].append({"lineitem": item["id"], "received": time.time(),
                                        "body": body, "repeat": again})
            self.save()

    def results(self, cid, n):
        item = self.data["lineitems"].get(n)
        if not item or item["context"] != cid:
            raise Refused(404, "no such line item")
        last = {}
        for s in self.data["scores"]:
            if s["lineitem"] == item["id"]:
                last[s["body"]["userId"]] = s["body"]
        return [{"id": f"{item['id']}/results/{u}", "scoreOf": item["id"], "userId": u,
                 "resultScore": b.get("scoreGiven"), "resultMaximum": b.get("scoreMaximum")}
                for u, b in last.items()]


def valid_timestamp(text):
    import datetime
    if not isinstance(text, str) or not (text.endswith("Z") or "+" in text[10:] or
                                         "-" in text[10:]):
        return False
    try:
        datetime.datetime.fromisoformat(text.replace("Z", "+00:00"))
    except ValueError:
        return False
    return True


def autopost(action, fields):
    """The page a browser submits at once: a POST form to `action` with hidden `fields`."""
    inputs = "".join(f'<input type="hidden" name="{html.escape(k)}" value="{html.escape(str(v))}">'
                     for k, v in fields.items())
    return (f'<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>Redirecting'
            f'</title></head><body><form id="autopost" method="post" action="{html.escape(action)}">'
            f'{inputs}<noscript><button type="submit">Continue</button></noscript></form>'
            f'<script>document.getElementById("autopost").submit();</script></body></html>')


class Handler(BaseHTTPRequestHandler):
    platform = None
    protocol_version = "HTTP/1.1"
    disable_nagle_algorithm = True  # headers and body leave at once, not a delayed ACK apart

    def log_message(self, fmt, *args):
        if os.environ.get("PLATFORM_VERBOSE"):
            sys.stderr.write("platform: " + fmt % args + "\n")

    # --- plumbing --------------------------------------------------------------------------
    def body(self):
        n = int(self.headers.get("Content-Length") or 0)
        return self.rfile.read(n) if n else b""

    def form(self, raw):
        return {k: v[0] for k, v in urllib.parse.parse_qs(raw.decode(), keep_blank_values=True).items()}

    def send(self, status, body, ctype="application/json", headers=()):
        if not isinstance(body, (bytes, str)):
            body = json.dumps(body)
        if isinstance(body, str):
            body = body.encode()
        self.send_response(status)
        self.send_header("Content-Type", ctype)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        for k, v in headers:
            self.send_header(k, v)
        self.end_headers()
        self.wfile.write(body)

    def cookie(self, name):
        jar = SimpleCookie(self.headers.get("Cookie", ""))
        return jar[name].value if name in jar else None

    def do_GET(self):
        self.route("GET", b"")

    def do_POST(self):
        self.route("POST", self.body())

    def do_PUT(self):
        self.route("PUT", self.body())

    def do_DELETE(self):
        self.route("DELETE", b"")

    def route(self, method, raw):
        p = self.platform
        url = urllib.parse.urlsplit(self.path)
        path = url.path
        q = {k: v[0] for k, v in urllib.parse.parse_qs(url.query).items()}
        try:
            parts = path.strip("/").split("/")
            if path == "/.well-known/openid-configuration":
                return self.send(200, p.openid_configuration())
            if path == "/jwks":
                return self.send(200, p.jwks(), "application/jwk-set+json")
            if path == "/register" and method == "POST":
                auth = self.headers.get("Authorization", "")
                token = auth[7:].strip() if auth.startswith("Bearer ") else None
                try:
                    body = json.loads(raw)
                except ValueError:
                    raise Refused(400, "the registration is not JSON")
                return self.send(200, p.register(token, body))
            if path == "/auth":
                fields = q if method == "GET" else self.form(raw)
                return self.send(200, p.authorize(fields, self.cookie("platform_user")), "text/html")
            if path == "/token" and method == "POST":
                return self.token(raw)
            if parts[0] == "ags" and len(parts) >= 3:
                return self.ags(method, parts, q, raw)
            if parts[0] == "nrps" and len(parts) == 2 and method == "GET":
                return self.nrps(parts[1], q)
            if path == "/deep-link-return" and method == "POST":
                links = p.deep_link_return(self.form(raw).get("JWT", ""))
                page = ("<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>Link "
                        "created</title></head><body><main><h1>Link created</h1><ul>" +
                        "".join(f'<li data-link="{html.escape(x["id"])}">{html.escape(x["title"])}</li>'
                                for x in links) + "</ul></main></body></html>")
                return self.send(200, page, "text/html")
            if parts[0] == "test":
                return self.test_control(method, parts[1:], q, raw)
            raise Refused(404, f"no {method} {path}")
        except Refused as e:
            self.send(e.status, {"error": str(e)})
        except Exception as e:  # a bug of the platform: say it loudly, answer 500
            import traceback
            traceback.print_exc()
            self.send(500, {"error": f"{type(e).__name__}: {e}"})

    def token(self, raw):
        p = self.platform
        if p.fault("token"):
            return self.send(503, {"error": "temporarily_unavailable"})
        try:
            answer = p.issue_token(self.form(raw))
        except Refused:
            with p.lock:
                p.calls["token"]["refused"] += 1
            raise
        with p.lock:
            p.calls["token"]["ok"] += 1
        self.send(200, answer)

    def nrps(self, cid, q):
        """A page of the context's membership container (NRPS 2.0): at most `limit` members
        (the tool's query parameter) and at most the platform's own page size, from `offset`
        (a parameter of this platform's next-page URLs), with a Link header rel="next" to the
        next page while members remain."""
        p = self.platform
        if p.fault("nrps"):
            return self.send(503, {"error": "temporarily unavailable"})
        try:
            p.bearer(self.headers.get("Authorization"), [SCOPE_NRPS])
            if NRPS_TYPE not in self.headers.get("Accept", ""):
                raise Refused(406, f"Accept must name {NRPS_TYPE}")
            ctx = p.data["contexts"].get(cid)
            if not ctx:
                raise Refused(404, "no such context")
            try:
                offset = int(q.get("offset", 0))
                limit = int(q["limit"]) if "limit" in q else None
            except ValueError:
                raise Refused(400, "limit and offset are whole numbers")
        except Refused:
            with p.lock:
                p.calls["nrps"]["refused"] += 1
            raise
        with p.lock:
            p.calls["nrps"].setdefault("authorization", []).append(
                self.headers.get("Authorization"))
        if p.nrps_hostile:
            return self.nrps_hostile(cid, offset)
        members = list(ctx["members"].values())
        size = min(x for x in (limit, p.nrps_page_size, len(members) + 1) if x)
        page = members[offset:offset + size]
        headers = []
        if offset + size < len(members):
            query = {"offset": offset + size}
            if limit:
                query["limit"] = limit
            headers.append(("Link", f'<{p.url(f"/nrps/{cid}")}?{urllib.parse.urlencode(query)}>; '
                                    'rel="next"'))
        with p.lock:
            p.calls["nrps"]["ok"] += 1
        return self.send(200, {"id": p.url(self.path), "context": {"id": ctx["id"],
                                                                  "title": ctx["title"]},
                               "members": page}, NRPS_TYPE, headers)

    def nrps_hostile(self, cid, offset):
        """A membership page as POST /test/nrps asked it to misbehave."""
        h = self.platform.nrps_hostile
        with self.platform.lock:
            self.platform.calls["nrps"]["ok"] += 1
        time.sleep(float(h.get("hang", 0)))
        headers = []
        if h.get("next"):
            headers.append(("Link", f'<{h["next"]}>; rel="next"'))
        elif h.get("endless"):
            headers.append(("Link", f'<{self.platform.url(f"/nrps/{cid}")}?offset={offset + 1}>; '
                                    'rel="next"'))
        if "drip" in h:
            self.send_response(200)
            self.send_header("Content-Type", NRPS_TYPE)
            self.send_header("Content-Length", str(1 << 20))
            self.end_headers()
            try:
                for _ in range(1 << 20):
                    self.wfile.write(b" ")
                    self.wfile.flush()
                    time.sleep(float(h["drip"]))
            except OSError:
                pass  # the tool gave up
            return None
        if "huge" in h:
            head = b'{"members": [{"user_id": "huge", "roles": ["Learner"], "name": "'
            tail = b'"}]}'
            n = max(int(h["huge"]) - len(head) - len(tail), 0)
            self.send_response(200)
            self.send_header("Content-Type", NRPS_TYPE)
            self.send_header("Content-Length", str(len(head) + n + len(tail)))
            self.end_headers()
            try:
                self.wfile.write(head)
                chunk = b"H" * (1 << 20)
                while n > 0:
                    self.wfile.write(chunk[:n])
                    n -= min(n, len(chunk))
                self.wfile.write(tail)
            except OSError:
                pass  # the tool gave up
            return None
        if "raw" in h:
            return self.send(200, base64.b64decode(h["raw"]), NRPS_TYPE, headers)
        members = list(self.platform.data["contexts"][cid]["members"].values())
        return self.send(200, {"members": members if offset == 0 else []}, NRPS_TYPE, headers)

    def ags(self, method, parts, q, raw):
        p = self.platform
        cid = parts[1]
        if parts[2] != "lineitems":
            raise Refused(404, "no such service")
        if len(parts) == 3:
            if method == "GET":
                p.bearer(self.headers.get("Authorization"), [SCOPE_LINEITEM, SCOPE_LINEITEM_RO])
                items = [dict((k, v) for k, v in i.items() if k != "context")
                         for i in p.data["lineitems"].values() if i["context"] == cid]
                for field, param in (("resourceLinkId", "resource_link_id"),
                                     ("resourceId", "resource_id"), ("tag", "tag")):
                    if param in q:
                        items = [i for i in items if i.get(field) == q[param]]
                return self.send(200, items, LINEITEMS_TYPE)
            if method == "POST":
                p.bearer(self.headers.get("Authorization"), [SCOPE_LINEITEM])
                if not self.headers.get("Content-Type", "").startswith(LINEITEM_TYPE):
                    raise Refused(415, f"Content-Type must be {LINEITEM_TYPE}")
                return self.send(201, p.new_lineitem(cid, json.loads(raw)), LINEITEM_TYPE)
        n = parts[3]
        if len(parts) == 4 and method == "GET":
            p.bearer(self.headers.get("Authorization"), [SCOPE_LINEITEM, SCOPE_LINEITEM_RO])
            item = p.data["lineitems"].get(n)
            if not item or item["context"] != cid:
                raise Refused(404, "no such line item")
            return self.send(200, {k: v for k, v in item.items() if k != "context"}, LINEITEM_TYPE)
        if len(parts) == 5 and parts[4] == "scores" and method == "POST":
            if p.fault("scores"):
                return self.send(503, {"error": "temporarily unavailable"})
            try:
                p.bearer(self.headers.get("Authorization"), [SCOPE_SCORE])
                if self.headers.get("Content-Type", "").split(";")[0].strip() != SCORE_TYPE:
                    raise Refused(415, f"Content-Type must be {SCORE_TYPE}")
                try:
                    body = json.loads(raw)
                except ValueError:
                    raise Refused(400, "the score is not JSON")
                p.record_score(cid, n, body)
            except Refused:
                with p.lock:
                    p.calls["scores"]["refused"] += 1
                raise
            with p.lock:
                p.calls["scores"]["ok"] += 1
            if p.slow_scores:
                time.sleep(p.slow_scores)  # a platform slow to answer: the tool still waits
            return self.send(200, b"", "text/plain")
        if len(parts) == 5 and parts[4] == "results" and method == "GET":
            p.bearer(self.headers.get("Authorization"), [SCOPE_RESULT])
            return self.send(200, p.results(cid, n), RESULTS_TYPE)
        raise Refused(404, "no such AGS resource")

    def test_control(self, method, parts, q, raw):
        p = self.platform
        what = parts[0] if parts else ""
        body = json.loads(raw) if raw and raw.strip().startswith(b"{") else {}
        if what == "registration-token" and method == "POST":
            token = secrets.token_urlsafe(16)
            with p.lock:
                p.registration_tokens.add(token)
            return self.send(200, {"token": token, "openid_configuration":
                                   p.url("/.well-known/openid-configuration")})
        if what == "state":
            with p.lock:
                return self.send(200, {k: v for k, v in p.data.items() if k != "scores"})
        if what == "scores":
            with p.lock:
                return self.send(200, p.data["scores"])
        if what == "calls":
            with p.lock:
                return self.send(200, {"calls": p.calls, "faults": p.faults})
        if what == "nrps" and method == "POST":
            p.nrps_page_size = body.get("page_size")
            p.nrps_hostile = {k: v for k, v in body.items() if k != "page_size"}
            return self.send(200, {"page_size": p.nrps_page_size})
        if what == "slow" and method == "POST":
            p.slow_scores = float(body["seconds"])
            return self.send(200, {"seconds": p.slow_scores})
        if what == "fail" and method == "POST":
            with p.lock:
                p.faults[body["endpoint"]] = int(body["times"])
            return self.send(200, {"faults": p.faults})
        if what == "launch":
            params = dict(q)
            params.update(body.get("params", {}))
            session, hint, page = p.start_launch(params, body, self.cookie("platform_user"))
            cookie = f"platform_user={session}; Path=/; HttpOnly; SameSite=Lax"
            return self.send(200, page, "text/html",
                             [("Set-Cookie", cookie), ("X-Launch-Hint", hint)])
        if what == "other-jwks":
            return self.send(200, {"keys": [json.loads(p.other_key.export_public())]})
        if what == "link" and method == "POST":
            reg = p.registration(body.get("client_id"))
            item = {"type": "ltiResourceLink", "title": body.get("title", "Raygrade"),
                    "url": reg["target_link_uri"], "custom": body.get("custom", {})}
            if body.get("scoreMaximum"):
                item["lineItem"] = {"scoreMaximum": body["scoreMaximum"],
                                    "label": body.get("title", "Raygrade"), "tag": "raygrade"}
            return self.send(200, p.create_link(body.get("context", "course-1"), reg, item))
        if what == "mint" and method == "POST":
            return self.send(200, {"id_token": p.sign(body.get("claims", {}), body.get("header"),
                                                       body.get("key", "platform"))})
        if what == "members" and method == "POST":
            ctx = p.context(body["context"])
            with p.lock:
                for m in body["members"]:
                    ctx["members"][m["user_id"]] = m
                p.save()
            return self.send(200, ctx)
        raise Refused(404, "no such test control")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--port", type=int, default=0)
    ap.add_argument("--host", default="127.0.0.1")
    ap.add_argument("--public-host", default=None,
                    help="the host name in the issuer (localhost to be another site than 127.0.0.1)")
    ap.add_argument("--state", required=True)
    args = ap.parse_args()
    platform = Platform(args.state)
    Handler.platform = platform
    server = ThreadingHTTPServer((args.host, args.port), Handler)
    server.daemon_threads = True
    port = server.server_address[1]
    platform.issuer = f"http://{args.public_host or args.host}:{port}"
    print(f"platform: {platform.issuer}", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
