"""A formulation that earns part of the credit (`Alternative.credit`): 12.41(b)'s pendulum motion, asked
without the small-angle approximation (issue 33). The exact motion is the chapter's pendulum released
from rest at theta0 = 2 rad, computed here from the closed form in Jacobi's sn with mpmath, not from
lagrade's own integration."""

from __future__ import annotations

import mpmath as mp
import numpy as np
import pytest
import sympy as sp

import lagrade

t = sp.Symbol("t")
G, L, THETA0 = 9.81, 1.0, 2.0


def _exact(times):
    k = np.sin(THETA0 / 2)
    K, w = float(mp.ellipk(k**2)), np.sqrt(G / L)
    return [2 * float(mp.asin(k * mp.ellipfun("sn", K - w * s, m=k**2))) for s in times]


def _motion(**parts):
    return next(p for p in lagrade.check("12.41", **parts).parts if p.part == "motion_b")


def test_the_exact_motion_is_full_marks():
    times = np.linspace(0.0, 4.0, 17)
    got = _motion(motion_b={"t": list(times), "theta": _exact(times)})
    assert got.verdict == "correct" and got.score == got.max_score, got.feedback


def test_the_small_angle_motion_earns_half_and_says_what_it_assumes():
    got = _motion(motion_b={"theta": THETA0 * sp.cos(sp.sqrt(sp.Rational(981, 100)) * t)})
    assert got.verdict == "partial" and got.score == pytest.approx(got.max_score / 2), got.feedback
    assert "small amplitudes" in got.feedback and "approximation" in got.feedback


def test_a_motion_right_in_neither_earns_nothing():
    got = _motion(motion_b={"theta": THETA0 * sp.cos(3 * t)})
    assert got.verdict == "incorrect" and got.score == 0, got.feedback


# --- issue 44 §2: the book asks the pendulum "solved", not small angles --------------------------------

def _reference(*leave_out: str) -> dict:
    import runpy

    from lagrade.problem.library import reference_dir

    ns = runpy.run_path(str(reference_dir() / "12.41" / "answer.py"))
    return {p.name: ns[p.name] for p in lagrade.load_problem("12.41").parts
            if p.name in ns and p.name not in leave_out}


def test_the_small_angle_solution_is_an_extra():
    parts = {p.name: p for p in lagrade.load_problem("12.41").parts}
    assert parts["solution_b"].extra and not parts["motion_b"].extra


def test_the_books_exact_answer_gets_full_marks_and_more_than_small_angles():
    """The exact motion without the small-angle solution is the book's whole answer: full marks; the
    small-angle motion in its place earns less (half of motion_b), however right solution_b is."""
    times = np.linspace(0.0, 4.0, 17)
    exact = lagrade.check("12.41", **_reference("solution_b", "motion_b"),
                          motion_b={"t": list(times), "theta": _exact(times)})
    assert exact.full_marks and exact.score == exact.max_score, str(exact)
    small = lagrade.check("12.41", **_reference("motion_b"),
                          motion_b={"theta": THETA0 * sp.cos(sp.sqrt(sp.Rational(981, 100)) * t)})
    assert small.score < exact.score


@pytest.mark.parametrize("form", ["table", "times", "rows"])
def test_an_exact_motion_bound_to_solution_b_is_graded_as_motion_b(form):
    """The catalogue names the trajectory `solution_b`: the exact motion at motion_b's numbers bound to
    it answers motion_b, and the book's whole answer written so gets full marks."""
    times = np.linspace(0.0, 4.0, 17)
    value = {"table": {"t": list(times), "theta": _exact(times)},
             "times": dict(zip([float(s) for s in times], _exact(times))),
             "rows": [[float(s), v] for s, v in zip(times, _exact(times))]}[form]
    res = lagrade.check("12.41", **_reference("solution_b", "motion_b"), solution_b=value)
    got = {p.part: p for p in res.parts}
    assert got["motion_b"].verdict == "correct", got["motion_b"].feedback
    assert "solution_b" in got["motion_b"].feedback
    assert got["solution_b"].verdict == "missing"
    assert res.full_marks


def test_a_symbolic_solution_b_stays_solution_b_and_motion_b_keeps_its_own_value():
    sol = {"theta": sp.Symbol("theta0") * sp.cos(sp.sqrt(sp.Symbol("g") / sp.Symbol("l")) * t)}
    got = {p.part: p for p in lagrade.check("12.41", solution_b=sol).parts}
    assert got["solution_b"].verdict == "correct" and got["motion_b"].verdict == "missing"
    times = np.linspace(0.0, 4.0, 17)
    wrong = {"t": list(times), "theta": [0.0] * len(times)}
    got = {p.part: p for p in lagrade.check("12.41", solution_b=wrong, motion_b={"t": list(times),
                                                                                "theta": _exact(times)}).parts}
    assert got["motion_b"].verdict == "correct" and got["solution_b"].verdict != "correct"
