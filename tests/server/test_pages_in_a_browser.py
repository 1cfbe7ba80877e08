"""The pages as students and the instructor live in them (issue 36), in Debian's Chromium driven by
Playwright (the system browser, nothing downloaded): a 390 px phone keeps its width after a verdict,
axe-core (``axe-playwright-python``, which bundles it) finds no serious or critical violation on any
student or instructor page, and the class page loads its own style and script under the server's
Content-Security-Policy. Skipped only without Chromium.

``LAGRADE_SCREENSHOT_DIR=/some/folder`` also keeps a screenshot of each page there."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest

from lagrade.uses.server.tokens import INSTRUCTOR, issue

pytestmark = pytest.mark.slow
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
if not os.path.exists(CHROMIUM):
    pytest.skip("no chromium (apt-get install -y chromium; .ci/run does)", allow_module_level=True)

from axe_playwright_python.sync_playwright import Axe  # noqa: E402  (a test dependency: lagrade[test])
from playwright import sync_api  # noqa: E402

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"]
PHONE = {"width": 390, "height": 844}
DESKTOP = {"width": 1100, "height": 1000}
#: 12.14 with a third of the coupling term: a wrong motion, so the page shows its picture too
WRONG_L = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)/3"
           " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)")
SERIOUS = ("serious", "critical")


@pytest.fixture(scope="module")
def chromium():
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        try:
            yield browser
        finally:
            browser.close()


def _shot(page, name: str) -> None:
    folder = os.environ.get("LAGRADE_SCREENSHOT_DIR")
    if folder:
        Path(folder).mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(Path(folder) / f"{name}.png"), full_page=True)


def sign_in(page, live_url: str, token: str) -> None:
    """The sign-in link, and its confirming button where the page asks for one."""
    page.goto(f"{live_url}/login?token={token}")
    confirm = page.locator('form[action="/login"] button[type=submit]')
    if confirm.count():
        confirm.click()
        page.wait_for_url(f"{live_url}/")


def _width(page) -> int:
    return page.evaluate("() => Math.max(document.documentElement.scrollWidth, document.body.scrollWidth)")


def _verdict(page, live_url: str) -> None:
    page.goto(f"{live_url}/p/12.14")
    page.fill('input[name="f:L"]', WRONG_L)
    page.locator('[data-field="L"] [data-preview][data-ready="yes"] math').wait_for(timeout=15000)
    page.click("#submit")
    page.locator('#result[data-state="graded"]').wait_for(timeout=120000)
    page.wait_for_function("() => { const i = document.querySelector('[data-plot] img'); return !i || i.complete; }",
                           timeout=15000)


def test_a_phone_keeps_its_width_after_a_verdict(graded, live_url, chromium):
    """Issue 36: at 390 px the page grew to 929 px after a verdict (verdict, score and feedback
    off-screen), and the preview ran past its box."""
    page = chromium.new_page(viewport=PHONE, is_mobile=True, has_touch=True)
    try:
        sign_in(page, live_url, issue(graded[0].state.server.secret, "phone-student"))
        _verdict(page, live_url)
        _shot(page, "phone-verdict")
        assert _width(page) == PHONE["width"]
        for cell in ("[data-verdict]", "[data-score-of]", "td.feedback", "[data-plot] img"):
            for el in page.locator(f"#result {cell}").all():
                box = el.bounding_box()
                assert box and box["x"] >= 0 and box["x"] + box["width"] <= PHONE["width"] + 0.5, (cell, box)
        # the preview of a long Lagrangian stays in its box: it wraps, or scrolls inside it
        page.fill('input[name="f:L"]', WRONG_L + " + m1*l1^2*theta1_d^2/7 + m2*l2^2*theta2_d^2/11")
        page.locator('[data-field="L"] [data-preview][data-ready="yes"] math').wait_for(timeout=15000)
        fits = page.evaluate("""() => Array.from(document.querySelectorAll('[data-preview]')).map(p => {
            const box = p.getBoundingClientRect(), style = getComputedStyle(p);
            return box.right <= window.innerWidth + 0.5 && (p.scrollWidth <= p.clientWidth + 1
                   || ['auto', 'scroll'].includes(style.overflowX));
        })""")
        assert all(fits), fits
        assert _width(page) == PHONE["width"]
        # the statement is math (MathML, as the preview's) and its figure is drawn, inside the phone
        assert page.locator("[data-statement] math").count() > 0
        figure = page.locator("[data-figure] img")
        figure.scroll_into_view_if_needed()
        page.wait_for_function("() => { const i = document.querySelector('[data-figure] img'); "
                               "return i && i.complete && i.naturalWidth > 0; }", timeout=15000)
        box = figure.bounding_box()
        assert box and box["x"] >= 0 and box["x"] + box["width"] <= PHONE["width"] + 0.5, box
    finally:
        page.close()


def test_the_read_as_cell_is_not_clipped_on_a_desktop(graded, live_url, chromium):
    """Issue 36: on a desktop the "read as" cell was cut at 26em with the table's half empty."""
    page = chromium.new_page(viewport=DESKTOP)
    try:
        sign_in(page, live_url, issue(graded[0].state.server.secret, "desktop-student"))
        _verdict(page, live_url)
        _shot(page, "desktop-verdict")
        hidden = page.evaluate("""() => Array.from(document.querySelectorAll('#result [data-echo] .readas'))
            .map(e => e.scrollWidth - e.clientWidth)""")
        assert hidden and max(hidden) <= 1, hidden
        assert _width(page) <= DESKTOP["width"]
    finally:
        page.close()


