"""The student page: the problem as `lagrade show`/`template` print it, a field per part, the
"read as" preview (MathML, parsed as answer.toml is), and verdicts and earlier attempts after a check."""

from __future__ import annotations

import re

import pytest
from serverkit import GOLDEN, sign_in, toml_answer


def _browser(app, client, student):
    browser = type(client)(app)
    return browser, {"X-CSRF-Token": sign_in(app, browser, student)}


def test_problem_page_shows_what_show_and_template_print(quiet_app):
    from click.testing import CliRunner

    from lagrade.cli import main

    app, client = quiet_app
    browser, _ = _browser(app, client, "alice")
    page = browser.get("/p/12.22").text
    from markupsafe import escape

    for command in ("show", "template"):
        printed = CliRunner().invoke(main, [command, "12.22"]).output
        assert str(escape(printed.strip())) in page, command
    for name in ("f:L", "f:eom", "f:a:m1", "f:a:m4", "f:S_t:S3", "f:a_case:m2"):
        assert f'name="{name}"' in page, name
    assert re.search(r'<textarea id="f-eom" name="f:eom"', page)


def test_preview_reads_text_and_latex_as_answer_toml_does(quiet_app):
    app, client = quiet_app
    browser, csrf = _browser(app, client, "alice")
    url = "/api/v1/problems/12.22/preview"
    r = browser.post(url, headers=csrf, json={"part": "L", "value": "m1*x_d^2/2"}).json()
    assert r["error"] is None and r["text"] == "m1*Derivative(x(t), t)**2/2"
    assert r["mathml"].startswith("<math") and "<mfrac>" in r["mathml"]
    r = browser.post(url, headers=csrf, json={"part": "L", "value": r"\frac{1}{2} m_1 \dot{x}^2"}).json()
    assert r["error"] is None and r["text"] == "m1*Derivative(x(t), t)**2/2"
    r = browser.post(url, headers=csrf, json={"part": "eom", "value": ["x_dd == g", "y_dd == 0"]}).json()
    assert r["error"] is None and r["text"].startswith("[")
    r = browser.post(url, headers=csrf, json={"part": "a", "value": {"m1": "g/2"}}).json()
    assert r["error"] is None
    bad = browser.post(url, headers=csrf, json={"part": "L", "value": "m1*x_d^^2"}).json()
    assert bad["error"] and "\n" not in bad["error"] and bad.get("mathml") is None
    unknown = browser.post(url, headers=csrf, json={"part": "L", "value": "mass*x_d"}).json()
    assert unknown["error"] and "mass" in unknown["error"]
    hostile = browser.post(url, headers=csrf, json={"part": "L", "value": "__import__('os').system('true')"}).json()
    assert hostile["error"]
    assert browser.post(url, json={"part": "L", "value": "m1"}).status_code == 403  # no CSRF header
    assert browser.post(url, headers=csrf, json={"part": "nope", "value": "m1"}).json()["error"].startswith("problem 12.22 has no part")


@pytest.mark.slow
def test_submit_shows_verdicts_and_earlier_attempts(graded):
    app, client, _ = graded
    browser, csrf = _browser(app, client, "grace")
    token = csrf["X-CSRF-Token"]
    values = toml_answer(GOLDEN / "12.22" / "wrong_case_upward.toml")
    form = {"csrf": token}
    for part, value in values.items():
        if isinstance(value, dict):
            form.update({f"f:{part}:{k}": v for k, v in value.items()})
        elif isinstance(value, list):
            form[f"f:{part}"] = "\n".join(value)
        else:
            form[f"f:{part}"] = value
    page = browser.post("/p/12.22/check", data=form).text
    verdicts = dict(re.findall(r'<tr data-part="([^"]+)">.*?data-verdict[^>]*>(\w+)<', page, flags=re.DOTALL))
    assert verdicts["a_case"] == "incorrect" and verdicts["L"] == "correct"
    assert "<math" in page  # the answer as read, rendered
    upload = browser.post("/p/12.22/check", data={"csrf": token},
                          files={"file": ("answer.toml", (GOLDEN / "12.22" / "correct_plain.toml").read_bytes())}).text
    assert re.search(r'data-score>5</span> / 5', upload)
    attempts = re.findall(r'href="/p/12\.22\?attempt=(\d+)"', browser.get("/p/12.22").text)
    assert len(attempts) == 2
    old = browser.get(f"/p/12.22?attempt={min(map(int, attempts))}").text
    assert 'data-state="graded"' in old and "incorrect" in old
    other, _ = _browser(app, client, "heidi")
    assert other.get(f"/p/12.22?attempt={attempts[0]}").status_code == 404  # not someone else's


