"""LTI 1.3 end to end: an LMS (tests/server/lti_platform.py, on lti1p3platform) and lagrade serve,
each on its own socket of 127.0.0.1. A launch signs a student in; the grade of a check appears in
the platform's gradebook (the AGS score it recorded); forged and replayed launches are refused."""

from __future__ import annotations

import re
import socket
import threading
import time
import tomllib

import pytest

pytest.importorskip("pylti1p3")
pytest.importorskip("uvicorn")

import httpx  # noqa: E402
from lti_platform import INSTRUCTOR, Platform, read_form, rsa_pem  # noqa: E402
from serverkit import GOLDEN, make_config  # noqa: E402

from lagrade.uses.server.app import create_app  # noqa: E402
from lagrade.uses.server.lti import LtiConfigError, load_config, student_id  # noqa: E402
from lagrade.uses.server.state import SESSION_COOKIE, SESSION_SECONDS  # noqa: E402
from lagrade.uses.server.tokens import student_of  # noqa: E402


def _socket() -> socket.socket:
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    return s


def _serve(app, sock: socket.socket, lifespan: str = "on"):
    import uvicorn

    server = uvicorn.Server(uvicorn.Config(app, lifespan=lifespan, log_level="warning"))
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    for _ in range(600):  # the tool's graders warm up first (lifespan)
        if server.started:
            return server, thread
        time.sleep(0.05)
    raise RuntimeError("server did not start")


@pytest.fixture(scope="module")
def lms(tmp_path_factory):
    """(platform, tool url, tool app): both running until the module's tests are done."""
    tmp = tmp_path_factory.mktemp("lti")
    tool_sock, lms_sock = _socket(), _socket()
    tool_url = f"http://127.0.0.1:{tool_sock.getsockname()[1]}"
    platform = Platform(f"http://127.0.0.1:{lms_sock.getsockname()[1]}", tool_url)
    (tmp / "lti.toml").write_text(platform.lti_toml(), encoding="utf-8")
    app = create_app(make_config(tmp, lti=tmp / "lti.toml", checks_per_minute=600, check_burst=100,
                                 roster=("alice",)))
    running = [_serve(platform.app, lms_sock, lifespan="off"), _serve(app, tool_sock)]
    yield platform, tool_url, app
    for server, thread in running:
        server.should_exit = True
        thread.join(timeout=30)


def _login(platform: Platform, client: httpx.Client, login: str, link: str) -> dict[str, str]:
    """The browser through the OIDC login: LMS -> tool's login -> LMS's authorization; the auth request's params."""
    r = client.get(platform.start_url(login, link))
    assert r.status_code == 302, r.text
    r = client.get(r.headers["location"])  # the tool's OIDC login initiation
    assert r.status_code == 302, r.text
    auth = httpx.URL(r.headers["location"])
    assert str(auth).startswith(f"{platform.url}/authorize")
    return dict(auth.params)


def _launch(platform: Platform, client: httpx.Client, login: str, link: str) -> tuple[str, dict[str, str]]:
    """The honest launch: the LMS's form (action, fields), as a browser would post it."""
    params = _login(platform, client, login, link)
    r = client.get(f"{platform.url}/authorize", params=params)
    assert r.status_code == 200, r.text
    return read_form(r.text)


def _post(client: httpx.Client, launch: tuple[str, dict[str, str]]) -> httpx.Response:
    action, fields = launch
    return client.post(action, data=fields)


def _signed_in(client: httpx.Client, tool_url: str) -> str | None:
    r = client.get(f"{tool_url}/")
    m = re.search(r"data-student>([^<]*)<", r.text)
    return m.group(1) if m else None


def _csrf(page: str) -> str:
    return re.search(r'name="csrf" value="([^"]+)"', page).group(1)


def _wait_for(cond, seconds: float = 60):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = cond()
        if value:
            return value
        time.sleep(0.1)
    return cond()


