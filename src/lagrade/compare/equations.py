"""Does a set of equations define the same rates as the reference?

Students write equations of motion (and Hamilton's equations) in any order, on either side, with
any nonzero factor, or as combinations of each other. What must hold is that each equation is
satisfied by the true rates at every state, and that together they determine all of them. Both
are checked numerically at sampled states: the rows are evaluated at the reference rates
(residual ~ 0) and their Jacobian in the unknown rates gives the rank. No symbolic solve.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy as sp

from lagrade.numbers.numeric import Vectorized, compile_exprs, compile_linear_solve, evaluate


@dataclass
class RowAnalysis:
    consistent: list[bool]
    trivial: list[bool]
    rank: int
    n: int
    labels: list[str]  # the unknown each row mainly determines
    #: the rows hold and fix every rate at the sampled states, but their determinant (relative to the
    #: reference's) takes both signs there: a factor such as q' or (r - l0) vanishes in between, where
    #: they no longer determine the motion (dE/dt = q'*(equation) = 0 is the classic)
    vanishing_factor: bool = False

    @property
    def wrong(self) -> list[int]:
        return [i for i, ok in enumerate(self.consistent) if not ok]

    @property
    def fraction(self) -> float:
        counted = sum(1 for t in self.trivial if not t)
        if not self.wrong and self.rank >= self.n:
            return 1.0
        return self.rank / max(self.n, counted)


def slopes(row: sp.Expr, unknowns: list[sp.Symbol]) -> dict[sp.Symbol, sp.Expr]:
    """``{u: sp.diff(row, u)}``, the same sympy expressions, built the way sympy builds them where the row
    is plainly linear (`_plain_slope`); any other row is differentiated by sympy. sympy's product rule
    through every factor of a long row is the cost this saves (a millisecond a row)."""
    out = {}
    for u in unknowns:
        d = _plain_slope(row, u)
        out[u] = sp.diff(row, u) if d is None else d
    return out


def _plain_slope(e: sp.Expr, u: sp.Symbol) -> sp.Expr | None:
    """d e / d u as sympy's ``diff`` gives it, for ``e`` made of sums and products in which ``u`` enters a
    product through one factor only and is reached that way down to ``u`` itself; None for any other
    shape. sympy differentiates a sum term by term (``Add(*[a.diff(u) ...])``) and a product by the
    Leibniz rule (``Mul`` of the factors with one of them differentiated, summed over the factors):
    the factors free of ``u`` have derivative 0, so only the one with ``u`` leaves a term, the product
    of the others and its derivative; a subexpression free of ``u`` is 0 and ``u`` itself 1."""
    if e == u:
        return sp.S.One
    if not e.has(u):
        return sp.S.Zero
    if e.is_Add:
        parts = [_plain_slope(a, u) for a in e.args]
        return None if any(p is None for p in parts) else sp.Add(*parts)
    if e.is_Mul:
        hit = [i for i, f in enumerate(e.args) if f.has(u)]
        if len(hit) != 1:
            return None
        d = _plain_slope(e.args[hit[0]], u)
        return None if d is None else sp.Mul(*e.args[:hit[0]], d, *e.args[hit[0] + 1:])
    return None


class CompiledRows:
    """Rows G(args, u) and their Jacobian in the unknowns u: evaluated once at the sampled states
    without compiling (`lagrade.numbers.numeric.evaluate`), compiled only for what a trajectory calls many times."""

    def __init__(self, rows: Sequence[sp.Expr], unknowns: Sequence[sp.Symbol], args: Sequence[sp.Symbol]):
        self.m, self.n = len(rows), len(unknowns)
        self.rows = list(rows)
        self.unknowns = list(unknowns)
        self.allargs = [*args, *unknowns]
        self.J_exprs = [d for r in rows for d in slopes(r, list(unknowns)).values()]  # sp.diff(r, u)
        # linear when no Jacobian entry depends on an unknown: only an entry that has one is differentiated
        self.linear = all(v not in j.free_symbols or sp.diff(j, v) == 0 for j in self.J_exprs for v in unknowns)
        self._direct = None
        if self.linear and self.m == self.n:
            zero = {u: 0 for u in unknowns}
            A = [self.J_exprs[i * self.n:(i + 1) * self.n] for i in range(self.m)]
            self._direct = compile_linear_solve(A, [-r.xreplace(zero) for r in self.rows], list(args))

    @cached_property
    def G(self):
        return compile_exprs(self.rows, self.allargs)

    @cached_property
    def J(self):
        return compile_exprs(self.J_exprs, self.allargs)

    def values(self, argv: Sequence[np.ndarray], u: np.ndarray) -> np.ndarray:
        return evaluate(self.rows, self.allargs, [*argv, *u])

    def jacobian(self, argv: Sequence[np.ndarray], u: np.ndarray) -> np.ndarray:
        K = np.broadcast(*argv).size
        return evaluate(self.J_exprs, self.allargs, [*argv, *u]).reshape(self.m, self.n, K)

    @property
    def solver(self) -> Vectorized:
        """The rates these rows define as a function of the argument rows (`solve`): for linear
        rows, the compiled solution itself, so a trajectory run can use it in machine code."""
        if self._direct is not None:
            return self._direct
        return lambda *argv: self.solve(argv)

    def solve(self, argv: Sequence[np.ndarray]) -> np.ndarray:
        """The rates these rows define (linear rows: one solve; otherwise two Newton steps)."""
        if self._direct is not None:
            return self._direct(*argv)
        K = np.broadcast(*argv).size
        u = np.zeros((self.n, K))
        for _ in range(1 if self.linear else 3):
            J = self.J(*argv, *u).reshape(self.m, self.n, K).transpose(2, 0, 1)
            g = self.G(*argv, *u).T[..., None]
            with np.errstate(all="ignore"):
                try:
                    step = (np.linalg.solve(J, g) if self.m == self.n else np.linalg.pinv(J) @ g)[..., 0].T
                except np.linalg.LinAlgError:
                    return np.full((self.n, K), np.nan)
            u = u - step
        return u


def analyse_rows(rows: CompiledRows, argv: Sequence[np.ndarray], truth: np.ndarray, labels: Sequence[str],
                 rtol: float = 1e-7, reference_jacobian: np.ndarray | None = None,
                 at_rest: tuple[Sequence[np.ndarray], np.ndarray | None] | None = None) -> RowAnalysis:
    """Which rows hold at the true rates, which are empty, and how many unknowns they fix.

    ``reference_jacobian`` (n, n, K), the reference equations' Jacobian in the rates (the mass
    matrix for Lagrange's equations; None for a constant one): a square system whose determinant
    relative to it changes sign between sampled states has a factor that vanishes in the domain.
    ``at_rest``: the same states with every velocity zero, and the reference Jacobian there (the
    most common initial state; a factor q' only vanishes there when velocities are sampled > 0)."""
    zero = np.zeros_like(truth)
    g_true = rows.values(argv, truth)
    g_zero = rows.values(argv, zero)
    J = rows.jacobian(argv, truth)  # (m, n, K)
    terms = np.abs(g_zero) + np.einsum("mnk,nk->mk", np.abs(J), np.abs(truth))
    scale = np.nanmax(np.where(np.isfinite(terms), terms, np.nan), axis=1, initial=0.0)
    # A row that is zero up to rounding (a constraint that holds identically) must not be judged
    # against its own rounding noise: measure every row against the system's overall size too.
    overall = float(np.nanmax(scale, initial=0.0)) or 1.0
    scale = np.maximum(np.where(np.isfinite(scale), scale, 0.0), 1e-9 * overall)
    # ... and whatever the tolerance asked, never below the rounding of the system's own terms
    floor = 1e-13 * overall
    consistent, trivial, main = [], [], []
    for i in range(rows.m):
        ok = bool(np.all(np.abs(g_true[i]) <= rtol * scale[i] + floor))
        jnorm = np.abs(J[i])
        empty = bool(np.all(jnorm <= 1e-12 * scale[i]))
        consistent.append(ok)
        trivial.append(ok and empty)
        weighted = jnorm * (1.0 + np.abs(truth))
        # an unknown whose entries are NaN at every state (a singular row) weighs nothing, without numpy's warning
        counted = np.isfinite(weighted).any(axis=1)
        weight = np.zeros(rows.n)
        if J.shape[2] and counted.any():
            weight[counted] = np.nanmedian(weighted[counted], axis=1)
        main.append(labels[int(np.nanargmax(weight))] if np.isfinite(weight).any() and weight.max() > 0 else "none")
    use = [i for i in range(rows.m) if consistent[i] and not trivial[i]]
    if use:
        sub = J[use].transpose(2, 0, 1)  # (K, r, n)
        ranks = []
        for Jk in sub:
            if not np.all(np.isfinite(Jk)):
                continue
            s = np.linalg.svd(Jk, compute_uv=False)
            ranks.append(int(np.sum(s > 1e-9 * max(s.max(initial=0.0), 1e-300))))
        rank = min(ranks) if ranks else 0
    else:
        rank = 0
    vanishing = rank >= rows.n and len(use) == rows.n and (
        _changes_sign(J[use], reference_jacobian)
        or (at_rest is not None and rows.linear
            and _vanishes_at_rest(rows.jacobian(at_rest[0], truth)[use], at_rest[1], J[use], reference_jacobian)))
    return RowAnalysis(consistent, trivial, rows.n - 1 if vanishing else rank, rows.n, main, vanishing)


def _det_ratio(J: np.ndarray, reference: np.ndarray | None) -> np.ndarray:
    with np.errstate(all="ignore"):
        ratio = np.linalg.det(J.transpose(2, 0, 1))
        return ratio if reference is None else ratio / np.linalg.det(reference.transpose(2, 0, 1))


def _vanishes_at_rest(J_rest: np.ndarray, reference_rest: np.ndarray | None, J: np.ndarray,
                      reference: np.ndarray | None) -> bool:
    """Is the determinant ratio zero (against its size in motion) at some state of rest?"""
    moving = np.abs(_det_ratio(J, reference))
    rest = np.abs(_det_ratio(J_rest, reference_rest))
    moving, rest = moving[np.isfinite(moving)], rest[np.isfinite(rest)]
    if not moving.size or not rest.size:
        return False
    return bool(np.any(rest <= 1e-9 * float(np.median(moving))))


def _changes_sign(J: np.ndarray, reference: np.ndarray | None) -> bool:
    """Does det(J) / det(reference) take both signs over the samples (beyond rounding)? The domain
    is connected, so by continuity it is zero somewhere in between."""
    ratio = _det_ratio(J, reference)
    ratio = ratio[np.isfinite(ratio)]
    if ratio.size < 2:
        return False
    tiny = 1e-9 * float(np.max(np.abs(ratio)))
    return bool(np.any(ratio > tiny) and np.any(ratio < -tiny))
