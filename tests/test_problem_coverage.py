"""Every problem keeps its contract: golden answers exist, and the two routes to the motion agree.

For every conservative, time-independent scene, Lagrange's equations and Hamilton's equations (by
the numerical Legendre transform) must give the same q(t) from the same initial state: a check of
the derivation that does not go through any hand-written answer.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem, problem_ids
from lagrade.compare.sampling import rng_for, sample_points, state_arrays
from lagrade.problem.symbols import T

ROOT = Path(__file__).resolve().parents[1]
IDS = problem_ids()


def test_every_chapter_id_is_covered():
    expected = {f"12.{n}" for n in range(1, 51)} | {f"ex12.{n}" for n in range(1, 9)}
    assert expected <= set(IDS)


@pytest.mark.parametrize("pid", IDS)
def test_golden_answers_and_reference_exist(pid):
    answers = ROOT / "tests" / "answers" / pid
    assert (ROOT / "reference_solutions" / pid / "answer.py").is_file()
    assert len(list(answers.glob("correct_*"))) >= 2, "at least two equivalent rewrites"
    assert len(list(answers.glob("wrong_*"))) >= 3, "at least three typical mistakes"


def _conservative_systems():
    for pid in IDS:
        problem = load_problem(pid)
        for system in problem.systems:
            mech = references(problem)[system.key]
            if all(q == 0 for q in mech.Q) and T not in mech.L.free_symbols and mech.is_quadratic_in_velocities:
                yield pytest.param(pid, system.key, id=f"{pid}{'-' + system.key if system.key else ''}")


@pytest.mark.parametrize("pid, key", list(_conservative_systems()))
def test_lagrange_and_hamilton_routes_give_the_same_motion(pid, key):
    problem = load_problem(pid)
    mech = references(problem)[key]
    n = len(mech.names)
    pts = sample_points(mech, 3, rng_for(pid, key, "routes"))
    q, qd, _, params = state_arrays(mech, pts)
    p = mech.momenta(q, qd, np.zeros(pts.K), params)
    acc = ACCURACY["default"]
    horizon = min(mech.system.horizon, 1.0)

    def lagrange(t, y):
        return np.concatenate([y[n:], mech.accelerations(y[:n], y[n:], np.full(y.shape[1], t), params)])

    def hamilton(t, y):
        return mech.hamilton_rates(y[:n], y[n:], np.full(y.shape[1], t), params)

    a = integrate(lagrange, np.concatenate([q, qd]), horizon, acc)
    b = integrate(hamilton, np.concatenate([q, p]), horizon, acc)
    assert a.ok and b.ok, (a.message, b.message)
    assert np.allclose(a.y[:n], b.y[:n], rtol=1e-6, atol=1e-7), "q(t) differs between the two routes"
