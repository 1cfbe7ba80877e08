"""Two-version questions (issue 33): where the book asks a quantity in two versions ("(a) using theta ...
(b) using y"), each version is its own part; both right is full marks, one version right and the other
wrong (or absent) is not, and a value bound to the shared catalogue name counts for the version it is
written in.

The answers graded here are derived below with sympy from the chapter's statements (Example 12.6 and
Exercise 12.6, Problems 12.5, 12.6, 12.39-12.40), not read from problems/ or reference_solutions/: a
wrong reference in a problem file fails the "both right" test.
"""

from __future__ import annotations

import pytest
import sympy as sp

import lagrade
from lagrade.problem.library import load_problem

t = sp.Symbol("t")


def _euler_lagrange(L, q):
    return sp.diff(sp.diff(L, q.diff(t)), t) - sp.diff(L, q)


def _hamilton(L, qs, moms):
    """Hamilton's equations of L by the Legendre transform, as Eq(q', dH/dp), Eq(p', -dH/dq)."""
    v = [sp.Symbol(f"v{i}") for i in range(len(qs))]
    P = [sp.Symbol(f"P{i}") for i in range(len(qs))]
    X = [sp.Symbol(f"X{i}") for i in range(len(qs))]
    Lv = L.subs({q.diff(t): vi for q, vi in zip(qs, v)}).subs(dict(zip(qs, X)))
    sol = sp.solve([sp.Eq(Pi, sp.diff(Lv, vi)) for Pi, vi in zip(P, v)], v, dict=True)[0]
    H = sp.simplify((sum(Pi * vi for Pi, vi in zip(P, v)) - Lv).subs(sol))
    back = {**dict(zip(X, qs)), **dict(zip(P, moms))}
    eqs = [sp.Eq(q.diff(t), sp.diff(H, Pi).subs(back)) for q, Pi in zip(qs, P)]
    eqs += [sp.Eq(p.diff(t), (-sp.diff(H, Xi)).subs(back)) for p, Xi in zip(moms, X)]
    return eqs


def ex12_6() -> dict:
    """Example 12.6: T = M y'^2/2 + I theta'^2/2, I = M R^2/2, rolling y = R theta, V = M g (l - y) sin(phi)."""
    M, R, g, l, phi = sp.symbols("M R g l phi", positive=True)
    theta0, w0, y0, v0 = sp.symbols("theta0 w0 y0 v0")
    theta, y = sp.Function("theta")(t), sp.Function("y")(t)

    def L_of(yy, th):
        return M * yy.diff(t) ** 2 / 2 + M * R**2 / 4 * th.diff(t) ** 2 - M * g * (l - yy) * sp.sin(phi)

    out = {}
    for key, q, L, ics in [("a", theta, L_of(R * theta, theta), {theta0: None, w0: None}),
                           ("b", y, L_of(y, y / R), {y0: None, v0: None})]:
        eq = sp.Eq(_euler_lagrange(L, q), 0)
        x0, xd0 = list(ics)
        motion = sp.dsolve(eq, q, ics={q.subs(t, 0): x0, q.diff(t).subs(t, 0): xd0}).rhs
        out[f"L_{key}"], out[f"eom_{key}"] = L, [eq]
        out[f"solution_{key}"] = {q.func.__name__: motion}
    assert sp.simplify(out["solution_b"]["y"] - (y0 + v0 * t + g * sp.sin(phi) * t**2 / 3)) == 0
    return out


def p12_5() -> dict:
    """Problem 12.5: gravity along the inclines, l2 = l - l1; with l a coordinate, the tension S does -S*dl."""
    m1, m2, g, alpha, beta, S_t = sp.symbols("m1 m2 g alpha beta S_t")
    l1, l = sp.symbols("l1 l")
    V = -m1 * g * sp.sin(alpha) * l1 - m2 * g * sp.sin(beta) * (l - l1)
    work_of_tension = {l1: 0, l: -S_t}  # -S (dl1 + dl2) = -S dl
    Q_a = {q.name: sp.simplify(-sp.diff(V, q) + work_of_tension[q]) for q in (l1, l)}
    Q_b = {"l1": sp.simplify(-sp.diff(V, l1))}
    return {"Q_a": Q_a, "Q_b": Q_b}


