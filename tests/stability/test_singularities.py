"""Coordinate singularities: spherical pendulum at theta = 0, polar r = 0.

Reason: at theta = 0 (spherical) or r = 0 (polar) the mass matrix is singular and the angle's rate is
unbounded; sampled states must stay away from them (every problem file's ranges are checked), and an
integration that approaches one must be reported, not returned as a plausible but wrong motion.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.problem.library import load_problem, problem_ids
from lagrade.numbers.numeric import compile_exprs
from lagrade.derive.reference import Mechanics
from lagrade.compare.sampling import rng_for, sample_points, state_arrays
from lagrade.compare.scene_model import scene_model

from .helpers import mechanics, params, reference_rates


@pytest.mark.parametrize("pid", problem_ids())
def test_sampled_states_avoid_singular_mass_matrices(pid):
    """Reason: the grader's random states (and trajectory starts) must not sit on a singularity:
    the normalized determinant det(M)/prod(diag M) (1 for a diagonal M, 0 at a singularity) of the
    mass matrix stays clear of 0, and no diagonal entry (e.g. m r^2, m R^2 sin^2 theta) vanishes."""
    problem = load_problem(pid)
    for system in problem.systems:
        mech = Mechanics(problem, system)
        n = len(mech.names)
        pts = sample_points(mech, 400, rng_for(pid, system.key, "singular"))
        q, qd, t, P = state_arrays(mech, pts)
        M = compile_exprs(list(mech.mass), mech.args)(*q, *qd, t, *P).reshape(n, n, -1)
        diag = np.abs(np.einsum("iik->ik", M))
        scale = np.abs(M).max(axis=(0, 1))
        assert np.all(diag.min(axis=0) > 1e-3 * scale), f"{pid}{system.key}: a sampled state is near a singularity"
        det = np.abs(np.linalg.det(M.transpose(2, 0, 1)))
        assert np.all(det / np.prod(diag, axis=0) > 1e-4), f"{pid}{system.key}: a sampled state is near a singularity"


def test_a_spherical_pendulum_heading_for_the_pole_is_reported():
    """Reason: with a tiny azimuthal velocity the bob passes within ~1e-5 rad of theta = 0, where
    phi' = p_phi/(m R^2 sin^2 theta) grows ~1e8-fold: the run must stop and say so."""
    mech = mechanics("12.16")
    P = params(mech, 1, m=1.0, R=1.0, g=9.8)
    y0 = np.array([[0.5], [0.0], [-1.0], [1e-5]])      # theta, phi, theta', phi'
    for rates in (reference_rates(mech, P), scene_model(mech).compiled_rates(P)):   # numpy, and the grading path
        run = integrate(rates, y0, 2.0, replace(ACCURACY["default"], max_rhs_evals=10**5))
        assert not run.ok
        assert run.message.startswith("trajectory 1 approaches a singularity at t = "), run.message


def test_a_spherical_pendulum_that_stays_clear_is_integrated_faithfully():
    """Reason: the guard must not fire on an ordinary motion: energy and p_phi stay conserved."""
    mech = mechanics("12.16")
    P = params(mech, 1, m=1.0, R=1.0, g=9.8)
    y0 = np.array([[0.8], [0.0], [-1.0], [1.0]])
    run = integrate(reference_rates(mech, P), y0, 2.0, replace(ACCURACY["default"], max_rhs_evals=10**5))
    assert run.ok
    th, thd, phd = run.y[0, 0], run.y[2, 0], run.y[3, 0]
    p_phi = np.sin(th) ** 2 * phd
    E = (thd ** 2 + np.sin(th) ** 2 * phd ** 2) / 2 - 9.8 * np.cos(th)
    assert np.ptp(p_phi) < 1e-8 and np.ptp(E) < 1e-7


def test_a_central_force_orbit_falling_into_r_zero_is_reported():
    """Reason: polar r = 0 (a radial plunge in an attractive 1/r potential, 12.48's field) is a collision
    singularity: reported, never integrated through."""
    mech = mechanics("12.48")
    P = params(mech, 1, m=1.0, k=1.0, a=0.1)
    y0 = np.array([[1.0], [0.0], [-0.5], [1e-4]])      # r, theta, r', theta': almost radial, falling in
    for rates in (reference_rates(mech, P), scene_model(mech).compiled_rates(P)):   # numpy, and the grading path
        run = integrate(rates, y0, 5.0, replace(ACCURACY["default"], max_rhs_evals=10**5))
        assert not run.ok
        assert run.message.startswith("trajectory 1 approaches a singularity at t = 0.76"), run.message
