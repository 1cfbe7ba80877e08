"""Compiling expressions to vectorized functions of whole batches of points.

Evaluating at many random points is the grader's first and cheapest evidence, and the same
compiled functions drive the trajectory integrations, so every expression is compiled once,
with common-subexpression elimination, and evaluated on whole arrays of points at a time.

A trajectory run calls its right-hand side about 800 times on a few states, where numpy code pays
a microsecond of call overhead per operation (27 us a call for a double pendulum's accelerations
at 4 states). Machine code is made by symengine's LLVM `Lambdify` (`Compiled`): a maintained
compiler that reads no CPython or numpy internals, 2-3 ms a function and 4 us a call from Python
(`benchmarks/compilers.py`), that pickles (the disk cache, `lagrade.derive.cache`). Where it declines
(a function it has no code for, complex values, a NaN rule it does not share with numpy), or
with ``LAGRADE_NATIVE=0``, numpy code is printed instead (`Generated`): the same numbers, slower.
Evidence used once is evaluated without compiling (`evaluate`).
"""

from __future__ import annotations

import os
import pickle
import threading
from collections.abc import Callable, Sequence

import numpy as np
import sympy as sp
from sympy.printing.numpy import NumPyPrinter

Vectorized = Callable[..., np.ndarray]


_COMPILED: dict[tuple, Vectorized] = {}
#: Least recently used entries go first: a bulk run compiles the reference's functions once and
#: reuses them for every answer, while each answer's own (a few tens of kB of machine code each)
#: are used for that answer only.
_COMPILED_MAX = 256


def machine_code() -> bool:
    """Whether `compile_exprs` makes machine code: symengine importable and ``LAGRADE_NATIVE`` not
    ``0`` (to prove grades the same without it, or to rule machine code out)."""
    if os.environ.get("LAGRADE_NATIVE", "1") == "0":
        return False
    try:
        import symengine  # noqa: F401
    except ImportError:
        return False
    return True


def backend() -> str:
    """What `compile_exprs` makes here (part of the disk cache's key): ``symengine <version>`` or ``numpy``."""
    if not machine_code():
        return "numpy"
    import symengine

    return f"symengine {symengine.__version__}"


