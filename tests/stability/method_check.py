"""The integrator's order and step control, checked in a fraction of a second before the suite runs.

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
  trial is shorter.

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


def _scipy_alone(y0: np.ndarray, t_end: float, rtol: float):
    """Per column: scipy's DOP853 alone, its evaluations and its end state."""
    nfev, ends = [], []
    for k in range(y0.shape[1]):
        s = ScipyDOP853(lambda t, y: _pendulums(t, y[:, None])[:, 0], 0.0, y0[:, k], t_end, rtol=rtol, atol=rtol)
        while s.status == "running":
            s.step()
        assert s.status == "finished", s.status
        nfev.append(s.nfev)
        ends.append(s.y)
    return max(nfev), np.array(ends).T


def check_the_method() -> list[str]:
    """What is wrong with the integrator's order or step control (empty: nothing). Milliseconds."""
    from scipy.special import ellipk

    problems = []
    y0 = np.array([AMPLITUDES, np.zeros_like(AMPLITUDES)])
    t_end = PERIODS * 4 * ellipk(np.sin(AMPLITUDES.max() / 2) ** 2) / np.sqrt(9.8)
    for rtol in TOLERANCES:
        cost, ends = _scipy_alone(y0, t_end, rtol)
        budget = int(COST_MARGIN * cost)
        run = solve(_pendulums, 0.0, y0, t_end, rtol=rtol, atol=rtol, t_eval=np.array([t_end]), max_evals=budget)
        if run.status != 0:
            problems.append(f"rtol {rtol:g}: pendulums over {PERIODS:g} periods need more than {budget} evaluations "
                            f"({COST_MARGIN} x the {cost} of scipy's DOP853 for the hardest alone): the method "
                            f"lost its order or its step control ({run.message})")
            continue
        diff = float(np.abs(run.y[:, :, -1] - ends).max())
        if diff > 10 * rtol:
            problems.append(f"rtol {rtol:g}: the end states differ from scipy's DOP853 by {diff:.2g} "
                            f"(more than 10 x rtol): the method lost its order, or its steps are not DOP853's")
    sol = DOP853(_pendulums, 0.0, y0, t_end, 1e-10, 1e-10, limit=1000)
    sol.h_abs[:] = t_end
    h = sol.h_abs.copy()
    if sol.step().any() or not np.all(sol.h_abs < h):
        problems.append(f"a trial step over the whole interval was accepted, or the next trial was not shorter "
                        f"({h} -> {sol.h_abs}): the step-size control does not shrink rejected steps")
    return problems
