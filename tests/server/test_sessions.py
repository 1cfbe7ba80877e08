"""Browser sessions (issue 36, item 7): the cookie is a session of the database, not the student's
permanent token; sign-out ends it; it is `Secure` behind HTTPS and `HttpOnly`; a sign-in link or
another site's form signs nobody in (login CSRF); an --open server gives each browser a guest of
its own; refused tokens are counted, logged and slowed."""

from __future__ import annotations

import http.client
import logging
import re
import shutil
import time

import pytest
from fastapi.testclient import TestClient
from serverkit import make_config, on_a_socket, sign_in

from lagrade.uses.server.app import create_app
from lagrade.uses.server.state import SESSION_COOKIE
from lagrade.uses.server.tokens import csrf_token, issue, student_of

ANSWER = {"answer": {"L": "m1*x_d^2/2"}}


def _set_cookie(response, name: str) -> str:
    """The Set-Cookie header of ``name`` in a response."""
    found = [h for h in response.headers.get_list("set-cookie") if h.startswith(f"{name}=")]
    assert found, response.headers
    return found[0]


def test_the_cookie_is_a_session_not_the_token(quiet_app):
    app, client = quiet_app
    token = issue(app.state.server.secret, "alice")
    page = client.get("/login", params={"token": token})
    form = re.search(r'name="login_csrf" value="([^"]+)"', page.text).group(1)
    r = client.post("/login", data={"token": token, "login_csrf": form}, follow_redirects=False)
    assert r.status_code == 303
    cookie = _set_cookie(r, SESSION_COOKIE)
    sid = client.cookies[SESSION_COOKIE]
    assert token not in cookie and token.split(".")[2] not in cookie and len(sid) >= 40
    assert "httponly" in cookie.lower() and "samesite=strict" in cookie.lower()
    assert "secure" not in cookie.lower()  # plain HTTP on 127.0.0.1: a Secure cookie would never come back
    assert "signed in as" in client.get("/").text
    # the token itself is no cookie: a browser that sends it as one is not signed in
    other = TestClient(app, cookies={SESSION_COOKIE: token})
    assert "Paste the token" in other.get("/").text
    assert other.get("/api/v1/problems").status_code == 401


def test_sign_out_ends_the_session_for_every_copy_of_its_cookie(quiet_app):
    app, client = quiet_app
    csrf = sign_in(app, client, "alice")
    sid = client.cookies[SESSION_COOKIE]
    stolen = TestClient(app, cookies={SESSION_COOKIE: sid})
    assert stolen.get("/api/v1/problems").status_code == 200
    r = client.post("/logout", data={"csrf": csrf}, follow_redirects=False)
    assert r.status_code == 303 and SESSION_COOKIE not in client.cookies
    assert stolen.get("/api/v1/problems").status_code == 401
    assert "Paste the token" in stolen.get("/").text
    assert stolen.post("/p/12.22/check", data={"f:L": "m1", "csrf": csrf}).status_code == 401
    # signing in again is a new session (and a new CSRF token)
    again = sign_in(app, client, "alice")
    assert client.cookies[SESSION_COOKIE] != sid and again != csrf


def test_cookies_are_secure_over_https(tmp_path):
    app = create_app(make_config(tmp_path), grade=False)
    with TestClient(app, base_url="https://testserver") as client:  # TLS here (uvicorn --ssl-certfile)
        page = client.get("/login", params={"token": issue(app.state.server.secret, "alice")})
        assert "secure" in _set_cookie(page, "lagrade_login").lower()
        sign_in(app, client, "alice")
        assert client.get("/").text.count("signed in as") == 1
    (tmp_path / "b").mkdir()
    other = create_app(make_config(tmp_path / "b", https=True), grade=False)
    with TestClient(other) as client:  # --https: a proxy in front that says nothing
        assert "secure" in _set_cookie(client.get("/"), "lagrade_login").lower()


@pytest.mark.parametrize("allowed", ["127.0.0.1", "192.0.2.1", ""])
def test_a_trusted_proxy_says_https_by_x_forwarded_proto(tmp_path, allowed):
    """uvicorn believes X-Forwarded-Proto from --forwarded-allow-ips only (by default from no one)."""
    from lagrade.cli.serve import proxy_options

    trusted = allowed == "127.0.0.1"
    app = create_app(make_config(tmp_path), grade=False)
    try:
        with on_a_socket(app, lifespan="auto", **proxy_options(allowed)) as url:
            port = int(url.rsplit(":", 1)[1])
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            conn.request("GET", "/", headers={"X-Forwarded-Proto": "https"})
            r = conn.getresponse()
            cookie = [v for k, v in r.getheaders() if k.lower() == "set-cookie" and v.startswith("lagrade_login=")][0]
            r.read()
            conn.close()
        assert ("secure" in cookie.lower()) == trusted, cookie
    finally:
        app.state.server.stop()