#: Content-Security-Policy refusals seen by any page of the axe walk (securitypolicyviolation events)
_REFUSED: list[str] = []
_LISTEN = ("document.addEventListener('securitypolicyviolation', e => "
           "console.error('CSP refused ' + e.violatedDirective + ' ' + e.blockedURI));")


def _listen(context) -> None:
    context.add_init_script(_LISTEN)
    context.on("console", lambda m: _REFUSED.append(m.text) if "CSP refused" in m.text
               or "Content Security Policy" in m.text else None)


def _axe(page, name: str) -> list[str]:
    results = Axe().run(page)
    bad = [f"{name}: {v['id']} ({v['impact']}) x{len(v['nodes'])}: {v['help']}: "
           f"{', '.join(str(n['target']) for n in v['nodes'][:3])}"
           for v in results.response["violations"] if v["impact"] in SERIOUS]
    return bad


def test_axe_finds_no_serious_violation_on_any_page(graded, live_url, chromium):
    """Every page a student or the instructor sees, in both widths: the sign-in page and its
    confirmation, the problems, a problem before and after a verdict (with its picture), an error
    page, the instructor's problems, the class page and a student's page of it."""
    secret = graded[0].state.server.secret
    found: list[str] = []
    for viewport in (DESKTOP, PHONE):
        context = chromium.new_context(viewport=viewport)
        _listen(context)
        page = context.new_page()
        try:
            tag = f"{viewport['width']}px"
            page.goto(f"{live_url}/")
            found += _axe(page, f"{tag} sign-in")
            page.goto(f"{live_url}/login?token={issue(secret, 'axe-student')}")
            found += _axe(page, f"{tag} sign-in link")
            sign_in(page, live_url, issue(secret, "axe-student"))
            found += _axe(page, f"{tag} problems")
            page.goto(f"{live_url}/p/12.22")
            found += _axe(page, f"{tag} problem")
            _verdict(page, live_url)
            found += _axe(page, f"{tag} verdict")
            page.goto(f"{live_url}/p/12.22?attempt=999999")
            found += _axe(page, f"{tag} error")
            page.goto(f"{live_url}/p/99.99")
            found += _axe(page, f"{tag} no such problem")
            page.goto(f"{live_url}/p/12.14")
            page.goto(live_url + page.locator("a[href*='?attempt=']").first.get_attribute("href"))
            page.locator("#result").wait_for(timeout=15000)
            found += _axe(page, f"{tag} an earlier attempt")
        finally:
            context.close()
        context = chromium.new_context(viewport=viewport)
        _listen(context)
        page = context.new_page()
        try:
            sign_in(page, live_url, issue(secret, INSTRUCTOR))
            found += _axe(page, f"{tag} instructor's problems")
            page.goto(f"{live_url}/class/")
            page.locator("body[data-loaded]").wait_for(timeout=15000)
            found += _axe(page, f"{tag} class page")
            page.locator("a[href^='students/']").first.click()
            page.locator("body[data-loaded]").wait_for(timeout=15000)
            found += _axe(page, f"{tag} a student's page")
        finally:
            context.close()
    assert not found, "\n".join(found)
    assert not _REFUSED, _REFUSED  # no page had a style, script or picture refused by its own policy


