"""Functions the book leaves general (V(r), U(xp, yp)): declared by a problem, written by answers, and
graded by putting several random smooth functions in their place (issue 21 §2)."""

from __future__ import annotations

import math

import pytest
import sympy as sp
from pydantic import ValidationError

from lagrade.derive import general_functions as gf
from lagrade.verdicts.grade import check
from lagrade.problem.notation import TextAnswerError, parse_math
from lagrade.problem.spec import GeneralFunction, Problem

t = sp.Symbol("t")
m, omega, k = sp.symbols("m omega k", positive=True)
r_, p_r, p_phip, p_phi = sp.symbols("r p_r p_phip p_phi")
V = sp.Function("V")
H_ROT = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r_**2) - omega * p_phip  # H' without its potential


def verdicts(pid: str, **parts) -> dict[str, str]:
    res = check(pid, grading_seconds=math.inf, **parts)
    return {p.part: p.verdict for p in res.parts if p.verdict != "missing"}


# --------------------------------------------------------------------------- substitutes

def test_random_functions_are_reproducible_and_differ_between_instances():
    f = GeneralFunction(name="V", args=["r"], concrete="k*r**2/2")
    first, again, other = gf.random_function(f, 1), gf.random_function(f, 1), gf.random_function(f, 2)
    assert first == again  # the disk cache of references relies on it
    assert first != other
    x = sp.Symbol("r")
    assert sp.diff(first(x), x, 2) != 0  # not linear: a wrong factor on V' cannot hide


def test_every_way_of_writing_a_derivative_gets_the_same_function():
    lam = gf.random_function(GeneralFunction(name="V", args=["r"], concrete="0"), 1)
    r, u = sp.Function("r")(t), sp.Symbol("u")
    want = sp.diff(lam(r_), r_).subs(r_, 1.3)
    forms = [sp.Derivative(V(r), r), V(r).diff(r), sp.Subs(sp.Derivative(V(u), u), u, r),
             V(r).diff(t) / r.diff(t)]
    for form in forms:
        got = gf.substitute(form, {"V": lam})
        assert not got.has(V), form
        assert float(got.subs(r, 1.3)) == pytest.approx(float(want)), form


def test_partial_derivatives_of_a_function_of_two_coordinates():
    U = sp.Function("U")
    lam = gf.random_function(GeneralFunction(name="U", args=["xp", "yp"], concrete="0"), 1)
    x, y = sp.Function("xp")(t), sp.Function("yp")(t)
    a, b = sp.symbols("a b")
    X, Y = sp.symbols("xp yp")
    at = {X: 0.4, Y: -0.7}
    for form, var in ((U(x, y).diff(x), X), (sp.Subs(sp.Derivative(U(a, b), b), (a, b), (x, y)), Y)):
        got = gf.substitute(form, {"U": lam}).subs({x: 0.4, y: -0.7})
        assert float(got) == pytest.approx(float(sp.diff(lam(X, Y), var).subs(at)))


# --------------------------------------------------------------------------- the problem file

def _problem(**system) -> dict:
    base = {"coordinates": [{"name": "r"}], "T": "m*r_d**2/2", "V": "V(r)",
            "functions": [{"name": "V", "args": ["r"], "concrete": "k*r**2/2"}]}
    return {"id": "x", "title": "x", "parameters": [{"name": "m"}, {"name": "k"}],
            "systems": [{**base, **system}], "parts": [{"name": "H", "kind": "hamiltonian"}]}


def test_a_problem_declares_its_functions_of_its_coordinates():
    assert Problem.model_validate(_problem()).systems[0].functions[0].args == ["r"]
    with pytest.raises(ValidationError, match="distinct coordinates"):
        Problem.model_validate(_problem(functions=[{"name": "V", "args": ["s"], "concrete": "0"}]))
    with pytest.raises(ValidationError, match="both a function and a parameter"):
        Problem.model_validate(_problem(functions=[{"name": "k", "args": ["r"], "concrete": "0"}]))


