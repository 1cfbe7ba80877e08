"""Contact loss: 12.4 (particle on a hoop), 12.33 (sphere on a sphere), 12.23 (ladder leaving the wall).

Reason: the constrained equations stay smooth past the point where the normal force changes sign, so
integrating through it gives a motion that is silently unphysical. The model of a scene that declares
unilateral_contact stops each trajectory where its multiplier (the constraint force) reaches zero,
located by event root-finding on the dense output; the angle found must agree with the closed form
to 1e-9 (it does to ~1e-13 at rtol 1e-12).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.compare.scene_model import SceneModel

from .helpers import mechanics, params

ACC = replace(ACCURACY["strict"], rtol=1e-12, atol=1e-12, max_rhs_evals=10**5, method="DOP853")


@pytest.mark.parametrize("pid", ["12.4", "12.33"])
def test_leaving_a_sphere_at_cos_theta_two_thirds(pid):
    mech = mechanics(pid)
    K = 3
    values = dict(m=[1.0, 2.0, 0.5], R=[1.0, 0.8, 1.7], g=[9.8, 1.0, 2.0])
    if pid == "12.33":
        values["r_s"] = [0.3, 0.1, 0.5]
    P = params(mech, K, **values)
    radius = np.array(values["R"]) + np.array(values.get("r_s", 0.0))
    theta0 = np.array([1e-3, 0.05, 0.2])    # released from (near) rest at the top: speed from energy
    y0 = np.array([theta0, 2 * np.sqrt(np.array(values["g"]) / radius) * np.sin(theta0 / 2)])
    model = SceneModel(mech)
    run = integrate(model.rates(P), y0, 5.0, ACC, events=model.events(y0, P))
    hits = run.events["contact lost (lam = 0)"]
    assert sorted(k for k, _, _ in hits) == [0, 1, 2]        # every trajectory leaves, once
    for k, t, yk in hits:
        assert abs(yk[0] - np.arccos(2 / 3)) < 1e-9
        assert run.t_stop[k] == t
    # the trajectory is frozen after leaving: no integration of the unphysical continuation
    assert np.all(np.diff(run.y[0, 0, run.t > run.t_stop[0]]) == 0)


def test_ladder_leaves_the_wall_at_sin_theta_two_thirds_of_the_start():
    mech = mechanics("12.23")
    K = 3
    P = params(mech, K, M=[1.0, 2.0, 0.7], l=[1.0, 1.5, 3.0], g=[9.8, 1.0, 2.5])
    theta0 = np.array([1.2, 0.9, 1.45])
    y0 = np.array([theta0, np.zeros(K)])           # released from rest
    model = SceneModel(mech)
    run = integrate(model.rates(P), y0, 5.0, ACC, events=model.events(y0, P))
    wall = run.events["contact lost (lam_w = 0)"]
    assert sorted(k for k, _, _ in wall) == [0, 1, 2]
    assert run.events["contact lost (lam_f = 0)"] == []       # the floor keeps pushing until then
    for k, _, yk in wall:
        assert abs(yk[0] - np.arcsin(2 * np.sin(theta0[k]) / 3)) < 1e-9


def test_scenes_without_contact_compile_no_event():
    """Reason: event functions cost an evaluation of the multipliers per step; only contact needs them."""
    for pid in ["12.43", "12.14", "12.7"]:
        mech = mechanics(pid)
        P = params(mech, 1, **{str(p): 1.0 for p in mech.params})
        assert SceneModel(mech).events(np.ones((2 * len(mech.names), 1)) * 0.3, P) == []