def test_preview_of_a_number_too_large_to_print_says_why(quiet_app):
    """``g*9^4999`` passed every reader bound and died printing (issue 43, item 4): the preview was empty,
    neither text nor error. It is refused with the bound named, as a check refuses it."""
    from lagrade.problem.limits import MAX_NUMBER_DIGITS

    app, client = quiet_app
    browser, csrf = _browser(app, client, "alice")
    for value in ("g*9^4999", r"g \cdot 9^{4999}"):
        r = browser.post("/api/v1/problems/12.22/preview", headers=csrf, json={"part": "L", "value": value}).json()
        assert r["error"] and f"limit {MAX_NUMBER_DIGITS}" in r["error"] and "\n" not in r["error"], r

def test_preview_is_bounded(quiet_app):
    app, client = quiet_app
    browser, csrf = _browser(app, client, "alice")
    url = "/api/v1/problems/12.22/preview"
    latex = r"\frac{1}{2} m_1 \dot{x}^2" + r" + \frac{1}{2} m_1 \dot{x}^2" * 30
    r = browser.post(url, headers=csrf, json={"part": "L", "value": latex}).json()
    assert "characters of LaTeX" in r["error"] and r.get("mathml") is None
    r = browser.post(url, headers=csrf, json={"part": "L", "value": "x + " * 600}).json()
    assert "longer than" in r["error"]


def test_a_preview_that_never_ends_is_cut_off_and_the_server_keeps_answering(tmp_path):
    """A power bomb typed in a field (issue 32): its preview is read in the preview process, cut off
    after ``preview_seconds``, while /healthz answers; the next preview is read again."""
    import threading
    import time

    from fastapi.testclient import TestClient
    from serverkit import make_config

    from lagrade.uses.server.app import create_app

    app = create_app(make_config(tmp_path, preview_seconds=3), grade=False)
    with TestClient(app) as client:
        browser, csrf = _browser(app, client, "alice")
        url = "/api/v1/problems/12.22/preview"
        assert browser.post(url, headers=csrf, json={"part": "L", "value": "m1*x_d^2"}).json()["error"] is None
        bomb = "(" * 30 + "3*g*x_d" + ")^2" * 30
        out: dict = {}
        ask = threading.Thread(target=lambda: out.update(browser.post(url, headers=csrf,
                                                                      json={"part": "L", "value": bomb}).json()),
                               daemon=True)
        ask.start()
        answered_meanwhile = 0  # health checks answered while the preview was still running
        while ask.is_alive():
            assert client.get("/healthz").status_code == 200
            answered_meanwhile += ask.is_alive()
            time.sleep(0.2)
        ask.join()  # a hang is caught by the test's own timeout, not by a clock read here
        # refused by the readers' size estimate at once, or cut off by the preview's own bound: never a hang,
        # and the server answers others meanwhile (the preview runs off the event loop)
        assert "too large" in out["error"] or ("longer than 3 s" in out["error"] and answered_meanwhile), out
        r = browser.post(url, headers=csrf, json={"part": "L", "value": "m1*x_d^2"}).json()
        assert r["error"] is None and "<math" in r["mathml"]


def test_a_browsers_errors_are_pages_of_the_site_not_json(quiet_app):
    """Issue 32: `?attempt=abc` and an expired CSRF token came back as raw JSON in the browser."""
    app, client = quiet_app
    browser, csrf = _browser(app, client, "alice")
    style = "font: 15px/1.45 system-ui"  # base.html's
    r = browser.get("/p/12.22", params={"attempt": "abc"})
    assert r.status_code == 422 and r.headers["content-type"].startswith("text/html")
    assert style in r.text and "attempt=&#39;abc&#39; is not understood" in r.text and 'href="/p/12.22"' in r.text
    r = browser.post("/p/12.22/check", data={"f:L": "m1*x_d^2", "csrf": "expired"})
    assert r.status_code == 403 and r.headers["content-type"].startswith("text/html")
    assert style in r.text and "CSRF token" in r.text and "Content-Security-Policy" in r.headers
    r = browser.get("/p/12.22", params={"attempt": 999})
    assert r.status_code == 404 and style in r.text
    r = browser.get("/class/")
    assert r.status_code == 401 and style in r.text
    # the API keeps answering JSON
    r = browser.get("/api/v1/submissions/abc")
    assert r.status_code == 422 and r.headers["content-type"].startswith("application/json")
    assert browser.get("/api/v1/problems/nope").json()["detail"].startswith("no problem")
