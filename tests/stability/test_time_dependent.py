"""Time-dependent scenes: 12.20 (moving origin), 12.24 (driven support), 12.47 (accelerated support),
12.49 (string pulled in).

Reason: where the Lagrangian depends on t explicitly, H = sum(p q') - L is not conserved; a model that
dropped the time dependence would conserve it. And a model is valid only on its interval (12.49: while
the string length l0 - k t is positive): sampled times stay inside it, and integrating past its end is
reported as a singularity, not continued with a negative length.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.problem.library import load_problem
from lagrade.compare.scene_model import SceneModel
from lagrade.compare.sampling import rng_for, sample_points, state_arrays

from .helpers import mechanics, reference_rates

ACC = replace(ACCURACY["default"], max_rhs_evals=10**5)


def _H_along(mech, horizon=None):
    pts = sample_points(mech, 4, rng_for(mech.problem.id, "H-along"))
    q, qd, _, P = state_arrays(mech, pts)
    n = len(mech.names)
    model = SceneModel(mech)
    horizon = horizon or mech.system.horizon
    run = integrate(model.rates(P), np.concatenate([q, qd]), horizon, ACC)
    assert run.ok, run.message
    H = []
    for i, t in enumerate(run.t):
        Y = run.y[..., i]
        tt = np.full(Y.shape[1], t)
        H.append(mech.hamiltonian(Y[:n], mech.momenta(Y[:n], Y[n:], tt, P), tt, P))
    return np.array(H).T, model


@pytest.mark.parametrize("pid", ["12.20", "12.24", "12.47", "12.49"])
def test_H_is_not_conserved_where_it_should_not_be(pid):
    mech = mechanics(pid)
    H, model = _H_along(mech)
    assert model.time_arg
    variation = np.ptp(H, axis=1) / np.maximum(np.abs(H).max(axis=1), 1.0)
    assert np.all(variation > 1e-4), variation


def test_H_is_conserved_in_an_autonomous_scene_for_contrast():
    H, model = _H_along(mechanics("12.43"))
    assert not model.time_arg
    assert np.all(np.ptp(H, axis=1) < 1e-8 * np.maximum(np.abs(H).max(axis=1), 1.0))


def test_sampled_times_keep_the_pulled_string_positive():
    """12.49: every (l0, k, t) the grader samples has l0 - k*t > 0 (worst case of the ranges)."""
    problem = load_problem("12.49")
    rng = {p.name: p.sample for p in problem.parameters}
    worst = rng["l0"][0] - rng["k"][1] * problem.systems[0].horizon
    assert worst > 0.1
    mech = mechanics("12.49")
    pts = sample_points(mech, 2000, rng_for("12.49", "valid"))
    _, _, t, P = state_arrays(mech, pts)
    names = [str(p) for p in mech.params]
    assert np.all(P[names.index("l0")] - P[names.index("k")] * t > 0)


def test_integrating_past_the_end_of_the_string_is_reported():
    """Past t = l0/k the length would be negative; the rates blow up as it reaches 0, and the run
    stops there with a message instead of continuing."""
    mech = mechanics("12.49")
    names = [str(p) for p in mech.params]
    P = np.array([[{"m": 1.0, "l0": 1.0, "k": 0.3, "g": 9.8}[n]] for n in names])
    y0 = np.array([[0.5], [0.0]])
    run = integrate(reference_rates(mech, P), y0, 10.0, ACC)      # the string is gone at t = 3.33
    assert not run.ok
    assert "singularity" in run.message or "more than" in run.message or "failed" in run.message
