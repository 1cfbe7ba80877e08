"""Words that say what was found (issue 45, item 4): a refusal's advice fits its reasons, a refusal says
whether it is certified, and an undeclared friction switch in an eom is named, not blamed on the motion."""

from __future__ import annotations

import json

import pytest
import sympy as sp

import lagrade

t = sp.Symbol("t")
m1, m2, m3, m4, g = sp.symbols("m1 m2 m3 m4 g", positive=True)
S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
A = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - S / m4}
ADVICE = "Write it as one formula, with exact numbers"


def _part(result, name):
    return next(p for p in result.parts if p.part == name)


def _json_part(result, name):
    return next(p for p in json.loads(result.model_dump_json())["parts"] if p["part"] == name)


def _H(extra=0, factor=1):
    th, p = sp.Function("theta")(t), sp.Function("p_theta")(t)
    m, ell = sp.symbols("m l", positive=True)
    return factor * p ** 2 / (2 * m * ell ** 2) - m * g * ell * sp.cos(th) + extra


@pytest.fixture
def without_the_exact_judge(monkeypatch):
    """These answers are in the exact judge's class (`lagrade.compare.exact`), which proves them wrong
    first (certified: true); the refusals' own words are tested with it off, as for an answer outside it."""
    from lagrade.compare import exact

    monkeypatch.setattr(exact, "is_zero", lambda *a, **k: None)
    monkeypatch.setattr(exact, "is_zero_given", lambda *a, **k: None)


@pytest.mark.parametrize("H", [_H(factor=sp.Float("1.000000001")), _H(extra=g * sp.exp(-10 ** 4 * (
        sp.Function("theta")(t) - sp.Rational(1, 3)) ** 2) / 1000)], ids=["inexact number", "narrow bump"])
def test_the_exact_judge_proves_them_wrong_first_and_says_what_the_screen_saw(H):
    got = _json_part(lagrade.check("12.43", H=H), "H")
    assert got["verdict"] == "incorrect" and got["method"] == "exact" and got["certified"] is True, got
    assert "exact arithmetic" in got["feedback"] and ("not exact" in got["feedback"] or "less than" in got["feedback"])


def test_a_refusal_by_the_numbers_rule_says_certified_false_and_asks_for_exact_numbers(without_the_exact_judge):
    """12.43's H with 1.000000001 in it: refused by the numbers rule, whose ``certified`` was null."""
    got = _json_part(lagrade.check("12.43", H=_H(factor=sp.Float("1.000000001"))), "H")
    assert got["verdict"] == "incorrect" and "not exact" in got["feedback"], got["feedback"]
    assert got["certified"] is False, got   # a refusal proves nothing wrong, and says so
    assert "exactly" in got["feedback"] and "one formula" not in got["feedback"], got["feedback"]


def test_a_refusal_by_the_negligible_rule_says_certified_false_and_no_advice_about_numbers(without_the_exact_judge,
                                                                                            monkeypatch):
    """12.43's H with a narrow bump (issue 45's family): refused by the negligible-part rule; its numbers
    are exact and it is one formula. (As grading runs its motion refutes it first, confirmed:
    tests/test_motion_refutes_bumps.py; off here, to read the rule's own words.)"""
    from lagrade.verdicts.checkers import admit

    monkeypatch.setattr(admit, "smooth_pending", lambda: False)
    th = sp.Function("theta")(t)
    m, ell = sp.symbols("m l", positive=True)
    bump = m * g * ell * sp.exp(-10 ** 4 * (th - sp.Rational(1, 3)) ** 2) / 1000
    got = _json_part(lagrade.check("12.43", H=_H(extra=bump)), "H")
    assert got["verdict"] == "incorrect" and "changes the whole by less than" in got["feedback"], got["feedback"]
    assert got["certified"] is False, got
    assert ADVICE not in got["feedback"] and "exact numbers" not in got["feedback"], got["feedback"]


def test_a_switch_that_is_one_formula_with_exact_numbers_is_not_told_to_become_one():
    """12.43's Hamilton's equations with an undeclared sign(p): one formula, exact numbers; the refusal
    names the switch and does not tell the student to write "one formula, with exact numbers"."""
    th, p = sp.Function("theta")(t), sp.Function("p_theta")(t)
    m, ell = sp.symbols("m l", positive=True)
    H = p ** 2 / (2 * m * ell ** 2) - m * g * ell * sp.cos(th)
    ham = [sp.Eq(th.diff(t), H.diff(p)), sp.Eq(p.diff(t), -H.diff(th) - sp.sign(p) / 10)]
    got = _part(lagrade.check("12.43", hamilton=ham), "hamilton")
    assert got.verdict == "incorrect" and "dry friction" in got.feedback, got.feedback
    assert ADVICE not in got.feedback and "exact numbers" not in got.feedback, got.feedback
    assert got.certified is False


def test_an_undeclared_friction_switch_in_an_eom_is_named_not_blamed_on_the_motion():
    """Its motion sticks and chatters, which no integrator follows: the eom read "changes too fast to be
    followed" while the Hamilton part named the switch (commit 49b1cd3); both name it now."""
    th = sp.Function("theta")(t)
    ell = sp.Symbol("l", positive=True)
    eom = sp.Eq(th.diff(t, 2), -g / ell * sp.sin(th) - 3 * g / ell * sp.sign(th.diff(t)))
    got = _part(lagrade.check("12.43", eom=eom), "eom")
    assert got.verdict == "incorrect"
    assert "too fast" not in got.feedback, got.feedback
    assert "a velocity-dependent switch (dry friction) that this problem does not have" in got.feedback, got.feedback