def test_the_class_page_loads_its_own_style_and_script(graded, live_url, chromium):
    """Issue 36: the server's own Content-Security-Policy refused the report's style.css and report.js."""
    context = chromium.new_context(viewport=DESKTOP)
    page = context.new_page()
    refused: list[str] = []
    page.on("console", lambda m: refused.append(m.text) if "Content Security Policy" in m.text else None)
    loaded: dict[str, tuple[int, str]] = {}
    page.on("response", lambda r: loaded.__setitem__(r.url.rsplit("/", 1)[-1], (r.status, r.headers.get(
        "content-type", ""))))
    try:
        sign_in(page, live_url, issue(graded[0].state.server.secret, INSTRUCTOR))
        page.goto(f"{live_url}/class/")
        page.locator("body[data-loaded]").wait_for(timeout=15000)
        _shot(page, "class-page")
        assert not refused, refused
        assert page.get_attribute("body", "data-errors") == "0"
        assert loaded["style.css"][0] == 200 and loaded["style.css"][1].startswith("text/css"), loaded
        assert loaded["report.js"][0] == 200 and "javascript" in loaded["report.js"][1], loaded
        # the style applies (the report's 70em column, not the browser's full width) and the script ran
        assert page.evaluate("() => getComputedStyle(document.body).maxWidth") != "none"
        assert page.locator("th.sortable").count() > 0
        csp = page.evaluate("async () => (await fetch('/class/')).headers.get('content-security-policy')")
        assert "default-src 'none'" in csp
    finally:
        context.close()


#: axe's rules behind issue 47's moderate findings: one <main>, content inside landmarks, headings in order
MODERATE_RULES = ("landmark-one-main", "region", "heading-order", "landmark-no-duplicate-main", "page-has-heading-one")


def test_after_a_check_focus_moves_to_the_result_and_it_is_announced(graded, live_url, chromium):
    """Issue 47: after a submit the result sat 1 400 px down and nothing moved focus to it; and the
    heading said "Attempt 6" on a student's second attempt (every student's submissions were counted)."""
    secret = graded[0].state.server.secret
    for other in ("focus-other-1", "focus-other-2"):  # others' attempts come first on the server
        page = chromium.new_page(viewport=DESKTOP)
        try:
            sign_in(page, live_url, issue(secret, other))
            page.goto(f"{live_url}/p/12.22")
            page.fill('input[name="f:L"]', f"m1*x_d^2/2 + {len(other)}*g*x")
            page.click("#submit")
            page.locator("#result").wait_for(timeout=120000)
        finally:
            page.close()
    page = chromium.new_page(viewport={"width": 1100, "height": 700})
    try:
        sign_in(page, live_url, issue(secret, "focus-student"))
        for n, value in enumerate(("m1*x_d^2/2", "m1*x_d^2/2 + g*x"), start=1):
            page.goto(f"{live_url}/p/12.22")
            page.fill('input[name="f:L"]', value)
            page.click("#submit")
            page.locator('#result[data-state="graded"]').wait_for(timeout=120000)
            page.wait_for_function("() => document.body.getAttribute('data-focused') === 'result'", timeout=15000)
            assert page.evaluate("() => document.activeElement.id") == "result"
            top = page.evaluate("() => document.getElementById('result').getBoundingClientRect().top")
            assert -2 <= top < 700, top  # scrolled to (to within a pixel), not 1 400 px down
            assert page.locator("#result [data-attempt-number]").inner_text() == str(n)
            page.wait_for_function("() => document.getElementById('announce').textContent.length > 0", timeout=15000)
            said = page.locator("#announce").inner_text()
            assert said.startswith(f"Attempt {n}: ") and "points" in said and "L " in said, said
            assert page.get_attribute("#announce", "role") == "status"
        # an earlier attempt opened from the list: no focus moved, nothing announced
        page.goto(live_url + page.locator("a[data-attempt='1']").get_attribute("href"))
        page.locator("#result").wait_for(timeout=15000)
        assert page.evaluate("() => document.activeElement === document.body")
        assert page.locator("#announce").inner_text() == ""
        assert page.locator("#result [data-attempt-number]").inner_text() == "1"
    finally:
        page.close()


