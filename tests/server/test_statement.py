"""The problem as a student sees it: the statement with math (MathML, as the preview's), and the
figure it refers to, drawn from the scene (bodies at a sample state, each coordinate's direction)."""

from __future__ import annotations

import re

from serverkit import PICTURE_CHUNKS, bearer, png_chunks, sign_in

from lagrade.verdicts.figure import draw
from lagrade.problem.library import load_problem
from lagrade.uses.server.statement import statement_html


def test_the_page_shows_the_statement_with_math_and_the_figure(quiet_app):
    app, client = quiet_app
    sign_in(app, client, "alice")
    page = client.get("/p/12.14").text
    block = re.search(r"<div class=\"statement\" data-statement>(.*?)</div>", page, re.S).group(1)
    assert "<math" in block and "&#952;" in block  # theta1 as the preview writes it: θ with a subscript
    assert '<a href="#figure" data-fig-ref>Fig. P12.14</a>' in block
    assert re.search(r'<figure id="figure" data-figure><img src="/api/v1/problems/12.14/figure.png"', page)
    png = client.get("/api/v1/problems/12.14/figure.png")
    assert png.status_code == 200 and png.headers["content-type"] == "image/png"
    assert set(png_chunks(png.content)) <= PICTURE_CHUNKS  # pixels, no words or numbers


def test_the_api_serves_the_statement_and_the_figure_to_a_token_only(quiet_app):
    app, client = quiet_app
    client.cookies.clear()
    assert client.get("/api/v1/problems/12.22/figure.png").status_code == 401
    out = client.get("/api/v1/problems/12.22", headers=bearer(app, "bob")).json()
    assert "<math" in out["statement_html"] and out["figure"] == "/api/v1/problems/12.22/figure.png"


def test_a_formula_of_the_text_is_math_and_plain_words_stay_words():
    html = statement_html(load_problem("12.22"))
    assert "<mo>-</mo><mi>y</mi>" in html  # "l1 - y" read as a formula
    assert "pulley A" in html and "Lagrange&#x27;s equations" in html


def test_every_problem_has_a_figure_drawn_from_its_scene():
    # with a [systems.figure] table (12.14) and without one (12.8: its coordinates alone)
    for pid in ("12.14", "12.8"):
        assert png_chunks(draw(load_problem(pid)))[0] == "IHDR"
    assert load_problem("12.14").systems[0].figure is not None


def test_the_page_and_the_api_say_how_to_type_a_rate(quiet_app):
    app, client = quiet_app
    sign_in(app, client, "alice")
    page = client.get("/p/12.14").text
    help_ = re.search(r'<p class="hint" id="typing" data-typing>([^<]*)</p>', page).group(1)
    assert "theta1&#39; (also theta1_d" in help_
    api = client.get("/api/v1/problems/12.14", headers=bearer(app, "bob")).json()["typing"]
    assert "theta1' (also theta1_d, theta1_dot or theta1dot)" in api