def test_launch_signs_in_and_the_grade_reaches_the_lms_gradebook(lms):
    platform, tool_url, app = lms
    platform.user("u-ada", "Ada Lovelace")
    lineitem = platform.link("link-1214", "12.14")
    with httpx.Client(timeout=150) as browser:
        action, fields = _launch(platform, browser, "u-ada", "link-1214")
        assert action == f"{tool_url}/lti/launch"
        r = browser.post(action, data=fields)
        assert r.status_code == 200, r.text
        assert "url=/p/12.14" in r.text  # on to the link's problem
        student = student_id(platform.url, platform.deployment_id, "u-ada")
        assert _signed_in(browser, tool_url) == student  # no token handed out; not on the roster either
        # the cookie is a session of this browser, HttpOnly, never a token that signs in anywhere
        cookie = browser.cookies[SESSION_COOKIE]
        assert "httponly" in r.headers["set-cookie"].lower()
        assert student_of(app.state.server.secret, cookie) is None
        assert app.state.server.db.session_student(cookie, SESSION_SECONDS) == student
        page = browser.get(f"{tool_url}/p/12.14")
        assert page.status_code == 200 and f"data-student>{student}<" in page.text

        answer = tomllib.loads((GOLDEN / "12.14" / "correct_plain.toml").read_text(encoding="utf-8"))
        r = browser.post(f"{tool_url}/api/v1/problems/12.14/check", json={"answer": answer},
                         headers={"x-csrf-token": _csrf(page.text)})
        assert r.status_code == 200, r.text
        assert r.json()["outcome"] == "graded"

    # within 20 s: the grade wakes the sender (its own retry comes only every 30 s)
    got = _wait_for(lambda: [s for s in platform.scores if s["userId"] == "u-ada"], seconds=20)
    assert got, f"no score reached the LMS (token requests: {platform.token_requests})"
    score = got[-1]
    assert score["link"] == "link-1214" and lineitem.endswith("/link-1214/lineitem")
    grade = {s.student: s for s in app.state.server.db.gradebook().students}[student].problems["12.14"]
    assert (score["scoreGiven"], score["scoreMaximum"]) == (grade.points, grade.possible)  # lagrade export's points
    assert score["scoreGiven"] == score["scoreMaximum"] > 0  # the correct answer, full marks
    assert score["gradingProgress"] == "FullyGraded" and score["activityProgress"] == "Submitted"


def test_a_new_grade_replaces_the_one_in_the_lms(lms):
    platform, tool_url, _app = lms
    platform.user("u-emmy", "Emmy Noether")
    platform.link("link-1214b", "12.14")
    with httpx.Client(timeout=150) as browser:
        _post(browser, _launch(platform, browser, "u-emmy", "link-1214b"))
        page = browser.get(f"{tool_url}/p/12.14")
        for name in ("correct_plain.toml", "wrong_uncoupled_frequencies.toml"):
            answer = tomllib.loads((GOLDEN / "12.14" / name).read_text(encoding="utf-8"))
            r = browser.post(f"{tool_url}/api/v1/problems/12.14/check", json={"answer": answer},
                             headers={"x-csrf-token": _csrf(page.text)})
            assert r.status_code == 200, r.text
            n = 1 if name.startswith("correct") else 2
            assert _wait_for(lambda: len([s for s in platform.scores if s["userId"] == "u-emmy"]) >= n)
    first, last = [s for s in platform.scores if s["userId"] == "u-emmy"][-2:]
    assert first["scoreGiven"] == first["scoreMaximum"] and last["scoreGiven"] < last["scoreMaximum"]


def test_a_grade_the_lms_could_not_take_is_sent_when_it_is_back(lms):
    from sqlalchemy import select

    from lagrade.uses.server.lti import lti_links

    platform, tool_url, app = lms
    lti = app.state.lti
    platform.user("u-sophie", "Sophie Germain")
    platform.link("link-down", "12.14")
    platform.down = True
    try:
        with httpx.Client(timeout=150) as browser:
            _post(browser, _launch(platform, browser, "u-sophie", "link-down"))
            page = browser.get(f"{tool_url}/p/12.14")
            answer = tomllib.loads((GOLDEN / "12.14" / "correct_plain.toml").read_text(encoding="utf-8"))
            r = browser.post(f"{tool_url}/api/v1/problems/12.14/check", json={"answer": answer},
                             headers={"x-csrf-token": _csrf(page.text)})
            assert r.status_code == 200, r.text

        def link_error():
            with app.state.server.db.engine.connect() as c:
                return c.execute(select(lti_links.c.error).where(lti_links.c.link_id == "link-down")).scalar_one()

        assert "503" in (_wait_for(link_error) or "")  # refused, and kept as not sent
        assert not [s for s in platform.scores if s["userId"] == "u-sophie"]
    finally:
        platform.down = False
    lti.send_due()  # what the sender's 30 s retry does
    got = [s for s in platform.scores if s["userId"] == "u-sophie"]
    assert len(got) == 1 and got[0]["scoreGiven"] == got[0]["scoreMaximum"] > 0
    assert link_error() is None
    assert lti.send_due() == 0  # sent once: nothing due now


