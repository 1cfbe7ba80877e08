"""The acceptance rule (checkers/admit.py): what agreement at sampled states may accept, unit by unit.

The attacks it was built against, end to end through `lagrade check`, are tests/security/verdicts/."""

from __future__ import annotations

import pytest
import sympy as sp

import lagrade
from lagrade.verdicts.checkers.admit import Refuted, linear_rows, simple_number

t = sp.Symbol("t")
m1, m2, m3, m4, g = sp.symbols("m1 m2 m3 m4 g", positive=True)
x, y, z = (sp.Function(n)(t) for n in "xyz")
S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
A = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - S / m4}


def part(result, name):
    return next(p for p in result.parts if p.part == name)


@pytest.mark.parametrize("typed, exact", [
    ("0.5", sp.Rational(1, 2)), ("0.333333333333", sp.Rational(1, 3)), ("-2.25", sp.Rational(-9, 4)),
    ("6.283185307179586", 2 * sp.pi), ("1.4142135623730951", sp.sqrt(2)), ("0", sp.S.Zero),
])
def test_a_typed_decimal_is_the_simple_number_it_rounds(typed, exact):
    assert simple_number(sp.Float(typed)) == exact


@pytest.mark.parametrize("typed", ["1.000000001", "0.3333333", "2.718281828", "1e-9"])
def test_a_float_that_is_no_simple_number_stays_inexact(typed):
    assert simple_number(sp.Float(typed)) is None


def test_a_float_with_more_digits_than_a_double_must_be_simple_to_all_of_them():
    assert simple_number(sp.Float("1." + "0" * 2900 + "1", 3000)) is None
    assert simple_number(sp.Float("0." + "5" + "0" * 40, 45)) == sp.Rational(1, 2)


def test_equations_with_other_roots_are_refuted_and_linear_ones_kept():
    a, b = sp.symbols("a b")
    u = sp.Symbol("x_dd")
    with pytest.raises(Refuted, match="allow other accelerations"):
        linear_rows([(u - a) * (u - b)], [u], "accelerations", 2.0)
    with pytest.raises(Refuted):
        linear_rows([sp.sin(u - a)], [u], "accelerations", 2.0)
    with pytest.raises(Refuted, match="multiplied by a switch"):
        linear_rows([sp.Heaviside(50 - a) * (u - a)], [u], "accelerations", 2.0)
    assert linear_rows([1 / u - 1 / a], [u], "accelerations", 2.0) == [a - u]  # cleared: one root
    assert linear_rows([3 * (u - a)], [u], "accelerations", 2.0) == [3 * (u - a)]


def test_a_result_with_the_accelerations_left_in_is_invalid():
    a = {**A, "m1": x.diff(t, 2) + y.diff(t, 2)}
    got = part(lagrade.check("12.22", a=a), "a")
    assert got.verdict == "invalid" and "still contains x''" in got.feedback, got.feedback


@pytest.mark.parametrize("wrap, construct", [
    (lambda e: sp.Max(1, m1 / 50) * e, "Max"),
    (lambda e: sp.Heaviside(50 - m2) * e, "Heaviside"),
    (lambda e: sp.Piecewise((e, t < 3), (0, True)), "Piecewise"),
    (lambda e: sp.sqrt((m1 - 50) ** 2) / (50 - m1) * e, "Abs"),   # sympy: |m1 - 50| for a real m1
    (lambda e: sp.sqrt((x.diff(t) - 50) ** 2) / (50 - x.diff(t)) * e, "root of a square"),
])
def test_a_switch_earns_nothing_without_a_proof(wrap, construct):
    got = part(lagrade.check("12.22", a={k: wrap(v) for k, v in A.items()}), "a")
    assert got.score == 0 and construct in got.feedback, got.feedback


def test_a_switch_that_is_no_switch_on_the_domain_keeps_full_marks():
    """sign and Abs of a positive mass are 1 and the mass: nothing switches where the physics lives."""
    a = {k: sp.sign(m1) * sp.Abs(m2) / m2 * v for k, v in A.items()}
    assert part(lagrade.check("12.22", a=a), "a").verdict == "correct"


def test_a_switch_proved_equal_is_accepted_as_proved():
    a = {**A, "m1": sp.Piecewise((A["m1"], m1 > 0), (0, True))}  # m1 > 0 always: proved
    got = part(lagrade.check("12.22", a=a), "a")
    assert got.verdict == "correct", got.feedback