def test_text_reads_calls_and_derivatives_of_declared_functions_only():
    r = sp.Function("r")(t)
    got = parse_math("p_r_d == -diff(V(r), r) + Derivative(V(r), r, 2)", ["r"], functions={"V": 1})
    assert got == sp.Eq(sp.Symbol("p_r_d"), -sp.Derivative(V(r), r) + sp.Derivative(V(r), (r, 2)))
    with pytest.raises(TextAnswerError, match="unknown function 'V'"):
        parse_math("V(r)", ["r"], known_names=["m"])
    with pytest.raises(TextAnswerError, match="takes 1 argument"):
        parse_math("V(r, r)", ["r"], functions={"V": 1})
    with pytest.raises(TextAnswerError, match="is a function of the coordinates"):
        parse_math("V + 1", ["r"], functions={"V": 1})
    primed = parse_math("-V'(r) + V''(r)", ["r"], functions={"V": 1})
    lam = sp.Lambda(r_, r_**3)
    assert gf.substitute(primed, {"V": lam}) == -3 * r**2 + 6 * r
    assert parse_math("{'xp': V'(r)}", ["r"], functions={"V": 1})["xp"].has(sp.Subs)
    with pytest.raises(TextAnswerError):
        parse_math("V'(r)", ["r"])  # no general function V: primes are not text notation


# --------------------------------------------------------------------------- grading

def test_the_general_form_is_right_and_the_stated_one_a_special_case():
    """Issue 33: the stated V = k r^2/2 is a special case of the general V(r) the book asks: partial."""
    assert verdicts("12.39", H=H_ROT + V(r_), H_p=H_ROT + k * r_**2 / 2) == {"H": "correct", "H_p": "partial"}


@pytest.mark.parametrize("potential", [-V(r_), 2 * V(r_), V(r_) + k * r_**2 / 2, V(r_)**2, sp.Derivative(V(r_), r_)])
def test_a_wrong_use_of_the_function_stays_wrong(potential):
    assert verdicts("12.39", H=H_ROT + potential)["H"] == "incorrect"


def test_an_answer_right_for_one_function_only_is_wrong(monkeypatch):
    """A potential term equal to V when V is the first substitute, and not otherwise: with one
    substitute it passes (so the construction is right), with the several the grader uses it fails."""
    lam = gf.random_function(GeneralFunction(name="V", args=["r"], concrete="k*r**2/2"), 1)
    lucky = H_ROT + lam(r_) + (V(r_) - lam(r_))**2
    monkeypatch.setattr("lagrade.verdicts.checkers.general.INSTANCES", 1)
    assert verdicts("12.39", H=lucky)["H"] == "correct"
    monkeypatch.undo()
    res = check("12.39", grading_seconds=math.inf, H=lucky)
    (part,) = [p for p in res.parts if p.part == "H"]
    assert part.verdict == "incorrect" and "some of them, not for all" in part.feedback


def test_hamilton_equations_with_the_general_force():
    r, phip = sp.Function("r")(t), sp.Function("phip")(t)
    pr, pp = sp.Function("p_r")(t), sp.Function("p_phip")(t)

    def eqs(force):
        return [sp.Eq(r.diff(t), pr / m), sp.Eq(phip.diff(t), pp / (m * r**2) - omega),
                sp.Eq(pr.diff(t), pp**2 / (m * r**3) + force), sp.Eq(pp.diff(t), 0)]

    assert verdicts("12.40", hamilton=eqs(-V(r).diff(r)))["hamilton"] == "correct"
    assert verdicts("12.40", hamilton=eqs(-k * r))["hamilton"] == "partial"  # the stated V: a special case
    assert verdicts("12.40", hamilton=eqs(V(r).diff(r)))["hamilton"] == "partial"
    assert verdicts("12.40", hamilton=eqs(-V(r)))["hamilton"] == "partial"
    assert verdicts("12.40", hamilton=eqs(0))["hamilton"] == "partial"  # right for V = 0: a special case


