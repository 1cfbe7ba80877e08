"""Compiling expressions to vectorized functions of whole batches of points.

Evaluating at many random points is the grader's first and cheapest evidence, and the same
compiled functions drive the trajectory integrations, so every expression is compiled once,
with common-subexpression elimination, and evaluated on whole arrays of points at a time:
as machine code where llvmlite is installed (:mod:`lagrade.native`), else as numpy code.
Evidence used once is evaluated without compiling (`evaluate`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from lagrade.native import compile_native

Vectorized = Callable[..., np.ndarray]


_COMPILED: dict[tuple, Vectorized] = {}
#: Least recently used entries go first: a bulk run compiles the reference's functions once and
#: reuses them for every answer, while each answer's own (a few tens of kB of machine code each)
#: are used for that answer only.
_COMPILED_MAX = 256


def compile_exprs(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """``f(*arrays) -> ndarray of shape (len(exprs), K)``, broadcasting constants over the batch.

    Memoized: the reference side of a problem compiles the same expressions for every answer, and
    in a bulk run that is most of the compiling (lambdify costs milliseconds per expression)."""
    exprs = _defined(exprs)
    key = (tuple(exprs), tuple(args))
    hit = _COMPILED.get(key)
    if hit is None:
        hit = _compile(exprs, args)
    _remember(key, hit)
    return hit


def _remember(key: tuple, made: Vectorized) -> None:
    """Keep ``made`` as the most recently used entry of the memo (the least recently used goes)."""
    _COMPILED.pop(key, None)
    if len(_COMPILED) >= _COMPILED_MAX:
        _COMPILED.pop(next(iter(_COMPILED)))
    _COMPILED[key] = made


def _compile(exprs: list[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    if not exprs:
        return _Empty()
    return compile_native(exprs, args) or compile_numpy(exprs, args)


def compile_numpy(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """The numpy form of `compile_exprs` (not memoized): where llvmlite is missing or cannot write
    an expression (complex intermediates, functions outside its vocabulary)."""
    exprs = _defined(exprs)
    try:
        return Generated(_generate(exprs, args), len(exprs))
    except Exception:  # noqa: BLE001  (an expression the numpy printer cannot write: lambdify's way)
        return _lambdified(exprs, args)


def call_blocks(f: Vectorized, *blocks: np.ndarray) -> np.ndarray:
    """``f(*args)`` with the arguments given as blocks of consecutive rows, each ``(rows, *shape)``
    or ``(rows, 1)`` for a constant per row: a right-hand side's q, q', t and parameters.

    Unpacking a batch into one array per argument costs a few microseconds per call, as much as
    machine code takes for the whole right-hand side; `lagrade.native.Native.blocks` copies each
    block once instead."""
    fast = getattr(f, "blocks", None)
    if fast is not None:
        return fast(*blocks)
    return f(*(row for b in blocks for row in b))


def as_row(x: np.ndarray | float) -> np.ndarray:
    """``x`` as a block of one row for `call_blocks`: (K,) -> (1, K), a number -> (1, 1). A method
    call, not ``np.reshape`` (which costs a microsecond per right-hand side call)."""
    return x.reshape(1, -1) if isinstance(x, np.ndarray) else np.full((1, 1), x, dtype=float)


def _defined(exprs: Sequence[sp.Expr]) -> list[sp.Expr]:
    """Sympified, with complex infinity (1/0 in sympy) as NaN: undefined, as numpy has it."""
    exprs = [sp.sympify(e) for e in exprs]
    return [e.xreplace({sp.zoo: sp.nan}) if e.has(sp.zoo) else e for e in exprs]


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


# --------------------------------------------------------------------------- evaluating once

_FUNCTIONS: dict[str, Callable[..., np.ndarray]] = {
    "sin": np.sin, "cos": np.cos, "tan": np.tan, "cot": lambda x: 1.0 / np.tan(x),
    "sec": lambda x: 1.0 / np.cos(x), "csc": lambda x: 1.0 / np.sin(x),
    "asin": np.arcsin, "acos": np.arccos, "atan": np.arctan, "atan2": np.arctan2,
    "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh, "asinh": np.arcsinh, "acosh": np.arccosh,
    "atanh": np.arctanh, "exp": np.exp, "Abs": np.abs, "sign": np.sign, "floor": np.floor,
    "ceiling": np.ceil, "re": np.real, "im": np.imag, "conjugate": np.conj,
    "Heaviside": lambda x, h=0.5: np.heaviside(x, h),
    "Max": lambda *a: np.maximum.reduce(np.broadcast_arrays(*a)),
    "Min": lambda *a: np.minimum.reduce(np.broadcast_arrays(*a)),
}
_COMPARE = {"StrictLessThan": np.less, "LessThan": np.less_equal, "StrictGreaterThan": np.greater,
            "GreaterThan": np.greater_equal, "Equality": np.equal, "Unequality": np.not_equal,
            "And": np.logical_and, "Or": np.logical_or, "Not": np.logical_not}


class _Unsupported(Exception):
    pass


def evaluate(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol], arrays: Sequence[np.ndarray]) -> np.ndarray:
    """``compile_exprs(exprs, args)(*arrays)`` for expressions evaluated once, without compiling.

    Most evidence is one evaluation at a few dozen sampled states; printing and compiling code for
    that costs milliseconds per expression, walking the expression tree with numpy (shared subtrees
    once) costs tens of microseconds. A node the walker does not know is compiled instead."""
    exprs = [sp.sympify(e) for e in exprs]
    try:
        return _walk(exprs, args, arrays)
    except _Unsupported:
        return compile_exprs(exprs, args)(*arrays)


def _walk(exprs: list[sp.Expr], args: Sequence[sp.Symbol], arrays: Sequence[np.ndarray]) -> np.ndarray:
    env: dict[sp.Basic, object] = {a: np.asarray(v, dtype=float) for a, v in zip(args, arrays)}

    def ev(e: sp.Basic):
        hit = env.get(e)
        if hit is not None:
            return hit
        if e.is_Number or e.is_NumberSymbol:
            r = np.complex128(complex(e)) if e.is_extended_real is False else np.float64(float(e))
        elif e is sp.I:
            r = np.complex128(1j)
        elif e.is_Add:
            parts = [ev(a) for a in e.args]
            r = parts[0]
            for x in parts[1:]:
                r = r + x
        elif e.is_Mul:
            parts = [ev(a) for a in e.args]
            r = parts[0]
            for x in parts[1:]:
                r = r * x
        elif e.is_Pow:
            base, exp = e.args
            b = ev(base)
            if exp is sp.S.Half:
                r = np.sqrt(b)
            elif exp.is_Integer:
                k = int(exp)
                r = b ** k if k > 0 else np.float64(1.0) / (b ** -k) if k < 0 else np.ones_like(b)
            else:
                r = np.power(b, ev(exp))
        elif isinstance(e, sp.Piecewise):
            conds = [np.broadcast_to(ev(c), shape) for _, c in e.args]
            vals = [np.broadcast_to(ev(v), shape) for v, _ in e.args]
            r = np.select(conds, vals, default=np.nan)
        elif e is sp.true or e is sp.false:
            r = np.bool_(bool(e))
        elif e is sp.zoo or e is sp.nan:
            r = np.float64(np.nan)
        elif type(e).__name__ in _COMPARE:
            r = _COMPARE[type(e).__name__](*(ev(a) for a in e.args))
        elif isinstance(e, sp.Function) and type(e).__name__ in _FUNCTIONS:
            r = _FUNCTIONS[type(e).__name__](*(ev(a) for a in e.args))
        elif isinstance(e, sp.log):
            r = np.log(ev(e.args[0])) if len(e.args) == 1 else np.log(ev(e.args[0])) / np.log(ev(e.args[1]))
        else:
            raise _Unsupported(type(e).__name__)
        env[e] = r
        return r

    shape = np.broadcast(*arrays).shape if arrays else ()
    out = np.empty((len(exprs), *shape))
    with np.errstate(all="ignore"):
        for i, e in enumerate(exprs):
            v = ev(e)
            out[i] = v.real if np.iscomplexobj(v) else v
    return out


def compile_linear_solve(A: Sequence[Sequence[sp.Expr]], b: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """``x(*arrays)`` of shape (n, K) with ``A x = b`` at each point of a batch, compiled once.

    Up to two unknowns the solution is written out (Cramer's rule, the determinant shared by CSE):
    one compiled call per evaluation and no LAPACK call, which is most of a 1- or 2-DOF right-hand
    side. Larger systems: in machine code, A and b and then the elimination in the same function
    (`lagrade.native`); in numpy code, A and b in one compiled call, then batched LU (`solve_batch`)."""
    n = len(b)
    if n == 1:
        return compile_exprs([sp.sympify(b[0]) / A[0][0]], args)
    if n == 2:
        (a, c), (d, e) = A
        det = a * e - c * d
        return compile_exprs([(e * b[0] - c * b[1]) / det, (a * b[1] - d * b[0]) / det], args)
    entries = _defined([*(x for row in A for x in row), *b])
    key = (tuple(entries), tuple(args), "solve")
    hit = _COMPILED.get(key)
    if hit is None:
        hit = compile_native(entries, args, solve=n) or _LinearSolve(compile_exprs(entries, args), n)
        _remember(key, hit)
    return hit


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