def test_a_sign_in_link_or_another_sites_form_signs_nobody_in(quiet_app):
    """Login CSRF: a page of another site that sends the browser to the attacker's sign-in link, or
    posts the attacker's token to /login, would sign the student in as the attacker."""
    app, client = quiet_app
    mallory = issue(app.state.server.secret, "mallory")
    page = client.get("/login", params={"token": mallory})
    assert page.status_code == 200 and "data-confirm>mallory<" in page.text
    assert SESSION_COOKIE not in client.cookies and "Paste the token" in client.get("/").text
    assert page.headers["referrer-policy"] == "no-referrer" and page.headers["cache-control"] == "no-store"
    form = re.search(r'name="login_csrf" value="([^"]+)"', page.text).group(1)
    # another site's form: no login cookie (SameSite=Strict), or a value it made up, or its Origin
    fresh = TestClient(app)
    for browser, data, headers in ((fresh, {"token": mallory, "login_csrf": form}, {}),
                                   (client, {"token": mallory}, {}),
                                   (client, {"token": mallory, "login_csrf": "0" * 32}, {}),
                                   (client, {"token": mallory, "login_csrf": form},
                                    {"Origin": "https://evil.example"})):
        r = browser.post("/login", data=data, headers=headers, follow_redirects=False)
        assert r.status_code == 403 and "sign-in form is not this server" in r.text, (data, headers)
        assert SESSION_COOKIE not in browser.cookies
    # the page's own button
    r = client.post("/login", data={"token": mallory, "login_csrf": form},
                    headers={"Origin": "http://testserver"}, follow_redirects=False)
    assert r.status_code == 303 and SESSION_COOKIE in client.cookies


def test_an_open_server_gives_each_browser_its_own_guest(tmp_path):
    app = create_app(make_config(tmp_path, open=True), grade=False)
    with TestClient(app) as one, TestClient(app) as two:
        names = []
        for browser in (one, two):
            page = browser.get("/").text
            names.append(re.search(r"data-student>([^<]+)<", page).group(1))
            sid = browser.cookies[SESSION_COOKIE]
            r = browser.post("/api/v1/problems/12.22/check", json=ANSWER,
                             headers={"X-CSRF-Token": csrf_token(app.state.server.secret, sid)})
            assert r.status_code == 202
        assert names[0] != names[1] and all(n.startswith("guest-") for n in names)
        # a guest's cookie is a session of this server (signed, with its time of issue), not a token
        # signed for "guest-..." that would sign that guest in anywhere, for ever
        assert student_of(app.state.server.secret, one.cookies[SESSION_COOKIE]) is None
        assert names[0] == re.search(r"data-student>([^<]+)<", one.get("/").text).group(1)  # it stays
        mine = one.get("/api/v1/problems/12.22/submissions").json()
        assert len(mine) == 1  # the other browser's attempt is not this one's
        # a guest's cookie call needs its CSRF token too
        assert one.post("/api/v1/problems/12.22/check", json=ANSWER).status_code == 403


def _session_rows(db) -> int:
    import sqlalchemy as sa

    with db.engine.connect() as c:
        return c.execute(sa.text("SELECT count(*) FROM server_sessions")).scalar_one()


def test_an_open_server_writes_no_session_row_per_visit(tmp_path):
    """Issue 43: every visit of a client that keeps no cookie (a crawler, a script, a link preview)
    wrote a guest's session row, never deleted. A guest's cookie is signed; a row is written only
    when a guest signs out (so that a copy of the cookie signs nobody in after)."""
    app = create_app(make_config(tmp_path, open=True), grade=False)
    db = app.state.server.db
    with TestClient(app) as crawler, TestClient(app) as browser:
        for _ in range(40):
            crawler.cookies.clear()
            assert crawler.get("/").status_code == 200 and crawler.get("/p/12.22").status_code == 200
        assert _session_rows(db) == 0
        name = re.search(r"data-student>([^<]+)<", browser.get("/").text).group(1)
        sid = browser.cookies[SESSION_COOKIE]
        csrf = {"X-CSRF-Token": csrf_token(app.state.server.secret, sid)}
        assert browser.post("/api/v1/problems/12.22/check", json=ANSWER, headers=csrf).status_code == 202
        for _ in range(10):
            assert re.search(r"data-student>([^<]+)<", browser.get("/").text).group(1) == name
        assert _session_rows(db) == 0
        with TestClient(app) as copy:
            copy.cookies.set(SESSION_COOKIE, sid)
            assert len(copy.get("/api/v1/problems/12.22/submissions").json()) == 1  # the same guest
            r = browser.post("/logout", data={"csrf": csrf["X-CSRF-Token"]}, follow_redirects=False)
            assert r.status_code == 303 and _session_rows(db) == 1
            assert copy.get("/api/v1/problems/12.22/submissions").json() == []  # signed out: "guest", shared
        forged = sid.rsplit(".", 1)[0] + ".0" * 16
        crawler.cookies.set(SESSION_COOKIE, forged)
        assert name not in crawler.get("/").text
    # a guest's cookie is refused once the server is not --open
    (tmp_path / "closed").mkdir()
    closed = create_app(make_config(tmp_path / "closed", db=str(tmp_path / "serve.sqlite")), grade=False)
    with TestClient(closed) as client:
        client.cookies.set(SESSION_COOKIE, sid)
        assert client.get("/api/v1/problems").status_code == 401


