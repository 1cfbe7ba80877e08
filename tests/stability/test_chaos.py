"""Chaos: the double pendulum (12.14/12.15) at large amplitude.

Reason: in a chaotic motion any two integrations that differ at the level of the integration
tolerance (a correct answer written in another algebraic form rounds differently, so the adaptive
steps differ) drift apart like rtol*exp(lambda*t). Over a long horizon a correct answer would be
rejected by amplified rounding alone. The grader therefore measures the amplification along the
reference motion and compares only over the window where rtol*A(t) stays below a tenth of the
comparison tolerance; a wrong answer must still be caught inside that window.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import sympy as sp

from lagrade.compare.trajectory import ACCURACY, compare_runs
from lagrade.uses.research.lyapunov import comparison_window, finite_time_lyapunov

from .helpers import mechanics, params, reference_rates, rewritten_rates

HORIZON = 20.0   # ten times the problem file's horizon: long enough for chaos to matter


@pytest.fixture(scope="module")
def scene():
    mech = mechanics("12.14")
    K = 3
    P = params(mech, K, m1=1.0, m2=1.0, l1=1.0, l2=1.0, g=9.8)
    y0 = np.array([[2.0, 1.8, -2.0], [2.2, -1.5, 1.9], [0.0, 0.5, 0.0], [0.0, 0.0, -0.5]])  # large amplitude
    return mech, P, y0


def test_the_motion_is_chaotic_with_a_measured_positive_exponent(scene):
    """Reason: the window argument rests on a measured exponent; it must be positive here."""
    mech, P, y0 = scene
    lam = finite_time_lyapunov(reference_rates(mech, P), y0, HORIZON, replace(ACCURACY["default"], max_rhs_evals=10**6))
    assert np.all(lam > 0.5), lam


def test_a_correct_answer_in_another_form_is_rejected_without_the_window(scene):
    """Reason: shows the failure the window prevents (amplified rounding over 20 s exceeds 1e-6)."""
    mech, P, y0 = scene
    acc = replace(ACCURACY["default"], max_rhs_evals=10**6, chaos_window=False)
    cmp = compare_runs(rewritten_rates(mech, P), reference_rates(mech, P), y0, list("abcd"), HORIZON, acc)
    assert not cmp.agree


def test_a_correct_answer_in_another_form_agrees_inside_the_lyapunov_window(scene):
    """Reason: the window follows from the measured FTLE; inside it the two correct motions agree."""
    mech, P, y0 = scene
    acc = replace(ACCURACY["default"], max_rhs_evals=10**6)
    cmp = compare_runs(rewritten_rates(mech, P), reference_rates(mech, P), y0, list("abcd"), HORIZON, acc)
    assert cmp.agree, cmp.describe()
    assert cmp.ftle is not None and cmp.ftle > 0.5
    assert 0.5 < cmp.window < HORIZON
    assert "Lyapunov" in cmp.describe()
    # the same window from the Benettin exponent, within a factor 2 (an equivalent argument)
    lam = finite_time_lyapunov(reference_rates(mech, P), y0, cmp.window, acc).max()
    assert 0.5 * cmp.window < comparison_window(lam, acc) < 2.5 * cmp.window


@pytest.mark.parametrize("mistake", [{"g": 1.001}, {"m2": 1.01}])
def test_a_wrong_answer_is_still_caught_inside_the_window(scene, mistake):
    """Reason: the window must not hide mistakes: a 0.1 % error in g separates well before it ends."""
    mech, P, y0 = scene
    (name, factor), = mistake.items()
    sym = sp.Symbol(name)
    acc = replace(ACCURACY["default"], max_rhs_evals=10**6)
    wrong = rewritten_rates(mech, P, perturb={sym: factor * sym})
    cmp = compare_runs(wrong, reference_rates(mech, P), y0, list("abcd"), HORIZON, acc)
    assert not cmp.agree
    assert cmp.separation_time < cmp.window
