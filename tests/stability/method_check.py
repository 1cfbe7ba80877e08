"""The integrator's order, step control, stage times, guard and events, checked in about a second
before the suite runs.

Every test of the stability suite leans on lagrade's DOP853 being DOP853. Two kinds of fault make it
*slow* rather than wrong, and a slow integrator hangs the suite instead of failing it (issue 34, item
4c): a one-coefficient error in the tableau (the error estimate no longer cancels to 8th order, so the
controller shrinks the steps until it believes the error: 70 x the evaluations of 12.43 at the default
tolerance for a change of 1e-4 in one stage coefficient), and a step-size control that never shrinks a
rejected step (it retries the same step for ever). `check_the_method` catches both in milliseconds:

- **cost**: pendulums at three amplitudes, 5 periods of the largest swing, at rtol 1e-6, 1e-9 and
  1e-12, must finish within 1.1 x the evaluations scipy's DOP853 (its own tableau and controller) takes
  for the hardest of them alone (the batch takes exactly that; `tests/stability/test_grading_path.py`
  holds it within 2 %). The budget stops a broken run at once;
- **the same motion**: the same runs end within 10 x rtol of scipy's. The integrator is scipy's
  DOP853 step for step (`tests/test_dop853.py`), so they agree to rounding amplified by the motion
  (measured: 0.04 x rtol at 1e-6, 0.05 x and 0.7 x at 1e-9 and 1e-12), while other steps at the
  same tolerance end up to 1.7e3 x rtol away (a safety factor of 0.8 instead of 0.9; the pendulum at
  2.8 rad amplifies errors). So a tableau error that keeps the cost but loses the order (a weight of
  the solution, which the error estimate does not see: 1e-6 more on one of them ends 4.5e-6 to 1e-2
  away) fails, and so does a change of the step control that changes the steps;
- **step control**: one oversized trial step (to the end of the interval) is rejected and the next
  trial is shorter;
- **stage times** (`check_the_time_dependence`, issue 45): the suite's scenes are autonomous, where
  the stage times c_s are never read. y' = w cos(w t) y in 8, 16 and 32 equal steps must converge to
  exp(sin(w t)) with order >= 6 (measured 7.8 and 6.9; a c_s 1e-3 off: 1 to 3), and the same cost and
  end states as scipy's DOP853 as above;
- **the singularity guard** (`check_the_guard`): it sees no rejected trial's end (a trial over the
  whole interval reaches rates of 2e3 where the pendulums' stay below 6.2), and a decay switched to a
  100 x faster branch, whose first trial there is oversized, is integrated to the end by `integrate`;
- **events** (`check_the_events`): x = cos(w t) reaches 0 at pi / (2 w) with v = -w, found to 1e-9
  (measured ~1e-13): a state interpolated at a wrong fraction of its step, a root finder stopped
  early or a dense output one power off is off by 1e-6 to 0.3.

``scripts/mutate_integrator.py`` applies twelve such faults to a copy of the source and shows each
one fails the suite (docs/numerics.md, "Mutations").

`tests/stability/conftest.py` runs it once per session before any stability test (every test of the
suite then errors at once with its message); `test_method.py` is the same check as a test of its own.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import DOP853 as ScipyDOP853

from lagrade.compare.dop853 import DOP853, solve

AMPLITUDES = np.array([0.3, 1.5, 2.8])
PERIODS = 5.0
TOLERANCES = (1e-6, 1e-9, 1e-12)
#: the batch's evaluations against scipy's hardest trajectory alone (measured: equal)
COST_MARGIN = 1.1


def _pendulums(t, Y):
    return np.stack([Y[1], -9.8 * np.sin(Y[0])])


def _scipy_columns(fun_k, y0: np.ndarray, t_end: float, rtol: float):
    """Per column k: scipy's DOP853 alone on ``fun_k(k)``, its evaluations (the most of them) and end states."""
    nfev, ends = [], []
    for k in range(y0.shape[1]):
        s = ScipyDOP853(fun_k(k), 0.0, y0[:, k], t_end, rtol=rtol, atol=rtol)
        while s.status == "running":
            s.step()
        assert s.status == "finished", s.status
        nfev.append(s.nfev)
        ends.append(s.y)
    return max(nfev), np.array(ends).T


