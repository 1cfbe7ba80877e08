"""The course page's last trips (issue 47, item 2), as plain HTTP (no browser; the browser suite,
test_pages_in_a_browser.py, checks the same in Chromium): the attempt number is the student's own,
the result after a check is marked to take focus and be announced, every page has one ``<main>`` and
headings in order, a session idles out, and the page's Content-Security-Policy runs no inline script."""

from __future__ import annotations

import re
import sqlite3
import time
from html.parser import HTMLParser

from fastapi.testclient import TestClient
from serverkit import make_config, sign_in

from lagrade.uses.server.app import create_app
from lagrade.uses.server.state import SESSION_COOKIE

L_FORMS = ["m1*x_d^2/2", "m1*x_d^2/2 + g*x", "m2*y_d^2/2"]


def _browser(app, student: str):
    client = TestClient(app)
    return client, sign_in(app, client, student)


def _check(client, csrf: str, value: str) -> str:
    r = client.post("/p/12.22/check", data={"csrf": csrf, "f:L": value})
    assert r.status_code in (200, 202), r.text
    return r.text


def test_the_attempt_number_counts_the_students_own(quiet_app):
    """Issue 47: bob's second attempt was headed "Attempt 6" (the server's 6th submission)."""
    app, _ = quiet_app
    alice, a_csrf = _browser(app, "alice")
    for value in L_FORMS:
        _check(alice, a_csrf, value)
    bob, b_csrf = _browser(app, "bob")
    first = _check(bob, b_csrf, L_FORMS[0])
    second = _check(bob, b_csrf, L_FORMS[1])
    assert re.search(r"data-attempt-number>1<", first) and re.search(r"data-attempt-number>2<", second)
    page = bob.get("/p/12.22").text
    assert re.findall(r'data-attempt="(\d+)">(\d+)</a>', page) == [("2", "2"), ("1", "1")]
    ids = re.findall(r'href="/p/12\.22\?attempt=(\d+)"', page)
    assert sorted(int(i) for i in ids) == [4, 5]  # the links still name the stored attempts
    again = bob.get(f"/p/12.22?attempt={ids[0]}").text
    assert re.search(r"data-attempt-number>2<", again)


def test_after_a_check_the_result_takes_focus_and_is_announced(quiet_app):
    app, _ = quiet_app
    client, csrf = _browser(app, "carol")
    page = _check(client, csrf, L_FORMS[0])
    result = re.search(r'<section id="result"[^>]*>', page)[0]
    assert "data-fresh" in result and 'tabindex="-1"' in result and 'aria-labelledby="result-heading"' in result
    assert re.search(r'data-announce="Attempt 1: stored and queued for grading\."', result), result
    assert re.search(r'<p id="announce"[^>]*role="status"[^>]*aria-live="polite"', page)
    # an attempt looked at later is not "fresh": nothing moves focus on a plain visit
    sid = re.search(r'href="/p/12\.22\?attempt=(\d+)"', page)[1]
    assert "data-fresh" not in client.get(f"/p/12.22?attempt={sid}").text
    # a check refused (nothing typed): the reason takes focus instead
    refused = client.post("/p/12.22/check", data={"csrf": csrf}).text
    assert re.search(r'<p class="error-box" data-error id="error" tabindex="-1" data-fresh>', refused)


