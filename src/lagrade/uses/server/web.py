"""The student page (and the instructor's live class page): Jinja2 templates, no script or style
fetched from anywhere; math is presentation MathML, which browsers render natively."""

from __future__ import annotations

import hmac
import json
import mimetypes
import secrets
import tempfile
import time
from pathlib import Path
from typing import Annotated

from fastapi import APIRouter, HTTPException, Query, Request
from fastapi.responses import HTMLResponse, RedirectResponse, Response
from fastapi.templating import Jinja2Templates

from lagrade.answer.reading.suffixes import ANSWER_SUFFIXES
from lagrade.uses.server.answers import AnswerTextError, to_toml
from lagrade.uses.server.api import MAX_ID, submit
from lagrade.uses.server.state import SESSION_COOKIE, SESSION_SECONDS, TEMPLATES, Who
from lagrade.uses.server.tokens import guest_session, login_csrf, student_of

router = APIRouter(include_in_schema=False)
templates = Jinja2Templates(directory=str(TEMPLATES))
#: a page runs only the scripts this server serves (/static/problem.js), none written into the page
#: (an injected ``<script>`` or ``onclick=`` does not run); its style is its own, inline
CSP = ("default-src 'none'; script-src 'self'; style-src 'unsafe-inline'; img-src 'self' data:; "
       "connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'")
#: the class page (the HTML report, which also opens from a folder: its error catcher is inline)
#: links its own style.css and report.js: from this server only
CLASS_CSP = ("default-src 'none'; script-src 'self' 'unsafe-inline'; style-src 'self' 'unsafe-inline'; "
             "img-src 'self' data:; connect-src 'self'; form-action 'self'; base-uri 'none'; frame-ancestors 'none'")
#: the pages' own scripts
STATIC = Path(__file__).parent / "static"
#: the sign-in form's nonce (see tokens.login_csrf), for the sign-in pages only
LOGIN_COOKIE = "lagrade_login"


def _server(request: Request):
    return request.app.state.server


def _page(request: Request, name: str, context: dict, status: int = 200, cookie: str | None = None) -> HTMLResponse:
    response = templates.TemplateResponse(request, name, context, status_code=status)
    response.headers["Content-Security-Policy"] = CSP
    response.headers["X-Content-Type-Options"] = "nosniff"
    response.headers["Referrer-Policy"] = "no-referrer"  # a sign-in link's token stays in this tab
    if cookie:
        _set_session(request, response, cookie)
    return response


def error_page(request: Request, status: int, message: str, headers: dict | None = None) -> HTMLResponse:
    """A browser's error as a page of the site (one line, and the way back), not raw JSON."""
    parts = request.url.path.split("/")
    back = f"/p/{parts[2]}" if len(parts) > 2 and parts[1] == "p" and parts[2] else None
    titles = {401: "Sign in first", 403: "Not allowed", 404: "Not found", 422: "Not understood",
              429: "Too many checks"}
    response = _page(request, "error.html", {"title": titles.get(status, "Something went wrong"), "who": None,
                                             "error": message, "status": status, "back": back}, status=status)
    for name, value in (headers or {}).items():
        response.headers[name] = value
    return response


def one_line_invalid(exc) -> str:
    """A request's invalid query or path value in one line: which, what was sent, what was expected."""
    errors = exc.errors()
    if not errors:
        return "the request was not understood"
    e = errors[0]
    where = str(e["loc"][-1]) if e.get("loc") else "the request"
    sent = e.get("input")
    return f"{where}={sent!r} is not understood: {e['msg'].lower()}" if sent is not None else \
        f"{where}: {e['msg'].lower()}"


def _secure(request: Request) -> bool:
    """Cookies are `Secure` over HTTPS: the server says it is reached so (--https, --ssl-certfile), or
    this request came over TLS (here, or through a proxy uvicorn trusts: X-Forwarded-Proto)."""
    return _server(request).config.https or request.url.scheme == "https"