def _forged(platform: Platform, tool_url: str, login: str, link: str, **how) -> tuple[httpx.Response, httpx.Client]:
    """A launch that went through the real login (state cookie and nonce issued) but posts a token forged ``how``."""
    browser = httpx.Client(timeout=60)
    params = _login(platform, browser, login, link)
    body = platform.claims(login, link, params["nonce"])
    key = how.pop("key", None)
    expires_in = how.pop("expires_in", 300)
    token = platform.id_token(body, key=key, expires_in=expires_in, **how)
    return browser.post(f"{tool_url}/lti/launch", data={"id_token": token, "state": params["state"]}), browser


def test_signing_out_ends_the_lti_session_and_a_copy_of_its_cookie(lms):
    platform, tool_url, app = lms
    platform.user("u-grace", "Grace Hopper")
    platform.link("link-out", "12.22")
    with httpx.Client(timeout=60) as browser:
        assert _post(browser, _launch(platform, browser, "u-grace", "link-out")).status_code == 200
        sid = browser.cookies[SESSION_COOKIE]
        page = browser.get(f"{tool_url}/")
        assert browser.post(f"{tool_url}/logout", data={"csrf": _csrf(page.text)},
                            follow_redirects=False).status_code == 303
    assert app.state.server.db.session_student(sid, SESSION_SECONDS) is None
    with httpx.Client(timeout=60, cookies={SESSION_COOKIE: sid}) as copy:
        assert _signed_in(copy, tool_url) is None


@pytest.mark.parametrize("how", [
    pytest.param({"key": "other"}, id="wrong-signature"),
    pytest.param({"aud": "another-tool"}, id="wrong-audience"),
    pytest.param({"aud": ["lagrade-tool-1", "another-tool"], "azp": "another-tool"}, id="not-the-authorized-party"),
    pytest.param({"expires_in": -120}, id="expired"),
    pytest.param({"https://purl.imsglobal.org/spec/lti/claim/deployment_id": "deployment-9"}, id="wrong-deployment"),
    pytest.param({"iss": "https://evil.example"}, id="wrong-issuer"),
    pytest.param({"nonce": "a-nonce-the-tool-never-issued"}, id="unknown-nonce"),
])
def test_a_forged_launch_is_refused(lms, how):
    platform, tool_url, _app = lms
    platform.user("u-mallory", "Mallory")
    platform.link("link-forged", "12.22")
    if how.get("key") == "other":
        how = {"key": rsa_pem()[0]}  # another key, under the platform's kid
    r, browser = _forged(platform, tool_url, "u-mallory", "link-forged", **how)
    try:
        assert r.status_code == 401, r.text
        assert "refused" in r.text and "lagrade_session" not in r.headers.get("set-cookie", "")
        assert _signed_in(browser, tool_url) is None
    finally:
        browser.close()


def test_the_honest_token_of_a_forged_attempt_still_works(lms):
    """The control of the forgeries above: the same login with the platform's own signature signs in."""
    platform, tool_url, _app = lms
    platform.user("u-mallory", "Mallory")
    platform.link("link-forged", "12.22")
    r, browser = _forged(platform, tool_url, "u-mallory", "link-forged")
    try:
        assert r.status_code == 200, r.text
        assert _signed_in(browser, tool_url) == student_id(platform.url, platform.deployment_id, "u-mallory")
    finally:
        browser.close()


