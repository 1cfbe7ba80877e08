"""The integrator as grading runs it, checked against closed forms over long runs (issue 23, §4).

Every run here goes through the objects a check uses: the scene's compiled rates
(`scene_model(mech).compiled_rates`, a `CompiledRates` of the compiled accelerations), the grading presets,
lagrade's one integrator (`lagrade.compare.dop853.DOP853`), and for contact the model's stop events
located on the dense output. A spy asserts that the integrator's steps really ran on the compiled
rates, so a broken step control, dense output or event locator fails here.

Bounds are stated per preset, about three times what this integrator measures (docs/numerics.md):
- simple pendulum (12.43) released at 0.3, 1.0 and 2.5 rad, 1000 periods of the largest swing, against
  the Jacobi-elliptic closed form: max angle error and max relative energy error;
- harmonic oscillator, 1000 periods sampled 7 times a period (the samples fall inside steps: the
  dense output is what is compared), against A cos(wt) + v0/w sin(wt);
- contact loss from the top of a sphere (12.4): the state where the multiplier vanishes, against
  cos(theta) = 2/3 cos(theta0) at release from rest, and the stop time against the quadrature;
- what accuracy costs: the evaluations a batch needs are those scipy's DOP853 needs for its hardest
  trajectory alone (a step-size control that grows or shrinks steps wrongly stays accurate, since the
  error test still rejects, but costs more).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import DOP853 as ScipyDOP853
from scipy.integrate import quad
from scipy.special import ellipj, ellipk

from lagrade.compare import dop853
from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.compare.scene_model import SceneModel, scene_model

from .helpers import custom, mechanics, params

#: preset -> (pendulum angle error, pendulum relative energy error, oscillator error / amplitude)
BOUNDS = {
    "fast": (0.1, 2e-5, 1.5e-4),
    "default": (2e-3, 3e-7, 1.5e-6),
    "strict": (2e-5, 3e-9, 1.5e-8),
}


@pytest.fixture
def steps(monkeypatch):
    """Counts the steps of the grading path's integrator (`DOP853.step`) taken on compiled rates."""
    calls = []
    original = dop853.DOP853.step

    def spy(self):
        calls.append(self.K)
        return original(self)
    monkeypatch.setattr(dop853.DOP853, "step", spy)
    return calls


def _acc(preset: str):
    return replace(ACCURACY[preset], max_rhs_evals=10**8, method="DOP853")


@pytest.mark.parametrize("preset", list(BOUNDS))
def test_pendulum_over_a_thousand_periods_matches_the_elliptic_solution(preset, steps):
    mech = mechanics("12.43")
    A = np.array([0.3, 1.0, 2.5])
    g, length = 9.8, 1.0
    P = params(mech, len(A), m=1.0, l=length, g=g)
    k = np.sin(A / 2)
    quarter = ellipk(k ** 2)
    w0 = np.sqrt(g / length)
    horizon = 1000 * (4 * quarter / w0).max()
    run = integrate(scene_model(mech).compiled_rates(P), np.array([A, np.zeros(len(A))]), horizon, _acc(preset),
                    t_eval=np.linspace(0.0, horizon, 20001))
    assert run.ok, run.message
    assert len(steps) > 1000, "the grading path's integrator did not step"
    sn = np.array([ellipj(quarter[i] - w0 * run.t, k[i] ** 2)[0] for i in range(len(A))])
    exact = 2 * np.arcsin(k[:, None] * sn)
    angle_error = np.abs(run.y[0] - exact).max()
    E = length ** 2 * run.y[1] ** 2 / 2 - g * length * np.cos(run.y[0])
    energy_error = (np.abs(E - E[:, :1]) / np.abs(E[:, :1])).max()
    angle_bound, energy_bound, _ = BOUNDS[preset]
    print(f"\n{preset}: 1000 periods, angle error {angle_error:.3g} (bound {angle_bound:g}), "
          f"energy error {energy_error:.3g} (bound {energy_bound:g}), {run.rhs_evals} evaluations")
    assert angle_error < angle_bound
    assert energy_error < energy_bound


