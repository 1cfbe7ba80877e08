"""LaTeX answers in answer.toml: the pre-pass, the name mapping, the refusals and the golden twins."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import lagrade
from lagrade.answer.reading import latex
from lagrade.answer.reading.latex import MAX_LATEX_CHARS, _antlr_converter, is_latex, parse_latex_answer
from lagrade.answer.reading.text import TextAnswerError, load_toml_answer, parse_math

ROOT = Path(__file__).resolve().parents[1]
t = sp.Symbol("t")
m, l, g, k, l0, m1, m2, eps, M = sp.symbols("m l g k l0 m1 m2 eps M")
theta, theta1, theta2, x, x1, r, phi = (sp.Function(n)(t) for n in "theta theta1 theta2 x x1 r phi".split())
p_theta, p_x = sp.Function("p_theta")(t), sp.Function("p_x")(t)

COORDS = ["theta", "theta1", "theta2", "x", "x1", "r", "phi", "p_theta", "p_x", "p_theta1"]
KNOWN = ["m", "l", "g", "k", "l0", "m1", "m2", "eps", "M", "l_a", "delta_theta", "t"]


def read(text: str, known: list[str] | None = KNOWN, coords: list[str] = COORDS):
    return parse_latex_answer(text, coords, known)


def same(a, b) -> bool:
    return sp.simplify(a - b) == 0


# --------------------------------------------------------------------------- the issue's example

def test_issue_example_equals_its_plain_text_twin():
    latex = read(r"\frac{1}{2} m l^2 \dot\theta^2 + m g l \cos\theta")
    plain = parse_math("m*l^2*theta_d^2/2 + m*g*l*cos(theta)", COORDS, KNOWN)
    assert latex == plain
    assert latex == m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * sp.cos(theta)


def test_equation_reads_as_eq():
    assert read(r"\ddot{\theta} = -\frac{g}{l}\sin\theta") == sp.Eq(theta.diff(t, 2), -g / l * sp.sin(theta))


# --------------------------------------------------------------------------- time derivatives

@pytest.mark.parametrize("text, expected", [
    (r"\dot{x}", x.diff(t)),
    (r"\dot x", x.diff(t)),
    (r"\dot\theta", theta.diff(t)),
    (r"\ddot{x}", x.diff(t, 2)),
    (r"\ddot \theta", theta.diff(t, 2)),
    ("x'", x.diff(t)),
    ("x''", x.diff(t, 2)),
    (r"\theta'", theta.diff(t)),
    (r"x^{\prime}", x.diff(t)),
    (r"x^{\prime\prime}", x.diff(t, 2)),
    (r"\dot{\theta}_1", theta1.diff(t)),
    (r"\dot{\theta_1}", theta1.diff(t)),
    (r"\dot\theta_{2}", theta2.diff(t)),
    (r"\theta_1'", theta1.diff(t)),
    (r"\theta'_1", theta1.diff(t)),
    (r"{\theta_1}''", theta1.diff(t, 2)),
    (r"\ddot{x}_1", x1.diff(t, 2)),
    (r"\dot p_\theta", p_theta.diff(t)),
    (r"\dot{p}_{\theta}", p_theta.diff(t)),
    (r"\frac{d\theta}{dt}", theta.diff(t)),
    (r"\frac{d^2 x}{dt^2}", x.diff(t, 2)),
    (r"\frac{d^{2}\theta_1}{dt^{2}}", theta1.diff(t, 2)),
    (r"\frac{\mathrm{d}x}{\mathrm{d}t}", x.diff(t)),
    (r"\dot\theta(t)", theta.diff(t)),
    (r"\theta(t)", theta),
    (r"p_\theta(t)", p_theta),
])
def test_time_derivatives(text, expected):
    assert read(text) == expected


def test_derivative_powers_and_products():
    assert read(r"\dot\theta^2") == theta.diff(t) ** 2
    assert read(r"\theta_1'^2") == theta1.diff(t) ** 2
    assert read(r"\dot{\theta}\,\dot{x}") == theta.diff(t) * x.diff(t)


def test_leibniz_operator_is_differentiated():
    got = read(r"\frac{d}{dt}\left(m l^2 \dot\theta\right) + m g l \sin\theta = 0")
    assert got == sp.Eq(m * l**2 * theta.diff(t, 2) + m * g * l * sp.sin(theta), 0)
    assert read(r"\frac{d^2}{dt^2} x") == x.diff(t, 2)


def test_dot_of_a_parameter_is_refused():
    with pytest.raises(TextAnswerError, match="applies to a coordinate"):
        read(r"\dot m")


# --------------------------------------------------------------------------- names

@pytest.mark.parametrize("text, expected", [
    (r"\theta_1", theta1),          # theta_{1} -> theta1: a coordinate
    (r"\theta_{1}", theta1),
    (r"m_1", m1),                   # m_{1} -> m1: a known name
    (r"l_0", l0),
    (r"l_{0}", l0),
    (r"p_{\theta}", p_theta),       # p_{theta} -> p_theta
    (r"p_x", p_x),
    (r"l_a", sp.Symbol("l_a")),     # kept with its underscore: that is the problem's name
    (r"\delta_\theta", sp.Symbol("delta_theta")),
    (r"\varphi", phi),              # \varphi is the problem's phi
    (r"\epsilon", eps),             # \epsilon is the problem's eps
    (r"\mathrm{eps}", eps),
    (r"\pi", sp.pi),
    (r"e^{t}", sp.exp(t)),           # e is Euler's number when the problem has no symbol e
    (r"M", M),
])
def test_names_map_to_the_problem(text, expected):
    assert read(text) == expected


def test_subscript_kept_when_joined_name_is_unknown():
    assert read(r"\theta_3", known=None) == sp.Symbol("theta_3")
    assert read(r"m_1", known=None) == sp.Symbol("m_1")
    assert read(r"\theta_1", known=None) == theta1  # a coordinate is recognized without known names


def test_e_is_a_symbol_when_the_problem_has_one():
    assert read("e", known=["e"]) == sp.Symbol("e")


def test_unknown_name_has_a_did_you_mean_hint():
    with pytest.raises(TextAnswerError, match=r"unknown name 'p_X'.*did you mean 'p_x'"):
        read(r"p_X")
    with pytest.raises(TextAnswerError, match="unknown name 'mu'"):
        read(r"\mu g")


# --------------------------------------------------------------------------- products and functions

def test_letter_before_parenthesis_is_a_product_not_a_function():
    assert read(r"k(r - l_0)^2") == k * (r - l0) ** 2
    assert read(r"m\left(l + g\right)") == m * (l + g)


def test_function_argument_without_parentheses_stops_at_a_derivative_or_spacing():
    assert read(r"\sin\theta\dot\theta") == sp.sin(theta) * theta.diff(t)
    assert read(r"\sin^2\theta\,\dot\phi^2") == sp.sin(theta) ** 2 * phi.diff(t) ** 2
    assert read(r"\cos{\theta} m") == sp.cos(theta) * m
    assert read(r"\sin\frac{\theta}{2} m") == sp.sin(theta / 2) * m
    assert read(r"\sin 2\theta") == sp.sin(2 * theta)
    assert read(r"\sin\theta\cos\theta") == sp.sin(theta) * sp.cos(theta)


def test_fractions_roots_and_brackets():
    assert read(r"2\pi\sqrt{\frac{l}{g}}") == 2 * sp.pi * sp.sqrt(l / g)
    assert read(r"\sqrt{l}") == sp.sqrt(l)
    assert read(r"\frac12 m") == m / 2
    assert read(r"\left[m + M\right] \cdot g") == (m + M) * g
    assert read(r"m \times g") == m * g
    assert read(r"\sqrt[3]{m}") == sp.cbrt(m)


# --------------------------------------------------------------------------- refusals

@pytest.mark.parametrize("text, message", [
    (r"\hat x", r"\\hat is not supported"),
    (r"\int x", r"\\int is not supported"),
    (r"\sum m", r"\\sum is not supported"),
    (r"\frac{\partial L}{\partial x}", r"\\partial is not supported"),
    ("k(r - l0)", r"would read as l times 0; write a subscript: l_0"),
    (r"\frac{1}{2} m x^2 + \theta2", r"write a subscript: \\theta_2"),
    ("1/2 m x^2", "ambiguous"),
    (r"\ddot\theta = -g/l \sin\theta", "ambiguous"),
    (r"x \le 2", "only equations"),
    ("x < 2", "only equations"),
    ("x = m = g", "only be used once"),
    ("2^{100000}", "too large"),
    (r"\frac{1}{2", "unbalanced braces"),
    ("$x$ + $m$", r"'\$' may only wrap"),
    (r"x!", "factorial"),
    ("", "empty"),
])
def test_refusals_are_clear(text, message):
    with pytest.raises(TextAnswerError, match=message):
        read(text)


def test_length_limit():
    with pytest.raises(TextAnswerError, match="too long"):
        read("x + " * (MAX_LATEX_CHARS // 4 + 1) + "x")


def test_slash_with_parenthesized_divisor_is_fine():
    assert read(r"m g/(l) = x") == sp.Eq(m * g / l, x)
    assert read(r"g/l") == g / l


# --------------------------------------------------------------------------- lists and routing

def test_items_separated_by_commas_or_double_backslash_make_a_list():
    expected = [sp.Eq(x.diff(t, 2), -g), sp.Eq(theta.diff(t, 2), 0)]
    assert read(r"\ddot x = -g, \ddot\theta = 0") == expected
    assert read(r"\ddot x = -g \\ \ddot\theta = 0") == expected
    assert read(r"\ddot x &= -g; \quad \ddot\theta &= 0") == expected


@pytest.mark.parametrize("text, latex", [
    (r"\frac{1}{2} m", True),
    ("$x^2$", True),
    (" $m g$ ", True),
    ("m*l^2*theta_d^2/2", False),
    ("x_dd == -g", False),
    ("2^3", False),
])
def test_is_latex(text, latex):
    assert is_latex(text) is latex


def test_toml_values_lists_and_dicts_in_latex(tmp_path):
    path = tmp_path / "answer.toml"
    path.write_text(
        "L = '\\frac{1}{2} m \\dot x^2'\n"
        "eom = ['m\\ddot x = -k x', \"x'' = -\\\\frac{k}{m} x\"]\n"
        "plain = 'm*x_dd + k*x'\n"
        "both = \"\\\\dot\\\\theta = \\\\frac{p_\\\\theta}{m l^2}, \\\\dot p_\\\\theta = -m g l \\\\sin\\\\theta\"\n"
        "solution = { x = '$l_0 \\cos(\\sqrt{k/m}\\, t)$' }\n"
        "bad = '\\frac{1}{2} m \\dot x^2 + \\hat y'\n",
        encoding="utf-8")
    values, problems = load_toml_answer(path, COORDS, KNOWN)
    assert values["L"] == m * x.diff(t) ** 2 / 2
    assert values["eom"] == [sp.Eq(m * x.diff(t, 2), -k * x), sp.Eq(x.diff(t, 2), -k * x / m)]
    assert values["plain"] == m * x.diff(t, 2) + k * x
    assert values["both"] == [sp.Eq(theta.diff(t), p_theta / (m * l**2)),
                              sp.Eq(p_theta.diff(t), -m * g * l * sp.sin(theta))]
    assert same(values["solution"]["x"], l0 * sp.cos(sp.sqrt(k / m) * t))
    assert "bad" not in values
    assert len(problems) == 1 and problems[0].line == 6 and r"\hat" in problems[0].message


# --------------------------------------------------------------------------- golden twins

LATEX_GOLDEN = sorted(ROOT.glob("tests/answers/*/correct_latex.toml"))


def test_at_least_ten_problems_have_a_latex_answer():
    assert len(LATEX_GOLDEN) >= 10


@pytest.mark.parametrize("path", LATEX_GOLDEN, ids=lambda p: p.parent.name)
def test_latex_answer_scores_as_its_python_twin(path):
    pid = path.parent.name
    latex = lagrade.check(pid, path)
    python = lagrade.check(pid, ROOT / "reference_solutions" / pid / "answer.py")
    assert not latex.problems, latex.problems
    assert latex.score == python.score == python.max_score
    assert {p.part: (p.verdict, p.score) for p in latex.parts} == \
        {p.part: (p.verdict, p.score) for p in python.parts}


def _latex_goldens():
    root = Path(__file__).resolve().parent / "answers"
    return sorted(p for p in root.glob("*/*.toml") if "\\\\" in p.read_text() or "\\" in p.read_text())


@pytest.mark.parametrize("path", _latex_goldens(), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_fast_sll_parse_reads_every_golden_latex_answer_as_the_full_parser_does(path, monkeypatch):
    """The fast reader and the SLL-first parse are only speed-ups: on every LaTeX answer we have, they
    must give what the full LL parser gives (values and problems alike)."""
    from lagrade.answer.reading import latex, latex_subset
    from lagrade.answer.reading.load import load_answer
    from lagrade.problem.library import load_problem

    problem = load_problem(path.parent.name)
    fast = load_answer(path, problem)
    monkeypatch.setattr(latex, "_parse_sll", lambda text: (_ for _ in ()).throw(ValueError("off")))
    monkeypatch.setattr(latex_subset, "read", lambda text, module: None)
    full = load_answer(path, problem)
    assert {k: str(v) for k, v in fast.values.items()} == {k: str(v) for k, v in full.values.items()}
    assert [str(p) for p in fast.problems] == [str(p) for p in full.problems]


# --------------------------------------------------------------------------- reading numbers fast

def _sympys_number(text):
    try:
        return sp.Number(text)
    except Exception as exc:  # noqa: BLE001
        return type(exc)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(text=st.one_of(st.integers(0, 10**30).map(str), st.text(alphabet="0123456789.,-e²٣ ", min_size=1, max_size=8)))
def test_the_converter_reads_a_number_as_sympy_does(text):
    module = _antlr_converter().sympy
    try:
        ours = module.Number(text)
    except Exception as exc:  # noqa: BLE001
        ours = type(exc)
    theirs = _sympys_number(text)
    assert ours == theirs and type(ours) is type(theirs)


@pytest.mark.parametrize("text", [
    r"\frac{1}{2} m_1 l^2 \dot{\theta}_1^2 + m_2 g l \cos\theta_1",
    r"\frac{3}{4} m l^{2} \dot\phi^{2} - 10 x^{12} + 0.25 k x",
    r"\sqrt{\frac{2 g}{3 l}} + 2^{10} \cdot 1000 - \frac{0}{7}",
    r"\ddot{\theta} = -\frac{3 g}{2 l}\sin\theta",
])
def test_latex_reads_the_same_with_whole_numbers_read_directly(text, monkeypatch):
    fast = read(text)
    # sympy's own reading: every number through sympy.Number, that is parse_expr
    calls = []
    monkeypatch.setattr(latex._WholeNumbersRead, "Number", lambda self, *a: calls.append(a) or self._module.Number(*a))
    slow = read(text)
    assert calls, "the converter did not read a number"
    assert fast == slow and sp.srepr(fast) == sp.srepr(slow)
