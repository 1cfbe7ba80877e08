"""Sign-in through the LMS (LTI 1.3) and grades back to it (Assignment and Grade Services).

An instructor adds lagrade to Canvas, Moodle or Blackboard as an LTI 1.3 tool (docs/server.md,
"Sign-in through the LMS"); ``lagrade serve --lti lti.toml`` names the platforms it trusts. Then:

* ``GET|POST /lti/login``: the platform's OIDC login initiation; answered with the redirect to the
  platform's authorization endpoint, carrying a ``state`` (also set as a short cookie: the launch
  must come back to the browser that started it) and a ``nonce`` (stored, single use).
* ``POST /lti/launch``: the id_token, a JWT, verified by pylti1p3 against the platform's JWKS
  (signature, issuer and client id = audience, deployment id, message type and version, ``exp``),
  the state against the cookie and the nonce consumed here, once (a replayed launch is refused).
  The LTI user (issuer, deployment, ``sub``) becomes a lagrade student the first time
  (``lti-<hash>``: no token to hand out); the resource link names a problem (the custom parameter
  ``problem=12.14``, or a target link URI ending in ``/p/12.14``); the browser is signed in.
* Grades flow back: when an attempt of a student who launched from a link is graded, the
  problem's points (the gradebook's, as ``lagrade export`` reports them) are POSTed to the link's
  line item (``<lineitem>/scores``) with an OAuth2 token obtained by a JWT assertion signed with the
  tool's key (pylti1p3's ServiceConnector). A thread sends them; a platform that is down gets them
  when it is back (what was sent is kept per link).
* ``GET /lti/jwks``: the tool's public key; ``GET /lti/config`` and ``/lti/config.json``: what the
  instructor pastes into the LMS (the JSON is Canvas's "Paste JSON"/"Enter URL" format).

pylti1p3 runs on any framework through its abstract request, cookie, session and launch-data
classes; they are implemented here for Starlette/FastAPI, with the launch data (nonces, states) in
the server's database.
"""

from __future__ import annotations

import asyncio
import hashlib
import json
import logging
import threading
import time
import tomllib
from datetime import UTC, datetime
from html import escape
from pathlib import Path
from typing import Any
from urllib.parse import urlsplit

from fastapi import APIRouter, HTTPException, Request
from fastapi.responses import HTMLResponse, JSONResponse, RedirectResponse, Response
from pydantic import BaseModel, ConfigDict, Field, ValidationError
from sqlalchemy import (
    Column,
    Float,
    Integer,
    MetaData,
    String,
    Table,
    Text,
    delete,
    func,
    insert,
    or_,
    select,
    update,
)

log = logging.getLogger("lagrade.uses.server.lti")

CLAIM = "https://purl.imsglobal.org/spec/lti/claim/"
AGS_CLAIM = "https://purl.imsglobal.org/spec/lti-ags/claim/endpoint"
SCORE_SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
STUDENT_PREFIX = "lti-"
#: seconds between the OIDC login and the launch (the state cookie and the nonce live this long)
LOGIN_SECONDS = 300

router = APIRouter(prefix="/lti", include_in_schema=False)


# ---------------------------------------------------------------------- the configuration