def test_an_imaginary_part_refutes_and_one_that_cancels_does_not():
    got = part(lagrade.check("12.22", a={**A, "m1": A["m1"] + 1000 * sp.I}), "a")
    assert got.verdict == "incorrect" and "imaginary" in got.feedback
    # cos(m2)**2 + sin(m2)**2 written through exp(I*m2): the imaginary parts cancel, and nothing is divided
    # by (dividing by cos(m2) would leave it undefined at m2 = pi/2, inside the domain: refused, issue 42)
    one = (sp.exp(sp.I * m2) + sp.exp(-sp.I * m2)) ** 2 / 4 + sp.sin(m2) ** 2
    assert part(lagrade.check("12.22", a={**A, "m1": A["m1"] * one}), "a").verdict == "correct"
    pole = {**A, "m1": A["m1"] * (sp.exp(sp.I * m2) + sp.exp(-sp.I * m2)) / (2 * sp.cos(m2))}
    got = part(lagrade.check("12.22", a=pole), "a")
    assert got.verdict != "correct" and "cos(m2)" in got.feedback, got.feedback


def test_inexact_numbers_earn_nothing_and_say_how_far_they_are():
    got = part(lagrade.check("12.22", a={k: sp.Float("1.000000001") * v for k, v in A.items()}), "a")
    assert got.score == 0 and "1.0e-9 from 1" in got.feedback, got.feedback
    got = part(lagrade.check("12.22", a={k: sp.Rational(10**9 + 1, 10**9) * v for k, v in A.items()}), "a")
    assert got.score == 0 and "not a simple fraction" in got.feedback, got.feedback
    got = part(lagrade.check("12.22", a={k: v + sp.exp(-1000) * g for k, v in A.items()}), "a")
    assert got.score == 0 and "far from the size" in got.feedback, got.feedback
    nearly_one = (1 + sp.Rational(1, 10**6)) ** sp.Rational(1, 1000)   # 1 + 1e-9, from small numbers
    got = part(lagrade.check("12.22", a={k: nearly_one * v for k, v in A.items()}), "a")
    assert got.score == 0 and "without being equal" in got.feedback, got.feedback
    exact = {k: sp.sqrt(8) / (2 * sp.sqrt(2)) * v for k, v in A.items()}   # exactly 1: no flag
    assert part(lagrade.check("12.22", a=exact), "a").verdict == "correct"


def test_a_purely_imaginary_constant_refutes():
    got = part(lagrade.check("12.22", a={**A, "m1": A["m1"] + 1000 * (sp.asin(2) - sp.pi / 2)}), "a")
    assert got.verdict == "incorrect" and "imaginary" in got.feedback, got.feedback


def test_declared_drag_keeps_its_velocity_switch():
    """12.34 declares drag -c a^3 theta' |theta'|: the student's Abs(theta') is the physics, sampled on
    both sides, and the equation is graded as any other."""
    m, a, c = sp.symbols("m a c", positive=True)
    th = sp.Function("theta")(t)
    eom = [sp.Eq(th.diff(t, 2), -c * a * th.diff(t) * sp.Abs(th.diff(t)) / m)]
    got = part(lagrade.check("12.34", eom=eom), "eom")
    assert got.verdict == "correct", got.feedback


def _screen_12_14():
    from lagrade.derive.reference import Mechanics
    from lagrade.problem.library import load_problem

    problem = load_problem("12.14")
    mech = Mechanics(problem, problem.systems[0])
    return mech, next(p for p in problem.parts if p.name == "L")


def test_a_part_too_small_to_matter_anywhere_sampled_is_named_and_the_rest_is_not():
    from lagrade.verdicts.checkers.admit import _negligible

    mech, L = _screen_12_14()
    m1_, m2_, l1_, g_, th1 = sp.symbols("m1 m2 l1 g theta1")
    right = (m1_ + m2_) * g_ * l1_ * sp.cos(th1) + m1_ * l1_ ** 2 * sp.Symbol("theta1_d") ** 2 / 2
    assert _negligible(right, L, mech) == []
    tiny = g_ * l1_ * m1_ * th1 * (m1_ * m2_ / (m1_ + m2_) ** 2) ** 200
    notes = _negligible(right + tiny, L, mech)
    assert len(notes) == 1 and "changes the whole by less than 1e-05" in notes[0]
    # inside a function, where the part's own size is not small but its effect is: cos(tiny) is 1
    assert _negligible(right * sp.cos((m1_ * m2_ / (m1_ + m2_) ** 2) ** 100), L, mech)


def test_an_expression_too_long_to_weigh_needs_a_proof(monkeypatch):
    from lagrade.verdicts.checkers import admit

    mech, L = _screen_12_14()
    m1_, g_, th1 = sp.symbols("m1 g theta1")
    monkeypatch.setattr(admit, "NEGLIGIBLE_NODES", 10)
    expr = sum(sp.cos(k * th1) * m1_ * g_ / k for k in range(1, 12))
    assert admit._negligible(expr, L, mech) == [f"it is too long ({sp.count_ops(expr)} operations) to be weighed part "
                                                "by part"]
