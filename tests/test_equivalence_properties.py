"""Invariants of equivalence: what physics allows must never cost a mark, and changes must be caught.

Property-based: hypothesis draws the total derivative, the factors, the order and the combinations.
"""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import lagrade

t = sp.Symbol("t")
m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
L_REF = ((m1 + m2) / 2 * l1**2 * w1**2 + m2 / 2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * sp.cos(th1 - th2)
         + (m1 + m2) * g * l1 * sp.cos(th1) + m2 * g * l2 * sp.cos(th2))
EOM_REF = [
    (m1 + m2) * l1 * th1.diff(t, 2) + m2 * l2 * (th2.diff(t, 2) * sp.cos(th1 - th2) + w2**2 * sp.sin(th1 - th2))
    + (m1 + m2) * g * sp.sin(th1),
    l2 * th2.diff(t, 2) + l1 * (th1.diff(t, 2) * sp.cos(th1 - th2) - w1**2 * sp.sin(th1 - th2)) + g * sp.sin(th2),
]
SETTINGS = settings(max_examples=8, deadline=None, suppress_health_check=list(HealthCheck), derandomize=True)
small = st.integers(-3, 3)


def verdict(**parts) -> str:
    result = lagrade.check("12.14", **parts)
    return result.verdicts()[next(iter(parts))]


@SETTINGS
@given(st.lists(small, min_size=4, max_size=4).filter(any))
def test_total_time_derivative_added_to_L_is_correct(c):
    F = c[0] * th1 * th2 + c[1] * sp.sin(th1) * t + c[2] * th2**2 + c[3] * m1 * sp.cos(th2)
    assert verdict(L=L_REF + F.diff(t) + 7) == "correct"


@SETTINGS
@given(st.sampled_from([2, -1, sp.Rational(1, 2), 3 * m1]))
def test_scaled_L_earns_partial_credit(c):
    r = lagrade.check("12.14", L=sp.expand(c * L_REF))
    assert r.verdicts()["L"] == "partial"
    assert "scaled" in r.parts[0].feedback


@SETTINGS
@given(st.sampled_from([0, 1]), st.sampled_from([sp.Integer(-2), m2, 1 + sp.cos(th1) ** 2, l1 * (3 + sp.sin(th2))]),
       small, st.booleans())
def test_equations_in_any_order_factor_and_combination(first, factor, k, swap_sides):
    rows = [sp.expand(factor * EOM_REF[0]), EOM_REF[1]]
    rows[1] = rows[1] + k * rows[0]
    if first:
        rows.reverse()
    eqs = [sp.Eq(0, -r) if swap_sides else r for r in rows]
    assert verdict(eom_exact=eqs) == "correct"


@SETTINGS
@given(st.integers(0, 4), st.sampled_from([sp.Rational(11, 10), sp.Rational(1, 2), -1, 2]))
def test_one_term_of_L_changed_is_caught(index, factor):
    terms = list(sp.Add.make_args(sp.expand(L_REF)))
    terms[index % len(terms)] *= factor
    assert verdict(L=sp.Add(*terms)) == "incorrect"


@SETTINGS
@given(st.integers(0, 1), st.sampled_from([sp.Rational(101, 100), -1, 0]))
def test_one_term_of_an_equation_changed_is_caught(row, factor):
    rows = list(EOM_REF)
    terms = list(sp.Add.make_args(sp.expand(rows[row])))
    terms[0] *= factor
    rows[row] = sp.Add(*terms)
    assert verdict(eom_exact=rows) in {"partial", "incorrect"}


def test_hamiltonian_plus_a_constant_is_correct_plus_a_function_of_time_is_not():
    """H is the energy up to a constant (issue 42): H + sin(t) gives the same Hamilton's equations, but its
    value is not the energy, so it is refused; H + 3 is right."""
    m, l = sp.symbols("m l", positive=True)
    th, p = sp.Function("theta")(t), sp.Function("p_theta")(t)
    H = p**2 / (2 * m * l**2) - m * g * l * sp.cos(th)
    assert lagrade.check("12.43", H=H + 3).verdicts()["H"] == "correct"
    assert lagrade.check("12.43", H=H + sp.sin(t) + 3).verdicts()["H"] == "incorrect"
    assert lagrade.check("12.43", H=2 * H).verdicts()["H"] == "incorrect"


@pytest.mark.parametrize("accuracy", ["fast", "default", "strict"])
def test_a_lagrangian_scaled_by_a_constant_near_1_is_a_scaled_lagrangian_under_every_preset(accuracy):
    """L times (1000001/1000000)**(1/100) (1 + 1e-8, issue 42's example) gives the same motion and the wrong
    momenta: the scaled-L credit, proved in exact arithmetic, whatever the preset's tolerance; never full."""
    m1, m2, l1, l2 = sp.symbols("m1 m2 l1 l2", positive=True)
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    w1, w2 = th1.diff(t), th2.diff(t)
    L = ((m1 + m2) / 2 * l1**2 * w1**2 + m2 / 2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * sp.cos(th1 - th2)
         + (m1 + m2) * g * l1 * sp.cos(th1) + m2 * g * l2 * sp.cos(th2))
    got = next(p for p in lagrade.check("12.14", accuracy=accuracy,
                                        L=L * sp.Rational(1000001, 1000000) ** sp.Rational(1, 100)).parts if p.part == "L")
    assert got.verdict == "partial" and got.score == 0.5 and "scaled" in got.feedback, got.feedback