def _same_as_scipy(fun, fun_k, y0: np.ndarray, t_end: float, what: str) -> list[str]:
    """The cost and end states of `solve` against scipy's DOP853 alone, at every tolerance."""
    problems = []
    for rtol in TOLERANCES:
        cost, ends = _scipy_columns(fun_k, y0, t_end, rtol)
        budget = int(COST_MARGIN * cost)
        run = solve(fun, 0.0, y0, t_end, rtol=rtol, atol=rtol, t_eval=np.array([t_end]), max_evals=budget)
        if run.status != 0:
            problems.append(f"rtol {rtol:g}: {what} need more than {budget} evaluations ({COST_MARGIN} x the "
                            f"{cost} of scipy's DOP853 for the hardest alone): the method lost its order or "
                            f"its step control ({run.message})")
            continue
        diff = float(np.abs(run.y[:, :, -1] - ends).max())
        if diff > 10 * rtol:
            problems.append(f"rtol {rtol:g}: {what} end {diff:.2g} away from scipy's DOP853 (more than 10 x "
                            f"rtol): the method lost its order, or its steps are not DOP853's")
    return problems


#: y' = w cos(w t) y, y = y0 exp(sin(w t)): the rates depend on t, so the stage times c_s count
GROWTH_W = np.array([0.5, 1.0, 2.0])
GROWTH_Y0 = np.array([[1.0, 2.0, 0.5]])
#: fixed steps over [0, 6] whose errors must fall at least 2^ORDER_FLOOR-fold per halving (measured:
#: 2^7.8 and 2^6.9 for 8 -> 16 -> 32 steps; DOP853 is of order 8; a stage time 1e-3 off drops it to 1-3)
ORDER_STEPS = (8, 16, 32)
ORDER_FLOOR = 6.0


def _growth(t, Y):
    return GROWTH_W * np.cos(GROWTH_W * t) * Y


def _fixed_steps(n: int, t_end: float) -> np.ndarray:
    """The batch after n equal steps (every one taken, whatever the error estimate says)."""
    sol = DOP853(_growth, 0.0, GROWTH_Y0, t_end, 1e-10, 1e-10)
    for _ in range(n):
        sol.h_abs[:] = t_end / n
        sol.rejected[:] = False
        sol.step()
        sol.advance(np.ones(sol.K, dtype=bool))
    return sol.y


def check_the_time_dependence() -> list[str]:
    """A non-autonomous problem with a closed form: every other problem of the suite is autonomous, where
    the stage times c_s are never read, so a wrong one went unnoticed (issue 45)."""
    t_end = 6.0
    exact = GROWTH_Y0 * np.exp(np.sin(GROWTH_W * t_end))
    errors = np.array([np.abs(_fixed_steps(n, t_end) - exact).max() for n in ORDER_STEPS])
    orders = np.log2(errors[:-1] / errors[1:])
    problems = []
    if not np.all(orders >= ORDER_FLOOR):
        problems.append(f"y' = w cos(w t) y in {ORDER_STEPS} equal steps: errors {errors} fall with order "
                        f"{np.round(orders, 2)} (at least {ORDER_FLOOR} expected, DOP853 is of order 8): "
                        "a stage time or a weight is wrong")
    problems += _same_as_scipy(_growth, lambda k: (lambda t, y: GROWTH_W[k] * np.cos(GROWTH_W[k] * t) * y),
                               GROWTH_Y0, 10.0, "y' = w cos(w t) y over [0, 10]")
    return problems