def _set_session(request: Request, response: Response, sid: str) -> None:
    """The session's cookie: a random id of a session in the database (sign-out ends it), never the token."""
    response.set_cookie(SESSION_COOKIE, sid, httponly=True, samesite="strict", secure=_secure(request),
                        max_age=SESSION_SECONDS, path="/")


def _who(request: Request) -> tuple[Who | None, str | None]:
    """(who, a new guest cookie to set): None when not signed in on a server that needs tokens."""
    server = _server(request)
    try:
        who = server.identify(request)
    except HTTPException:
        return None, None
    if who.session is None and server.config.open:  # a browser on an open server: a guest of its own
        sid, student = guest_session(server.secret, time.time())  # signed: no row written per visit
        return Who(student, sid), sid
    if who.session is None:
        return None, None  # a Bearer header is for the API; the pages want a signed-in browser
    return who, None


@router.get("/", response_class=HTMLResponse)
def index(request: Request):
    server = _server(request)
    who, cookie = _who(request)
    if who is None:
        return _sign_in_page(request, {})
    items = [{"id": pid, "title": p.title, "parts": len(p.parts)} for pid, p in server.problems.items()]
    return _page(request, "index.html", {"title": server.assignment.title or server.assignment.name, "who": who,
                                         "problems": items, "csrf": server.csrf(who)}, cookie=cookie)


def _sign_in_page(request: Request, context: dict, status: int = 200) -> HTMLResponse:
    """The sign-in form (or a sign-in link's confirmation), with its login-CSRF token: the form's
    value is an HMAC of a nonce in a cookie of this browser (SameSite=Strict, so another site's form
    posts without it)."""
    server = _server(request)
    nonce = request.cookies.get(LOGIN_COOKIE) or ""
    if not 16 <= len(nonce) <= 64:
        nonce = secrets.token_urlsafe(18)
    ctx = {"title": "Sign in", "who": None, "error": None, "confirm": None, "token": "",
           "login_csrf": login_csrf(server.secret, nonce), **context}
    response = _page(request, "login.html", ctx, status=status)
    response.set_cookie(LOGIN_COOKIE, nonce, httponly=True, samesite="strict", secure=_secure(request),
                        max_age=3600, path="/")
    response.headers["Cache-Control"] = "no-store"
    return response


def _token_student(request: Request, token: str, how: str) -> str:
    """The student of a token this server issued and lets in; else counted, logged and 401 (or 429)."""
    server = _server(request)
    student = student_of(server.secret, token)
    if student is None:
        server.failed_sign_in(request, how)
        raise HTTPException(401, "this is not a token this server issued; paste the token from your instructor")
    try:
        return server._allowed(student)
    except HTTPException:
        server.failed_sign_in(request, f"{how}, {student!r} not let in")
        raise


@router.get("/login")
def login_link(request: Request, token: str = ""):
    """The sign-in link ``/login?token=...``: a page that says whom it signs in, and a button (a
    POST with the login-CSRF token). A link alone signs nobody in: another site could send the
    browser to the attacker's own link and read what the student then types."""
    if not token.strip():
        return _sign_in_page(request, {})
    try:
        student = _token_student(request, token, "sign-in link")
    except HTTPException as exc:
        if exc.status_code == 429:
            raise
        return _sign_in_page(request, {"error": exc.detail}, status=401)
    return _sign_in_page(request, {"confirm": student, "token": token.strip()})


@router.post("/login")
async def login_form(request: Request):
    server = _server(request)
    form = await request.form(max_files=0, max_fields=4)
    origin = request.headers.get("origin")
    nonce = request.cookies.get(LOGIN_COOKIE, "")
    sent = str(form.get("login_csrf", ""))
    if (origin and origin != "null" and origin.split("://", 1)[-1] != request.headers.get("host", "")) or \
            not nonce or not hmac.compare_digest(sent, login_csrf(server.secret, nonce)):
        return _sign_in_page(request, {"error": "this sign-in form is not this server's own, or it expired; "
                                                "sign in again here"}, status=403)
    token = str(form.get("token", "")).strip()
    try:
        student = _token_student(request, token, "sign-in form")
    except HTTPException as exc:
        if exc.status_code == 429:
            raise
        return _sign_in_page(request, {"error": exc.detail}, status=401)
    old = request.cookies.get(SESSION_COOKIE)
    if old:
        server.end_session(old)  # one browser, one session: the one it had ends
    response = RedirectResponse("/", status_code=303)
    _set_session(request, response, server.db.open_session(student))
    response.delete_cookie(LOGIN_COOKIE, path="/")
    return response


