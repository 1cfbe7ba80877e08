"""Who may call what: tokens (401 without), roster, open mode, CSRF on cookie sessions, size and rate limits.

No grader runs here: a check is stored and answered 202 (queued)."""

from __future__ import annotations

import re

from fastapi.testclient import TestClient
from serverkit import bearer, make_config, sign_in

from lagrade.uses.server.app import create_app
from lagrade.uses.server.tokens import issue, student_of

ANSWER = {"answer": {"L": "m1*x_d^2/2"}}
API = [("get", "/api/v1/problems", None), ("get", "/api/v1/problems/12.22", None),
       ("post", "/api/v1/problems/12.22/check", ANSWER),
       ("post", "/api/v1/problems/12.22/preview", {"part": "L", "value": "m1*x_d^2"}),
       ("get", "/api/v1/submissions/1", None), ("get", "/api/v1/problems/12.22/submissions", None)]


def test_every_api_route_needs_a_token(quiet_app):
    app, client = quiet_app
    for method, url, body in API:
        r = getattr(client, method)(url, **({"json": body} if body else {}))
        assert r.status_code == 401, (url, r.status_code)
        assert r.headers["www-authenticate"] == "Bearer"
        assert "\n" not in r.json()["detail"] and "Bearer" in r.json()["detail"]
        forged = {"Authorization": "Bearer " + issue(b"another server's secret" * 2, "alice")}
        assert getattr(client, method)(url, headers=forged, **({"json": body} if body else {})).status_code == 401
    assert client.get("/api/v1/problems", headers=bearer(app, "alice")).status_code == 200
    assert app.state.server.db.counts() == {}  # nothing was stored by the refused checks


def test_tokens_are_signed_and_tamper_evident():
    secret = b"s" * 32
    token = issue(secret, "jdoe@example.edu")
    assert student_of(secret, token) == "jdoe@example.edu"
    prefix, name, mac = token.split(".")
    other = issue(secret, "mallory").split(".")[1]
    assert student_of(secret, f"{prefix}.{other}.{mac}") is None  # a name swapped under a valid MAC
    assert student_of(secret, token[:-1] + ("0" if token[-1] != "0" else "1")) is None
    assert student_of(b"t" * 32, token) is None
    assert student_of(secret, "garbage") is None


def test_roster_limits_who_may_sign_in(tmp_path):
    app = create_app(make_config(tmp_path, roster=("alice",)), grade=False)
    with TestClient(app) as client:
        assert client.get("/api/v1/problems", headers=bearer(app, "alice")).status_code == 200
        r = client.get("/api/v1/problems", headers=bearer(app, "bob"))
        assert r.status_code == 401 and "roster" in r.json()["detail"]


def test_open_server_needs_no_token(tmp_path):
    app = create_app(make_config(tmp_path, open=True), grade=False)
    with TestClient(app) as client:
        assert [p["id"] for p in client.get("/api/v1/problems").json()] == ["12.22", "12.14"]
        r = client.post("/api/v1/problems/12.22/check", json=ANSWER)
        assert r.status_code == 202 and r.json()["state"] == "queued"
        page = client.get("/")
        assert page.status_code == 200 and "12.22" in page.text and "lagrade_session" in page.headers["set-cookie"]


def test_closed_server_pages_ask_to_sign_in(quiet_app):
    app, client = quiet_app
    assert "Paste the token" in client.get("/").text
    assert client.get("/login", params={"token": "lg1.bad.bad"}).status_code == 401
    sign_in(app, client, "alice")
    assert "signed in as" in client.get("/").text


def _sign_in(app, client, student="alice") -> str:
    """Signed in; the session's CSRF token."""
    return sign_in(app, client, student)


def test_forms_and_cookie_calls_need_the_csrf_token(quiet_app):
    app, client = quiet_app
    good = _sign_in(app, client)
    page = client.get("/p/12.22").text
    assert f'name="csrf" value="{good}"' in page
    # the form without, or with a wrong, token: refused and nothing stored
    assert client.post("/p/12.22/check", data={"f:L": "m1*x_d^2/2"}).status_code == 403
    assert client.post("/p/12.22/check", data={"f:L": "m1*x_d^2/2", "csrf": "0" * 32}).status_code == 403
    assert client.post("/api/v1/problems/12.22/check", json=ANSWER).status_code == 403  # cookie, no header
    assert client.post("/logout", data={}).status_code == 403
    assert app.state.server.db.counts() == {}
    r = client.post("/p/12.22/check", data={"f:L": "m1*x_d^2/2", "csrf": good})
    assert r.status_code == 200 and 'data-state="queued"' in r.text
    r = client.post("/api/v1/problems/12.22/check", json=ANSWER, headers={"X-CSRF-Token": good})
    assert r.status_code == 202
    assert app.state.server.db.counts() == {"queued": 1}  # the same answer by form and by API: one attempt