def check_the_guard() -> list[str]:
    """The singularity guard (``watch``) sees only states of the motion, never a rejected trial's end.

    A trial over the whole interval (pendulums) is rejected, and every rate the guard sees stays within
    the motion's (|theta'| and |theta''| below sqrt(2 g (1 - cos 2.8)) < 9.8 and g); and a decay that
    switches to a branch 100 x faster, whose first trial there reaches rates 1e9-fold the start's, is
    integrated to the end by the grader's `integrate` (with the guard on), not stopped as a singularity."""
    from dataclasses import replace

    from lagrade.compare.trajectory import ACCURACY, BatchedEvent, integrate

    problems = []
    y0 = np.array([AMPLITUDES, np.zeros_like(AMPLITUDES)])
    seen = []
    sol = DOP853(_pendulums, 0.0, y0, 20.0, 1e-10, 1e-10, limit=10**5,
                 watch=lambda t, f: seen.append(float(np.abs(f).max())))
    sol.h_abs[:] = 20.0
    sol.advance(sol.step())
    for _ in range(20):
        sol.advance(sol.step())
    if max(seen) > 9.8 + 1e-9:
        problems.append(f"the singularity guard saw rates of {max(seen):.3g} on pendulums whose rates stay "
                        "below 9.8: it watched a rejected trial step")

    rate = np.ones(2)

    def rates(t, Y):
        return -rate * Y

    def faster(k, t, yk):
        rate[k] = 100.0

    ev = BatchedEvent("switch", lambda t, Y: Y[0] - 0.5, action="switch", direction=-1, on_event=faster)
    run = integrate(rates, np.array([[1.0, 2.0]]), 2.0, replace(ACCURACY["default"], method="DOP853"),
                    events=[ev], t_eval=np.linspace(0.0, 2.0, 5))
    if not run.ok:
        problems.append(f"a decay switching to a faster branch was stopped ({run.message}): the singularity "
                        "guard watched the rejected trial after the switch")
    return problems


def check_the_events() -> list[str]:
    """Events located on the dense output where they are known exactly: x = cos(w t) reaches 0 falling
    at t = pi / (2 w) with v = -w (rtol 1e-10: found to ~1e-13)."""
    from lagrade.compare.dop853 import ColumnEvent

    w = np.array([0.7, 1.0, 1.9, 3.1])
    y0 = np.array([np.ones_like(w), np.zeros_like(w)])
    run = solve(lambda t, Y: np.stack([Y[1], -w ** 2 * Y[0]]), 0.0, y0, 5.0, rtol=1e-10, atol=1e-10,
                t_eval=np.array([5.0]), events=[ColumnEvent(lambda t, Y: Y[0], direction=-1)], max_evals=10**4)
    problems = []
    if run.status != 0 or sorted(k for _, k, _, _ in run.events) != list(range(len(w))):
        return [f"x = cos(w t): not one event per trajectory ({run.message}, {len(run.events)} events)"]
    for _, k, t, yk in run.events:
        dt, dy = abs(t - np.pi / (2 * w[k])), float(np.abs(yk - [0.0, -w[k]]).max())
        if dt > 1e-9 or dy > 1e-9:
            problems.append(f"x = cos({w[k]:g} t) reaches 0 at t = {t!r} with state {yk} (exactly pi/(2w) and "
                            f"(0, -w): {dt:.2g} and {dy:.2g} off): the event's root or state is not the dense "
                            "output's")
    return problems


def check_the_method() -> list[str]:
    """What is wrong with the integrator's order, step control, stage times, singularity guard or events
    (empty: nothing). About a second."""
    from scipy.special import ellipk

    y0 = np.array([AMPLITUDES, np.zeros_like(AMPLITUDES)])
    t_end = PERIODS * 4 * ellipk(np.sin(AMPLITUDES.max() / 2) ** 2) / np.sqrt(9.8)
    problems = _same_as_scipy(_pendulums, lambda k: (lambda t, y: _pendulums(t, y[:, None])[:, 0]), y0, t_end,
                              f"pendulums over {PERIODS:g} periods")
    sol = DOP853(_pendulums, 0.0, y0, t_end, 1e-10, 1e-10, limit=1000)
    sol.h_abs[:] = t_end
    h = sol.h_abs.copy()
    if sol.step().any() or not np.all(sol.h_abs < h):
        problems.append(f"a trial step over the whole interval was accepted, or the next trial was not shorter "
                        f"({h} -> {sol.h_abs}): the step-size control does not shrink rejected steps")
    return problems + check_the_time_dependence() + check_the_guard() + check_the_events()