def test_an_unknown_bare_name_of_a_function_says_how_to_write_it():
    res = check("12.39", grading_seconds=math.inf, H=H_ROT + sp.Symbol("V"))
    (part,) = [p for p in res.parts if p.part == "H"]
    assert part.verdict == "invalid" and "V(r)" in part.feedback


def test_feedback_on_a_general_answer_names_no_substitute():
    res = check("12.39", grading_seconds=math.inf, H=H_ROT - V(r_), H_p=H_ROT + V(r_))
    for part in res.parts:
        assert "exp" not in part.feedback and "sin" not in part.feedback


# --------------------------------------------------------------------------- LaTeX, show, cache

def test_latex_reads_calls_primes_and_leibniz_derivatives_of_a_declared_function():
    from lagrade.answer.reading.latex import parse_latex_answer

    r = sp.Function("r")(t)
    F = {"V": 1}
    assert parse_latex_answer(r"\frac{p_r^2}{2m} + V(r)", ["r", "p_r"], None, F) == \
        sp.Function("p_r")(t)**2 / (2 * sp.Symbol("m")) + V(r)
    for tex in (r"V'(r)", r"V^{\prime}(r)", r"\frac{dV(r)}{dr}"):
        got = parse_latex_answer(tex, ["r"], None, F)
        lam = sp.Lambda(r_, r_**3)
        assert gf.substitute(got, {"V": lam}) == 3 * r**2, tex
    assert parse_latex_answer("m(a+b)", ["r"], None, F) == sp.Symbol("m") * (sp.Symbol("a") + sp.Symbol("b"))
    assert parse_latex_answer("V(r)", ["r"], None) == sp.Symbol("V") * r  # undeclared: a product, as before


@pytest.mark.parametrize("text", ["V'(r)", "V''(r) + 2", r"\mathit{ZQC} = \frac{p}{m r^3} - V'(r)", "V'(r) V'(s)",
                                  "x' + 1", "V' (r)", r"\alpha'(r)"])
def test_the_fast_latex_reader_reads_a_primed_call_as_sympy_does(text):
    from test_latex_subset import assert_same_or_declined

    assert_same_or_declined(text)


def test_show_and_template_name_the_function():
    from lagrade.problem.describe import show_text, template_text
    from lagrade.problem.library import load_problem

    problem = load_problem("12.26")
    assert "function  U(xp, yp)" in show_text(problem)
    assert 'U = Function("U")' in template_text(problem)


def test_substitute_scenes_survive_the_disk_cache_format():
    import pickle

    from lagrade.verdicts.grade import references
    from lagrade.problem.library import load_problem

    problem = load_problem("12.40")
    refs = references(problem)
    mech = refs.instance("Sp", 2)
    back = pickle.loads(pickle.dumps(refs))
    assert back.systems["Sp\0" + "2"].functions == mech.functions
    assert mech.L != refs["Sp"].L and not mech.L.has(V)


def test_a_call_with_the_wrong_arguments_is_invalid_with_the_reason():
    phi = sp.Symbol("phi")
    res = check("12.39", grading_seconds=math.inf, H=H_ROT + V(r_, phi))
    (part,) = [p for p in res.parts if p.part == "H"]
    assert part.verdict == "invalid" and "takes 1 argument" in part.feedback