def test_a_replayed_launch_is_refused(lms):
    platform, tool_url, _app = lms
    platform.user("u-eve", "Eve")
    platform.link("link-replay", "12.22")
    with httpx.Client(timeout=60) as browser:
        action, fields = _launch(platform, browser, "u-eve", "link-replay")
        assert browser.post(action, data=fields).status_code == 200
        again = browser.post(action, data=fields)  # the same id_token and state, same browser
        assert again.status_code == 401 and "nonce" in again.text.lower()
    with httpx.Client(timeout=60) as other:  # a captured launch posted from another browser
        r = other.post(action, data=fields)
        assert r.status_code == 401
        assert _signed_in(other, tool_url) is None


def test_a_launch_posted_many_times_at_once_signs_in_once(lms):
    """The nonce is spent in one transaction after every check: of launches racing with one token, one wins."""
    from concurrent.futures import ThreadPoolExecutor

    platform, _tool_url, _app = lms
    platform.user("u-race", "Racer")
    platform.link("link-race", "12.22")
    with httpx.Client(timeout=60) as browser:
        action, fields = _launch(platform, browser, "u-race", "link-race")
        cookies = dict(browser.cookies)
    barrier = threading.Barrier(6)

    def post(_):
        with httpx.Client(timeout=60, cookies=cookies) as c:
            barrier.wait(timeout=30)
            return c.post(action, data=fields).status_code

    with ThreadPoolExecutor(6) as pool:
        codes = sorted(pool.map(post, range(6)))
    assert codes == [200] + [401] * 5, codes


def test_a_launch_without_the_browsers_state_cookie_is_refused(lms):
    """Login CSRF: a launch made for one browser, posted from another (no state cookie), signs no one in."""
    platform, tool_url, _app = lms
    platform.user("u-trudy", "Trudy")
    platform.link("link-csrf", "12.22")
    with httpx.Client(timeout=60) as attacker:
        action, fields = _launch(platform, attacker, "u-trudy", "link-csrf")
    with httpx.Client(timeout=60) as victim:
        r = victim.post(action, data=fields)
        assert r.status_code == 401 and "State not found" in r.text
        assert _signed_in(victim, tool_url) is None


@pytest.mark.parametrize("problem, target, lands", [
    ("12.22", None, "/p/12.22"),  # Moodle: the custom parameter problem=12.22
    (None, "/p/12.22", "/p/12.22"),  # Canvas: the tool URL typed for the assignment
    (None, None, "/"),  # no problem named: the assignment's index
])
def test_the_link_names_the_problem(lms, problem, target, lands):
    platform, tool_url, _app = lms
    platform.user("u-link", "Linker")
    link = f"link-{problem}-{target}"
    platform.link(link, problem, target=f"{tool_url}{target}" if target else None)
    with httpx.Client(timeout=60) as browser:
        r = _post(browser, _launch(platform, browser, "u-link", link))
        assert r.status_code == 200, r.text
        assert f"url={lands}\"" in r.text


def test_an_instructor_launch_opens_the_class_page(lms):
    platform, tool_url, _app = lms
    platform.user("u-prof", "Prof", roles=(INSTRUCTOR,))
    platform.link("link-prof", "12.14")
    with httpx.Client(timeout=60) as browser:
        r = _post(browser, _launch(platform, browser, "u-prof", "link-prof"))
        assert r.status_code == 200 and "url=/class/" in r.text
        assert _signed_in(browser, tool_url) == "@instructor"


def test_the_tools_jwks_and_the_config_an_instructor_pastes(lms):
    platform, tool_url, _app = lms
    keys = httpx.get(f"{tool_url}/lti/jwks").json()["keys"]
    assert len(keys) == 1 and keys[0]["kty"] == "RSA" and keys[0]["alg"] == "RS256" and keys[0]["kid"]
    assert "d" not in keys[0]  # the public half only
    conf = httpx.get(f"{tool_url}/lti/config.json").json()
    assert conf["oidc_initiation_url"] == f"{tool_url}/lti/login"
    assert conf["target_link_uri"] == f"{tool_url}/lti/launch"
    assert conf["public_jwk_url"] == f"{tool_url}/lti/jwks"
    assert "https://purl.imsglobal.org/spec/lti-ags/scope/score" in conf["scopes"]
    page = httpx.get(f"{tool_url}/lti/config")
    assert page.status_code == 200
    for value in (f"{tool_url}/lti/login", f"{tool_url}/lti/launch", f"{tool_url}/lti/jwks", "problem=12.22"):
        assert value in page.text