@pytest.mark.parametrize("preset", list(BOUNDS))
def test_dense_output_between_steps_matches_the_oscillator(preset, steps):
    mech = custom({"id": "osc", "title": "harmonic oscillator",
                   "parameters": [{"name": "m"}, {"name": "k"}],
                   "systems": [{"coordinates": [{"name": "x"}], "effects": ["spring"],
                                "T": "m*x_d**2/2", "V": "k*x**2/2"}],
                   "parts": [{"name": "L", "kind": "lagrangian"}]})
    m, kk = np.array([1.0, 2.0, 0.5]), np.array([1.0, 3.0, 7.0])
    P = params(mech, 3, m=m, k=kk)
    w = np.sqrt(kk / m)
    x0, v0 = np.array([1.0, -0.5, 0.2]), np.array([0.0, 1.0, -2.0])
    horizon = 1000 * 2 * np.pi / w.min()
    t_eval = np.linspace(0.0, horizon, 7 * 1000 + 1)   # off the steps' ends: the dense output gives them
    run = integrate(scene_model(mech).compiled_rates(P), np.array([x0, v0]), horizon, _acc(preset), t_eval=t_eval)
    assert run.ok, run.message
    assert len(steps) > 1000
    exact = x0[:, None] * np.cos(w[:, None] * run.t) + (v0 / w)[:, None] * np.sin(w[:, None] * run.t)
    amplitude = np.hypot(x0, v0 / w)
    error = (np.abs(run.y[0] - exact) / amplitude[:, None]).max()
    print(f"\n{preset}: oscillator, 1000 periods, error/amplitude {error:.3g} (bound {BOUNDS[preset][2]:g}), "
          f"{run.rhs_evals} evaluations")
    assert error < BOUNDS[preset][2]


@pytest.mark.parametrize("preset", list(BOUNDS))
def test_a_batch_costs_what_scipys_dop853_costs_its_hardest_trajectory(preset, steps):
    """12.43's pendulum at five amplitudes over 20 periods of the largest swing: the batch's evaluations
    against scipy's DOP853 stepping each trajectory alone on the same compiled rates and tolerances."""
    mech = mechanics("12.43")
    A = np.array([0.1, 0.7, 1.5, 2.5, 3.0])
    P = params(mech, len(A), m=1.0, l=1.0, g=9.8)
    horizon = 20 * 4 * ellipk(np.sin(A.max() / 2) ** 2) / np.sqrt(9.8)
    acc = _acc(preset)
    y0 = np.array([A, np.zeros(len(A))])
    run = integrate(scene_model(mech).compiled_rates(P), y0, horizon, acc, t_eval=np.array([0.0, horizon]))
    assert run.ok, run.message
    assert steps, "the grading path's integrator did not step"
    alone = []
    for k in range(len(A)):
        rates_k = scene_model(mech).compiled_rates(P[:, k:k + 1])
        solver = ScipyDOP853(lambda t, y, r=rates_k: r(t, y[:, None])[:, 0], 0.0, y0[:, k], horizon,
                             rtol=acc.rtol, atol=acc.atol)
        while solver.status == "running":
            solver.step()
        assert solver.status == "finished"
        alone.append(solver.nfev)
    print(f"\n{preset}: batch {run.rhs_evals} evaluations; scipy's DOP853 alone {alone}")
    assert max(alone) > 500
    assert abs(run.rhs_evals - max(alone)) <= 0.02 * max(alone), (run.rhs_evals, alone)


@pytest.mark.parametrize("preset", ["default", "strict"])
def test_contact_loss_is_located_where_the_closed_form_says(preset):
    mech = mechanics("12.4")
    values = {"m": [1.0, 2.0, 0.5], "R": [1.0, 0.8, 1.7], "g": [9.8, 1.0, 2.0]}
    P = params(mech, 3, **values)
    R, g = np.array(values["R"]), np.array(values["g"])
    theta0 = np.array([0.05, 0.2, 0.6])
    y0 = np.array([theta0, np.zeros(3)])                     # released from rest
    model = SceneModel(mech)
    run = integrate(scene_model(mech).compiled_rates(P), y0, 20.0, _acc(preset), events=model.events(y0, P))
    hits = sorted(run.events["contact lost (lam = 0)"], key=lambda h: h[0])
    assert [k for k, _, _ in hits] == [0, 1, 2]
    for k, t, yk in hits:
        leave = np.arccos(2 / 3 * np.cos(theta0[k]))
        # time to slide from theta0 to the leaving angle, from energy: theta'^2 = 2 g/R (cos theta0 - cos theta)
        rate, c0 = 2 * g[k] / R[k], np.cos(theta0[k])
        t_exact = quad(lambda th, c0=c0, rate=rate: 1 / np.sqrt(rate * (c0 - np.cos(th))),
                       theta0[k], leave, limit=200)[0]
        assert abs(yk[0] - leave) < 1e-7, (preset, k, yk[0] - leave)
        assert abs(t - t_exact) < 1e-6 * max(t_exact, 1.0), (preset, k, t - t_exact)


def test_a_singular_chart_is_named_on_the_grading_path():
    """The spherical pendulum passing ~1e-5 rad from its pole: the run stops and names the trajectory
    and the time; it never returns a motion (nor a generic failure)."""
    mech = mechanics("12.16")
    P = params(mech, 2, m=1.0, R=1.0, g=9.8)
    y0 = np.array([[0.5, 0.8], [0.0, 0.0], [-1.0, -1.0], [1e-5, 1.0]])      # theta, phi, theta', phi'
    run = integrate(scene_model(mech).compiled_rates(P), y0, 2.0, _acc("default"))
    assert not run.ok
    assert run.message.startswith("trajectory 1 approaches a singularity at t = ")
    assert "a coordinate singularity or a collision" in run.message
