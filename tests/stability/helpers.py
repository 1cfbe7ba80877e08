"""Shared set-up of the stability suite: scenes with chosen parameters and states."""

from __future__ import annotations

import numpy as np
import sympy as sp

from lagrade.problem.library import load_problem
from lagrade.compare.scene_model import SceneModel
from lagrade.derive.reference import Mechanics
from lagrade.problem.spec import Problem


def mechanics(pid: str, key: str | None = None) -> Mechanics:
    problem = load_problem(pid)
    return Mechanics(problem, problem.systems[0] if key is None else problem.system(key))


def custom(data: dict) -> Mechanics:
    problem = Problem.model_validate(data)
    return Mechanics(problem, problem.systems[0])


def params(mech: Mechanics, K: int, **values) -> np.ndarray:
    """Parameter array (P, K) from ``name=value`` (a number or a length-K sequence)."""
    return np.array([np.broadcast_to(np.asarray(values[str(p)], dtype=float), (K,)) for p in mech.params])


def lagrange_rates(accel, n: int):
    def rates(t, Y):
        return np.concatenate([Y[n:], accel(Y[:n], Y[n:], np.full(Y.shape[1], t))])
    return rates


def reference_rates(mech: Mechanics, P: np.ndarray):
    return lagrange_rates(lambda q, qd, t: mech.accelerations(q, qd, t, P), len(mech.names))


def rewritten_rates(mech: Mechanics, P: np.ndarray, rewrite=sp.expand_trig, perturb: dict | None = None):
    """A student's answer: the same accelerations in another algebraic form (other rounding), optionally
    with a mistake (``perturb`` substitutes symbols, e.g. ``{g: 1.001*g}``)."""
    acc = [rewrite(sp.together(a)) for a in mech.accelerations_symbolic]
    if perturb:
        acc = [a.xreplace(perturb) for a in acc]
    args = [*mech.s.q, *mech.s.qd, sp.Symbol("t"), *mech.params]
    f = sp.lambdify(args, acc, modules="numpy")

    def accel(q, qd, t):
        out = f(*q, *qd, t, *P)
        return np.array([np.broadcast_to(np.asarray(o, dtype=float), t.shape) for o in out])

    return lagrange_rates(accel, len(mech.names))


__all__ = ["SceneModel", "custom", "lagrange_rates", "mechanics", "params", "reference_rates", "rewritten_rates"]
