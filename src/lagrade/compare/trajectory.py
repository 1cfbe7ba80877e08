"""Trajectory evidence: integrate the student's and the reference dynamics side by side.

Both systems start from the same sampled states with the same parameter values; all K
trajectories are integrated as one batched system (one `solve_ivp` call per side), then compared
in the tolerance-scaled norm ``|y - y_ref| / (atol + rtol*|y_ref|)``. For a wrong answer the
comparison says when the motions separate and which coordinate goes wrong first.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

Rates = Callable[[float, np.ndarray], np.ndarray]  # (t, y of shape (dim, K)) -> (dim, K)


@dataclass(frozen=True)
class Accuracy:
    """Integration and comparison tolerances; the comparison is looser than the integration."""

    name: str = "default"
    rtol: float = 1e-10
    atol: float = 1e-10
    compare_rtol: float = 1e-6
    compare_atol: float = 1e-6
    trajectories: int = 4
    max_rhs_evals: int = 20000


ACCURACY = {
    "fast": Accuracy("fast", 1e-8, 1e-8, 1e-4, 1e-4, 2, 8000),
    "default": Accuracy(),
    "strict": Accuracy("strict", 1e-12, 1e-12, 1e-8, 1e-8, 6, 60000),
}


class _TooManyEvaluations(Exception):
    pass


@dataclass
class Run:
    """One batched integration: times, states (dim, K, len(t)), where it stopped and why."""

    t: np.ndarray
    y: np.ndarray
    ok: bool
    message: str
    rhs_evals: int
    seconds: float


def integrate(rates: Rates, y0: np.ndarray, horizon: float, acc: Accuracy, samples: int = 201) -> Run:
    """Integrate K states at once with DOP853; a blow-up or runaway cost ends the run, not the grader."""
    dim, K = y0.shape
    t_eval = np.linspace(0.0, horizon, samples)
    count = 0

    def fun(t: float, flat: np.ndarray) -> np.ndarray:
        nonlocal count
        count += 1
        if count > acc.max_rhs_evals:
            raise _TooManyEvaluations
        with np.errstate(all="ignore"):
            return np.asarray(rates(t, flat.reshape(dim, K)), dtype=float).reshape(-1)

    start = time.perf_counter()
    try:
        with np.errstate(all="ignore"):
            sol = solve_ivp(fun, (0.0, horizon), y0.reshape(-1), method="DOP853", t_eval=t_eval,
                            rtol=acc.rtol, atol=acc.atol)
        y = sol.y.reshape(dim, K, -1)
        ok = sol.status == 0 and bool(np.all(np.isfinite(y)))
        message = "" if ok else (sol.message if sol.status != 0 else "the state became infinite or undefined")
        return Run(sol.t, y, ok, message, count, time.perf_counter() - start)
    except _TooManyEvaluations:
        return Run(t_eval[:1], y0[..., None], False, f"needed more than {acc.max_rhs_evals} steps",
                   count, time.perf_counter() - start)
    except (ValueError, ZeroDivisionError, np.linalg.LinAlgError, FloatingPointError) as exc:
        return Run(t_eval[:1], y0[..., None], False, f"integration failed ({exc})", count,
                   time.perf_counter() - start)


@dataclass
class Comparison:
    agree: bool
    horizon: float
    separation_time: float | None = None
    component: str | None = None
    max_error: float = 0.0
    note: str = ""
    seconds: float = 0.0
    rhs_evals: int = 0

    def describe(self) -> str:
        if self.agree:
            return f"trajectories agree over t in [0, {self.horizon:g}]"
        if self.note:
            return self.note
        return (f"from the same initial state your motion separates from the true one at t = "
                f"{self.separation_time:.3g}; {self.component} goes wrong first")


def compare_runs(student: Rates, reference: Rates, y0: np.ndarray, labels: list[str], horizon: float,
                 acc: Accuracy) -> Comparison:
    """Integrate both from ``y0`` and compare; ``labels`` names each state component."""
    ref = integrate(reference, y0, horizon, acc)
    if not ref.ok:
        return Comparison(False, horizon, note=f"reference integration failed: {ref.message}",
                          seconds=ref.seconds, rhs_evals=ref.rhs_evals)
    stu = integrate(student, y0, horizon, acc)
    seconds = ref.seconds + stu.seconds
    evals = ref.rhs_evals + stu.rhs_evals
    n = min(stu.y.shape[-1], ref.y.shape[-1])
    err = np.abs(stu.y[..., :n] - ref.y[..., :n]) / (acc.compare_atol + acc.compare_rtol * np.abs(ref.y[..., :n]))
    err = np.where(np.isfinite(err), err, np.inf)
    bad = err > 1.0
    if not bad.any() and stu.ok:
        return Comparison(True, horizon, max_error=float(err.max(initial=0.0)), seconds=seconds, rhs_evals=evals)
    if bad.any():
        first_t = int(np.argmax(bad.any(axis=(0, 1))))
        comp = int(np.argmax(err[:, :, first_t].max(axis=1)))
        return Comparison(False, horizon, float(ref.t[first_t]), labels[comp], float(err.max()),
                          seconds=seconds, rhs_evals=evals)
    return Comparison(False, horizon, float(stu.t[-1]) if stu.t.size else 0.0, "the motion",
                      note=f"your equations could not be integrated: {stu.message}",
                      seconds=seconds, rhs_evals=evals)
