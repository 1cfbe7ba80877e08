"""Rejections that are proofs: the difference that refuted an answer, enclosed in ball arithmetic.

A sampled state refutes an answer when, in floating point, its value is farther from the reference's
than the tolerance. That is strong evidence but not a proof: rounding decides what "farther" means.
Here the same quantity is evaluated again with python-flint's ``arb`` (midpoint-radius intervals whose
radius bounds every rounding error) at the same state, rounded to exact rationals; where the reference
needs the true accelerations, they are solved from the scene's mass matrix in ``arb_mat``. An
enclosure that excludes zero proves the answer differs from the reference at that exact point: a
certificate an instructor can check, made of the point and the enclosure.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction

import sympy as sp

PRECISION = 128  # bits: far beyond what rounding in the tolerance comparison could hide


class Uncertifiable(Exception):
    """The quantity has a construct ball arithmetic here does not cover (complex values, a switch)."""


@dataclass
class Certificate:
    """An exact point where the quantity is provably nonzero, and its enclosure."""

    quantity: str
    point: dict[str, str]
    enclosure: str

    def text(self) -> str:
        at = ", ".join(f"{k} = {v}" for k, v in self.point.items())
        return f"{self.quantity} lies in {self.enclosure}, which excludes 0, at the exact point {at}"


def _flint():
    import flint

    flint.ctx.prec = PRECISION
    return flint


_FUNCTIONS = {
    "sin": "sin", "cos": "cos", "tan": "tan", "cot": "cot", "sec": "sec", "csc": "csc", "asin": "asin",
    "acos": "acos", "atan": "atan", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "coth": "coth",
    "sech": "sech", "csch": "csch", "asinh": "asinh", "acosh": "acosh", "atanh": "atanh", "exp": "exp",
    "log": "log", "erf": "erf", "erfc": "erfc", "gamma": "gamma", "LambertW": "lambertw",
}


class Balls:
    """Sympy expressions evaluated as arb balls at one exact point (shared subexpressions once)."""

    def __init__(self, point: Mapping[sp.Symbol, Fraction]):
        flint = _flint()
        self.arb = flint.arb
        self.values: dict[sp.Basic, object] = {s: flint.arb(flint.fmpq(v.numerator, v.denominator))
                                               for s, v in point.items()}

    def set(self, symbol: sp.Symbol, ball) -> None:
        self.values[symbol] = ball

    def __call__(self, expr: sp.Basic):
        hit = self.values.get(expr)
        if hit is not None:
            return hit
        out = self._eval(expr)
        self.values[expr] = out
        return out

    def _eval(self, e: sp.Basic):
        arb = self.arb
        flint = _flint()
        if e.is_Rational:
            return arb(flint.fmpq(int(e.p), int(e.q)))
        if e.is_Float:
            return arb(flint.fmpq(*Fraction(sp.Rational(e)).as_integer_ratio()))
        if e is sp.pi:
            return arb.pi()
        if e is sp.E:
            return arb(1).exp()
        if e.is_Symbol:
            raise Uncertifiable(f"no value for {e}")
        if e.is_Add:
            out = arb(0)
            for a in e.args:
                out = out + self(a)
            return out
        if e.is_Mul:
            out = arb(1)
            for a in e.args:
                out = out * self(a)
            return out
        if e.is_Pow:
            base, exp = e.args
            b = self(base)
            if exp.is_Integer:
                return b ** int(exp)
            if exp == sp.S.Half:
                return b.sqrt()
            if exp == -sp.S.Half:
                return b.rsqrt()
            return b ** self(exp)
        name = type(e).__name__
        if name == "atan2":
            return arb.atan2(self(e.args[0]), self(e.args[1]))
        if name == "Abs":
            return abs(self(e.args[0]))
        if name == "sign":
            return self(e.args[0]).sgn()
        if name in ("Max", "Min"):
            out = self(e.args[0])
            for a in e.args[1:]:
                out = out.max(self(a)) if name == "Max" else out.min(self(a))
            return out
        method = _FUNCTIONS.get(name)
        if method is None or len(e.args) != 1:
            raise Uncertifiable(f"{name} is not evaluated in ball arithmetic here")
        return getattr(self(e.args[0]), method)()


def excludes_zero(ball) -> bool:
    return bool(ball.is_finite() and not ball.contains(0))


def exact_point(values: Mapping[sp.Symbol, float]) -> dict[sp.Symbol, Fraction]:
    """The floating-point state as the exact rationals it is (every double is one)."""
    return {s: Fraction(float(v)) for s, v in values.items()}


def with_truth(mech, balls: Balls) -> None:
    """The scene's true accelerations at the point (mass matrix solved in arb_mat), then the derived
    quantities reference expressions use: constrained coordinates, multipliers and momenta."""
    flint = _flint()
    n = len(mech.names)
    M = flint.arb_mat(n, n, [balls(mech.mass[i, j]) for i in range(n) for j in range(n)])
    f = flint.arb_mat(n, 1, [balls(e) for e in mech.force])
    try:
        acc = M.solve(f)
    except (ZeroDivisionError, ValueError) as exc:
        raise Uncertifiable(f"the mass matrix is not provably invertible there ({exc})") from None
    for i, a in enumerate(mech.s.qdd):
        balls.set(a, acc[i, 0])
    for v, p in zip(mech.s.qd, mech.s.p):
        balls.set(p, balls(sp.diff(mech.L, v)))
    for c, e in mech.constrained.items():
        balls.set(c, balls(e))
    for lam, e in mech.multiplier_exprs.items():
        balls.set(lam, balls(e))


def velocities_from_momenta(mech, balls: Balls) -> None:
    """q' from p = dL/dq' (linear in q': solved in arb_mat), for a phase-space point (q, p, t)."""
    flint = _flint()
    n = len(mech.names)
    zero = {v: 0 for v in mech.s.qd}
    A = flint.arb_mat(n, n, [balls(sp.diff(mech.L, a, b).xreplace(zero)) for a in mech.s.qd for b in mech.s.qd])
    rhs = flint.arb_mat(n, 1, [balls(p) - balls(sp.diff(mech.L, v).xreplace(zero))
                               for p, v in zip(mech.s.p, mech.s.qd)])
    try:
        qd = A.solve(rhs)
    except (ZeroDivisionError, ValueError) as exc:
        raise Uncertifiable(f"the velocities are not provably determined there ({exc})") from None
    for i, v in enumerate(mech.s.qd):
        balls.set(v, qd[i, 0])


def hamilton_truth(mech, balls: Balls) -> None:
    """The true rates at a phase point: q' from the momenta, p' = dL/dq + Q there (Lagrange's equation)."""
    velocities_from_momenta(mech, balls)
    for q, pd, Qi in zip(mech.s.q, mech.s.pd, mech.Q):
        balls.set(pd, balls(sp.diff(mech.L, q) + Qi))


def certify(quantity: str, expr: sp.Expr, values: Mapping[sp.Symbol, float], *, mech=None,
            truth: bool = False, phase: bool = False) -> Certificate | None:
    """A certificate that ``expr`` is nonzero at the state ``values`` (floats, taken exactly), or None.
    ``truth``: the true accelerations (and what follows from them) are needed; ``phase``: the point is
    (q, p, t), and the velocities and the true p' are solved first."""
    point = exact_point({s: v for s, v in values.items() if s in expr.free_symbols or truth or phase})
    try:
        balls = Balls(point)
        if phase:
            hamilton_truth(mech, balls)
        if truth:
            with_truth(mech, balls)
        ball = balls(sp.sympify(expr))
    except (Uncertifiable, ArithmeticError, ValueError, TypeError):
        return None
    if not excludes_zero(ball):
        return None
    derived = _derived(mech) if truth else set()
    if phase:
        derived |= {*mech.s.qd, *mech.s.pd}
    needed = (_inputs(mech, phase) if truth or phase else set()) | (expr.free_symbols - derived)
    used = sorted((s for s in point if s in needed), key=str)
    return Certificate(quantity, {str(s): str(sp.Rational(point[s].numerator, point[s].denominator)) for s in used},
                       ball.str(12, radius=True))


def _derived(mech) -> set[sp.Symbol]:
    """What `with_truth` computes rather than reads from the point."""
    return {*mech.s.qdd, *mech.s.p, *mech.multipliers, *mech.constrained}


def _inputs(mech, phase: bool) -> set[sp.Symbol]:
    """The state the truth is computed from: (q, q', t, parameters), or (q, p, t, parameters)."""
    from lagrade.problem.symbols import T

    return {*mech.s.q, *(mech.s.p if phase else mech.s.qd), T, *mech.params}


def root_between(expr: sp.Expr, x: sp.Symbol, lo: float, hi: float, values: Mapping[sp.Symbol, float],
                 quantity: str) -> Certificate | None:
    """A certificate that ``expr = 0`` has a root for ``x`` in [lo, hi]: opposite signs at the two ends,
    and an enclosure over the whole interval that is finite (no pole or cut in between, so the function
    is continuous there and crosses zero)."""
    flint = _flint()
    point = exact_point({s: v for s, v in values.items() if s in expr.free_symbols and s != x})
    a, b = Fraction(lo), Fraction(hi)
    try:
        ends = []
        for end in (a, b):
            balls = Balls({**point, x: end})
            ends.append(balls(expr))
        whole = Balls(point)
        mid, rad = (a + b) / 2, (b - a) / 2
        whole.set(x, flint.arb(flint.fmpq(mid.numerator, mid.denominator), flint.arb(flint.fmpq(rad.numerator, rad.denominator))))
        over = whole(expr)
    except (Uncertifiable, ArithmeticError, ValueError, TypeError):
        return None
    if not (excludes_zero(ends[0]) and excludes_zero(ends[1]) and over.is_finite()):
        return None
    if not ((ends[0] > 0 and ends[1] < 0) or (ends[0] < 0 and ends[1] > 0)):
        return None
    at = {str(s): str(sp.Rational(v.numerator, v.denominator)) for s, v in sorted(point.items(), key=lambda kv: str(kv[0]))}
    at[str(x)] = f"[{sp.Rational(a.numerator, a.denominator)}, {sp.Rational(b.numerator, b.denominator)}]"
    return Certificate(quantity, at, f"{ends[0].str(8, radius=True)} at one end and {ends[1].str(8, radius=True)} "
                                     f"at the other, finite in between")


def pivoted_columns(matrix):
    """The column order of a QR factorization with column pivoting (Businger and Golub, what LAPACK's
    ``geqp3`` computes): at each step the column of largest norm in the complement of those chosen. In
    numpy, for the few rows a minor has here, so that a check does not import ``scipy.linalg`` (about
    0.3 s, a quarter of a check's own work) for the order alone; the norms are recomputed at each step
    rather than downdated, which LAPACK does only for speed."""
    import numpy as np

    a = np.array(matrix, dtype=float, copy=True)
    m, n = a.shape
    order = np.arange(n)
    for j in range(min(m, n)):
        norms = np.einsum("ij,ij->j", a[j:, j:], a[j:, j:])
        p = j + int(np.argmax(norms))
        if p != j:
            a[:, [j, p]], order[[j, p]] = a[:, [p, j]], order[[p, j]]
        x = a[j:, j]
        alpha = np.linalg.norm(x)
        if alpha == 0.0:
            break
        v = x.copy()
        v[0] += np.copysign(alpha, x[0])
        v /= np.linalg.norm(v)
        a[j:, j:] -= 2.0 * np.outer(v, v @ a[j:, j:])
    return order


def outside_span(quantity: str, rows: list[list[sp.Expr]], target: list[sp.Expr], rows_at, target_at,
                 values: Mapping[sp.Symbol, float]) -> Certificate | None:
    """A certificate that the vector ``target`` is not a combination of the vectors ``rows`` (each a list
    of expressions, one per column) at a point: a square minor of the stacked matrix, its columns picked
    where the floating-point values (``rows_at``, ``target_at``) make it largest, is provably nonzero."""
    import numpy as np

    rows_at = np.asarray(rows_at, dtype=float).reshape(len(rows), -1)
    if not np.all(np.isfinite(rows_at)):
        return None
    rank = np.linalg.matrix_rank(rows_at) if rows_at.size else 0
    if 0 < rank < len(rows):  # dependent vectors (a quantity given twice): keep independent ones
        keep = pivoted_columns(rows_at.T)
        rows, rows_at = [rows[i] for i in sorted(keep[:rank])], rows_at[sorted(keep[:rank])]
    stacked = np.vstack([rows_at, np.asarray(target_at, dtype=float).reshape(1, -1)])
    if not np.all(np.isfinite(stacked)):
        return None
    size = len(rows) + 1
    if stacked.shape[1] < size:
        return None
    pivots = pivoted_columns(stacked)
    cols = sorted(pivots[:size])
    minor = sp.Matrix([[r[c] for c in cols] for r in [*rows, target]]).det(method="berkowitz")
    return certify(quantity, minor, values)


def value_at(expr: sp.Expr, values: Mapping[sp.Symbol, float], *, mech=None, truth: bool = False):
    """The arb ball of ``expr`` at the exact point, or None where it cannot be had."""
    point = exact_point({s: v for s, v in values.items() if s in expr.free_symbols or truth})
    try:
        balls = Balls(point)
        if truth:
            with_truth(mech, balls)
        return balls(sp.sympify(expr))
    except (Uncertifiable, ArithmeticError, ValueError, TypeError):
        return None


def sign_change(quantity: str, expr: sp.Expr, first: Mapping[sp.Symbol, float],
                second: Mapping[sp.Symbol, float]) -> Certificate | None:
    """A certificate that ``expr`` (continuous on the convex sampled box) is provably positive at one
    point and negative at the other, so zero somewhere on the segment between them."""
    a, b = value_at(expr, first), value_at(expr, second)
    if a is None or b is None or not (excludes_zero(a) and excludes_zero(b)) or (a > 0) == (b > 0):
        return None
    used = sorted(expr.free_symbols, key=str)
    at = {str(s): f"{sp.Rational(Fraction(float(first[s])))} then {sp.Rational(Fraction(float(second[s])))}"
          for s in used if s in first and s in second}
    return Certificate(quantity, at, f"{a.str(8, radius=True)} at the first and {b.str(8, radius=True)} at the second")


def zero_at(quantity: str, expr: sp.Expr, values: Mapping[sp.Symbol, float]) -> Certificate | None:
    """A certificate that ``expr`` is exactly zero at an exact point (a ball of radius 0 at 0)."""
    ball = value_at(expr, values)
    if ball is None or not ball.is_zero():
        return None
    at = {str(s): str(sp.Rational(Fraction(float(values[s])))) for s in sorted(expr.free_symbols, key=str)
          if s in values}
    return Certificate(quantity, at, "exactly 0")
