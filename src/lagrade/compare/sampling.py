"""Random points from a scene's physical domain.

Answers are evaluated where the physics lives: positive masses and lengths, angles and
distances in the ranges the problem file gives (away from coordinate singularities). A seeded
generator makes every verdict reproducible.
"""

from __future__ import annotations

import zlib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp

from lagrade.derive.reference import Mechanics
from lagrade.problem.symbols import T


@dataclass
class Points:
    """A batch of K states with parameter values, keyed by symbol."""

    values: dict[sp.Symbol, np.ndarray]
    K: int

    def __getitem__(self, sym: sp.Symbol) -> np.ndarray:
        return self.values[sym]

    def args(self, symbols: list[sp.Symbol]) -> list[np.ndarray]:
        return [self.values[s] for s in symbols]


def rng_for(*keys: str) -> np.random.Generator:
    return np.random.default_rng(zlib.crc32("/".join(keys).encode()))


def grouped(pts: Points, mech: Mechanics, symbols: Sequence[str] = (), per_group: int = 4) -> Points:
    """``pts`` with the parameters, t and ``symbols`` shared by groups of ``per_group`` states (so
    that 'constant' can be told from 'state-dependent': the Lagrangian's comparison)."""
    for sym in [*mech.params, T, *(sp.Symbol(s) for s in symbols)]:
        v = pts.values[sym]
        pts.values[sym] = np.repeat(v[::per_group], per_group)
    return pts


def sample_points(mech: Mechanics, K: int, rng: np.random.Generator,
                  extra: Mapping[str, tuple[float, float]] | Sequence[str] = ()) -> Points:
    """States (q, qd, qdd, p, t) and parameters; ``qdd`` random (for identities in the accelerations)
    and ``qdd_ref`` the accelerations the reference dynamics gives at those states. ``extra``: a
    part's own symbols (``Part.symbol_domains``), each with its range, or names sampled in [0.5, 1.5]."""
    vals: dict[sp.Symbol, np.ndarray] = {}
    for p in mech.parameters:
        vals[sp.Symbol(p.name)] = rng.uniform(*p.sample, K)
    domains = extra if isinstance(extra, Mapping) else {name: (0.5, 1.5) for name in extra}
    for name, (lo, hi) in domains.items():
        vals.setdefault(sp.Symbol(name), rng.uniform(lo, hi, K))
    coords = {c.name: c for c in mech.system.coordinates}
    for name, q, qd, qdd in zip(mech.names, mech.s.q, mech.s.qd, mech.s.qdd):
        c = coords[name]
        vals[q] = rng.uniform(*c.sample, K)
        vals[qd] = rng.uniform(*c.velocity, K)
        vals[qdd] = rng.uniform(-1.0, 1.0, K)
    vals[T] = rng.uniform(0.0, mech.system.horizon, K)
    return Points(vals, K)


def state_arrays(mech: Mechanics, pts: Points) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    q = np.array(pts.args(mech.s.q)).reshape(len(mech.names), pts.K)
    qd = np.array(pts.args(mech.s.qd)).reshape(len(mech.names), pts.K)
    params = np.array(pts.args(mech.params)).reshape(len(mech.params), pts.K)
    return q, qd, pts[T], params


def with_reference_dynamics(mech: Mechanics, pts: Points) -> Points:
    """Add the reference accelerations, momenta and multipliers at each state of ``pts``.

    After this, ``q_dd`` symbols hold the *true* accelerations (what reference expressions such
    as ``x_dd + y_dd`` mean), and constrained coordinates and multipliers have their values.
    """
    q, qd, t, params = state_arrays(mech, pts)
    vals = dict(pts.values)
    acc = mech.accelerations(q, qd, t, params)
    for sym, a in zip(mech.s.qdd, acc):
        vals[sym] = a
    mom = mech.momenta(q, qd, t, params)
    for sym, p in zip(mech.s.p, mom):
        vals[sym] = p
    base = [*mech.s.q, *mech.s.qd, *mech.s.qdd, T, *mech.params]
    base_vals = [vals[s] for s in base]
    from lagrade.numbers.numeric import evaluate

    if mech.constrained:
        syms = list(mech.constrained)
        for sym, v in zip(syms, evaluate([mech.constrained[s] for s in syms], base, base_vals)):
            vals[sym] = v
    if mech.multiplier_exprs:
        syms = list(mech.multiplier_exprs)
        for sym, v in zip(syms, evaluate([mech.multiplier_exprs[s] for s in syms], base, base_vals)):
            vals[sym] = v
    return Points(vals, pts.K)
