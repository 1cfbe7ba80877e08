"""Compiling expressions to vectorized numpy functions.

Evaluating at many random points is the grader's first and cheapest evidence, and the same
compiled functions drive the trajectory integrations, so every expression is compiled once,
with common-subexpression elimination, and evaluated on whole arrays of points at a time.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
import sympy as sp
from sympy.printing.numpy import NumPyPrinter

Vectorized = Callable[..., np.ndarray]


_COMPILED: dict[tuple, Vectorized] = {}
_COMPILED_MAX = 2048


def compile_exprs(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """``f(*arrays) -> ndarray of shape (len(exprs), K)``, broadcasting constants over the batch.

    Memoized: the reference side of a problem compiles the same expressions for every answer, and
    in a bulk run that is most of the compiling (lambdify costs milliseconds per expression)."""
    exprs = [sp.sympify(e) for e in exprs]
    exprs = [e.xreplace({sp.zoo: sp.nan}) if e.has(sp.zoo) else e for e in exprs]  # undefined: NaN, as numpy
    key = (tuple(exprs), tuple(args))
    hit = _COMPILED.get(key)
    if hit is not None:
        return hit
    if len(_COMPILED) >= _COMPILED_MAX:
        _COMPILED.pop(next(iter(_COMPILED)))
    _COMPILED[key] = made = _compile(exprs, args)
    return made


def _compile(exprs: list[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    if not exprs:
        return _Empty()
    try:
        return Generated(_generate(exprs, args), len(exprs))
    except Exception:  # noqa: BLE001  (an expression the numpy printer cannot write: lambdify's way)
        return _lambdified(exprs, args)


class _Empty:
    def __call__(self, *arrays: np.ndarray) -> np.ndarray:
        return np.zeros((0, np.broadcast(*arrays).size if arrays else 1))


class Generated:
    """A compiled batch function that pickles as its source, so reference derivations can be kept
    on disk (:mod:`lagrade.cache`) and loaded in a fraction of the time compiling them takes."""

    def __init__(self, source: str, count: int):
        self.source, self.count = source, count
        namespace: dict = {"numpy": np}
        exec(compile(source, "<lagrade compiled>", "exec"), namespace)  # noqa: S102  (our own printed code)
        self._fill = namespace["_fill"]

    def __call__(self, *arrays: np.ndarray) -> np.ndarray:
        shape = np.broadcast(*arrays).shape if arrays else ()
        with np.errstate(all="ignore"):
            return self._fill(*arrays, np.empty((self.count, *shape)))

    def __reduce__(self):
        return Generated, (self.source, self.count)


def _generate(exprs: list[sp.Expr], args: Sequence[sp.Symbol]) -> str:
    """Straight-line numpy code that writes each expression into a row of a preallocated array.

    The right-hand side of a batched integration is called hundreds of times per trajectory run, on
    arrays of a few dozen entries, where numpy's per-call overhead is the whole cost: lambdify's
    list-of-results wrapper and a copy per row cost about as much as the arithmetic itself."""
    names = [sp.Symbol(f"_a{i}") for i in range(len(args))]
    exprs = [e.xreplace(dict(zip(args, names))) for e in exprs]
    shared, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("_c"), order="none")
    printer = NumPyPrinter({"fully_qualified_modules": True, "inline": True, "allow_unknown_functions": False})
    lines = [f"def _fill({', '.join(n.name for n in names)}, _out):"]
    lines += [f"    {sym} = {printer.doprint(e)}" for sym, e in shared]
    for i, (e, whole) in enumerate(zip(reduced, exprs)):
        code = printer.doprint(e)
        lines.append(f"    _out[{i}] = " + (f"numpy.real({code})" if whole.has(sp.I) else code))
    lines.append("    return _out")
    source = "\n".join(lines)
    if "# Not supported" in source:
        raise ValueError("the numpy printer cannot write one of the expressions")
    trial = Generated(source, len(exprs))  # an unknown name or function surfaces here, not mid-integration
    trial(*np.ones((len(names), 1)))
    return source


def _lambdified(exprs: list[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    raw = sp.lambdify(list(args), exprs, modules="numpy", cse=True, docstring_limit=0)
    count = len(exprs)

    def evaluate(*arrays: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):
            out = raw(*arrays)
            shape = np.broadcast(*arrays).shape if arrays else ()
            result = np.empty((count, *shape))
            for i, o in enumerate(out):  # assignment broadcasts constants; no copies per entry
                result[i] = o.real if np.iscomplexobj(o) else o
            return result

    return evaluate


def compile_linear_solve(A: Sequence[Sequence[sp.Expr]], b: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """``x(*arrays)`` of shape (n, K) with ``A x = b`` at each point of a batch, compiled once.

    Up to two unknowns the solution is written out (Cramer's rule, the determinant shared by CSE):
    one compiled call per evaluation and no LAPACK call, which is most of a 1- or 2-DOF right-hand
    side. Larger systems: A and b in one compiled call, then batched LU (`solve_batch`)."""
    n = len(b)
    if n == 1:
        return compile_exprs([sp.sympify(b[0]) / A[0][0]], args)
    if n == 2:
        (a, c), (d, e) = A
        det = a * e - c * d
        return compile_exprs([(e * b[0] - c * b[1]) / det, (a * b[1] - d * b[0]) / det], args)
    return _LinearSolve(compile_exprs([*(x for row in A for x in row), *b], args), n)


class _LinearSolve:
    def __init__(self, both: Vectorized, n: int):
        self.both, self.n = both, n

    def __call__(self, *arrays: np.ndarray) -> np.ndarray:
        out = self.both(*arrays)
        n, K = self.n, out.shape[1]
        return solve_batch(out[:n * n].reshape(n, n, K), out[n * n:])


def scale_of(*values: np.ndarray) -> float:
    """A magnitude against which a difference counts as zero (robust to values near zero)."""
    finite = [np.abs(v[np.isfinite(v)]) for v in values]
    biggest = max((float(f.max()) for f in finite if f.size), default=1.0)
    return max(biggest, 1.0)


def agree(a: np.ndarray, b: np.ndarray, rtol: float = 1e-8) -> np.ndarray:
    """Pointwise agreement of two evaluations, NaN-aware (both undefined counts as agreeing)."""
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    tol = rtol * scale_of(a, b)
    both_nan = np.isnan(a) & np.isnan(b)
    with np.errstate(invalid="ignore"):
        return both_nan | (np.abs(a - b) <= tol)


def solve_batch(M: np.ndarray, f: np.ndarray) -> np.ndarray:
    """Solve ``M[:, :, k] x_k = f[:, k]`` for a batch: M (n, n, K), f (n, K) -> x (n, K).

    One singular state gives NaN for that state only, never for the whole batch."""
    n, K = f.shape
    with np.errstate(all="ignore"):
        if n == 1:
            return f / M[0]
        stack = M.transpose(2, 0, 1)
        try:
            return np.linalg.solve(stack, f.T[..., None])[..., 0].T
        except np.linalg.LinAlgError:
            out = np.full((n, K), np.nan)
            for k in range(K):
                try:
                    out[:, k] = np.linalg.solve(stack[k], f[:, k])
                except np.linalg.LinAlgError:
                    pass
            return out
