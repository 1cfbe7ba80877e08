"""Every path parameter that does not parse is a 404 or a 422, never a 500 (issue 32, item 4).

``GET /api/v1/submissions/<an id beyond int64>`` reached the database, which cannot hold it, and
answered 500 (TestClient re-raises the server's exception: such a test fails with the traceback)."""

from __future__ import annotations

import pytest
from serverkit import bearer, sign_in

BEYOND = str(2**63)  # one past the largest id the database holds
IDS = [BEYOND, str(10**40), "-1", "0", "abc", "1.5", "1e3", "%00"]


@pytest.mark.parametrize("sid", IDS)
@pytest.mark.parametrize("route", ["/api/v1/submissions/{}", "/api/v1/submissions/{}/plot.png"])
def test_a_submission_id_that_does_not_parse(quiet_app, route, sid):
    app, client = quiet_app
    r = client.get(route.format(sid), headers=bearer(app, "alice"))
    assert r.status_code in (404, 422), (sid, r.status_code, r.text[:200])


def test_the_largest_id_is_just_not_found(quiet_app):
    app, client = quiet_app
    r = client.get(f"/api/v1/submissions/{2**63 - 1}", headers=bearer(app, "alice"))
    assert r.status_code == 404


@pytest.mark.parametrize("page", ["%00", "a" * 5000, "../../etc/passwd"])
def test_a_class_page_that_cannot_exist(quiet_app, instructor, page, monkeypatch):
    """A NUL byte, or a name longer than the file system takes, was a 500 (ValueError, OSError)."""
    from lagrade.uses.bulk import html_report

    monkeypatch.setattr(html_report, "write_report", lambda book, folder, *_: (folder / "index.html").write_text("ok"))
    app, client = quiet_app
    assert client.get("/class/").status_code == 401
    sign_in(app, client, instructor)  # the page wants a browser
    r = client.get(f"/class/{page}")
    assert r.status_code == 404, (page[:20], r.status_code)
    assert client.get("/class/").text == "ok"  # the report itself is served