class _Outline(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.mains = 0
        self.levels: list[int] = []
        self.inline_scripts = 0
        self.handlers: list[str] = []

    def handle_starttag(self, tag, attrs):
        if tag == "main":
            self.mains += 1
        if re.fullmatch(r"h[1-6]", tag):
            self.levels.append(int(tag[1]))
        if tag == "script" and not dict(attrs).get("src"):
            self.inline_scripts += 1
        self.handlers += [name for name, _ in attrs if name.startswith("on")]


def _outline(html: str) -> _Outline:
    o = _Outline()
    o.feed(html)
    return o


def _pages(app) -> dict[str, str]:
    anonymous = TestClient(app)
    client, csrf = _browser(app, "dora")
    pages = {"sign-in": anonymous.get("/").text, "problems": client.get("/").text,
             "problem": client.get("/p/12.22").text, "verdict": _check(client, csrf, L_FORMS[0]),
             "error": client.get("/p/99.99").text, "no attempt": client.get("/p/12.22?attempt=99999").text}
    return pages


def test_every_page_has_one_main_and_headings_in_order(quiet_app):
    """axe's moderate findings: ``landmark-one-main``, ``region`` and ``heading-order``."""
    app, _ = quiet_app
    for name, html in _pages(app).items():
        o = _outline(html)
        assert o.mains == 1, name
        assert o.levels and o.levels[0] == 1, (name, o.levels)
        for before, after in zip(o.levels, o.levels[1:]):
            assert after <= before + 1, (name, o.levels)  # never h2 -> h4


def test_the_csp_runs_no_inline_script(quiet_app):
    app, _ = quiet_app
    client, _ = _browser(app, "erin")
    r = client.get("/p/12.22")
    csp = r.headers["content-security-policy"]
    scripts = re.search(r"script-src ([^;]*)", csp)[1]
    assert "'unsafe-inline'" not in scripts and "'self'" in scripts, csp
    for name, html in _pages(app).items():
        o = _outline(html)
        assert o.inline_scripts == 0 and not o.handlers, (name, o.inline_scripts, o.handlers)
    assert '<script src="/static/problem.js"></script>' in r.text
    js = client.get("/static/problem.js")
    assert js.status_code == 200 and js.headers["content-type"].startswith("text/javascript")
    assert "data-fresh" in js.text and "/preview" in js.text
    for bad in ("/static/nope.js", "/static/..%2Fweb.py", "/static/problem.css"):
        assert client.get(bad).status_code == 404, bad


def _age(app, cookie: str, seconds: float) -> None:
    import sqlalchemy as sa

    from lagrade.uses.server.db import _session_key, server_sessions

    with app.state.server.db.engine.begin() as c:
        c.execute(sa.update(server_sessions).where(server_sessions.c.key == _session_key(cookie))
                  .values(last_seen=time.time() - seconds))


def _last_seen(app, cookie: str) -> float:
    import sqlalchemy as sa

    from lagrade.uses.server.db import _session_key, server_sessions

    with app.state.server.db.engine.connect() as c:
        return c.execute(sa.select(server_sessions.c.last_seen)
                         .where(server_sessions.c.key == _session_key(cookie))).scalar_one_or_none()


def test_a_session_idles_out(tmp_path):
    """Issue 47: a session lived 120 days whether used or not. Now it ends after
    ``session_idle_minutes`` (``lagrade serve --session-idle``) without a request; each use keeps it."""
    app = create_app(make_config(tmp_path, session_idle_minutes=30), grade=False)
    with TestClient(app) as client:
        sign_in(app, client, "frank")
        cookie = client.cookies[SESSION_COOKIE]
        assert "frank" in client.get("/").text
        _age(app, cookie, 29 * 60)  # used 29 minutes ago: still signed in, and the use is noted
        assert "frank" in client.get("/p/12.22").text
        assert time.time() - _last_seen(app, cookie) < 60
        _age(app, cookie, 31 * 60)  # 31 minutes without a request: signed out, the row gone
        assert "Paste the token" in client.get("/").text
        assert _last_seen(app, cookie) is None
        assert client.get("/api/v1/problems").status_code == 401


def test_the_idle_limit_has_a_default_and_a_flag(tmp_path):
    from click.testing import CliRunner

    from lagrade.cli import main
    from lagrade.uses.server.config import ServerConfig

    assert ServerConfig.model_fields["session_idle_minutes"].default == 480
    help_text = CliRunner().invoke(main, ["serve", "--help"]).output
    assert "--session-idle" in help_text and "480" in help_text


def test_a_database_from_before_the_idle_limit_gets_its_column(tmp_path):
    """An older server's sessions table has no ``last_seen``: the column is added, and its sessions
    idle from their sign-in."""
    db = tmp_path / "old.sqlite"
    app = create_app(make_config(tmp_path, db=str(db)), grade=False)
    with TestClient(app) as client:
        sign_in(app, client, "gus")
        cookie = client.cookies[SESSION_COOKIE]
    app.state.server.db.close()
    with sqlite3.connect(db) as c:
        c.execute("ALTER TABLE server_sessions DROP COLUMN last_seen")
    again = create_app(make_config(tmp_path, db=str(db)), grade=False)
    with TestClient(again) as client:
        client.cookies.set(SESSION_COOKIE, cookie)
        assert "gus" in client.get("/").text
    with sqlite3.connect(db) as c:
        assert "last_seen" in {r[1] for r in c.execute("PRAGMA table_info(server_sessions)")}


def test_the_static_script_is_the_packages_file(quiet_app):
    """The script the page runs is the package's file, byte for byte (no template fills it)."""
    from lagrade.uses.server.web import STATIC

    app, _ = quiet_app
    client, _ = _browser(app, "hana")
    assert client.get("/static/problem.js").content == (STATIC / "problem.js").read_bytes()
