"""An LTI 1.3 platform (an LMS as lagrade sees it) on 127.0.0.1, built on ``lti1p3platform``.

It does what Canvas or Moodle does for a tool: the OIDC third-party login initiation (``/start``
sends the browser to the tool's login URL), the authorization endpoint (``/authorize``: an
id_token signed with the platform's RSA key, returned as the auto-posted form), its JWKS, the OAuth2
token endpoint (client credentials with the tool's JWT assertion, verified against the tool's JWKS)
and the AGS scores endpoint of each line item, which records what it receives: ``scores`` is the
platform's gradebook. ``id_token()`` signs launches the tests forge (another key, another audience,
an expired token).
"""

from __future__ import annotations

import html
import json
import re
import time
import typing as t

import jwt
import pytest

pytest.importorskip("lti1p3platform")

from cryptography.hazmat.primitives import serialization  # noqa: E402
from cryptography.hazmat.primitives.asymmetric import rsa  # noqa: E402
from fastapi import FastAPI, HTTPException, Request  # noqa: E402
from fastapi.responses import HTMLResponse, JSONResponse  # noqa: E402
from lti1p3platform.ltiplatform import LTI1P3PlatformConfAbstract  # noqa: E402
from lti1p3platform.message_launch import LTIAdvantageMessageLaunchAbstract  # noqa: E402
from lti1p3platform.oidc_login import OIDCLoginAbstract  # noqa: E402
from lti1p3platform.registration import Registration  # noqa: E402

LEARNER = "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"
INSTRUCTOR = "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"
SCORE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"


def rsa_pem() -> tuple[str, str]:
    key = rsa.generate_private_key(public_exponent=65537, key_size=2048)
    private = key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                                serialization.NoEncryption()).decode()
    public = key.public_key().public_bytes(serialization.Encoding.PEM,
                                           serialization.PublicFormat.SubjectPublicKeyInfo).decode()
    return private, public


class _Conf(LTI1P3PlatformConfAbstract):
    def init_platform_config(self, **kwargs: t.Any) -> None:
        self._reg = kwargs["registration"]

    def get_registration_by_params(self, **kwargs: t.Any) -> Registration:
        return self._reg


class _Login(OIDCLoginAbstract):
    def set_lti_message_hint(self, **kwargs: t.Any) -> None:
        self._lti_message_hint = kwargs["link"]

    def get_redirect(self, url: str):
        from fastapi.responses import RedirectResponse

        return RedirectResponse(url, status_code=302)


