"""Dissipation: 12.34 (quadratic air drag), 12.35 (drag and friction), and dry Coulomb friction.

Reason: with dissipative forces only, the energy must decrease monotonically along every motion
(dE/dt = Q.q' <= 0). Forces written with |q'| or sign(q') are not smooth at zero speed: integrating
across the kink forces tiny steps, and for dry friction the motion may stick. The model replaces each
|v| and sign(v) by a branch sign, locates v = 0 by an event, and restarts on the right branch (or
sticks when static friction holds), so the step size never has to resolve the kink.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.compare.scene_model import SceneModel

from .helpers import custom, mechanics, params

ACC = replace(ACCURACY["default"], max_rhs_evals=10**5, method="DOP853")


@pytest.mark.parametrize("pid", ["12.34", "12.35"])
def test_energy_decreases_monotonically(pid):
    mech = mechanics(pid)
    K = 4
    values = dict(m=[1.0, 2.0, 0.5, 1.0], a=[1.0, 0.5, 2.0, 1.0], c=[0.5, 1.0, 2.0, 0.2])
    if pid == "12.35":
        values["mu"] = [0.1, 0.5, 1.0, 0.3]
    P = params(mech, K, **values)
    y0 = np.array([[0.0, 1.0, -2.0, 0.5], [2.0, -1.5, 0.3, -0.2]])   # both directions of motion
    model = SceneModel(mech)
    assert model.machinery.switching == ("theta_d",)
    run = integrate(model.rates(P), y0, 3.0, ACC, events=model.events(y0, P), samples=601)
    assert run.ok
    thd = run.y[1]
    E = 0.5 * np.array(values["m"])[:, None] * (np.array(values["a"])[:, None] * thd) ** 2
    assert np.all(np.diff(E, axis=1) < 0)
    # the speed decays like 1/t and never reaches zero: no branch change was needed
    assert run.events["sign change of theta_d"] == []


#: the same dry friction written as a problem author (or a student) may write it
COULOMB_FORMS = {
    "sign": "-mu*m*g*sign(x_d)",
    "v/|v|": "-mu*m*g*x_d/Abs(x_d)",
    "|v|/v": "-mu*m*g*Abs(x_d)/x_d",
}   # Heaviside and Piecewise forms (not in the problem-file notation) are in tests/test_effects.py


def _coulomb(form: str = "sign"):
    return custom({"id": "12.99", "title": "block on a spring with dry friction",
                   "parameters": [{"name": "m"}, {"name": "k"}, {"name": "mu", "sample": [0.1, 0.3]}, {"name": "g"}],
                   "systems": [{"effects": ["spring", "gravity", "dissipation_friction"], "T": "m*x_d**2/2",
                                "V": "k*x**2/2", "Q": {"x": COULOMB_FORMS[form]},
                                "coordinates": [{"name": "x"}]}],
                   "parts": [{"name": "L", "kind": "lagrangian"}]})


def _closed_form_rest(x0, d):
    """Each half swing ends |2d| closer to the centre (d = mu m g / k); it sticks once |x| <= d."""
    x = x0
    while abs(x) > d:
        x = -(x - np.sign(x) * 2 * d)
    return x


@pytest.mark.parametrize("form", list(COULOMB_FORMS))
def test_dry_friction_sign_change_is_an_event_and_sticking_matches_the_closed_form(form):
    mech = _coulomb(form)
    K = 3
    P = params(mech, K, m=1.0, k=10.0, mu=[0.2, 0.1, 0.3], g=9.8)
    y0 = np.array([[1.0, -0.8, 2.0], [0.0, 0.0, 0.0]])
    model = SceneModel(mech)
    acc = replace(ACC, rtol=1e-12, atol=1e-12)
    run = integrate(model.rates(P), y0, 10.0, acc, events=model.events(y0, P), samples=2001)
    assert run.ok
    for k, mu in enumerate([0.2, 0.1, 0.3]):
        rest = _closed_form_rest(y0[0, k], mu * 9.8 / 10)
        assert abs(run.y[0, k, -1] - rest) < 1e-9
    E = 0.5 * run.y[1] ** 2 + 5.0 * run.y[0] ** 2
    assert np.all(np.diff(E, axis=1) <= 1e-12)
    assert run.rhs_evals < 3000, run.rhs_evals


def test_without_the_event_the_kink_costs_tiny_steps():
    """Reason: shows what the event saves: integrating sign(v) directly chatters around v = 0 once the
    block should stick, and exhausts the budget (or needs many times the evaluations)."""
    mech = _coulomb()
    P = params(mech, 3, m=1.0, k=10.0, mu=[0.2, 0.1, 0.3], g=9.8)
    y0 = np.array([[1.0, -0.8, 2.0], [0.0, 0.0, 0.0]])
    y0 = np.array([[1.0, -0.8, 2.0], [0.1, -0.1, 0.2]])
    model = SceneModel(mech)
    with_events = integrate(model.rates(P), y0, 10.0, ACC, events=model.events(y0, P))
    raw = SceneModel(mech)   # branches never armed: the exact sign(v) at every evaluation
    plain = integrate(raw.rates(P), y0, 10.0, ACC)
    assert (not plain.ok) or plain.rhs_evals > 5 * with_events.rhs_evals
