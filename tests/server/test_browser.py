"""A real browser on the student page: Debian's Chromium driven by Playwright (the system browser,
nothing downloaded). Types a Lagrangian, sees the MathML preview, submits, reads the verdicts; no
request leaves 127.0.0.1. Skipped without Chromium or Playwright.

``LAGRADE_SCREENSHOT=/path.png`` also saves a screenshot of the page with its verdicts there."""

from __future__ import annotations

import os
import shutil
from urllib.parse import urlparse

import pytest

from lagrade.uses.server.tokens import issue

pytestmark = pytest.mark.slow
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
sync_api = pytest.importorskip("playwright.sync_api")
if not os.path.exists(CHROMIUM):
    pytest.skip("no chromium (apt-get install -y chromium)", allow_module_level=True)

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"]
RIGHT_L = ("m1*(x_d + y_d)^2/2 + m2*(x_d - y_d)^2/2 + m3*(z_d - x_d)^2/2 + m4*(x_d + z_d)^2/2 "
           "+ g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) + m4*(l3 - x + l2 - z))")


def test_type_preview_submit_and_read_the_verdict(graded, live_url, tmp_path):
    app = graded[0]
    token = issue(app.state.server.secret, "browser-student")
    requests = []
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        try:
            page = browser.new_page(viewport={"width": 1100, "height": 1400})
            page.on("request", lambda r: requests.append(r.url))
            errors = []
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.goto(f"{live_url}/login?token={token}")
            page.click("text=sign in as browser-student")  # the link asks before it signs in
            page.click("text=12.22")
            page.wait_for_url("**/p/12.22")
            field = page.locator('input[name="f:L"]')
            field.type(RIGHT_L, delay=1)
            preview = page.locator('[data-field="L"] [data-preview][data-ready="yes"] math')
            preview.wait_for(timeout=15000)
            assert preview.evaluate("e => e.getBoundingClientRect().width") > 100  # rendered, not raw text
            page.fill('input[name="f:a:m1"]', "x_dd + y_dd")
            page.locator('[data-field="a"] [data-preview][data-ready="yes"]').wait_for(timeout=15000)
            page.fill('input[name="f:a:m2"]', "x_dd +* y_dd")
            bad = page.locator('[data-field="a"] .preview.error')
            bad.wait_for(timeout=15000)
            assert bad.inner_text().strip()
            page.fill('input[name="f:a:m2"]', "")
            page.click("#submit")
            page.locator('#result[data-state="graded"]').wait_for(timeout=120000)
            verdicts = {row.get_attribute("data-part"): row.locator("[data-verdict]").inner_text()
                        for row in page.locator("#result tr[data-part]").all()}
            assert verdicts["L"] == "correct" and verdicts["eom"] == "missing", verdicts
            shot = os.environ.get("LAGRADE_SCREENSHOT") or str(tmp_path / "serve.png")
            page.screenshot(path=shot, full_page=True)
            assert not errors, errors
        finally:
            browser.close()
    hosts = {urlparse(u).hostname for u in requests if not u.startswith(("data:", "about:"))}
    assert hosts == {"127.0.0.1"}, hosts


def test_a_wrong_motion_shows_its_picture(graded, live_url, tmp_path):
    """12.14 with a third of the coupling term typed in: the page shows the picture of the two
    motions, loaded from this server, and its alternative text holds no number."""
    app = graded[0]
    token = issue(app.state.server.secret, "browser-plot")
    wrong = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)/3"
             " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)")
    requests = []
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        try:
            page = browser.new_page(viewport={"width": 1100, "height": 1400})
            page.on("request", lambda r: requests.append(r.url))
            page.goto(f"{live_url}/login?token={token}")
            page.click("text=sign in as browser-plot")
            page.wait_for_url(f"{live_url}/")
            page.goto(f"{live_url}/p/12.14")
            page.fill('input[name="f:L"]', wrong)
            page.click("#submit")
            page.locator('#result[data-state="graded"]').wait_for(timeout=120000)
            img = page.locator("[data-plot] img")
            img.wait_for(timeout=15000)
            page.wait_for_function("() => document.querySelector('[data-plot] img').complete", timeout=15000)
            assert img.evaluate("e => e.naturalWidth") > 300 and img.evaluate("e => e.naturalHeight") > 200
            assert not any(ch.isdigit() for ch in img.get_attribute("alt"))
            shot = os.environ.get("LAGRADE_SCREENSHOT_PLOT") or str(tmp_path / "serve-plot.png")
            page.screenshot(path=shot, full_page=True)
        finally:
            browser.close()
    assert any(u.endswith("/plot.png") for u in requests)
    hosts = {urlparse(u).hostname for u in requests if not u.startswith(("data:", "about:"))}
    assert hosts == {"127.0.0.1"}, hosts
