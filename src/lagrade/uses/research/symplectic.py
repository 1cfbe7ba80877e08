"""Symplectic integrators for conservative scenes, batched over K states like the grader.

- `StormerVerlet`: H = p.M^-1.p/2 + V(q) with a constant mass matrix (the simple pendulum 12.43, a
  spring): explicit, order 2, one force evaluation per step.
- `implicit_midpoint`: any H(q, p) (a mass matrix that depends on q, as in the double pendulum 12.14),
  y_{n+1} = y_n + h f((y_n + y_{n+1})/2), solved by fixed-point iteration to round-off; order 2.
- `compose4`: the symmetric triple-jump composition (Yoshida) of either, order 4, still symplectic.

Fixed step sizes: a symplectic method keeps the energy error bounded (no drift) over exponentially long
times, which an adaptive non-symplectic method such as DOP853 does not (docs/numerics.md, "long runs").
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import sympy as sp

from lagrade.numbers.numeric import compile_exprs
from lagrade.derive.reference import Mechanics
from lagrade.problem.symbols import T

YOSHIDA = (1 / (2 - 2 ** (1 / 3)), -(2 ** (1 / 3)) / (2 - 2 ** (1 / 3)), 1 / (2 - 2 ** (1 / 3)))


def is_conservative(mech: Mechanics) -> bool:
    """No generalized forces and no explicit time: H is conserved."""
    return all(e == 0 for e in mech.Q) and not mech.L.has(T)


def is_separable(mech: Mechanics) -> bool:
    """T = qd.M.qd/2 with M constant, V = V(q): Stormer-Verlet applies."""
    if not is_conservative(mech):
        return False
    qd = mech.s.qd
    hess = [sp.diff(mech.L, a, b) for a in qd for b in qd]
    linear = [sp.diff(mech.L, a).xreplace({v: 0 for v in qd}) for a in qd]
    return all(not h.free_symbols & {*mech.s.q, *qd} for h in hess) and all(sp.simplify(x) == 0 for x in linear)


@dataclass
class SymplecticRun:
    t: np.ndarray
    q: np.ndarray       # (n, K, len(t))
    p: np.ndarray
    force_evals: int
    seconds: float
    method: str


class StormerVerlet:
    """Kick-drift-kick leapfrog for a separable scene, batched over K states."""

    def __init__(self, mech: Mechanics):
        if not is_separable(mech):
            raise ValueError("Stormer-Verlet needs H = p.M^-1.p/2 + V(q) with a constant M")
        self.mech = mech
        qd = mech.s.qd
        self.n = len(qd)
        self._minv = compile_exprs(list(sp.Matrix([[sp.diff(mech.L, a, b) for b in qd] for a in qd]).inv()),
                                   list(mech.params))
        self._force = compile_exprs([sp.diff(mech.L, q) for q in mech.s.q], [*mech.s.q, *mech.params])

    def run(self, q0: np.ndarray, p0: np.ndarray, params: np.ndarray, h: float, steps: int,
            record_every: int = 1, order: int = 2) -> SymplecticRun:
        n, K = q0.shape
        Minv = self._minv(*params).reshape(n, n, K)
        F = lambda q: self._force(*q, *params)  # noqa: E731
        q, p = q0.astype(float).copy(), p0.astype(float).copy()
        subs = YOSHIDA if order == 4 else (1.0,)
        ts, qs, ps = [0.0], [q.copy()], [p.copy()]
        evals = 1
        start = time.perf_counter()
        f = F(q)
        for i in range(1, steps + 1):
            for c in subs:
                hc = h * c
                p += 0.5 * hc * f
                q += hc * np.einsum("ijk,jk->ik", Minv, p)
                f = F(q)
                evals += 1
                p += 0.5 * hc * f
            if i % record_every == 0:
                ts.append(i * h)
                qs.append(q.copy())
                ps.append(p.copy())
        return SymplecticRun(np.array(ts), np.stack(qs, -1), np.stack(ps, -1), evals, time.perf_counter() - start,
                             f"Stormer-Verlet{' (Yoshida order 4)' if order == 4 else ''}")


def implicit_midpoint(rates: Callable[[float, np.ndarray], np.ndarray], y0: np.ndarray, h: float, steps: int,
                      record_every: int = 1, order: int = 2, tol: float = 1e-14, max_iter: int = 50
                      ) -> tuple[np.ndarray, np.ndarray, int, float]:
    """Implicit midpoint rule (order 2, or 4 by composition) for y' = rates(t, y), y of shape (dim, K).

    Returns (t, y (dim, K, len(t)), rate evaluations, seconds).
    """
    y = np.asarray(y0, dtype=float).copy()
    subs = YOSHIDA if order == 4 else (1.0,)
    ts, ys = [0.0], [y.copy()]
    evals = 0
    start = time.perf_counter()
    t = 0.0
    for i in range(1, steps + 1):
        for c in subs:
            hc = h * c
            k = np.asarray(rates(t + hc / 2, y), dtype=float)
            evals += 1
            for _ in range(max_iter):
                k_new = np.asarray(rates(t + hc / 2, y + 0.5 * hc * k), dtype=float)
                evals += 1
                done = np.max(np.abs(k_new - k) * abs(hc)) <= tol * (1.0 + np.max(np.abs(y)))
                k = k_new
                if done:
                    break
            y = y + hc * k
            t += hc
        if i % record_every == 0:
            ts.append(t)
            ys.append(y.copy())
    return np.array(ts), np.stack(ys, -1), evals, time.perf_counter() - start


def hamilton_rates(mech: Mechanics, params: np.ndarray):
    """(t, Y=(q, p)) -> (q', p') of the scene, batched: the right-hand side for `implicit_midpoint`,
    the model grading integrates (`SceneModel.hamilton_rates`)."""
    from lagrade.compare.scene_model import scene_model

    return scene_model(mech).hamilton_rates(params)