class Platform(BaseModel):
    """One LMS registration: what the LMS shows the instructor after they add the tool."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    #: the platform's issuer (``iss``): https://canvas.instructure.com, or Moodle's site URL
    issuer: str
    #: the client id the LMS gave the tool (Canvas: the developer key's id)
    client_id: str
    #: the LMS's OIDC authorization endpoint (Moodle: "Authentication request URL")
    auth_login_url: str
    #: the LMS's OAuth2 token endpoint (Moodle: "Access token URL")
    auth_token_url: str
    #: the LMS's public keys (Moodle: "Public keyset URL")
    key_set_url: str
    #: the deployments of the tool this server accepts launches from
    deployment_ids: tuple[str, ...] = Field(min_length=1)
    #: the ``aud`` of the token request, when it is not the token endpoint (Canvas, some Blackboards)
    auth_audience: str | None = None


class LtiConfig(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    #: the address students reach this server at (the LMS redirects there): https://lagrade.example.edu
    url: str
    #: what the LMS lists the tool as
    title: str = "lagrade"
    platforms: tuple[Platform, ...] = Field(min_length=1, alias="platform")
    #: a launch by the course's instructor (LIS role Instructor or Administrator) opens the class page
    instructors: bool = True


class LtiConfigError(ValueError):
    """The LTI file cannot be used; the message names it and what was expected."""


def load_config(path: Path) -> LtiConfig:
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise LtiConfigError(f"{path}: cannot be read ({exc}); expected a TOML file with url = ... and "
                             "[[platform]] tables (docs/server.md)") from None
    try:
        config = LtiConfig.model_validate(data)
    except ValidationError as exc:
        e = exc.errors()[0]
        where = ".".join(str(x) for x in e["loc"]) or "the file"
        raise LtiConfigError(f"{path}: {where}: {e['msg'].lower()} (docs/server.md, 'Sign-in through the LMS')") from None
    if urlsplit(config.url).scheme not in ("http", "https") or not urlsplit(config.url).netloc:
        raise LtiConfigError(f"{path}: url = {config.url!r} is not an address; expected https://host[:port]")
    return config


# ---------------------------------------------------------------------- the tables

lti_metadata = MetaData()
#: who an LTI user is here: (issuer, deployment, sub) -> the lagrade student made on the first launch
lti_users = Table(
    "lti_users", lti_metadata,
    Column("issuer", String(500), primary_key=True), Column("deployment_id", String(255), primary_key=True),
    Column("sub", String(255), primary_key=True), Column("student", String(200), nullable=False, unique=True),
    Column("name", Text), Column("email", Text), Column("created_at", String(30), nullable=False),
)
#: a student's launches from a resource link: its problem and line item, and the last grade sent there
lti_links = Table(
    "lti_links", lti_metadata,
    Column("student", String(200), primary_key=True), Column("issuer", String(500), primary_key=True),
    Column("client_id", String(255), primary_key=True), Column("link_id", String(255), primary_key=True),
    Column("deployment_id", String(255), nullable=False), Column("sub", String(255), nullable=False),
    Column("problem", String(50)), Column("ags", Text),
    Column("sent_attempt", Integer), Column("sent_at", String(30)), Column("error", Text),
)
#: pylti1p3's launch data: nonces (single use), states, launches; each with its expiry (epoch seconds)
lti_store = Table(
    "lti_store", lti_metadata,
    Column("key", String(255), primary_key=True), Column("value", Text, nullable=False),
    Column("expires", Float, nullable=False),
)


def _now() -> str:
    return time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime()) + "Z"


def student_id(issuer: str, deployment_id: str, sub: str) -> str:
    """The lagrade student of an LTI user: stable, opaque, never a name another student could take."""
    digest = hashlib.sha256(json.dumps([issuer, deployment_id, sub]).encode()).hexdigest()
    return STUDENT_PREFIX + digest[:20]


# ---------------------------------------------------------------------- pylti1p3 on Starlette


def _pylti():
    """pylti1p3's classes, subclassed for this server (imported when LTI is configured)."""
    import requests
    from pylti1p3.cookie import CookieService
    from pylti1p3.exception import LtiException
    from pylti1p3.launch_data_storage.base import LaunchDataStorage
    from pylti1p3.message_launch import MessageLaunch
    from pylti1p3.oidc_login import OIDCLogin
    from pylti1p3.redirect import Redirect
    from pylti1p3.request import Request as LtiRequest
    from pylti1p3.session import SessionService

    class HttpSession(requests.Session):
        """requests with a timeout: pylti1p3 passes none, and a platform that hangs must not hang a launch."""

        def request(self, *args, **kwargs):
            kwargs.setdefault("timeout", 15)
            return super().request(*args, **kwargs)

    class StarletteRequest(LtiRequest):
        def __init__(self, request: Request, form: dict[str, str], secure: bool) -> None:
            self._params = {**dict(request.query_params), **form}
            self._secure = secure

        @property
        def session(self):
            raise NotImplementedError("launch data live in the database (DatabaseStorage)")

        def is_secure(self) -> bool:
            return self._secure

        def get_param(self, key: str) -> str:
            return self._params.get(key, "")

    class Cookies(CookieService):
        """The state cookie: read from the request, set on the response (:meth:`apply`). Behind HTTPS it
        is ``SameSite=None; Secure`` (the launch is a cross-site POST from the LMS); over plain HTTP
        (a test on 127.0.0.1) ``Lax``, which a same-site launch still carries."""

        def __init__(self, request: Request, secure: bool) -> None:
            self._cookies = request.cookies
            self._secure = secure
            self._set: list[tuple[str, str, int | None]] = []

        def _name(self, name: str) -> str:
            return f"{self._cookie_prefix}-{name}"

        def get_cookie(self, name: str) -> str | None:
            return self._cookies.get(self._name(name))

        def set_cookie(self, name: str, value, exp: int | None = 3600) -> None:
            self._set.append((self._name(name), str(value), exp))

        def apply(self, response: Response) -> None:
            for name, value, exp in self._set:
                response.set_cookie(name, value, max_age=exp, httponly=True, path="/lti/",
                                    secure=self._secure, samesite="none" if self._secure else "lax")

    class DatabaseStorage(LaunchDataStorage):
        """pylti1p3's launch data in the server's database, with expiry; keys are global (the state
        cookie binds a launch to its browser)."""

        def __init__(self, db) -> None:
            super().__init__()
            self._db = db

        def get_session_cookie_name(self):
            return None

        def can_set_keys_expiration(self) -> bool:
            return True

        def get_value(self, key: str):
            key, now = self._prepare_key(key), time.time()
            with self._db.engine.connect() as c:
                value = c.execute(select(lti_store.c.value).where(lti_store.c.key == key,
                                                                  lti_store.c.expires > now)).scalar_one_or_none()
            return json.loads(value) if value is not None else None

        def set_value(self, key: str, value, exp: int | None = None) -> None:
            key, now = self._prepare_key(key), time.time()
            with self._db._write, self._db.engine.begin() as c:
                c.execute(delete(lti_store).where((lti_store.c.key == key) | (lti_store.c.expires <= now)))
                c.execute(insert(lti_store).values(key=key, value=json.dumps(value), expires=now + (exp or LOGIN_SECONDS)))

        def check_value(self, key: str) -> bool:
            return self.get_value(key) is not None

        def take(self, key: str) -> bool:
            """Remove the key; True if it was there and alive (one caller only ever gets True)."""
            key, now = self._prepare_key(key), time.time()
            with self._db._write, self._db.engine.begin() as c:
                gone = c.execute(delete(lti_store).where(lti_store.c.key == key, lti_store.c.expires > now))
            return gone.rowcount == 1

    class Session(SessionService):
        def __init__(self, storage: DatabaseStorage) -> None:  # noqa: D107  (no request session: the database)
            self.data_storage = storage
            self._launch_data_lifetime = LOGIN_SECONDS

        def take_nonce(self, nonce: str) -> bool:
            return self.data_storage.take(self._get_key("nonce", nonce))

    class Redirector(Redirect):
        def __init__(self, location: str) -> None:
            self._location = location

        def do_redirect(self) -> Response:
            return RedirectResponse(self._location, status_code=302)

        def do_js_redirect(self) -> Response:
            return self.do_redirect()

        def set_redirect_url(self, location: str) -> None:
            self._location = location

        def get_redirect_url(self) -> str:
            return self._location

    class Login(OIDCLogin):
        def get_redirect(self, url: str) -> Redirector:
            return Redirector(url)

    class Launch(MessageLaunch):
        def _get_request_param(self, key: str) -> str:
            return self._request.get_param(key)

        def validate_jwt_signature(self):
            super().validate_jwt_signature()
            # pylint's decode skips `aud` (it compares aud[0] with the client id): the spec's rule in
            # full, with more than one audience the authorized party must be this tool
            body, client_id = self._get_jwt_body(), self._registration.get_client_id()
            aud = body.get("aud")
            auds = aud if isinstance(aud, list) else [aud]
            if client_id not in auds or (len(auds) > 1 and body.get("azp") != client_id):
                raise LtiException(f"the id_token is not for this tool (aud {aud!r}, expected {client_id!r})")
            if "exp" not in body or "iat" not in body:
                raise LtiException("the id_token has no exp or iat")
            return self

        def save_launch_data(self):
            # the nonce is spent here, once, after every other check: a replayed launch finds it gone
            if not self._session_service.take_nonce(self._get_jwt_body().get("nonce", "")):
                raise LtiException("the nonce was used already (a replayed launch)")
            return super().save_launch_data()

    return {"HttpSession": HttpSession, "Request": StarletteRequest, "Cookies": Cookies,
            "Storage": DatabaseStorage, "Session": Session, "Login": Login, "Launch": Launch,
            "LtiException": LtiException}