def test_the_substitute_scenes_are_the_books_physics():
    """The derivation with a random V, against an independent Legendre transform of the book's L with
    the same V (sympy alone): H' = p_r^2/2m + p_phip^2/(2 m r^2) - omega p_phip + V(r)."""
    from lagrade.verdicts.grade import references
    from lagrade.problem.library import load_problem

    mech = references(load_problem("12.39")).instance("Sp", 3)
    lam = gf.random_function(GeneralFunction(name="V", args=["r"], concrete="0"), 3)
    rd, phipd = sp.symbols("r_d phip_d")
    L = m * (rd**2 + r_**2 * (phipd + omega)**2) / 2 - lam(r_)
    sol = sp.solve([sp.Eq(p_r, sp.diff(L, rd)), sp.Eq(p_phip, sp.diff(L, phipd))], [rd, phipd], dict=True)[0]
    H = p_r * sol[rd] + p_phip * sol[phipd] - L.subs(sol)
    plain = {s: sp.Symbol(s.name) for s in H.free_symbols}
    assert sp.simplify(mech.hamiltonian_symbolic - H.xreplace(plain)) == 0


# --- special cases of a general function (issue 33) -------------------------------------------------

def _special_cases():
    """(problem, part, answer, the case it is right for) on the four ids with a general function: each
    answer is derived here from the chapter's set-up with the function replaced by the special case."""
    xp, yp = sp.Function("xp")(t), sp.Function("yp")(t)
    x, p_x = sp.Function("x")(t), sp.Function("p_x")(t)
    w, kk = sp.symbols("omega k")
    U = sp.Function("U")

    def L_rotating(potential):  # 12.26: a particle in the frame rotating at omega, T from the fixed frame's
        X = xp * sp.cos(w * t) - yp * sp.sin(w * t)
        Y = xp * sp.sin(w * t) + yp * sp.cos(w * t)
        return sp.expand(m * (X.diff(t) ** 2 + Y.diff(t) ** 2) / 2) - potential

    H_line = p_x**2 / (2 * m)  # 12.36: V = 0
    return [
        ("12.26", "L", L_rotating(0), "U = 0"),
        ("12.26", "L", L_rotating(kk * (xp**2 + yp**2) / 2), "U = k*(xp**2 + yp**2)/2"),
        ("12.36", "H", H_line, "V = 0"),
        ("12.39", "H_p", H_ROT + k * r_**2 / 2, "V = k*r**2/2"),
        ("12.39", "H_p", H_ROT, "V = 0"),
    ], [("12.26", "L", L_rotating(U(xp, yp))), ("12.36", "H", H_line + sp.Function("V")(x)),
        ("12.39", "H_p", H_ROT + V(r_))]


SPECIAL, GENERAL = _special_cases()


@pytest.mark.parametrize("pid, part, value, case", SPECIAL, ids=[f"{p}-{n}-{c}" for p, n, _, c in SPECIAL])
def test_a_special_case_earns_what_the_statement_promises(pid, part, value, case):
    """Issue 44: where the book names no force (12.26, 12.36) the answer is checked for the force it
    states, and right is right; where it names a general one (12.39) a special case is partial, with a note."""
    graded = {p.part: p for p in check(pid, grading_seconds=math.inf, **{part: value}).parts}[part]
    if pid in ("12.26", "12.36"):
        assert graded.verdict == "correct" and graded.score == graded.max_score, graded.feedback
        assert f"Checked for the force your answer states ({case})" in graded.feedback
        return
    assert graded.verdict == "partial" and 0 < graded.score < graded.max_score, graded.feedback
    assert f"Right for {case}" in graded.feedback and "asks for a general" in graded.feedback


@pytest.mark.parametrize("pid, part, value", GENERAL, ids=[f"{p}-{n}" for p, n, _ in GENERAL])
def test_the_same_answer_with_the_general_function_is_right(pid, part, value):
    """The guard of the test above: the special cases come from a right general answer."""
    graded = {p.part: p for p in check(pid, grading_seconds=math.inf, **{part: value}).parts}[part]
    assert graded.verdict == "correct", graded.feedback


def test_an_answer_the_function_does_not_enter_is_right_without_it():
    """12.39's H' - H = -omega p_phip has no V in it: not a special case, full credit."""
    assert verdicts("12.39", H_diff=-omega * sp.Symbol("p_phip"))["H_diff"] == "correct"
