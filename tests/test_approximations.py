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