# ---------------------------------------------------------------------- the tool


class Lti:
    """The LTI side of one server: its platforms, its key, the launches and the grades it sends."""

    def __init__(self, config: LtiConfig, server) -> None:
        from pylti1p3.tool_config import ToolConfDict

        self.config, self.server, self.db = config, server, server.db
        self.url = config.url.rstrip("/")
        self.secure = self.url.startswith("https://")
        self.p = _pylti()
        lti_metadata.create_all(self.db.engine)
        self.private_pem = self.db.kept("lti_private_key", _new_private_key)
        self.public_pem = _public_pem(self.private_pem)
        self.jwk = _jwk(self.public_pem)
        conf: dict[str, list[dict[str, Any]]] = {}
        for pl in config.platforms:
            conf.setdefault(pl.issuer, []).append({
                "default": False, "client_id": pl.client_id, "auth_login_url": pl.auth_login_url,
                "auth_token_url": pl.auth_token_url, "auth_audience": pl.auth_audience, "key_set_url": pl.key_set_url,
                "key_set": None, "deployment_ids": list(pl.deployment_ids)})
        self.tool = ToolConfDict(conf)
        for pl in config.platforms:
            self.tool.set_private_key(pl.issuer, self.private_pem, client_id=pl.client_id)
            self.tool.set_public_key(pl.issuer, self.public_pem, client_id=pl.client_id)
        self.storage = self.p["Storage"](self.db)
        self._wake = threading.Event()
        self._stopping = False
        self._thread: threading.Thread | None = None
        self._connectors: dict[tuple[str, str], Any] = {}
        self._sending = threading.Lock()
        self.sent = 0

    # ------------------------------------------------------------------ the scores thread

    def start(self) -> None:
        self._thread = threading.Thread(target=self._run, name="lagrade-lti-scores", daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._stopping = True
        self._wake.set()
        if self._thread is not None:
            self._thread.join(timeout=20)

    def wake(self, _attempt: int | None = None) -> None:
        """An attempt was graded (or a link launched): send what is due."""
        self._wake.set()

    def _run(self) -> None:
        while not self._stopping:
            self._wake.wait(timeout=30)  # also a retry, every 30 s, of what a platform refused
            self._wake.clear()
            if self._stopping:
                break
            try:
                self.send_due()
            except Exception:  # noqa: BLE001
                log.exception("sending grades to the LMS failed; retried in 30 s")

    def send_due(self) -> int:
        """POST the score of every link whose problem has a newer graded attempt than the one sent."""
        with self._sending:  # one pass at a time: a grade is sent once
            return self._send_due()

    def _send_due(self) -> int:
        from lagrade.uses.server.db import server_submissions

        latest = (select(server_submissions.c.student, server_submissions.c.problem,
                         func.max(server_submissions.c.id).label("latest"))
                  .where(server_submissions.c.state == "graded",
                         server_submissions.c.student.in_(select(lti_links.c.student)))
                  .group_by(server_submissions.c.student, server_submissions.c.problem).subquery())
        q = (select(lti_links, latest.c.latest)
             .join(latest, (latest.c.student == lti_links.c.student) & (latest.c.problem == lti_links.c.problem))
             .where(lti_links.c.ags.is_not(None),
                    or_(lti_links.c.sent_attempt.is_(None), lti_links.c.sent_attempt != latest.c.latest)))
        sent = 0
        with self.db.engine.connect() as c:
            due = [(row, row.latest) for row in c.execute(q)]
        for link, attempt in due:
            try:
                given, maximum, comment = self._points(link.student, link.problem)
                self._post_score(link, given, maximum, comment)
            except Exception as exc:  # noqa: BLE001  (a platform down, a token refused: kept, retried)
                log.warning("the grade of %s on %s could not be sent to %s: %s", link.student, link.problem,
                            link.issuer, exc)
                self._mark(link, None, f"{type(exc).__name__}: {exc}"[:500])
                continue
            self._mark(link, attempt, None)
            sent += 1
        self.sent += sent
        return sent

    def _points(self, student: str, problem: str) -> tuple[float, float, str]:
        """The problem's points as the gradebook has them (the same rounding as ``lagrade export``)."""
        from lagrade.uses.bulk.assignment import points
        from lagrade.uses.server.db import parts, submissions
        from lagrade.uses.server.grading import totals

        assigned = next(ap for ap in self.server.assignment.problems if ap.id == problem)
        with self.db.engine.connect() as c:
            row = c.execute(select(submissions).where(submissions.c.student == student,
                                                      submissions.c.problem == problem)).first()
            ps = [dict(r._mapping) for r in c.execute(select(parts).where(parts.c.student == student,
                                                                          parts.c.problem == problem))]
        given, maximum = points(assigned, ps, totals(self.server.plan).get(problem, 0.0))
        comment = f"lagrade: {row.status}" if row is not None else "lagrade"
        return given, maximum, comment

    def _connector(self, issuer: str, client_id: str):
        """pylti1p3's ServiceConnector of one registration (it keeps its access tokens)."""
        from pylti1p3.service_connector import ServiceConnector

        key = (issuer, client_id)
        if key not in self._connectors:
            registration = self.tool.find_registration_by_params(issuer, client_id)
            session = self.p["HttpSession"]()
            session.headers["User-Agent"] = "lagrade-lti"
            self._connectors[key] = ServiceConnector(registration, session)
        return self._connectors[key]

    def _post_score(self, link, given: float, maximum: float, comment: str) -> None:
        from pylti1p3.assignments_grades import AssignmentsGradesService
        from pylti1p3.grade import Grade

        service = AssignmentsGradesService(self._connector(link.issuer, link.client_id), json.loads(link.ags))
        grade = (Grade().set_score_given(given).set_score_maximum(maximum).set_user_id(link.sub)
                 .set_timestamp(datetime.now(UTC).isoformat(timespec="milliseconds"))
                 .set_activity_progress("Submitted").set_grading_progress("FullyGraded").set_comment(comment))
        try:
            service.put_grade(grade)
        except Exception:
            self._connectors.pop((link.issuer, link.client_id), None)  # an expired token: a new one next time
            raise

    def _mark(self, link, attempt: int | None, error: str | None) -> None:
        where = (lti_links.c.student == link.student, lti_links.c.issuer == link.issuer,
                 lti_links.c.client_id == link.client_id, lti_links.c.link_id == link.link_id)
        values: dict[str, Any] = {"error": error}
        if attempt is not None:
            values.update(sent_attempt=attempt, sent_at=_now())
        with self.db._write, self.db.engine.begin() as c:
            c.execute(update(lti_links).where(*where).values(**values))

    # ------------------------------------------------------------------ launches

    def student_for(self, body: dict) -> tuple[str, bool]:
        """(the student of the launch's user, made now?)."""
        issuer, deployment, sub = body["iss"], body[CLAIM + "deployment_id"], body["sub"]
        student = student_id(issuer, deployment, sub)
        key = (lti_users.c.issuer == issuer, lti_users.c.deployment_id == deployment, lti_users.c.sub == sub)
        with self.db._write, self.db.engine.begin() as c:
            found = c.execute(select(lti_users.c.student).where(*key)).scalar_one_or_none()
            if found is not None:
                c.execute(update(lti_users).where(*key).values(name=body.get("name"), email=body.get("email")))
                return found, False
            c.execute(insert(lti_users).values(issuer=issuer, deployment_id=deployment, sub=sub, student=student,
                                               name=body.get("name"), email=body.get("email"), created_at=_now()))
            self.db._add_student(c, student)
        return student, True

    def problem_for(self, body: dict) -> str | None:
        """The problem a resource link is for: the custom parameter ``problem``, else a target link URI
        ``.../p/<id>``; None: the assignment's index."""
        custom = body.get(CLAIM + "custom") or {}
        pid = str(custom.get("problem") or "").strip()
        if not pid:
            path = urlsplit(body.get(CLAIM + "target_link_uri") or "").path.rstrip("/")
            head, _, tail = path.rpartition("/")
            pid = tail if head.endswith("/p") else ""
        if pid and pid not in self.server.problems:
            raise HTTPException(422, f"the LMS link names problem {pid!r}, which this assignment does not have "
                                     f"(its problems: {', '.join(self.server.assignment.ids)}); ask your instructor")
        return pid or None

    def remember_link(self, student: str, body: dict, problem: str | None) -> None:
        link = body.get(CLAIM + "resource_link") or {}
        ags = body.get(AGS_CLAIM)
        ags_json = json.dumps(ags) if isinstance(ags, dict) and SCORE_SCOPE in (ags.get("scope") or []) \
            and ags.get("lineitem") else None
        key = dict(student=student, issuer=body["iss"], client_id=_aud(body), link_id=str(link.get("id", "")))
        values = dict(deployment_id=body[CLAIM + "deployment_id"], sub=body["sub"], problem=problem, ags=ags_json)
        where = [getattr(lti_links.c, k) == v for k, v in key.items()]
        with self.db._write, self.db.engine.begin() as c:
            old = c.execute(select(lti_links).where(*where)).first()
            if old is None:
                c.execute(insert(lti_links).values(**key, **values))
            elif (old.problem, old.ags) != (problem, ags_json):
                c.execute(update(lti_links).where(*where).values(**values, sent_attempt=None))
        if ags_json and problem:
            self.wake()

    def config_json(self) -> dict:
        """Canvas's LTI 1.3 JSON configuration (Developer Keys > + LTI Key > Method: Paste JSON / Enter URL)."""
        host = urlsplit(self.url).hostname
        return {
            "title": self.config.title,
            "description": "Checks answers to Lagrangian dynamics problems; grades return to the gradebook.",
            "oidc_initiation_url": f"{self.url}/lti/login",
            "target_link_uri": f"{self.url}/lti/launch",
            "public_jwk_url": f"{self.url}/lti/jwks",
            "scopes": [SCORE_SCOPE, "https://purl.imsglobal.org/spec/lti-ags/scope/lineitem.readonly",
                       "https://purl.imsglobal.org/spec/lti-ags/scope/result.readonly"],
            "extensions": [{
                "platform": "canvas.instructure.com", "privacy_level": "anonymous", "domain": host,
                "settings": {"placements": [{"placement": "link_selection", "message_type": "LtiResourceLinkRequest",
                                             "target_link_uri": f"{self.url}/lti/launch", "windowTarget": "_blank"},
                                            {"placement": "assignment_selection",
                                             "message_type": "LtiResourceLinkRequest",
                                             "target_link_uri": f"{self.url}/lti/launch", "windowTarget": "_blank"}]},
            }],
            "custom_fields": {},
        }


def _aud(body: dict) -> str:
    aud = body.get("aud")
    return aud[0] if isinstance(aud, list) else str(aud)


def _new_private_key() -> str:
    from cryptography.hazmat.primitives import serialization
    from cryptography.hazmat.primitives.asymmetric import rsa

    key = rsa.generate_private_key(public_exponent=65537, key_size=2048)
    return key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                             serialization.NoEncryption()).decode()