def test_expired_session_rows_are_deleted(quiet_app):
    import sqlalchemy as sa

    from lagrade.uses.server.db import server_sessions
    from lagrade.uses.server.state import SESSION_SECONDS

    app, client = quiet_app
    db = app.state.server.db
    old = db.open_session("alice")
    with db.engine.begin() as c:
        c.execute(sa.update(server_sessions).values(created_at=time.time() - SESSION_SECONDS - 1))
    assert db.session_student(old, SESSION_SECONDS) is None and _session_rows(db) == 1
    sign_in(app, client, "bob")
    assert _session_rows(db) == 1  # bob's; alice's expired row is gone


def test_refused_tokens_are_counted_logged_and_slowed(tmp_path, caplog):
    app = create_app(make_config(tmp_path, failed_sign_ins_per_minute=1, failed_sign_in_burst=3), grade=False)
    server = app.state.server
    with TestClient(app) as client, caplog.at_level(logging.WARNING, logger="lagrade.uses.server"):
        assert client.get("/login", params={"token": "lg1.bad.bad"}).status_code == 401
        assert client.get("/api/v1/problems", headers={"Authorization": "Bearer lg1.x.y"}).status_code == 401
        page = client.get("/")
        form = re.search(r'name="login_csrf" value="([^"]+)"', page.text).group(1)
        assert client.post("/login", data={"token": "guess", "login_csrf": form}).status_code == 401
        assert server.failed_sign_ins == 3
        r = client.post("/login", data={"token": "guess2", "login_csrf": form})
        assert r.status_code == 429 and "retry-after" in r.headers
        assert server.failed_sign_ins == 4
        # a right token still signs in from elsewhere; this address waits
        assert client.get("/api/v1/problems", headers={"Authorization": "Bearer " + issue(server.secret, "a")}) \
            .status_code == 200
    lines = [r.getMessage() for r in caplog.records if r.name == "lagrade.uses.server"]
    assert len(lines) == 4 and all("refused sign-in" in line and "testclient" in line for line in lines), lines


def test_serve_over_tls_with_a_certificate(tmp_path):
    """`lagrade serve --ssl-certfile/--ssl-keyfile` hands them to uvicorn: the pages over HTTPS,
    the cookies `Secure`, a browser signed in through them."""
    import ssl
    import subprocess

    import httpx

    openssl = shutil.which("openssl")
    if openssl is None:
        pytest.skip("no openssl to make a test certificate (apt-get install -y openssl)")
    cert, key = tmp_path / "cert.pem", tmp_path / "key.pem"
    subprocess.run([openssl, "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1", "-subj", "/CN=127.0.0.1",
                    "-addext", "subjectAltName=IP:127.0.0.1", "-keyout", str(key), "-out", str(cert)],
                   check=True, capture_output=True, timeout=60)
    app = create_app(make_config(tmp_path), grade=False)
    try:
        trust = ssl.create_default_context(cafile=str(cert))
        with on_a_socket(app, lifespan="auto", ssl_certfile=str(cert), ssl_keyfile=str(key)) as url, \
                httpx.Client(base_url=url, verify=trust, timeout=10) as browser:
            page = browser.get("/login", params={"token": issue(app.state.server.secret, "alice")})
            assert "secure" in _set_cookie(page, "lagrade_login").lower()
            token = issue(app.state.server.secret, "alice")
            form = re.search(r'name="login_csrf" value="([^"]+)"', page.text).group(1)
            r = browser.post("/login", data={"token": token, "login_csrf": form}, follow_redirects=False)
            assert r.status_code == 303 and "secure" in _set_cookie(r, SESSION_COOKIE).lower()
            assert "signed in as" in browser.get("/").text
    finally:
        app.state.server.stop()


def test_plain_http_off_this_machine_is_warned_about(tmp_path):
    from click.testing import CliRunner

    from lagrade.cli import main
    from lagrade.cli.serve import plain_http_warning

    assert "plain HTTP on 0.0.0.0" in plain_http_warning("0.0.0.0", tls=False, https=False)
    assert plain_http_warning("0.0.0.0", tls=True, https=False) is None
    assert plain_http_warning("0.0.0.0", tls=False, https=True) is None  # a proxy in front does TLS
    assert plain_http_warning("127.0.0.1", tls=False, https=False) is None
    assert plain_http_warning("localhost", tls=False, https=False) is None
    (tmp_path / "hw.toml").write_text("x", encoding="utf-8")
    (tmp_path / "cert.pem").write_text("x", encoding="utf-8")
    r = CliRunner().invoke(main, ["serve", "--assignment", str(tmp_path / "hw.toml"),
                                  "--ssl-certfile", str(tmp_path / "cert.pem")])
    assert r.exit_code == 2 and "--ssl-keyfile" in r.output