@router.post("/logout")
async def logout(request: Request):
    """Sign-out ends the session in the database: its cookie, wherever a copy of it is, signs nobody in."""
    server = _server(request)
    who, _ = _who(request)
    form = await request.form(max_files=0, max_fields=3)
    if who is not None:
        server.require_csrf(who, str(form.get("csrf", "")))
        if who.session:
            server.end_session(who.session)
    response = RedirectResponse("/", status_code=303)
    response.delete_cookie(SESSION_COOKIE, path="/")
    return response


def _problem_context(request: Request, who: Who, pid: str) -> dict:
    from lagrade.problem.describe import typing_help
    from lagrade.uses.server.rules import rows, standing

    server = _server(request)
    p = server.problem(pid)
    return {"title": f"Problem {pid}", "who": who, "pid": pid, "problem": p, "show": server.text("show", pid),
            "statement": server.statement(pid), "typing": typing_help(p),
            "rules": standing(server, who.student, pid, who.instructor),
            "template": server.text("template", pid), "fields": server.fields(pid), "csrf": server.csrf(who),
            "attempts": rows(server, server.db.attempts(who.student, pid, limit=20), who), "result": None, "error": None,
            "values": {}, "fresh": False}


@router.get("/static/{name}")
def static(name: str):
    """The pages' own scripts (``problem.js``): files of this package, never a path from the request."""
    files = {f.name: f for f in STATIC.glob("*.js")}
    if name not in files:
        raise HTTPException(404, f"no file {name[:80]!r} here")
    return Response(files[name].read_bytes(), media_type="text/javascript; charset=utf-8",
                    headers={"X-Content-Type-Options": "nosniff", "Cache-Control": "no-cache"})


@router.get("/p/{pid}", response_class=HTMLResponse)
def problem_page(pid: str, request: Request, attempt: Annotated[int | None, Query(ge=1, le=MAX_ID)] = None):
    server = _server(request)
    who, cookie = _who(request)
    if who is None:
        return RedirectResponse("/", status_code=303)
    ctx = _problem_context(request, who, pid)
    if attempt is not None:
        att = server.db.attempt(attempt)
        if att is None or att.student != who.student or att.problem != pid:
            raise HTTPException(404, f"no attempt {attempt} of yours at problem {pid}")
        from lagrade.uses.server.rules import view

        ctx["result"] = view(server, att, who)
    return _page(request, "problem.html", ctx, cookie=cookie)