def _public_pem(private_pem: str) -> str:
    from cryptography.hazmat.primitives import serialization

    key = serialization.load_pem_private_key(private_pem.encode(), password=None)
    return key.public_key().public_bytes(serialization.Encoding.PEM,
                                         serialization.PublicFormat.SubjectPublicKeyInfo).decode()


def _jwk(public_pem: str) -> dict:
    from pylti1p3.registration import Registration

    return dict(Registration.get_jwk(public_pem))  # with its kid (the key's thumbprint), alg RS256, use sig


# ---------------------------------------------------------------------- the routes


def _lti(request: Request) -> Lti:
    lti = getattr(request.app.state, "lti", None)
    if lti is None:
        raise HTTPException(404, "this server takes no LTI launches (lagrade serve --lti)")
    return lti


async def _form(request: Request) -> dict[str, str]:
    if request.method != "POST":
        return {}
    form = await request.form(max_files=0, max_fields=50)
    return {k: str(v) for k, v in form.items()}


@router.api_route("/login", methods=["GET", "POST"])
async def login(request: Request):
    """OIDC login initiation (third party initiated login): the redirect to the platform's authorization."""
    lti = _lti(request)
    form = await _form(request)
    req = lti.p["Request"](request, form, lti.secure)
    target = req.get_param("target_link_uri")
    if target and not target.startswith(lti.url + "/"):
        raise HTTPException(400, f"target_link_uri {target!r} is not this tool ({lti.url})")
    cookies = lti.p["Cookies"](request, lti.secure)
    session = lti.p["Session"](lti.storage)
    oidc = lti.p["Login"](req, lti.tool, session, cookies)
    try:
        response = await asyncio.to_thread(oidc.redirect, f"{lti.url}/lti/launch")
    except Exception as exc:  # noqa: BLE001  (OIDCException, an unknown issuer: pylti1p3 raises plain Exception)
        raise HTTPException(400, f"this LMS login cannot be used: {exc}") from None
    cookies.apply(response)
    return response