def p12_6() -> dict:
    """Problem 12.6: r = R (cos theta, sin theta), Q_q = F . dr/dq; s = R theta."""
    R, F_x, F_y = sp.symbols("R F_x F_y")
    s, theta = sp.Function("s")(t), sp.Function("theta")(t)
    d_s, d_theta = sp.symbols("delta_s delta_theta")

    def Q(angle, q):
        r = sp.Matrix([R * sp.cos(angle), R * sp.sin(angle)])
        return sp.simplify(sp.Matrix([F_x, F_y]).dot(r.diff(q)))

    Q_s, Q_theta = Q(s / R, s), Q(theta, theta)
    return {"Q_a": {"s": Q_s}, "dW_a": Q_s * d_s, "Q_b": {"theta": Q_theta}, "dW_b": Q_theta * d_theta}


def p12_40() -> dict:
    """Problems 12.39-12.40: a central V(r); the rotating frame phip = phi - omega t, and the fixed one."""
    m, omega = sp.symbols("m omega", positive=True)
    V = sp.Function("V")
    r, phi, phip = (sp.Function(n)(t) for n in ("r", "phi", "phip"))
    p_r, p_phi, p_phip = (sp.Function(n)(t) for n in ("p_r", "p_phi", "p_phip"))
    L_fixed = m * (r.diff(t) ** 2 + r**2 * phi.diff(t) ** 2) / 2 - V(r)
    L_rot = L_fixed.subs(phi, phip + omega * t).doit()
    return {"hamilton": _hamilton(L_rot, [r, phip], [p_r, p_phip]),
            "hamilton_fixed": _hamilton(L_fixed, [r, phi], [p_r, p_phi])}


def _wrong(value):
    """The same answer with a factor 2 (and, for equations, a term t) in it: wrong in every version."""
    if isinstance(value, dict):
        return {k: 2 * v for k, v in value.items()}
    if isinstance(value, list):
        return [sp.Eq(e.lhs, 2 * e.rhs + t) if isinstance(e, sp.Eq) else 2 * e + t for e in value]
    return 2 * value


#: problem id -> (derivation, the versions' parts (a), (b), the shared names {version part: catalogue name})
CASES = {
    "ex12.6": (ex12_6, ["L_a", "eom_a", "solution_a"], ["L_b", "eom_b", "solution_b"],
               {"L_a": "L", "eom_a": "eom", "solution_a": "solution", "L_b": "L", "eom_b": "eom",
                "solution_b": "solution"}),
    "12.5": (p12_5, ["Q_a"], ["Q_b"], {"Q_a": "Q", "Q_b": "Q"}),
    "12.6": (p12_6, ["Q_a", "dW_a"], ["Q_b", "dW_b"], {"Q_a": "Q", "dW_a": "dW", "Q_b": "Q", "dW_b": "dW"}),
    "12.40": (p12_40, ["hamilton"], ["hamilton_fixed"], {"hamilton": "hamilton", "hamilton_fixed": "hamilton"}),
}


def _scores(pid: str, values: dict) -> dict:
    return {p.part: (p.verdict, p.score, p.max_score) for p in lagrade.check(pid, **values).parts}


@pytest.mark.parametrize("pid", CASES)
def test_both_versions_right_is_full_marks_on_those_parts(pid):
    derive, a, b, _ = CASES[pid]
    values = derive()
    got = _scores(pid, values)
    assert all(got[n][0] == "correct" for n in a + b), got