def test_pages_fetch_nothing_from_elsewhere(quiet_app):
    app, client = quiet_app
    _sign_in(app, client)
    for url in ("/", "/p/12.22", "/p/12.14"):
        r = client.get(url)
        assert "default-src 'none'" in r.headers["content-security-policy"]
        assert not re.search(r"""(src|href)=["']?(https?:)?//""", r.text), url


def test_request_size_is_bounded(tmp_path):
    app = create_app(make_config(tmp_path, max_body=4096), grade=False)
    with TestClient(app) as client:
        h = bearer(app, "alice")
        r = client.post("/api/v1/problems/12.22/check", headers=h, json={"answer": {"L": "x" * 5000}})
        assert r.status_code == 413 and "\n" not in r.json()["detail"] and "4096" in r.json()["detail"]
        r = client.post("/api/v1/problems/12.22/check", headers=h, files={"file": ("answer.py", b"#" * 5000)})
        assert r.status_code == 413

        def chunks():  # no Content-Length: counted as it streams in
            for _ in range(10):
                yield b"x" * 1000

        r = client.post("/api/v1/problems/12.22/check", headers={**h, "Content-Type": "application/json"},
                        content=chunks())
        assert r.status_code == 413
        assert client.post("/api/v1/problems/12.22/check", headers=h, json=ANSWER).status_code == 202
        assert app.state.server.db.counts() == {"queued": 1}


def test_checks_are_rate_limited_per_token(tmp_path):
    app = create_app(make_config(tmp_path, checks_per_minute=1, check_burst=3), grade=False)
    with TestClient(app) as client:
        alice, bob = bearer(app, "alice"), bearer(app, "bob")
        codes = [client.post("/api/v1/problems/12.22/check", headers=alice,
                             json={"answer": {"L": f"m1*x_d^2/{i + 2}"}}).status_code for i in range(5)]
        assert codes == [202, 202, 202, 429, 429]
        r = client.post("/api/v1/problems/12.22/check", headers=alice, json=ANSWER)
        assert r.status_code == 429 and int(r.headers["retry-after"]) >= 1
        assert client.post("/api/v1/problems/12.22/check", headers=bob, json=ANSWER).status_code == 202
        assert app.state.server.db.counts() == {"queued": 4}


def test_bad_requests_get_one_line(quiet_app):
    app, client = quiet_app
    h = bearer(app, "alice")
    cases = [({"json": {"answer": {}}}, 422), ({"json": {"answers": {"L": "x"}}}, 422),
             ({"json": {"answer": {"L": 1.5}}}, 422), ({"content": b"{not json", "headers": {"Content-Type": "application/json"}}, 422),
             ({"files": {"file": ("answer.txt", b"L = 1")}}, 422), ({"content": b"L = 1", "headers": {"Content-Type": "text/plain"}}, 415)]
    for kw, code in cases:
        headers = {**h, **kw.pop("headers", {})}
        r = client.post("/api/v1/problems/12.22/check", headers=headers, **kw)
        assert r.status_code == code, (kw, r.status_code, r.text)
        detail = r.json()["detail"]
        assert isinstance(detail, str) and "\n" not in detail and "expected" in detail
    r = client.post("/api/v1/problems/12.99/check", headers=h, json=ANSWER)
    assert r.status_code == 404 and "12.22" in r.json()["detail"]
    assert app.state.server.db.counts() == {}


def test_the_page_says_when_checks_are_rate_limited(tmp_path):
    app = create_app(make_config(tmp_path, checks_per_minute=1, check_burst=1), grade=False)
    with TestClient(app) as client:
        good = _sign_in(app, client)
        assert client.post("/p/12.22/check", data={"f:L": "m1", "csrf": good}).status_code == 200
        r = client.post("/p/12.22/check", data={"f:L": "m2*x_d", "csrf": good})
        assert r.status_code == 429 and "too many checks" in r.text and 'value="m2*x_d"' in r.text


def test_the_api_is_documented_by_openapi(quiet_app):
    app, client = quiet_app
    doc = client.get("/openapi.json").json()
    assert {"/api/v1/problems", "/api/v1/problems/{pid}", "/api/v1/problems/{pid}/check",
            "/api/v1/problems/{pid}/preview", "/api/v1/submissions/{sid}"} <= set(doc["paths"])
    body = doc["paths"]["/api/v1/problems/{pid}/check"]["post"]["requestBody"]["content"]
    assert set(body) == {"application/json", "multipart/form-data"}
    assert client.get("/docs").status_code == 404  # Swagger's page would load scripts from a CDN
