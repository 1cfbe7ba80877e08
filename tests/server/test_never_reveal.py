"""No response of the server carries a reference value.

Every route, with right and wrong answers for every problem of the test assignment, by API and by
the web page; each response's text (the JSON's strings, the page's text) is checked with
``tests/leaks.py``'s ``reveals``: textually against the references written in the problem file, and
every run of mathematics in it parsed and compared, as an expression, with the references, L, T,
V, H, the accelerations and the equations of motion. The student's own values quoted back to them
(``read_as*``, a page's "read as" cell and refilled fields) are left out: a right answer echoed is
the student's, not the server's. The reference solutions' values are also looked for as text.
"""

from __future__ import annotations

import re
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest
from serverkit import (
    GOLDEN,
    PICTURE_CHUNKS,
    PROBLEMS,
    REPO,
    bearer,
    golden,
    png_chunks,
    sign_in,
    toml_answer,
)

from lagrade.answer.reading.load import load_answer
from lagrade.problem.library import load_problem

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from leaks import reveals, squash

pytestmark = pytest.mark.slow
ECHO_KEYS = {"read_as", "read_as_text", "read_as_mathml"}


class _Text(HTMLParser):
    """The text a page shows, without what echoes the student's input, scripts and styles."""

    def __init__(self) -> None:
        super().__init__()
        self.out: list[str] = []
        self.skip = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag in ("script", "style", "textarea") or "data-echo" in a:
            self.skip += 1
        elif tag == "input" and a.get("type") not in ("hidden", "file") and a.get("value"):
            pass  # a refilled field: the student's own text (attribute values are not collected)

    def handle_endtag(self, tag):
        if self.skip and tag in ("script", "style", "textarea", "td"):
            self.skip -= 1

    def handle_data(self, data):
        if not self.skip and data.strip():
            self.out.append(data.strip())


def page_texts(html: str) -> list[str]:
    p = _Text()
    p.feed(html)
    return p.out


def json_texts(obj) -> list[str]:
    if isinstance(obj, dict):
        return [t for k, v in obj.items() if k not in ECHO_KEYS for t in json_texts(v)]
    if isinstance(obj, list):
        return [t for v in obj for t in json_texts(v)]
    return [obj] if isinstance(obj, str) else []


def reference_strings(pid: str) -> list[str]:
    """The reference solution's values as sympy prints them (longer than a name)."""
    problem = load_problem(pid)
    loaded = load_answer(REPO / "reference_solutions" / pid / "answer.py", problem)
    out = []

    def walk(v):
        if isinstance(v, dict):
            for x in v.values():
                walk(x)
        elif isinstance(v, (list, tuple)):
            for x in v:
                walk(x)
        elif not isinstance(v, (bool, int)):
            text = squash(str(v))
            if len(text) >= 12:
                out.append(text)
            if type(v).__name__ == "Equality":
                walk(v.rhs)  # x'' = <the value>: the value is the secret, x'' is a name

    walk(loaded.values)
    return out


def assert_hides(pid: str, texts: list[str], where: str, textual: bool = True) -> None:
    """``textual``: also look for the reference solution's printed values as substrings (not for a
    student's echoed value, which may hold one with a sign in front: that is compared as an expression)."""
    refs = reference_strings(pid) if textual else []
    for text in texts:
        found = reveals(pid, text)
        assert not found, f"{where}: {text!r} reveals {found}"
        flat = squash(text)
        for r in refs:
            assert r not in flat, f"{where}: {text!r} quotes the reference solution"


def answers(pid: str) -> list[tuple[str, str, bytes]]:
    """(label, file name, bytes): the reference solution (right), the golden right and wrong files."""
    out = [("reference", "answer.py", (REPO / "reference_solutions" / pid / "answer.py").read_bytes())]
    for p in golden(pid):
        out.append((p.name, f"answer{p.suffix}", p.read_bytes()))
    return out


