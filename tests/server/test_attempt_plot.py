"""The picture of a wrong motion on the server: `lagrade check --plot`'s PNG, made by the grader,
served to the attempt's owner only, shown on the page; pixels only (no text chunk, no number of the
true motion as text, no vector path).

The answers here are values no other test of the session sends: the graders keep verdicts by value
(lagrade.verdicts.verdict_memo), and a verdict kept from before carries no motion to draw."""

from __future__ import annotations

import numpy as np
import pytest
from serverkit import PICTURE_CHUNKS, bearer, png_chunks, sign_in

from lagrade.uses.server.tokens import INSTRUCTOR

pytestmark = pytest.mark.slow

#: 12.14's L with half the coupling term: the motion separates, the picture shows it
WRONG_L = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta2 - theta1)/2"
           " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)")
#: with 3/2 of it the kinetic energy is not positive at the start: these equations cannot be integrated
NO_MOTION_L = WRONG_L.replace("cos(theta2 - theta1)/2", "cos(theta2 - theta1)*3/2")
RIGHT_L = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)"
           " + g*l1*(m1 + m2)*cos(theta1) + m2*g*l2*cos(theta2)")
def _pixels(data: bytes) -> np.ndarray:
    import io

    import matplotlib.image

    return matplotlib.image.imread(io.BytesIO(data), format="png")[..., :3]


def test_a_wrong_motion_gets_its_picture_and_only_its_owner_sees_it(graded):
    app, client, _ = graded
    owner = bearer(app, "plot-owner")
    plain = client.post("/api/v1/problems/12.14/check", headers=bearer(app, "plot-not-asked"),
                        json={"answer": {"L": WRONG_L.replace("theta1)/2", "theta1)/4")}}).json()
    assert "plot" not in plain  # the API draws it when asked (it costs more than the grade)
    r = client.post("/api/v1/problems/12.14/check?plot=true", headers=owner, json={"answer": {"L": WRONG_L}})
    assert r.status_code == 200, r.text
    body = r.json()
    sid = body["submission_id"]
    assert {p["part"]: p["verdict"] for p in body["parts"]}["L"] == "incorrect"
    assert body["plot"] == f"/api/v1/submissions/{sid}/plot.png"

    got = client.get(body["plot"], headers=owner)
    assert got.status_code == 200 and got.headers["content-type"] == "image/png"
    assert got.headers["x-content-type-options"] == "nosniff" and "private" in got.headers["cache-control"]
    kinds = png_chunks(got.content)
    assert set(kinds) <= PICTURE_CHUNKS, kinds
    rgb = _pixels(got.content)
    true_motion = (rgb.max(axis=-1) < 0.15).sum()  # black
    yours = ((rgb[..., 0] > 0.7) & (rgb[..., 1] < 0.35) & (rgb[..., 2] < 0.35)).sum()  # tab:red, dashed
    assert true_motion > 500 and yours > 200, (true_motion, yours)

    assert client.get(body["plot"], headers=bearer(app, "someone-else")).status_code == 404
    assert client.get(body["plot"]).status_code == 401
    assert client.get(body["plot"], headers=bearer(app, INSTRUCTOR)).content == got.content  # the instructor sees all

    # the page shows it to its owner, with words only around it
    browser = type(client)(app)
    sign_in(app, browser, "plot-owner")
    page = browser.get(f"/p/12.14?attempt={sid}").text
    assert f'<img src="/api/v1/submissions/{sid}/plot.png" alt="' in page
    alt = page.split(f'<img src="/api/v1/submissions/{sid}/plot.png" alt="')[1].split('"')[0]
    assert alt and not any(ch.isdigit() for ch in alt)
    assert browser.get(f"/api/v1/submissions/{sid}/plot.png").content == got.content  # the browser's cookie


def test_a_right_motion_has_no_picture(graded):
    app, client, _ = graded
    h = bearer(app, "plot-right")
    body = client.post("/api/v1/problems/12.14/check?plot=true", headers=h, json={"answer": {"L": RIGHT_L}}).json()
    assert all(p["verdict"] == "correct" for p in body["parts"] if p["part"] == "L") and "plot" not in body
    r = client.get(f"/api/v1/submissions/{body['submission_id']}/plot.png", headers=h)
    assert r.status_code == 404 and "no picture" in r.json()["detail"]


def test_no_picture_of_the_true_motion_alone(graded):
    """Equations that cannot be integrated draw no curve of their own: the true motion alone would
    show nothing of the answer, so there is no picture."""
    app, client, _ = graded
    h = bearer(app, "plot-nothing")
    body = client.post("/api/v1/problems/12.14/check?plot=true", headers=h, json={"answer": {"L": NO_MOTION_L}}).json()
    assert {p["part"]: p["verdict"] for p in body["parts"]}["L"] == "incorrect" and "plot" not in body


def test_a_value_graded_before_still_gets_its_picture(graded):
    """The graders keep verdicts by value, without the motion; a page that asks for the picture of a
    value graded before gets it all the same (graded again, unkept, to draw it)."""
    app, client, _ = graded
    value = {"answer": {"L": WRONG_L.replace("theta1)/2", "theta1)/5")}}
    first = client.post("/api/v1/problems/12.14/check", headers=bearer(app, "plot-first"), json=value).json()
    assert "plot" not in first
    h = bearer(app, "plot-second")
    again = client.post("/api/v1/problems/12.14/check?plot=true", headers=h, json=value).json()
    assert again["submission_id"] != first["submission_id"] and again["parts"] == first["parts"]
    assert client.get(again["plot"], headers=h).status_code == 200