class Platform:
    """The platform at ``url`` with the tool at ``tool_url`` registered as ``client_id`` in ``deployment_id``."""

    def __init__(self, url: str, tool_url: str, client_id: str = "lagrade-tool-1",
                 deployment_id: str = "deployment-1") -> None:
        self.url, self.tool_url = url, tool_url
        self.client_id, self.deployment_id = client_id, deployment_id
        self.private_pem, self.public_pem = rsa_pem()
        self.registration = (Registration().set_iss(url).set_client_id(client_id).set_deployment_id(deployment_id)
                             .set_oidc_login_url(f"{tool_url}/lti/login").set_launch_url(f"{tool_url}/lti/launch")
                             .set_tool_key_set_url(f"{tool_url}/lti/jwks")
                             .set_platform_public_key(self.public_pem).set_platform_private_key(self.private_pem))
        self.users: dict[str, dict] = {}  # login_hint -> name, roles
        self.links: dict[str, dict] = {}  # resource link id -> problem, line item
        self.scores: list[dict] = []  # what the AGS scores endpoints received: the gradebook
        self.token_requests = 0
        self.down = False  # the scores endpoints answer 503 (an LMS in maintenance)
        self.app = self._app()

    # ------------------------------------------------------------------ what an LMS admin sets up

    def user(self, login: str, name: str, roles: tuple[str, ...] = (LEARNER,)) -> None:
        self.users[login] = {"name": name, "roles": list(roles)}

    def link(self, link_id: str, problem: str | None, target: str | None = None) -> str:
        """A resource link (an assignment in the course) with its line item; returns the line item URL.
        ``problem``: its custom parameter ``problem`` (Moodle's way); ``target``: the URL the instructor
        typed for it instead (Canvas's way), sent as the target link URI."""
        self.links[link_id] = {"problem": problem, "lineitem": f"{self.url}/lineitems/{link_id}/lineitem",
                               "target": target}
        return self.links[link_id]["lineitem"]

    def start_url(self, login: str, link_id: str) -> str:
        return f"{self.url}/start?user={login}&link={link_id}"

    def lti_toml(self) -> str:
        """The --lti file an instructor writes from what this LMS shows them."""
        return (f'url = "{self.tool_url}"\n\n[[platform]]\nissuer = "{self.url}"\nclient_id = "{self.client_id}"\n'
                f'auth_login_url = "{self.url}/authorize"\nauth_token_url = "{self.url}/token"\n'
                f'key_set_url = "{self.url}/jwks"\ndeployment_ids = ["{self.deployment_id}"]\n')

    # ------------------------------------------------------------------ signing

    def claims(self, login: str, link_id: str, nonce: str) -> dict:
        user, link = self.users[login], self.links[link_id]
        conf = _Conf(registration=self.registration)
        launch = _Launch(None, conf)
        launch._registration = self.registration
        if link["target"]:
            launch.set_launch_url(link["target"])
        launch.set_user_data(login, user["roles"], full_name=user["name"])
        launch.set_resource_link_claim(link_id, title=f"Problem {link['problem']}")
        if link["problem"]:
            launch.set_custom_parameters_claim({"problem": link["problem"]})
        launch.set_launch_context_claim("course-1", context_title="Classical Mechanics")
        launch.set_ags(lineitems_url=f"{self.url}/lineitems", lineitem_url=link["lineitem"],
                       allow_creating_lineitems=False)
        body = launch.get_launch_message()
        body["nonce"] = nonce
        return body

    def id_token(self, body: dict, key: str | None = None, expires_in: int = 300, **changes: t.Any) -> str:
        """``body`` signed with the platform's key (or ``key``) under the platform's kid."""
        body = {**body, **changes}
        now = int(time.time())
        body.setdefault("iat", now if expires_in > 0 else now + expires_in - 60)
        body.setdefault("exp", now + expires_in)
        return Registration.encode_and_sign(body, key or self.private_pem, headers={"kid": self.registration.get_kid()})

    # ------------------------------------------------------------------ the LMS's endpoints

    def _app(self) -> FastAPI:
        app = FastAPI()
        conf = _Conf(registration=self.registration)

        @app.get("/start")
        def start(request: Request, user: str, link: str):
            login = _Login(request, conf)
            login.set_lti_message_hint(link=link)
            if self.links[link]["target"]:
                login.set_launch_url(self.links[link]["target"])
            return login.initiate_login(user)

        @app.get("/authorize")
        def authorize(request: Request):
            q = dict(request.query_params)
            if q.get("redirect_uri") != f"{self.tool_url}/lti/launch":
                raise HTTPException(400, f"redirect_uri {q.get('redirect_uri')!r} is not registered")
            if q.get("client_id") != self.client_id or q.get("response_type") != "id_token" or q.get("scope") != "openid":
                raise HTTPException(400, "not an OIDC authorization request of the registered tool")
            body = self.claims(q["login_hint"], q["lti_message_hint"], q["nonce"])
            return HTMLResponse(form(q["redirect_uri"], {"id_token": self.id_token(body), "state": q["state"]}))

        @app.get("/jwks")
        def jwks():
            return {"keys": self.registration.get_jwks()}

        @app.post("/token")
        async def token(request: Request):
            data = {k: str(v) for k, v in (await request.form()).items()}
            self.token_requests += 1
            try:
                conf.get_registration()
                answer = conf.get_access_token(data)  # the assertion verified against the tool's JWKS
                # lti1p3platform skips the assertion's audience; an LMS checks it is its token endpoint
                assertion = jwt.decode(data["client_assertion"], _public_of(conf.get_tool_public_key()),
                                       algorithms=["RS256"], audience=f"{self.url}/token")
            except Exception as exc:  # noqa: BLE001
                return JSONResponse({"error": "invalid_client", "error_description": str(exc)}, status_code=401)
            if assertion.get("iss") != self.client_id or assertion.get("sub") != self.client_id:
                return JSONResponse({"error": "invalid_client", "error_description": "iss or sub"}, status_code=401)
            return answer

        @app.post("/lineitems/{link_id}/lineitem/scores")
        async def scores(link_id: str, request: Request):
            bearer = request.headers.get("authorization", "").removeprefix("Bearer ")
            try:
                allowed = conf.validate_token(bearer, allowed_scopes=[SCORE])
            except Exception as exc:  # noqa: BLE001
                raise HTTPException(401, f"bad access token: {exc}") from None
            if not allowed:
                raise HTTPException(403, "the token lacks the score scope")
            if self.down:
                raise HTTPException(503, "down for maintenance")
            if request.headers.get("content-type") != "application/vnd.ims.lis.v1.score+json":
                raise HTTPException(415, "expected application/vnd.ims.lis.v1.score+json")
            self.scores.append({"link": link_id, **json.loads(await request.body())})
            return JSONResponse({}, status_code=200)

        return app


class _Launch(LTIAdvantageMessageLaunchAbstract):
    def render_launch_form(self, launch_data, **kwargs):  # pragma: no cover  (the tests sign through Platform)
        raise NotImplementedError


def _public_of(key: bytes | str) -> str:
    return key.decode() if isinstance(key, bytes) else key


def form(action: str, fields: dict[str, str]) -> str:
    inputs = "".join(f'<input type="hidden" name="{html.escape(k)}" value="{html.escape(v)}">' for k, v in fields.items())
    return (f'<!doctype html><form id="launch" method="post" action="{html.escape(action)}">{inputs}</form>'
            '<script>document.getElementById("launch").submit()</script>')


def read_form(page: str) -> tuple[str, dict[str, str]]:
    """(action, fields) of the auto-posted launch form."""
    action = html.unescape(re.search(r'action="([^"]*)"', page).group(1))
    fields = {html.unescape(n): html.unescape(v) for n, v in re.findall(r'name="([^"]*)" value="([^"]*)"', page)}
    return action, fields
