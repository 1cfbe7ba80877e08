"""Finite-time Lyapunov exponents along a scene's motion (Benettin's method, batched).

Each of the K states is integrated together with a displaced copy (one batched system of 2K
trajectories); every ``renorm`` time units the displacement is measured and scaled back to its
initial size, and the logarithms of the growth factors are summed. The exponent over [0, T] is that
sum over T. It sets the comparison window of chaotic scenes (`lagrade.compare.trajectory`): two
correct integrations that differ by ``rtol`` drift apart like ``rtol * exp(lambda * t)``.
"""

from __future__ import annotations

import numpy as np

from lagrade.compare.trajectory import Accuracy, Rates, integrate


def finite_time_lyapunov(rates: Rates, y0: np.ndarray, T: float, acc: Accuracy, renorm: float = 0.5,
                         delta: float = 1e-8, seed: int = 0) -> np.ndarray:
    """The largest finite-time Lyapunov exponent (1/time) of each of the K trajectories over [0, T]."""
    dim, K = y0.shape
    rng = np.random.default_rng(seed)
    d = rng.standard_normal((dim, K))
    d *= delta / np.linalg.norm(d, axis=0)
    a, b = y0.astype(float).copy(), y0 + d
    total = np.zeros(K)
    t = 0.0

    def pair(tt, Y: np.ndarray) -> np.ndarray:
        t1, t2 = (tt, tt) if np.ndim(tt) == 0 else (tt[:K], tt[K:])  # one time per trajectory, or one for all
        return np.concatenate([rates(t1, Y[:, :K]), rates(t2, Y[:, K:])], axis=1)

    while t < T - 1e-12:
        step = min(renorm, T - t)
        shifted = lambda tt, Y, t=t: pair(tt + t, Y)  # noqa: E731
        run = integrate(shifted, np.concatenate([a, b], axis=1), step, acc, samples=2, method="DOP853", guard=False)
        if not run.ok:
            raise RuntimeError(f"Lyapunov integration failed: {run.message}")
        a, b = run.y[:, :K, -1], run.y[:, K:, -1]
        sep = b - a
        size = np.linalg.norm(sep, axis=0)
        total += np.log(size / delta)
        b = a + sep * (delta / size)
        t += step
    return total / T


def comparison_window(lyap: float, acc: Accuracy, safety: float = 10.0) -> float:
    """Time over which integration errors of size rtol, grown like exp(lyap*t), stay below
    compare_rtol/safety: ``ln(compare_rtol / (safety*rtol)) / lyap`` (infinite for lyap <= 0)."""
    if lyap <= 0:
        return float("inf")
    return float(np.log(acc.compare_rtol / (safety * acc.rtol)) / lyap)