@pytest.mark.parametrize("pid", PROBLEMS)
def test_no_api_response_reveals_a_reference(graded, pid):
    app, client, _ = graded
    h = bearer(app, f"walker-{pid}")
    assert_hides(pid, json_texts(client.get("/api/v1/problems", headers=h).json()), "GET /api/v1/problems")
    assert_hides(pid, json_texts(client.get(f"/api/v1/problems/{pid}", headers=h).json()), f"GET /api/v1/problems/{pid}")
    assert_hides(pid, [client.get("/openapi.json").text], "GET /openapi.json")
    sids = []
    for label, name, data in answers(pid):
        r = client.post(f"/api/v1/problems/{pid}/check", headers=h, files={"file": (name, data)})
        assert r.status_code == 200, r.text
        body = r.json()
        sids.append(body["submission_id"])
        assert_hides(pid, json_texts(body), f"check {pid} {label}")
        if name.endswith(".toml"):
            r = client.post(f"/api/v1/problems/{pid}/check", headers=h,
                            json={"answer": toml_answer(GOLDEN / pid / label)})
            assert_hides(pid, json_texts(r.json()), f"check {pid} {label} as JSON")
        if label.startswith("wrong"):  # an incorrect single value echoed is the student's wrong value: checked too
            problem = load_problem(pid)
            single = {part.name for part in problem.parts if part.kind in ("lagrangian", "hamiltonian")
                      or part.kind == "expression" and not isinstance(part.reference, dict)}
            wrong = [body["read_as_text"][p["part"]] for p in body["parts"] if p["verdict"] == "incorrect"
                     and p["part"] in body["read_as_text"] and p["part"] in single]
            assert_hides(pid, wrong, f"echo of {pid} {label}", textual=False)
    for sid in sids:
        assert_hides(pid, json_texts(client.get(f"/api/v1/submissions/{sid}", headers=h).json()), f"submission {sid}")
    assert_hides(pid, json_texts(client.get(f"/api/v1/problems/{pid}/submissions", headers=h).json()), "attempts")
    for label, name, data in answers(pid):
        if label.startswith("wrong") and name.endswith(".toml"):
            for part, value in toml_answer(GOLDEN / pid / label).items():
                r = client.post(f"/api/v1/problems/{pid}/preview", headers=h, json={"part": part, "value": value})
                assert r.status_code == 200
                # the preview shows the student's own text back (text, mathml): what the server adds is the error
                assert_hides(pid, [r.json()["error"] or ""], f"preview {pid} {label} {part}")


@pytest.mark.parametrize("pid", PROBLEMS)
def test_no_page_reveals_a_reference(graded, pid):
    app, client, _ = graded
    browser = type(client)(app)
    csrf = sign_in(app, browser, f"browser-{pid}")
    for url in ("/", f"/p/{pid}"):
        r = browser.get(url)
        assert r.status_code == 200
        assert_hides(pid, page_texts(r.text), f"GET {url}")
    for label, name, data in answers(pid):
        r = browser.post(f"/p/{pid}/check", data={"csrf": csrf}, files={"file": (name, data)})
        assert r.status_code == 200 and 'data-state="graded"' in r.text, r.text[-500:]
        assert_hides(pid, page_texts(r.text), f"POST /p/{pid}/check {label}")
        if name.endswith(".toml"):  # typed into the form
            fields = {}
            for part, value in toml_answer(GOLDEN / pid / label).items():
                if isinstance(value, list):
                    fields[f"f:{part}"] = "\n".join(value)
                elif isinstance(value, dict):
                    fields.update({f"f:{part}:{k}": v for k, v in value.items()})
                else:
                    fields[f"f:{part}"] = str(value)
            r = browser.post(f"/p/{pid}/check", data={"csrf": csrf, **fields})
            assert r.status_code == 200 and 'data-state="graded"' in r.text
            assert_hides(pid, page_texts(r.text), f"form {pid} {label}")
    for sid in re.findall(rf'href="/p/{re.escape(pid)}\?attempt=(\d+)"', browser.get(f"/p/{pid}").text):
        page = browser.get(f"/p/{pid}?attempt={sid}").text
        assert_hides(pid, page_texts(page), f"attempt {sid}")
        if f"/api/v1/submissions/{sid}/plot.png" in page:  # the picture: pixels only (test_attempt_plot.py)
            png = browser.get(f"/api/v1/submissions/{sid}/plot.png").content
            assert set(png_chunks(png)) <= PICTURE_CHUNKS
            flat = squash(png.decode("latin-1"))
            assert not [r for r in reference_strings(pid) if r in flat], f"picture {sid}"


def test_the_walk_finds_a_reference_when_one_is_shown():
    """The check itself works: the reference L of 12.22, or its value written otherwise, is caught."""
    ref = (REPO / "reference_solutions" / "12.22" / "answer.py").read_text()
    assert "T = m1 / 2" in ref
    with pytest.raises(AssertionError):
        assert_hides("12.22", [("feedback: expected m1*(x_d + y_d)**2/2 + m2*(x_d - y_d)**2/2 + m3*(z_d - x_d)**2/2 "
                                "+ m4*(x_d + z_d)**2/2 + g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) "
                                "+ m4*(l3 - x + l2 - z))")], "a leak")
    with pytest.raises(AssertionError):
        assert_hides("12.14", [("the frequencies are sqrt((g*(l1 + l2)*(m1 + m2) - sqrt(g**2*(l1 + l2)**2*(m1 + m2)**2 "
                                "- 4*g**2*l1*l2*m1*(m1 + m2)))/(2*l1*l2*m1))")], "a leak")
    with pytest.raises(AssertionError):  # on a page, as text
        assert_hides("12.14", page_texts("<p>L = (m1+m2)/2*l1^2*theta1_d^2 + m2/2*l2^2*theta2_d^2 + m2*l1*l2*theta1_d*"
                                         "theta2_d*cos(theta1-theta2) + (m1+m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)"
                                         "</p>"), "a leak")
    with pytest.raises(AssertionError):  # in a JSON response, outside the echo
        assert_hides("12.22", json_texts({"read_as_text": {"a": "x"}, "parts": [{"feedback": "S1 = 4*g/(1/m1 + 1/m2 "
                                                                                  "+ 1/m3 + 1/m4)"}]}), "a leak")