def compile_exprs(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """``f(*arrays) -> ndarray of shape (len(exprs), K)``, broadcasting constants over the batch.

    Memoized: the reference side of a problem compiles the same expressions for every answer, and
    in a bulk run that is most of the compiling (milliseconds per function)."""
    exprs = _defined(exprs)
    key = (tuple(exprs), tuple(args), machine_code())
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
    return compile_machine(exprs, args) or compile_numpy(exprs, args)


# --------------------------------------------------------------------------- machine code


class _Declined(Exception):
    pass


def compile_machine(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Compiled | None:
    """Machine code for ``exprs`` (not memoized), or None where symengine cannot compile them to
    what numpy code computes, or machine code is switched off (`machine_code`)."""
    if not exprs or not args or not machine_code():
        return None
    import symengine as se

    # symengine's cse names its temporaries x0, x1, ... and confuses them with arguments of those
    # names (12.8's x1, x2): the arguments get names it never makes
    names = [se.Symbol(f"_a{i}") for i in range(len(args))]
    try:
        rename = dict(zip((se.sympify(a) for a in args), names))
        forms = [_llvm_form(se.sympify(_real(e)).xreplace(rename)) if e.has(*_REWRITTEN)
                 else se.sympify(_real(e)).xreplace(rename) for e in _defined(exprs)]
        # -O0: 1.4-2.2 ms a compile instead of 4 at -O3, for calls under 0.15 us slower at 4-64 states
        # (12.14's and 12.37's accelerations): a student's equations are compiled once for ~800 calls
        f = se.Lambdify(names, forms, backend="llvm", cse=True, real=True, opt_level=0)
        # a function just compiled keeps its LLVM module and optimiser, about 460 kB; loaded from its
        # object code, about 10 kB (measured over 200): 0.1 ms here keeps a bulk run's memo small
        f = pickle.loads(pickle.dumps(f))
    except Exception:  # noqa: BLE001  (conversion or code generation declined: numpy code, same numbers)
        return None
    return Compiled(f, len(forms), len(args))


#: what `_llvm_form` rewrites (the others are left as they are, without walking them in Python)
_REWRITTEN = (sp.sign, sp.Max, sp.Min, sp.Piecewise, sp.Heaviside)


def _real(e: sp.Expr) -> sp.Expr:
    """``e`` for symengine: real, Heaviside as the Piecewise numpy code evaluates (symengine has none)."""
    if not isinstance(e, sp.Expr) or e.has(sp.I):
        raise _Declined("complex values: numpy code takes the real part at the end")
    return e.replace(sp.Heaviside, lambda *a: sp.Heaviside(*a).rewrite(sp.Piecewise)) if e.has(sp.Heaviside) else e


def _llvm_form(e):
    """A symengine expression with numpy's NaN rules spelled out where symengine's code differs:
    sign, Max and Min of NaN are NaN, ``!=`` with NaN holds, a Piecewise no branch of which holds
    is NaN. Conditions become nested Piecewise on ordered comparisons, the one kind both share."""
    import symengine as se

    memo: dict = {}

    def choose(cond, then, other):
        """``then`` where ``cond`` holds as numpy evaluates it, else ``other``."""
        kind = type(cond).__name__
        if kind == "BooleanTrue":
            return then
        if kind == "BooleanFalse":
            return other
        if kind == "Unequality":
            return se.Piecewise((other, se.Eq(*cond.args)), (then, True))
        if kind == "Not":
            return choose(cond.args[0], other, then)
        if kind == "And":
            first, *rest = cond.args
            return choose(first, choose(se.And(*rest), then, other) if rest else then, other)
        if kind == "Or":
            first, *rest = cond.args
            return choose(first, then, choose(se.Or(*rest), then, other) if rest else other)
        if kind in ("Equality", "LessThan", "StrictLessThan"):
            return se.Piecewise((then, cond), (other, True))
        raise _Declined(kind)

    def walk(e):
        hit = memo.get(e)
        if hit is not None:
            return hit
        args = e.args
        new = [walk(a) for a in args]
        kind = type(e).__name__
        if kind == "sign":
            x = new[0]
            r = se.Piecewise((1, x > 0), (-1, x < 0), (0, se.Eq(x, 0)), (se.nan, True))
        elif kind in ("Max", "Min"):  # x_i where it is >= (<=) every other: no branch holds for NaN
            r = se.nan
            for i, x in reversed(list(enumerate(new))):
                r = choose(se.And(*[x >= y if kind == "Max" else x <= y for j, y in enumerate(new) if j != i]), x, r)
        elif kind == "Piecewise":
            r = se.nan
            for value, cond in reversed(list(zip(new[::2], new[1::2]))):
                r = choose(cond, value, r)
        elif all(a is b for a, b in zip(args, new)):
            r = e
        else:  # relations and connectives have no ``func`` in symengine
            make = {"Equality": se.Eq, "Unequality": se.Ne, "LessThan": se.Le, "StrictLessThan": se.Lt,
                    "And": se.And, "Or": se.Or, "Not": se.Not}.get(kind)
            r = make(*new) if make else e.func(*new)
        memo[e] = r
        return r

    return walk(e)


def is_machine_code(f: object) -> bool:
    """Whether ``f`` (made by `compile_exprs` or `compile_linear_solve`) runs machine code."""
    return isinstance(getattr(f, "both", f), Compiled)


class Compiled:
    """Machine code with the calling convention of `Generated`: ``f(*arrays) -> ndarray (count,
    *shape)``, arrays and numbers broadcasting together; ``blocks`` takes blocks of rows.

    The code is called on one contiguous buffer of points (a row of arguments per point) through
    symengine's ``unsafe_eval``, which trusts the sizes: they are checked here. It pickles as
    symengine's object code, and its machine code goes with its last reference."""

    __slots__ = ("_scratch", "count", "f", "nargs")

    def __init__(self, f, count: int, nargs: int):
        self.f, self.count, self.nargs = f, count, nargs
        self._scratch = threading.local()  # per thread: the buffers of `blocks`, kept between calls

    def __reduce__(self):
        return Compiled, (self.f, self.count, self.nargs)

    def __call__(self, *arrays: np.ndarray) -> np.ndarray:
        if len(arrays) != self.nargs:
            raise ValueError(f"{len(arrays)} arguments given, {self.nargs} expected")
        shape = ()
        for a in arrays:  # the common case (equal shapes and numbers) without numpy's broadcast
            s = getattr(a, "shape", ())
            if s and s != shape:
                if shape:
                    shape = np.broadcast(*arrays).shape
                    break
                shape = s
        src = np.empty((*shape, self.nargs))
        for i, a in enumerate(arrays):
            src[..., i] = a
        return self._run(src, shape)

    def blocks(self, *blocks: np.ndarray) -> np.ndarray:
        """The same, the arguments given as blocks of consecutive rows, each ``(rows, K)`` or
        ``(rows, 1)``: q, q', t and the parameters of a batch, each copied once."""
        K, rows, equal = blocks[0].shape[1], 0, True
        for b in blocks:
            rows += b.shape[0]
            if b.shape[1] != K:
                K, equal = max(K, b.shape[1]), False
        if rows != self.nargs:
            raise ValueError(f"{rows} arguments given in blocks, {self.nargs} expected")
        # the integrator's calls: buffers kept from call to call and one numpy call to fill them
        # (about a quarter of a call's 5 us: 12.14 at K = 4 and 64)
        kept = getattr(self._scratch, "kept", None)
        if kept is None or kept[0] != K:
            src, out = np.empty((K, self.nargs)), np.empty((K, self.count))
            kept = self._scratch.kept = (K, src, out, src.reshape(-1), out.reshape(-1))
        _, src, out, src_flat, out_flat = kept
        if equal:
            np.concatenate([b.T for b in blocks], axis=1, out=src)
        else:
            row = 0
            for b in blocks:
                end = row + b.shape[0]
                src[:, row:end] = b.T  # a (rows, 1) block broadcasts over the columns
                row = end
        self.f.unsafe_eval(src_flat, out_flat, K)
        return out.T.copy()  # the caller's own: the buffers serve the next call

    def _run(self, src: np.ndarray, shape: tuple) -> np.ndarray:
        size = src.size // self.nargs
        out = np.empty((size, self.count))
        if size:
            self.f.unsafe_eval(src.reshape(-1), out.reshape(-1), size)
        return np.ascontiguousarray(out.T).reshape((self.count, *shape))


def compile_numpy(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Vectorized:
    """The numpy form of `compile_exprs` (not memoized): where machine code is switched off or
    declines an expression (complex intermediates, functions outside symengine's vocabulary)."""
    exprs = _defined(exprs)
    try:
        return Generated(_generate(exprs, args), len(exprs))
    except Exception:  # noqa: BLE001  (an expression the numpy printer cannot write: lambdify's way)
        return _lambdified(exprs, args)


def call_blocks(f: Vectorized, *blocks: np.ndarray) -> np.ndarray:
    """``f(*args)`` with the arguments given as blocks of consecutive rows, each ``(rows, *shape)``
    or ``(rows, 1)`` for a constant per row: a right-hand side's q, q', t and parameters.

    Unpacking a batch into one array per argument costs a few microseconds per call, as much as
    machine code takes for the whole right-hand side; `Compiled.blocks` copies each block once
    into the one buffer its code reads instead."""
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
    on disk (:mod:`lagrade.derive.cache`) and loaded in a fraction of the time compiling them takes."""

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
    side. Larger systems: A and b in one compiled call, then batched LU (`solve_batch`): written out,
    the elimination grows as n^3 in the compiled code, and LAPACK's loop is already machine code."""
    n = len(b)
    if n == 1:
        return compile_exprs([sp.sympify(b[0]) / A[0][0]], args)
    if n == 2:
        (a, c), (d, e) = A
        det = a * e - c * d
        return compile_exprs([(e * b[0] - c * b[1]) / det, (a * b[1] - d * b[0]) / det], args)
    entries = _defined([*(x for row in A for x in row), *b])
    key = (tuple(entries), tuple(args), machine_code(), "solve")
    hit = _COMPILED.get(key)
    if hit is None:
        hit = _LinearSolve(compile_exprs(entries, args), n)
        _remember(key, hit)
    return hit


class _LinearSolve:
    def __init__(self, both: Vectorized, n: int):
        self.both, self.n = both, n

    def __call__(self, *arrays: np.ndarray) -> np.ndarray:
        return self._solved(self.both(*arrays))

    def blocks(self, *blocks: np.ndarray) -> np.ndarray:
        return self._solved(call_blocks(self.both, *blocks))

    def _solved(self, out: np.ndarray) -> np.ndarray:
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


# --------------------------------------------------------------------------- right-hand sides


class CompiledRates:
    """Rates ``(t, Y (dim, K)) -> (dim, K)`` from ``f`` of the rows [Y, t, constants].

    A trajectory run evaluates its rates about 800 times; kept as data (one compiled function of
    the argument rows) rather than a closure, a call is one `call_blocks` and the integrator can
    double the batch (`pair`). ``copied``: the first ``copied`` rates are the state rows
    ``copied .. 2 copied - 1`` as they are (q' = q-dot of a second-order system, whose ``f`` gives
    the accelerations only); ``f`` writes the other ``dim - copied``. ``constants``: (C, K) per
    trajectory, or (C, 1) shared; they are the parameters (and a part's extra symbols) of each
    sampled state. ``timed=False``: ``f`` has no t row (an autonomous scene's model compiles none,
    `lagrade.compare.scene_model.SceneModel.compiled_rates`), so the rows are [Y, constants].
    """

    __slots__ = ("_kept", "constants", "copied", "dim", "f", "timed")

    def __init__(self, f: Vectorized, dim: int, constants: np.ndarray, copied: int = 0, timed: bool = True):
        self.f, self.dim, self.copied, self.timed = f, dim, copied, timed
        values = np.asarray(constants, dtype=float)
        self.constants = np.ascontiguousarray(values[:, None] if values.ndim == 1 else values)
        self._kept = threading.local()

    def __call__(self, t: float | np.ndarray, Y: np.ndarray) -> np.ndarray:
        if not isinstance(self.f, Compiled):
            body = call_blocks(self.f, Y, as_row(t), self.constants) if self.timed \
                else call_blocks(self.f, Y, self.constants)
            c = self.copied
            return np.concatenate([Y[c:2 * c], body]) if c else body
        # Machine code: the points' rows are written into a buffer that already holds the constants
        # (kept per thread and batch size), so a call is two copies in, the code, and one out: half
        # the cost of `call_blocks` for the integrator's 800 calls a run (docs/performance.md).
        dim, c, K = self.dim, self.copied, Y.shape[1]
        kept = getattr(self._kept, "buffers", None)
        if kept is None or kept[0] != K:
            src, out = np.empty((K, self.f.nargs)), np.empty((K, self.f.count))
            src[:, dim + self.timed:] = self.constants.T
            time_col = src[:, dim] if self.timed else None
            kept = self._kept.buffers = (K, src.reshape(-1), out.reshape(-1), src[:, :dim], time_col, out.T)
        _, src, out, state, time, body = kept
        state[...] = Y.T
        if time is not None:
            time[...] = t
        self.f.f.unsafe_eval(src, out, K)
        result = np.empty((dim, K))
        result[:c] = Y[c:2 * c]
        result[c:] = body
        return result

    def pair(self) -> CompiledRates:
        """The same rates for a batch of twice the columns: each state and a displaced copy of it."""
        return CompiledRates(self.f, self.dim, np.concatenate([self.constants, self.constants], axis=1)
                             if self.constants.shape[1] > 1 else self.constants, self.copied, self.timed)