@router.post("/launch")
async def launch(request: Request):
    """The launch: the id_token verified; the LTI user signed in as their lagrade student."""
    from lagrade.uses.server import web
    from lagrade.uses.server.state import SESSION_COOKIE
    from lagrade.uses.server.tokens import INSTRUCTOR

    lti = _lti(request)
    form = await _form(request)
    req = lti.p["Request"](request, form, lti.secure)
    cookies = lti.p["Cookies"](request, lti.secure)
    session = lti.p["Session"](lti.storage)
    message = lti.p["Launch"](req, lti.tool, session, cookies, requests_session=lti.p["HttpSession"]())

    def validate() -> dict:
        message.validate()
        return dict(message.get_launch_data())

    try:
        body = await asyncio.to_thread(validate)
    except Exception as exc:  # noqa: BLE001  (LtiException, or pylti1p3's plain Exception for an unknown issuer)
        log.warning("LTI launch refused: %s", exc)
        raise HTTPException(401, f"this launch from the LMS was refused ({exc}); open the assignment again "
                                 "from the LMS") from None
    teacher = lti.config.instructors and message.check_teacher_access()
    if teacher:
        student, problem = INSTRUCTOR, None
        target = "/class/"
    else:
        problem = lti.problem_for(body)
        student, _ = await asyncio.to_thread(lti.student_for, body)
        await asyncio.to_thread(lti.remember_link, student, body, problem)
        target = f"/p/{problem}" if problem else "/"
    name = body.get("name") or body.get("given_name") or ""
    # a page, not a redirect: the session cookie is SameSite=Strict, which a browser leaves off a
    # redirect that a cross-site POST started; a same-site refresh from this page carries it
    page = (f"<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>Signed in · lagrade</title>"
            f"<meta http-equiv=\"refresh\" content=\"0;url={escape(target)}\"></head><body>"
            f"<p>Signed in{' as ' + escape(name) if name else ''}. <a href=\"{escape(target)}\" data-next>"
            f"Continue</a></p></body></html>")
    response = HTMLResponse(page)
    response.headers["Content-Security-Policy"] = web.CSP
    # a session of this browser (sign-out ends it), never the student's permanent token in a cookie
    old = request.cookies.get(SESSION_COOKIE)
    if old:
        await asyncio.to_thread(lti.server.end_session, old)  # one browser, one session
    sid = await asyncio.to_thread(lti.server.db.open_session, student)
    web._set_session(request, response, sid)
    return response