@router.post("/p/{pid}/check", response_class=HTMLResponse)
async def problem_check(pid: str, request: Request):
    server = _server(request)
    who, _ = _who(request)
    if who is None:
        raise HTTPException(401, "not signed in; open the sign-in link your instructor gave you")
    server.problem(pid)
    form = await request.form(max_files=1, max_fields=200)
    server.require_csrf(who, str(form.get("csrf", "")))
    ctx = _problem_context(request, who, pid)
    ctx["fresh"] = True  # focus goes to the result, or to the reason there is none (static/problem.js)
    upload = form.get("file")
    values: dict = {}
    if upload is not None and not isinstance(upload, str) and upload.filename:
        suffix = Path(upload.filename).suffix
        if suffix not in ANSWER_SUFFIXES:
            ctx["error"] = f"{upload.filename!r} is neither answer.py, answer.toml nor answer.ipynb"
            return _page(request, "problem.html", ctx, status=422)
        data = await upload.read()
    else:
        for f in ctx["fields"]:
            name = f"f:{f['name']}"
            if f["shape"] == "dict":
                d = {k: str(form.get(f"{name}:{k}", "")).strip() for k in f["keys"]}
                if any(d.values()):
                    values[f["name"]] = {k: v for k, v in d.items() if v}
            elif f["shape"] == "list":
                items = [line.strip() for line in str(form.get(name, "")).splitlines() if line.strip()]
                if items:
                    values[f["name"]] = items
            elif str(form.get(name, "")).strip():
                values[f["name"]] = str(form.get(name)).strip()
        ctx["values"] = values
        if not values:
            ctx["error"] = "type at least one part, or choose an answer.py / answer.toml file"
            return _page(request, "problem.html", ctx, status=422)
        try:
            suffix, data = ".toml", to_toml(values)
        except AnswerTextError as exc:
            ctx["error"] = str(exc)
            return _page(request, "problem.html", ctx, status=422)
    try:
        response = await submit(server, who, pid, suffix, data, plot=True)  # the page shows the picture
    except HTTPException as exc:  # a rate limit: said on the page, the typed answer kept
        ctx["error"] = exc.detail
        return _page(request, "problem.html", ctx, status=exc.status_code)
    ctx["result"] = json.loads(response.body)
    fresh = _problem_context(request, who, pid)
    ctx["attempts"], ctx["rules"] = fresh["attempts"], fresh["rules"]
    return _page(request, "problem.html", ctx)


@router.get("/class/{path:path}")
def class_page(path: str, request: Request):
    """The instructor's live class page: the HTML report of ``lagrade report --html``, made now."""
    server = _server(request)
    who, _ = _who(request)
    if who is None or not who.instructor:
        raise HTTPException(401, "the class page needs the instructor's token (lagrade tokens prints it)")
    from lagrade.uses.bulk.html_report import write_report

    with tempfile.TemporaryDirectory(prefix="lagrade-class-") as tmp:
        try:
            write_report(server.db.gradebook(), Path(tmp), server.config.problems_dirs)
        except Exception as exc:  # noqa: BLE001  (nothing graded yet, a database away)
            return error_page(request, 503, f"no class report yet: {exc}")
        try:  # a NUL byte or a name too long for the file system is no page either (not a 500)
            target = (Path(tmp) / (path or "index.html")).resolve()
            found = target.is_relative_to(Path(tmp).resolve()) and target.is_file()
        except (ValueError, OSError):
            found = False
        if not found:
            raise HTTPException(404, f"no page {path[:80]!r} in the class report")
        kind = {".html": "text/html; charset=utf-8", ".css": "text/css; charset=utf-8",
                ".js": "text/javascript; charset=utf-8"}.get(target.suffix) or \
            mimetypes.guess_type(target.name)[0] or "application/octet-stream"
        response = Response(target.read_bytes(), media_type=kind)
    response.headers["Content-Security-Policy"] = CLASS_CSP
    response.headers["X-Content-Type-Options"] = "nosniff"
    response.headers["Referrer-Policy"] = "no-referrer"
    response.headers["Cache-Control"] = "no-store"  # the class's grades
    return response


@router.get("/healthz")
def health(request: Request):
    """200 once the server can grade: a grader is warm (the first check on a loaded machine otherwise
    waited over a minute for one to warm up behind a green health check); until then 503 with
    ``Retry-After``, so that a load balancer or a deploy script waits. An app made without graders
    (``create_app(grade=False)``, the tests') has none to wait for."""
    from fastapi.responses import JSONResponse

    server = _server(request)
    queue = server.queue
    warm = queue.ready() if queue is not None else 0
    ok = warm > 0 or not server.grades
    body = {"ok": ok, "graders_ready": warm, "queued": queue.pending() if queue is not None else 0}
    if not ok:
        body["detail"] = "the graders are warming up (they load the problems and derive their references)"
    return JSONResponse(body, status_code=200 if ok else 503, headers={} if ok else {"Retry-After": "1"})