@pytest.mark.parametrize("pid", CASES)
@pytest.mark.parametrize("wrong_side", ["a", "b"])
def test_one_version_wrong_is_not_full_marks(pid, wrong_side):
    derive, a, b, _ = CASES[pid]
    values = derive()
    bad = a if wrong_side == "a" else b
    for name in bad:
        values[name] = _wrong(values[name])
    got = _scores(pid, values)
    assert all(got[n][0] == "correct" for n in (b if wrong_side == "a" else a)), got
    assert all(got[n][0] != "correct" and got[n][1] < got[n][2] for n in bad), got


@pytest.mark.parametrize("pid", CASES)
@pytest.mark.parametrize("side", ["a", "b"])
def test_one_version_under_the_shared_name_gets_that_versions_credit_only(pid, side):
    derive, a, b, shared = CASES[pid]
    values = derive()
    given = a if side == "a" else b
    other = b if side == "a" else a
    got = _scores(pid, {shared[n]: values[n] for n in given})
    problem = load_problem(pid)
    assert all(got[n][0] == "correct" for n in given), got
    assert all(got[n][0] == "missing" for n in other), got
    assert sum(got[n][1] for n in given + other) == sum(problem.part(n).weight for n in given)


def test_a_shared_name_is_read_by_its_coordinates():
    from lagrade.answer.reading.load import version_for

    problem = load_problem("12.5")
    assert version_for(problem, "Q", {"l1": 1}) == "Q_b"
    assert version_for(problem, "Q", {"l1": 1, "l": 2}) == "Q_a"
    assert version_for(problem, "Q", {"l1": 1}, taken={"Q_b"}) is None  # bound by its own name: that wins
    six = load_problem("12.6")
    assert version_for(six, "dW", sp.Symbol("delta_s") * sp.sin(sp.Function("theta")(t))) == "dW_a"


# --- two versions everywhere alike (issue 44 item 7) -------------------------------------------------


def test_1230_cartesian_equations_bound_to_eom_are_the_cartesian_version():
    """12.30 asks the equations in both Cartesian and polar coordinates: Cartesian ones bound to the
    catalogue's `eom` are graded as eom_xy (not refused with a derivative message), and the polar
    version is missing with the note every two-version id gives."""
    m, omega = sp.symbols("m omega", positive=True)
    x, y = sp.Function("x")(t), sp.Function("y")(t)
    along_the_wire = m * (x.diff(t, 2) * sp.cos(omega * t) + y.diff(t, 2) * sp.sin(omega * t))
    got = {p.part: p for p in lagrade.check("12.30", eom=[along_the_wire, x * sp.sin(omega * t) - y * sp.cos(omega * t)]).parts}
    assert got["eom_xy"].verdict == "correct", got["eom_xy"].feedback
    assert got["eom"].verdict == "missing" and "the problem asks both versions" in got["eom"].feedback


def test_1239_a_missing_version_says_the_problem_asks_both():
    m = sp.Symbol("m", positive=True)
    r, p_r, p_phi = sp.Function("r")(t), sp.Function("p_r")(t), sp.Function("p_phi")(t)
    V = sp.Function("V")
    fixed = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r**2) + V(r)
    got = {p.part: p for p in lagrade.check("12.39", H=fixed).parts}
    assert got["H"].verdict == "correct", got["H"].feedback
    assert got["H_p"].verdict == "missing" and "the problem asks both versions" in got["H_p"].feedback


@pytest.mark.parametrize("pid", ["ex12.6", "12.5", "12.6", "12.30", "12.39", "12.40"])
def test_every_missing_version_says_the_problem_asks_both(pid):
    """An empty answer: each version of each two-version question is 'not answered', and says the
    problem asks both versions (whether or not the shared name went to the other one)."""
    problem = load_problem(pid)
    versions = [p for p in problem.parts if p.version_of is not None]
    assert versions, f"{pid} has no two-version question"
    got = {p.part: p for p in lagrade.check(pid).parts}
    for part in versions:
        said = got[part.name].feedback
        assert said.startswith("not answered") and "the problem asks both versions" in said, said