def test_a_login_for_another_tool_is_refused(lms):
    platform, tool_url, _app = lms
    r = httpx.get(f"{tool_url}/lti/login", params={"iss": platform.url, "login_hint": "x",
                                                   "target_link_uri": "https://elsewhere.example/launch"})
    assert r.status_code == 400
    r = httpx.get(f"{tool_url}/lti/login", params={"iss": "https://unknown.example", "login_hint": "x",
                                                   "target_link_uri": f"{tool_url}/lti/launch"})
    assert r.status_code == 400


def test_an_lti_file_that_cannot_be_used_is_said_in_one_line(tmp_path):
    path = tmp_path / "lti.toml"
    path.write_text('url = "https://lagrade.example.edu"\n[[platform]]\nissuer = "https://canvas.instructure.com"\n')
    with pytest.raises(LtiConfigError, match=r"platform\.0\.client_id: field required"):
        load_config(path)
    path.write_text("url = 'lagrade'\n[[platform]]\nissuer='i'\nclient_id='c'\nauth_login_url='a'\n"
                    "auth_token_url='t'\nkey_set_url='k'\ndeployment_ids=['d']\n")
    with pytest.raises(LtiConfigError, match="is not an address"):
        load_config(path)


def test_no_lti_routes_without_lti(quiet_app):
    _app, client = quiet_app
    assert client.get("/lti/jwks").status_code == 404


@pytest.mark.slow
def test_a_launch_in_chromium_lands_on_a_page_with_math_a_figure_and_no_axe_violation(lms):
    """Debian's Chromium through the LMS's own pages: the launch signs in with an HttpOnly session
    cookie (no token), the problem page shows the statement's MathML and the drawn figure, and
    axe-core finds no serious or critical violation on the launch's page, the problem page or the
    configuration page an instructor reads."""
    import os
    import shutil

    chromium = shutil.which("chromium") or "/usr/bin/chromium"
    if not os.path.exists(chromium):
        pytest.skip("no chromium")
    sync_api = pytest.importorskip("playwright.sync_api")
    from axe_playwright_python.sync_playwright import Axe

    platform, tool_url, app = lms
    platform.user("u-chrome", "Chrome Student")
    platform.link("link-chrome", "12.22")
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
             "--disable-component-update", "--disable-sync"]
    bad: list[str] = []

    def axe(page, name):
        bad.extend(f"{name}: {v['id']} ({v['impact']})" for v in Axe().run(page).response["violations"]
                   if v["impact"] in ("serious", "critical"))

    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium, args=flags)
        try:
            context = browser.new_context(viewport={"width": 390, "height": 844})
            page = context.new_page()
            landed = []
            page.on("response", lambda r: landed.append(r) if r.url == f"{tool_url}/lti/launch" else None)
            page.goto(platform.start_url("u-chrome", "link-chrome"))
            page.wait_for_url(f"{tool_url}/p/12.22", timeout=60000)
            assert landed and landed[0].status == 200
            student = student_id(platform.url, platform.deployment_id, "u-chrome")
            assert page.locator("[data-student]").inner_text() == student
            cookie = next(c for c in context.cookies() if c["name"] == SESSION_COOKIE)
            assert cookie["httpOnly"] and cookie["sameSite"] == "Strict"
            assert student_of(app.state.server.secret, cookie["value"]) is None
            assert page.locator("[data-statement] math").count() > 0
            page.wait_for_function("() => { const i = document.querySelector('[data-figure] img'); "
                                   "return i && i.complete && i.naturalWidth > 0; }", timeout=15000)
            axe(page, "problem after a launch")
            page.goto(f"{tool_url}/lti/config")
            axe(page, "LTI configuration page")
            context.close()
            # the launch's own page ("Signed in ... Continue"), as another launch returns it, without
            # its 0 s refresh (which would leave it before axe reads it)
            with httpx.Client(timeout=60) as other:
                r = _post(other, _launch(platform, other, "u-chrome", "link-chrome"))
            assert r.status_code == 200 and "data-next" in r.text
            page = browser.new_page()
            page.set_content(re.sub(r"<meta http-equiv=\"refresh\"[^>]*>", "", r.text))
            axe(page, "launch page")
            page.close()
        finally:
            browser.close()
    assert not bad, bad