@router.get("/jwks")
def jwks(request: Request) -> JSONResponse:
    """The tool's public key: the platform verifies the tool's token requests with it."""
    return JSONResponse({"keys": [_lti(request).jwk]})


@router.get("/config.json")
def config_json(request: Request) -> JSONResponse:
    return JSONResponse(_lti(request).config_json())


@router.get("/config", response_class=HTMLResponse)
def config_page(request: Request):
    """What the instructor pastes into the LMS, field by field (Moodle's names), and Canvas's JSON."""
    from lagrade.uses.server import web

    lti = _lti(request)
    rows = [("Tool URL", f"{lti.url}/lti/launch"), ("LTI version", "LTI 1.3"), ("Public key type", "Keyset URL"),
            ("Public keyset", f"{lti.url}/lti/jwks"), ("Initiate login URL", f"{lti.url}/lti/login"),
            ("Redirection URI(s)", f"{lti.url}/lti/launch"),
            ("Custom parameters (one link per problem)", "problem=" + (lti.server.assignment.ids[0] if
                                                                     lti.server.assignment.ids else "12.14")),
            ("Canvas JSON URL", f"{lti.url}/lti/config.json")]
    table = "".join(f"<tr><th scope=\"row\">{escape(k)}</th><td><code>{escape(v)}</code></td></tr>" for k, v in rows)
    body = (f"<p>Add lagrade to the LMS as an LTI 1.3 tool with these values (docs/server.md, "
            f"'Sign-in through the LMS'); then give this server the LMS's values in the --lti file.</p>"
            f"<table data-lti-config>{table}</table>"
            f"<h2>Canvas: Paste JSON</h2><pre>{escape(json.dumps(lti.config_json(), indent=2))}</pre>"
            f"<h2>Problems</h2><p>{', '.join(escape(p) for p in lti.server.assignment.ids)}</p>")
    page = (f"<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>LTI 1.3 configuration · lagrade"
            f"</title></head><body><h1>LTI 1.3 configuration</h1>{body}</body></html>")
    response = HTMLResponse(page)
    response.headers["Content-Security-Policy"] = web.CSP
    return response
