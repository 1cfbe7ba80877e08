"""Long runs: energy over 10^4 periods of a conservative scene (12.43, the simple pendulum).

Reason: a symplectic method (Stormer-Verlet) conserves a modified energy exactly, so its energy error
stays bounded (it oscillates, it does not grow) however long the run; an adaptive non-symplectic method
such as the grader's default DOP853 lets it drift. Measured and printed here (pytest -s shows it):
the symplectic error over 10^4 periods, and the default's drift rate (measured over 300 periods, since
10^4 periods of adaptive DOP853 would take minutes) extrapolated to 10^4 periods, and bounded.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy.special import ellipk

from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.compare.scene_model import SceneModel
from lagrade.uses.research.symplectic import StormerVerlet

from .helpers import mechanics, params

AMPLITUDES = np.array([0.5, 2.0])
G, L = 9.8, 1.0


def _period(theta0):
    return 4 * np.sqrt(L / G) * ellipk(np.sin(theta0 / 2) ** 2)


def _energy(theta, thd):
    return L ** 2 * thd ** 2 / 2 - G * L * np.cos(theta)


@pytest.fixture(scope="module")
def mech():
    return mechanics("12.43")


def test_symplectic_energy_error_stays_bounded_over_ten_thousand_periods(mech, record_property):
    P = params(mech, 2, m=1.0, l=L, g=G)
    T = _period(AMPLITUDES).max()
    h = T / 24
    steps = int(1e4 * T / h)
    run = StormerVerlet(mech).run(AMPLITUDES[None, :], np.zeros((1, 2)), P, h, steps, record_every=8)
    E = _energy(run.q[0], run.p[0] / L ** 2)
    rel = np.abs(E - E[:, :1]) / np.abs(E[:, :1])
    tenth = rel.shape[1] // 10
    first, last = rel[:, :tenth].max(axis=1), rel[:, -tenth:].max(axis=1)
    print(f"\nStormer-Verlet, h = T/24, 10^4 periods: max relative energy error first 10% {first}, last 10% {last}")
    record_property("symplectic_energy_error", float(rel.max()))
    assert np.all(rel.max(axis=1) < 0.1)   # h = T/24 is coarse; the point is that it does not grow
    assert np.all(last <= 1.05 * first)        # bounded: no secular growth


def test_default_integrator_energy_drift_is_bounded(mech, record_property):
    """The drift of the grader's DOP853 at its default rtol 1e-10 is measured (printed) and bounded:
    under 2.5e-10 of the energy per period, under 7e-8 over 300 periods (about three times what
    it measures); tests/stability/test_grading_path.py bounds it over 1000 periods on the grading path."""
    P = params(mech, 2, m=1.0, l=L, g=G)
    periods = 300
    horizon = periods * _period(AMPLITUDES).max()
    model = SceneModel(mech)
    acc = replace(ACCURACY["default"], max_rhs_evals=10**6, method="DOP853")
    run = integrate(model.rates(P), np.array([AMPLITUDES, [0.0, 0.0]]), horizon, acc, samples=301)
    assert run.ok
    E = _energy(run.y[0], run.y[1])
    err = (E - E[:, :1]) / np.abs(E[:, :1])
    slope = np.polyfit(np.arange(err.shape[1]) * periods / (err.shape[1] - 1), err.T, 1)[0]
    print(f"\nDOP853 rtol 1e-10 over {periods} periods: relative energy error at the end {err[:, -1]}, "
          f"drift {slope} per period, extrapolated to 10^4 periods {slope * 1e4}")
    record_property("dop853_drift_per_period", [float(s) for s in slope])
    assert np.all(np.abs(slope) < 2.5e-10)
    assert np.all(np.abs(err).max(axis=1) < 7e-8)