def test_axe_finds_no_landmark_or_heading_finding(graded, live_url, chromium):
    """Issue 47: axe's moderate findings (no ``<main>``, content outside landmarks, headings out of
    order) on the student's pages; and the page's own script runs under a CSP without 'unsafe-inline'."""
    secret = graded[0].state.server.secret
    context = chromium.new_context(viewport=DESKTOP)
    refused: list[str] = []
    context.add_init_script(_LISTEN)
    context.on("console", lambda m: refused.append(m.text) if "CSP refused" in m.text
               or "Content Security Policy" in m.text else None)
    page = context.new_page()
    found: list[str] = []

    def moderate(name: str) -> None:
        results = Axe().run(page)
        found.extend(f"{name}: {v['id']} ({v['impact']}): {', '.join(str(n['target']) for n in v['nodes'][:3])}"
                     for v in results.response["violations"] if v["id"] in MODERATE_RULES)

    try:
        page.goto(f"{live_url}/")
        moderate("sign-in")
        sign_in(page, live_url, issue(secret, "axe-moderate"))
        moderate("problems")
        response = page.goto(f"{live_url}/p/12.22")
        assert "'unsafe-inline'" not in response.headers["content-security-policy"].split("script-src", 1)[1] \
            .split(";")[0]
        moderate("problem")
        page.fill('input[name="f:L"]', "m1*x_d^2/2")
        page.locator('[data-field="L"] [data-preview][data-ready="yes"] math').wait_for(timeout=15000)  # the script ran
        page.click("#submit")
        page.locator('#result[data-state="graded"]').wait_for(timeout=120000)
        moderate("verdict")
        page.goto(f"{live_url}/p/99.99")
        moderate("error")
    finally:
        context.close()
    assert not found, "\n".join(found)
    assert not refused, refused


def test_an_idle_session_signs_the_browser_out(graded, live_url, chromium):
    """Issue 47: sessions lived 120 days with no idle limit; after ``session_idle_minutes`` without a
    request the page asks to sign in again."""
    import sqlalchemy as sa

    from lagrade.uses.server.db import _session_key, server_sessions

    app = graded[0]
    context = chromium.new_context(viewport=DESKTOP)
    page = context.new_page()
    try:
        sign_in(page, live_url, issue(app.state.server.secret, "idle-student"))
        assert page.locator("[data-student]").inner_text() == "idle-student"
        cookie = next(c["value"] for c in context.cookies() if c["name"] == "lagrade_session")
        idle = 60 * app.state.server.config.session_idle_minutes
        with app.state.server.db.engine.begin() as c:
            c.execute(sa.update(server_sessions).where(server_sessions.c.key == _session_key(cookie))
                      .values(last_seen=sa.literal(__import__("time").time() - idle - 1)))
        page.goto(f"{live_url}/p/12.22")
        page.wait_for_url(f"{live_url}/")
        assert page.locator("input#token").count() == 1 and page.locator("[data-student]").count() == 0
    finally:
        context.close()
