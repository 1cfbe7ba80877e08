"""Machine code for the right-hand sides an integration calls hundreds of times (LLVM, via llvmlite).

A trajectory run calls its right-hand side about 800 times on a batch of a few states. In numpy
each of the few dozen operations in a double pendulum's accelerations costs a microsecond of
call overhead whatever the batch size, so the arithmetic itself is noise: one evaluation costs
about 25 us, a numba-compiled one under 1 us. numba takes about a second to import and hundreds of
milliseconds to compile each function, more than a whole check. llvmlite (numba's own LLVM
binding) loads in about 20 ms, and its ORC JIT turns the straight-line IR printed here into
machine code in about a millisecond, which a student's equations of motion repay within one
trajectory run.

What is compiled: one function ``f(double *in, double *out, int64 K)`` that loops over the K
columns of ``in`` (one row per argument) and writes each expression into a row of ``out``, with
common subexpressions computed once per column; the same loop also reads its arguments in place
from numpy arrays when called from Python (`Native.blocks`). The arithmetic is IEEE double without
fast-math (no reassociation), calling the C library for sin, cos, exp, ... Anything outside that
vocabulary (complex values, unknown functions) makes `compile_native` return None, and the caller
keeps the numpy code. For an integration, `Stages` links such a function (a scene's rates) with a
loop over Runge-Kutta stages, so that one call does a whole DOP853 step of a batch: in Python, a
stage of a double pendulum at 4 states cost about 15 us, in this loop under 1 us.
"""

from __future__ import annotations

import ctypes
import functools
import itertools
import math
import os
import sys
import threading
from collections.abc import Sequence

import numpy as np
import sympy as sp

__all__ = ["Native", "Stages", "available", "backend", "compile_native"]


@functools.cache
def _llvm():
    """(llvmlite.ir, llvmlite.binding, native target), or None: without llvmlite, or with
    ``LAGRADE_NATIVE=0`` (to compare against, or to rule native code out), numpy code is used."""
    if os.environ.get("LAGRADE_NATIVE", "1") == "0":
        return None
    try:
        import llvmlite.binding as binding
        import llvmlite.ir as ir
    except ImportError:
        return None
    try:
        binding.initialize()  # required before llvmlite 0.45, an error after
    except RuntimeError:
        pass
    try:
        binding.initialize_native_target()
        binding.initialize_native_asmprinter()
        return ir, binding, binding.Target.from_default_triple()
    except Exception:  # noqa: BLE001  (no native target here: the numpy code grades the same)
        return None


def available() -> bool:
    """Whether native code can be made here (llvmlite importable, not switched off)."""
    return _llvm() is not None


def backend() -> str:
    """What `lagrade.numeric.compile_exprs` makes here: ``llvmlite <version>`` or ``numpy``."""
    if _llvm() is None:
        return "numpy"
    import llvmlite

    return f"llvmlite {llvmlite.__version__}"


class _Unsupported(Exception):
    pass


_UNARY = {  # sympy function name -> C library function
    "sin": "sin", "cos": "cos", "tan": "tan", "asin": "asin", "acos": "acos", "atan": "atan",
    "sinh": "sinh", "cosh": "cosh", "tanh": "tanh", "asinh": "asinh", "acosh": "acosh",
    "atanh": "atanh", "exp": "exp", "floor": "floor", "ceiling": "ceil",
}
_RECIPROCAL = {"cot": "tan", "sec": "cos", "csc": "sin"}
_COMPARE = {"StrictLessThan": "<", "LessThan": "<=", "StrictGreaterThan": ">", "GreaterThan": ">=",
            "Equality": "==", "Unequality": "!="}


class _Emitter:
    """Prints a sympy expression DAG as LLVM IR in one basic block (shared subtrees once)."""

    def __init__(self, ir, module, builder, env):
        self.ir, self.module, self.b, self.env = ir, module, builder, env
        self.double = ir.DoubleType()
        self.bool = ir.IntType(1)

    def const(self, x: float):
        return self.ir.Constant(self.double, x)

    def libm(self, name: str, arity: int = 1):
        fn = self.module.globals.get(name)
        if fn is None:
            fn = self.ir.Function(self.module, self.ir.FunctionType(self.double, [self.double] * arity), name=name)
        return fn

    def intrinsic(self, name: str):
        return self.module.declare_intrinsic(name, [self.double])

    def ev(self, e: sp.Basic):
        hit = self.env.get(e)
        if hit is not None:
            return hit
        r = self._emit(e)
        self.env[e] = r
        return r

    def _emit(self, e: sp.Basic):  # noqa: C901, PLR0911, PLR0912  (one case per kind of node)
        b = self.b
        if e is sp.nan or e is sp.zoo:  # undefined: NaN, as numpy
            return self.const(math.nan)
        if e.is_Number or e.is_NumberSymbol:
            if e.is_extended_real is False:
                raise _Unsupported("complex constant")
            return self.const(float(e))
        if e.is_Add:
            parts = [self.ev(a) for a in e.args]
            r = parts[0]
            for x in parts[1:]:
                r = b.fadd(r, x)
            return r
        if e.is_Mul:
            num, den = [], []
            for a in e.args:
                if a.is_Pow and a.exp.is_Rational and a.exp.is_negative:
                    den.append(self.ev(sp.Pow(a.base, -a.exp, evaluate=False)))
                elif a.is_Rational and not a.is_Integer and a.p in (1, -1):
                    num.append(self.const(float(a.p)))
                    den.append(self.const(float(a.q)))
                else:
                    num.append(self.ev(a))
            r = num[0] if num else self.const(1.0)
            for x in num[1:]:
                r = b.fmul(r, x)
            if den:
                d = den[0]
                for x in den[1:]:
                    d = b.fmul(d, x)
                r = b.fdiv(r, d)
            return r
        if e.is_Pow:
            return self._pow(e.base, e.exp)
        if isinstance(e, sp.Piecewise):
            r = self.const(math.nan)
            for value, cond in reversed(e.args):
                r = b.select(self.ev_bool(cond), self.ev(value), r)
            return r
        name = type(e).__name__
        if name in ("Max", "Min"):
            op = ">" if name == "Max" else "<"
            vals = [self.ev(a) for a in e.args]
            r = vals[0]
            for x in vals[1:]:  # NaN propagates, as numpy.maximum / minimum
                keep = b.or_(b.fcmp_ordered(op, r, x), b.fcmp_unordered("uno", r, r))
                r = b.select(keep, r, x)
            return r
        if isinstance(e, sp.Function):
            args = e.args
            if name in _UNARY and len(args) == 1:
                return b.call(self.libm(_UNARY[name]), [self.ev(args[0])])
            if name in _RECIPROCAL and len(args) == 1:
                return b.fdiv(self.const(1.0), b.call(self.libm(_RECIPROCAL[name]), [self.ev(args[0])]))
            if name == "log":
                r = b.call(self.libm("log"), [self.ev(args[0])])
                if len(args) == 2:
                    r = b.fdiv(r, b.call(self.libm("log"), [self.ev(args[1])]))
                return r
            if name == "atan2" and len(args) == 2:
                return b.call(self.libm("atan2", 2), [self.ev(args[0]), self.ev(args[1])])
            if name == "Abs" and len(args) == 1:
                return b.call(self.intrinsic("llvm.fabs"), [self.ev(args[0])])
            if name == "sign" and len(args) == 1:
                x = self.ev(args[0])
                zero = self.const(0.0)
                r = b.select(b.fcmp_ordered(">", x, zero), self.const(1.0),
                             b.select(b.fcmp_ordered("<", x, zero), self.const(-1.0), zero))
                return b.select(b.fcmp_unordered("uno", x, x), x, r)  # sign(NaN) = NaN, as numpy
            if name == "Heaviside" and len(args) in (1, 2):
                x = self.ev(args[0])
                at0 = self.ev(args[1]) if len(args) == 2 else self.const(0.5)
                zero = self.const(0.0)
                r = b.select(b.fcmp_ordered(">", x, zero), self.const(1.0),
                             b.select(b.fcmp_ordered("==", x, zero), at0, zero))
                return b.select(b.fcmp_unordered("uno", x, x), x, r)
        raise _Unsupported(name)

    def _pow(self, base: sp.Basic, exp: sp.Basic):
        b = self.b
        if exp.is_Integer and abs(int(exp)) <= 64:
            k = int(exp)
            if k == 0:
                return self.const(1.0)
            x, r = self.ev(base), None
            n = abs(k)
            while n:  # square-and-multiply, as numpy's integer powers
                if n & 1:
                    r = x if r is None else b.fmul(r, x)
                n >>= 1
                if n:
                    x = b.fmul(x, x)
            return b.fdiv(self.const(1.0), r) if k < 0 else r
        if exp == sp.S.Half:
            return b.call(self.intrinsic("llvm.sqrt"), [self.ev(base)])
        if exp == -sp.S.Half:
            return b.fdiv(self.const(1.0), b.call(self.intrinsic("llvm.sqrt"), [self.ev(base)]))
        if exp.is_extended_real is False:
            raise _Unsupported("complex power")
        return b.call(self.libm("pow", 2), [self.ev(base), self.ev(exp)])

    def ev_bool(self, c: sp.Basic):
        b = self.b
        if c is sp.true:
            return self.ir.Constant(self.bool, 1)
        if c is sp.false:
            return self.ir.Constant(self.bool, 0)
        name = type(c).__name__
        if name in _COMPARE:
            op = _COMPARE[name]
            lhs, rhs = self.ev(c.args[0]), self.ev(c.args[1])
            return b.fcmp_unordered(op, lhs, rhs) if op == "!=" else b.fcmp_ordered(op, lhs, rhs)
        if name in ("And", "Or"):
            parts = [self.ev_bool(a) for a in c.args]
            r = parts[0]
            for x in parts[1:]:
                r = b.and_(r, x) if name == "And" else b.or_(r, x)
            return r
        if name == "Not":
            return b.not_(self.ev_bool(c.args[0]))
        raise _Unsupported(name)


def _solved(ir, b, values: list, n: int) -> list:
    """x with A x = r for A (n*n entries, row by row) and r (n entries) following in ``values``:
    Gaussian elimination with partial pivoting, unrolled (n is small, and known when compiling).
    A zero pivot makes the whole solution NaN, as `lagrade.numeric.solve_batch` has it."""
    double = ir.DoubleType()
    fabs = b.module.declare_intrinsic("llvm.fabs", [double])
    a = [values[i * n:(i + 1) * n] for i in range(n)]
    r = values[n * n:]
    zero = ir.Constant(double, 0.0)
    singular = ir.Constant(ir.IntType(1), 0)
    for col in range(n):
        for i in range(col + 1, n):  # keep the larger |entry| in the pivot row: the largest after the pass
            swap = b.fcmp_ordered(">", b.call(fabs, [a[i][col]]), b.call(fabs, [a[col][col]]))
            for j in range(col, n):
                a[col][j], a[i][j] = b.select(swap, a[i][j], a[col][j]), b.select(swap, a[col][j], a[i][j])
            r[col], r[i] = b.select(swap, r[i], r[col]), b.select(swap, r[col], r[i])
        pivot = a[col][col]
        singular = b.or_(singular, b.fcmp_ordered("==", pivot, zero))
        for i in range(col + 1, n):
            f = b.fdiv(a[i][col], pivot)
            for j in range(col + 1, n):
                a[i][j] = b.fsub(a[i][j], b.fmul(f, a[col][j]))
            r[i] = b.fsub(r[i], b.fmul(f, r[col]))
    x = [None] * n
    for i in reversed(range(n)):
        acc = r[i]
        for j in range(i + 1, n):
            acc = b.fsub(acc, b.fmul(a[i][j], x[j]))
        x[i] = b.fdiv(acc, a[i][i])
    nan = ir.Constant(double, math.nan)
    return [b.select(singular, nan, v) for v in x]


def _entry(ir, module, name: str):
    """The function ``name`` of the rates' module, declared in ``module`` (defined there by
    `_module_ir`, declared by the modules linked with it): one signature for all of them.

    ``lagrade_body(double **arg, i64 *step, double *out, i64 K)``; ``lagrade_fill(double *in,
    double *out, i64 K)``."""
    double, i64 = ir.DoubleType(), ir.IntType(64)
    dptr = double.as_pointer()
    args = {"lagrade_body": [dptr.as_pointer(), i64.as_pointer(), dptr, i64], "lagrade_fill": [dptr, dptr, i64]}[name]
    return ir.Function(module, ir.FunctionType(ir.VoidType(), args), name=name)


def _module_ir(exprs: list[sp.Expr], args: Sequence[sp.Symbol], solve: int = 0) -> str:
    """The LLVM IR of ``void lagrade_body(double **arg, i64 *step, double *out, i64 K)``: argument i
    of column k is ``arg[i][k * step[i]]`` (step 0: one value for every column), expression j goes
    to ``out[j * K + k]``; and of ``void lagrade_fill(double *in, double *out, i64 K)``, the same on
    one contiguous row per argument. With ``solve`` = n, the expressions are A (n*n) and r (n) and
    what is written is x with A x = r (`_solved`)."""
    ir, _, _ = _llvm()
    double, i64 = ir.DoubleType(), ir.IntType(64)
    dptr = double.as_pointer()
    nargs = len(args)
    module = ir.Module(name="lagrade")
    body = _entry(ir, module, "lagrade_body")
    arg, step, dst, K = body.args
    entry, loop, done = (body.append_basic_block(x) for x in ("entry", "loop", "done"))
    b = ir.IRBuilder(entry)
    rows = [(b.load(b.gep(arg, [ir.Constant(i64, i)])), b.load(b.gep(step, [ir.Constant(i64, i)])))
            for i in range(nargs)]
    b.cbranch(b.icmp_signed(">", K, ir.Constant(i64, 0)), loop, done)
    b.position_at_end(loop)
    k = b.phi(i64)
    k.add_incoming(ir.Constant(i64, 0), entry)
    env = {a: b.load(b.gep(row, [b.mul(k, stride)])) for a, (row, stride) in zip(args, rows)}
    # each distinct subexpression once (the emitter's memo): sympy's cse also shares parts of products
    # and sums, 53 operations instead of 71 for a double pendulum's accelerations, but took two thirds
    # of a compile (about 17 of 26 ms), paid for every answer's equations, for 1-3% faster calls
    emit = _Emitter(ir, module, b, env)
    values = [emit.ev(e) for e in exprs]
    if solve:
        values = _solved(ir, b, values, solve)
    for j, v in enumerate(values):
        at = b.add(b.mul(ir.Constant(i64, j), K), k)
        b.store(v, b.gep(dst, [at]))
    nxt = b.add(k, ir.Constant(i64, 1))
    k.add_incoming(nxt, loop)
    b.cbranch(b.icmp_signed("<", nxt, K), loop, done)
    b.position_at_end(done)
    b.ret_void()

    fill = _entry(ir, module, "lagrade_fill")
    src, out, K = fill.args
    b = ir.IRBuilder(fill.append_basic_block("entry"))
    table = b.alloca(dptr, ir.Constant(i64, max(nargs, 1)))
    steps = b.alloca(i64, ir.Constant(i64, max(nargs, 1)))
    for i in range(nargs):
        b.store(b.gep(src, [b.mul(ir.Constant(i64, i), K)]), b.gep(table, [ir.Constant(i64, i)]))
        b.store(ir.Constant(i64, 1), b.gep(steps, [ir.Constant(i64, i)]))
    b.call(body, [table, steps, out, K])
    b.ret_void()
    return str(module)


# ----------------------------------------------------------------------------- calls from Python
#
# A ctypes call costs about a microsecond before the machine code starts, more than a double
# pendulum's accelerations take for a few states. `Native.blocks` therefore calls a second entry
# point as a builtin function of CPython's own (METH_FASTCALL, made with PyCFunction_NewEx), which
# reads numpy's array structs itself: type, dimensions, dtype, data and strides at the offsets of
# numpy's public PyArrayObject_fields (numpy 1.x and 2.x alike). Whatever it does not
# expect (another type or dtype, byte order, shape) it declines, and the copying path answers.
# The first use checks it against that path (`_fastcall_works`); a mismatch switches it off.

_METH_FASTCALL = 0x0080
_NPY_DOUBLE = 12
_NPY_WRITEABLE = 0x0400
#: byte offsets in numpy's PyArrayObject_fields and PyArray_Descr (64-bit CPython)
_DATA, _ND, _DIMS, _STRIDES, _DESCR, _FLAGS, _TYPE_NUM, _BYTEORDER = 16, 24, 32, 40, 56, 64, 28, 26


class _MethodDef(ctypes.Structure):
    _fields_ = [("ml_name", ctypes.c_char_p), ("ml_meth", ctypes.c_void_p), ("ml_flags", ctypes.c_int),
                ("ml_doc", ctypes.c_char_p)]


@functools.cache
def _fastcall_possible() -> bool:
    """CPython with the GIL on a 64-bit machine: the layouts the entry point reads."""
    import sysconfig

    return (sys.implementation.name == "cpython" and ctypes.sizeof(ctypes.c_void_p) == 8
            and not sysconfig.get_config_var("Py_GIL_DISABLED") and os.environ.get("LAGRADE_FASTCALL", "1") != "0")


@functools.cache  # the same text for every function of this shape: written once per process
def _call_ir(nargs: int, count: int) -> str:
    """``PyObject *lagrade_call(PyObject *self, PyObject *const *args, Py_ssize_t n)``: args[0] is the
    output, a writeable C-contiguous float64 array (count, K); args[1:] are blocks of argument rows,
    float64 arrays (rows, K) or (rows, 1), any strides. Fills the output and returns None, or
    touches nothing and returns False when the arguments are not of that form."""
    ir, _, _ = _llvm()
    i8, i32, i64, double = ir.IntType(8), ir.IntType(32), ir.IntType(64), ir.DoubleType()
    p8, dptr = i8.as_pointer(), double.as_pointer()
    module = ir.Module(name="lagrade_call")
    body = _entry(ir, module, "lagrade_body")
    fn = ir.Function(module, ir.FunctionType(p8, [p8, p8.as_pointer(), i64]), name="lagrade_call")
    _, argv, n = fn.args
    b = ir.IRBuilder(fn.append_basic_block("entry"))
    c = lambda x: ir.Constant(i64, x)  # noqa: E731

    def pointer(value: int, ty):
        return b.inttoptr(c(value), ty)

    incref = pointer(ctypes.cast(ctypes.pythonapi.Py_IncRef, ctypes.c_void_p).value,
                     ir.FunctionType(ir.VoidType(), [p8]).as_pointer())
    table = b.alloca(dptr, c(max(nargs, 1)))
    steps = b.alloca(i64, c(max(nargs, 1)))
    at = b.alloca(i64)
    decline = fn.append_basic_block("decline")

    def field(obj, offset: int, ty):
        return b.load(b.bitcast(b.gep(obj, [c(offset)]), ty.as_pointer()))

    def require(cond, name: str):
        nxt = fn.append_basic_block(name)
        b.cbranch(cond, nxt, decline)
        b.position_at_end(nxt)

    def float64_matrix(obj, name: str):
        """Checks obj is a float64 ndarray of 2 dimensions; its (data, dims, strides, flags)."""
        require(b.icmp_unsigned("==", b.ptrtoint(field(obj, 8, p8), i64), c(id(np.ndarray))), name + "_type")
        require(b.icmp_signed("==", field(obj, _ND, i32), ir.Constant(i32, 2)), name + "_nd")
        descr = field(obj, _DESCR, p8)
        require(b.and_(b.icmp_signed("==", field(descr, _TYPE_NUM, i32), ir.Constant(i32, _NPY_DOUBLE)),
                       b.icmp_signed("!=", field(descr, _BYTEORDER, i8), ir.Constant(i8, ord(">")))), name + "_dtype")
        return (field(obj, _DATA, p8), field(obj, _DIMS, i64.as_pointer()), field(obj, _STRIDES, i64.as_pointer()),
                field(obj, _FLAGS, i32))

    require(b.icmp_signed(">=", n, c(1)), "has_out")
    data, dims, strides, flags = float64_matrix(b.load(argv), "out")
    K = b.load(b.gep(dims, [c(1)]))
    require(b.and_(b.icmp_signed("==", b.load(dims), c(count)),
                   b.icmp_signed("!=", b.and_(flags, ir.Constant(i32, _NPY_WRITEABLE)), ir.Constant(i32, 0))),
            "out_shape")
    require(b.and_(b.icmp_signed("==", b.load(b.gep(strides, [c(1)])), c(8)),
                   b.icmp_signed("==", b.load(strides), b.mul(K, c(8)))), "out_contiguous")
    out = b.bitcast(data, dptr)
    b.store(c(0), at)

    def block(j):
        data, dims, strides, _ = float64_matrix(b.load(b.gep(argv, [j])), "block")
        rows, cols = b.load(dims), b.load(b.gep(dims, [c(1)]))
        row_step, col_step = b.load(strides), b.load(b.gep(strides, [c(1)]))
        require(b.or_(b.icmp_signed("==", cols, K), b.icmp_signed("==", cols, c(1))), "block_columns")
        require(b.and_(b.icmp_signed("==", b.srem(col_step, c(8)), c(0)),
                       b.icmp_signed("<=", b.add(b.load(at), rows), c(nargs))), "block_rows")
        step = b.select(b.icmp_signed("==", cols, c(1)), c(0), b.sdiv(col_step, c(8)))

        def row(r):
            i = b.load(at)
            b.store(b.bitcast(b.gep(data, [b.mul(r, row_step)]), dptr), b.gep(table, [i]))
            b.store(step, b.gep(steps, [i]))
            b.store(b.add(i, c(1)), at)
        _loop(ir, b, c(0), rows, row)

    _loop(ir, b, c(1), n, block)
    require(b.icmp_signed("==", b.load(at), c(nargs)), "all_rows")
    b.call(body, [table, steps, out, K])
    none = pointer(id(None), p8)
    b.call(incref, [none])
    b.ret(none)
    b.position_at_end(decline)
    false = pointer(id(False), p8)
    b.call(incref, [false])
    b.ret(false)
    return str(module)


def _builtin(address: int):
    """(a builtin function object of CPython whose code is the METH_FASTCALL entry at ``address``,
    the method record it points into): keep both as long as the code."""
    new = ctypes.pythonapi.PyCFunction_NewEx
    new.restype = ctypes.py_object
    new.argtypes = [ctypes.c_void_p, ctypes.py_object, ctypes.py_object]
    method = _MethodDef(b"lagrade_call", address, _METH_FASTCALL, None)
    return new(ctypes.addressof(method), None, None), method


@functools.cache
def _fastcall_works() -> bool:
    """The builtin entry point against the copying path on the layouts the grader passes, and
    declining what it must not read: once per process, before any answer relies on it."""
    a, b_, c_ = sp.symbols("a b c")
    probe = Native(_module_ir([a + 2 * b_ - c_, a * c_], [a, b_, c_]), 2, 3)
    library = _Library(probe.ir_text, also=[("lagrade_call", _call_ir(3, 2))])
    call, method = _builtin(library.also["lagrade_call"])
    probe._fn = _SIGNATURE(library.address)
    probe._library = library
    grid = np.arange(18.0).reshape(3, 6) / 7.0
    cases = [(grid[:1, :4], grid[1:2, :4], grid[2:, :4]), (grid[:2, ::2], np.full((1, 1), 0.5)),
             (grid[:, 1:4],), (np.asfortranarray(grid[:, :3]),)]
    try:
        for blocks in cases:
            out = np.full((2, blocks[0].shape[1]), np.nan)
            if call(out, *blocks) is not None or not np.array_equal(out, probe.blocks(*blocks)):
                return False
        row = grid[:1, :4]
        declined = [(np.empty((2, 4)), row.astype(np.float32), row, row), (np.empty((2, 4)), row[0], row, row),
                    (np.empty((2, 4)), row, row), (np.empty((2, 4)), grid[:, :4], row),
                    (np.empty((3, 4)), row, row, row), (np.empty((2, 4)), row, row, grid[:1, :3]),
                    (np.empty((2, 4)).T.copy().T, row, row, row), (np.empty((2, 4)), row.astype(">f8"), row, row),
                    (np.empty((2, 4)), row, 1.0, row), ()]
        return all(call(*args) is False for args in declined)
    except Exception:  # noqa: BLE001  (anything unexpected: the copying path, which is always right)
        return False


# PYFUNCTYPE keeps the GIL over the call: calls last microseconds, and releasing and taking the
# GIL back would cost as much as the arithmetic
_SIGNATURE = ctypes.PYFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int64)

#: Functions linked into one ORC JIT before the next goes to a new one. A JIT keeps about 20 kB for
#: every library ever linked into it, freed or not, and is itself freed with its last function: a
#: bulk run compiles a few functions per answer, and its memory must not grow with the class.
_LIBRARIES_PER_JIT = 128
_jit_lock = threading.Lock()
_jit: list = []  # [LLJIT, libraries linked into it]
_library_names = itertools.count()


class _Library:
    """One linked function: its machine code lives as long as this object, and the JIT it was
    linked into at least as long (a JIT freed before its libraries takes them down with it)."""

    __slots__ = ("address", "also", "jit", "tracker")

    def __init__(self, ir_text: str, symbol: str = "lagrade_fill", also: Sequence[tuple[str, str]] = ()):
        from llvmlite.binding.orcjit import JITLibraryBuilder

        _, binding, target = _llvm()
        with _jit_lock:
            if not _jit or _jit[1] >= _LIBRARIES_PER_JIT:
                # code generation at -O0 takes 1 ms for a double pendulum's accelerations, at -O2
                # 6 ms, for code 0-7% slower at the grader's 4-64 states per call (20% at 1024): the
                # grader compiles each student's equations once for a few hundred calls
                _jit[:] = [binding.create_lljit_compiler(target.create_target_machine(opt=0)), 0]
            self.jit = _jit[0]
            _jit[1] += 1
            name = f"lagrade{next(_library_names)}"
            builder = JITLibraryBuilder().add_ir(ir_text).add_current_process().export_symbol(symbol)
            for other, other_ir in also:  # more entry points, in modules of their own
                builder.add_ir(other_ir).export_symbol(other)
            self.tracker = builder.link(self.jit, name)
        self.address = self.tracker[symbol]
        self.also = {other: self.tracker[other] for other, _ in also}

    def __del__(self):
        tracker = getattr(self, "tracker", None)
        if tracker is not None and not sys.is_finalizing():  # at exit, the process frees it all
            tracker.close()  # before the reference to the JIT goes


class Native:
    """A compiled batch function with the calling convention of `lagrade.numeric.Generated`:
    ``f(*arrays) -> ndarray (count, *shape)``, arrays and scalars broadcasting together.

    It pickles as its IR, since machine code addresses do not survive a process, and is compiled
    again on its first call after loading (about a millisecond): a reference loaded from the disk
    cache pays only for the functions its check actually calls."""

    def __init__(self, ir_text: str, count: int, nargs: int):
        self.ir_text, self.count, self.nargs = ir_text, count, nargs
        self._fn = None
        self._call = self._method = None  # the builtin-function entry point of `blocks`, where it works
        self._scratch = threading.local()  # per thread: buffers filled and read around one call
        self._stages: dict[tuple[int, int], Stages] = {}

    def _build(self):
        fast = _fastcall_possible() and _fastcall_works()
        also = [("lagrade_call", _call_ir(self.nargs, self.count))] if fast else []
        self._library = _Library(self.ir_text, also=also)
        if fast:
            self._call, self._method = _builtin(self._library.also["lagrade_call"])
        self._fn = _SIGNATURE(self._library.address)
        return self._fn

    def _buffers(self, shape: tuple) -> tuple:
        """This thread's (shape, in, out, their addresses, columns) for a batch of this shape."""
        kept = getattr(self._scratch, "kept", None)
        if kept is None or kept[0] != shape:
            src, out = np.empty((self.nargs, *shape)), np.empty((self.count, *shape))
            kept = self._scratch.kept = (shape, src, out, src.ctypes.data, out.ctypes.data, math.prod(shape))
        return kept

    def __call__(self, *arrays: np.ndarray) -> np.ndarray:
        # A call costs a few microseconds of Python around well under one of arithmetic, so the
        # buffers and their addresses (a microsecond each to look up) are kept from call to call;
        # the result is a copy, since callers keep results across calls.
        fn = self._fn or self._build()
        shape = ()
        for a in arrays:  # the common case (equal shapes and scalars) without numpy's broadcast
            s = getattr(a, "shape", ())
            if s and s != shape:
                if shape:
                    shape = np.broadcast(*arrays).shape
                    break
                shape = s
        _, src, out, src_at, out_at, size = self._buffers(shape)
        for i, a in enumerate(arrays):  # one row per argument; a constant fills its row
            src[i] = a
        fn(src_at, out_at, size)
        return out.copy()

    def blocks(self, *blocks: np.ndarray) -> np.ndarray:
        """The same, the arguments given as blocks of consecutive rows, each ``(rows, *shape)`` or
        ``(rows, 1)``: q, q', t and the parameters of a batch, read in place by the machine code
        (2-D float64 blocks of K or 1 columns), else copied once each (see
        `lagrade.numeric.call_blocks`)."""
        fn = self._fn or self._build()
        call = self._call
        if call is not None:
            out = np.empty((self.count, blocks[0].shape[-1]))
            if call(out, *blocks) is None:
                return out
        shape = blocks[0].shape[1:]
        for b in blocks:
            s = b.shape[1:]
            if s != shape and s != (1,):
                shape = np.broadcast_shapes(*(b.shape[1:] for b in blocks))
                break
        _, src, out, src_at, out_at, size = self._buffers(shape)
        row = 0
        for b in blocks:
            end = row + b.shape[0]
            src[row:end] = b
            row = end
        if row != self.nargs:
            raise ValueError(f"{row} arguments given in blocks, {self.nargs} expected")
        fn(src_at, out_at, size)
        return out.copy()

    def stages(self, dim: int, copied: int = 0) -> Stages:
        """The Runge-Kutta stage loop around this function (`Stages`), made once per layout: the
        reference's rates serve every answer of a bulk run."""
        made = self._stages.get((dim, copied))
        if made is None:
            made = self._stages[(dim, copied)] = Stages(self, dim, copied)
        return made

    def __reduce__(self):
        return Native, (self.ir_text, self.count, self.nargs)


def compile_native(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol], solve: int = 0) -> Native | None:
    """Machine code for ``exprs`` over the batch, or None (no llvmlite, or a node it cannot write).

    ``solve`` = n: ``exprs`` are the n*n entries of A (row by row) and the n of r, and the function
    gives x with A x = r at each point (a linear solve per state, inside the same machine code)."""
    if _llvm() is None or not exprs:
        return None
    exprs = [sp.sympify(e) for e in exprs]
    if solve and len(exprs) != solve * (solve + 1):
        raise ValueError(f"a solve of {solve} unknowns takes {solve * (solve + 1)} expressions, not {len(exprs)}")
    if any(e.has(sp.I) for e in exprs):
        return None
    try:
        text = _module_ir(exprs, list(args), solve)
    except _Unsupported:
        return None
    _llvm()[1].parse_assembly(text).verify()  # LLVM aborts on malformed IR: find out here, loudly
    made = Native(text, solve or len(exprs), len(args))
    made._build()
    return made


# ----------------------------------------------------------------------------- Runge-Kutta stages


def _loop(ir, b, start, stop, body) -> None:
    """``for (i = start; i < stop; ++i) body(i)`` at the builder's position (i64 bounds)."""
    i64 = ir.IntType(64)
    before = b.block
    head, inside, after = (b.append_basic_block(x) for x in ("head", "body", "after"))
    b.branch(head)
    b.position_at_end(head)
    i = b.phi(i64)
    i.add_incoming(start, before)
    b.cbranch(b.icmp_signed("<", i, stop), inside, after)
    b.position_at_end(inside)
    body(i)
    i.add_incoming(b.add(i, ir.Constant(i64, 1)), b.block)
    b.branch(head)
    b.position_at_end(after)


#: ``void lagrade_stages(Z, T, h, coef, in, out, rates, amax, K, s0, s1)``; see `Stages`.
_STAGES_SIGNATURE = ctypes.PYFUNCTYPE(None, *[ctypes.c_void_p] * 8, ctypes.c_int64, ctypes.c_int64, ctypes.c_int64)
#: columns of the stage coefficient table: [1, a_s0, ..., a_s(s-1)] for stages up to 15
STAGE_COLUMNS = 17


@functools.cache  # the same text for every answer's rates of this layout: written once per process
def _stages_ir(dim: int, copied: int) -> str:
    """The IR of the stage loop around ``lagrade_fill`` (declared, linked in from the rates' module)."""
    ir, _, _ = _llvm()
    double, i64 = ir.DoubleType(), ir.IntType(64)
    dptr = double.as_pointer()
    module = ir.Module(name="lagrade_stages")
    fill = _entry(ir, module, "lagrade_fill")
    fn = ir.Function(module, ir.FunctionType(ir.VoidType(), [dptr] * 8 + [i64] * 3), name="lagrade_stages")
    Z, T, h, coef, src, out, rates, amax, K, s0, s1 = fn.args
    b = ir.IRBuilder(fn.append_basic_block("entry"))
    c = lambda x: ir.Constant(i64, x)  # noqa: E731
    fabs = module.declare_intrinsic("llvm.fabs", [double])
    size = b.mul(c(dim), K)            # entries of a state: dim rows of K columns
    acc = b.alloca(double)  # in the entry block: an alloca inside a loop would grow the stack per pass
    _loop(ir, b, c(0), K, lambda k: b.store(ir.Constant(double, 0.0), b.gep(amax, [k])))

    def stage(s):
        row = b.mul(s, c(STAGE_COLUMNS))

        def entry(i):  # the stage's state: Z[0] + sum_j coef[s, j] Z[j]  (Z[0] is y, coef[s, 0] = 1)
            b.store(b.load(b.gep(Z, [i])), acc)
            _loop(ir, b, c(1), b.add(s, c(1)), lambda j: b.store(
                b.fadd(b.load(acc), b.fmul(b.load(b.gep(coef, [b.add(row, j)])),
                                            b.load(b.gep(Z, [b.add(b.mul(j, size), i)])))), acc))
            b.store(b.load(acc), b.gep(src, [i]))

        _loop(ir, b, c(0), size, entry)
        _loop(ir, b, c(0), K, lambda k: b.store(b.load(b.gep(T, [b.add(b.mul(s, K), k)])),
                                                b.gep(src, [b.add(size, k)])))
        b.call(fill, [src, out, K])
        dst = b.mul(b.add(s, c(1)), size)

        def rows(first: int, last: int, source, shift: int):
            """Rates of rows first..last-1, read from ``source`` ``shift`` rows further on."""
            def column(d, k):
                i = b.add(b.mul(d, K), k)
                r = b.load(b.gep(source, [b.add(b.mul(c(shift), K), i)]))
                b.store(r, b.gep(rates, [i]))
                b.store(b.fmul(r, b.load(b.gep(h, [k]))), b.gep(Z, [b.add(dst, i)]))
                size_r = b.call(fabs, [r])
                top = b.gep(amax, [k])
                old = b.load(top)
                b.store(b.select(b.fcmp_ordered(">", size_r, old), size_r, old), top)
            _loop(ir, b, c(first), c(last), lambda d: _loop(ir, b, c(0), K, lambda k: column(d, k)))

        rows(0, copied, src, copied)               # q' = the state's velocity rows
        rows(copied, dim, out, -copied)            # what the compiled rates wrote

    _loop(ir, b, s0, s1, stage)
    b.ret_void()
    return str(module)


class Stages:
    """Explicit Runge-Kutta stages of a batch in one call of machine code, around compiled rates.

    ``rates`` is a `Native` of the argument rows [state (dim rows), t, constants...]; it writes the
    last ``dim - copied`` rates, the first ``copied`` being state rows ``copied .. 2 copied - 1`` as
    they are (q' = q-dot of a second-order system). Stage s (from ``s0`` up to ``s1``) reads the
    stacked scaled stages ``Z`` ((17, dim*K): y, h K_0, h K_1, ...), the stage times ``T`` ((16, K))
    and the steps ``h`` ((K,)), and writes ``Z[s + 1] = h * rates(T[s], Z[0] + sum_j coef[s, j] Z[j])``;
    the state of the last stage is left in the first dim rows of ``src`` and its rates (unscaled) in
    ``rates`` ((dim, K)), and ``amax`` ((K,)) gets each column's largest |rate| over the stages (the
    integrator's singularity guard).
    """

    def __init__(self, rates: Native, dim: int, copied: int = 0):
        if rates.count != dim - copied:
            raise ValueError(f"rates write {rates.count} rows, {dim - copied} expected")
        self.rates, self.dim, self.copied = rates, dim, copied
        self._library = None

    def _build(self):
        _, binding, _ = _llvm()
        module = binding.parse_assembly(self.rates.ir_text)
        module.link_in(binding.parse_assembly(_stages_ir(self.dim, self.copied)))
        module.verify()
        self._library = _Library(str(module), "lagrade_stages")
        return _STAGES_SIGNATURE(self._library.address)

    def bind(self, Z: np.ndarray, T: np.ndarray, h: np.ndarray, coef: np.ndarray, src: np.ndarray,
             out: np.ndarray, rates: np.ndarray, amax: np.ndarray):
        """``run(s0, s1)`` on these buffers (C-contiguous float64)."""
        K = h.shape[0]
        shapes = {"Z": (Z, (STAGE_COLUMNS, self.dim * K)), "T": (T, (STAGE_COLUMNS - 1, K)),
                  "coef": (coef, (STAGE_COLUMNS - 1, STAGE_COLUMNS)), "src": (src, (self.rates.nargs, K)),
                  "out": (out, (self.rates.count, K)), "rates": (rates, (self.dim, K)), "amax": (amax, (K,))}
        for name, (a, shape) in shapes.items():
            if a.shape != shape or a.dtype != np.float64 or not a.flags.c_contiguous:
                raise ValueError(f"{name}: a C-contiguous float64 array of shape {shape} expected")
        fn = self._build() if self._library is None else _STAGES_SIGNATURE(self._library.address)
        call = functools.partial(fn, Z.ctypes.data, T.ctypes.data, h.ctypes.data, coef.ctypes.data,
                                 src.ctypes.data, out.ctypes.data, rates.ctypes.data, amax.ctypes.data, K)

        def run(s0: int, s1: int) -> None:
            if not 0 < s0 <= s1 < STAGE_COLUMNS:  # the machine code writes Z[s0 + 1 .. s1] unchecked
                raise ValueError(f"stages {s0}..{s1 - 1}: 1 <= s0 <= s1 <= {STAGE_COLUMNS - 1} expected")
            call(s0, s1)

        # the machine code has only the addresses: the buffers (and the code) live as long as `run`
        run.keep = (Z, T, h, coef, src, out, rates, amax, self._library)
        return run

    def bind_columns(self, buffers: dict[str, np.ndarray]):
        """``loop(ints, reals) -> status``: `dop853_columns`' whole loop without events on these
        buffers (every name of `COLUMN_BUFFERS`; the stage kernel's as given to `bind`), calling this
        kernel; or None without native code. ``ints`` (int64) and ``reals`` (float64) hold the
        scalars, in and out, named by ``COLUMN_INTS`` and ``COLUMN_REALS``; the loop sets K, n_eval and dim."""
        address = _column_loop()
        if address is None:
            return None
        if self._library is None:
            self._build()
        dim, K, n_eval = self.dim, buffers["h"].shape[0], buffers["t_eval"].shape[0]
        n = dim * K
        sizes = {"Z": STAGE_COLUMNS * n, "T": (STAGE_COLUMNS - 1) * K, "h": K,
                 "coef": (STAGE_COLUMNS - 1) * STAGE_COLUMNS, "src": self.rates.nargs * K, "out": self.rates.count * K,
                 "rates": n, "amax": K, "F0": n, "t": K, "h_abs": K, "absa_old": n, "absa_new": n, "P": 7 * n,
                 "t_eval": n_eval, "samples": n * n_eval, "E": 2 * 13, "W": 7 * 16, "limit": K, "ynew": n,
                 "t_new": K, "t_next": K, "C": 16, "rejected": K, "active": K, "accepted": K, "i_eval": K}
        flags, indices = ("rejected", "active", "accepted"), ("i_eval",)
        arrays = []
        for name in COLUMN_BUFFERS:  # the machine code reads and writes them unchecked
            a = buffers[name]
            dtype = np.bool_ if name in flags else np.int64 if name in indices else np.float64
            if a.dtype != dtype or a.size != sizes[name] or not a.flags.c_contiguous or not a.flags.writeable:
                raise ValueError(f"{name}: a writeable C-contiguous {np.dtype(dtype).name} array of {sizes[name]} "
                                 f"entries expected")
            arrays.append(a)
        table = (ctypes.c_void_p * (len(arrays) + 1))(*[a.ctypes.data for a in arrays], self._library.address)
        fn = _COLUMNS_SIGNATURE(address)
        shape = {"K": K, "n_eval": n_eval, "dim": dim}

        def loop(ints: np.ndarray, reals: np.ndarray) -> int:
            if ints.shape != (len(COLUMN_INTS),) or ints.dtype != np.int64 or not ints.flags.c_contiguous \
                    or reals.shape != (len(COLUMN_REALS),) or reals.dtype != np.float64 or not reals.flags.c_contiguous:
                raise ValueError("the loop's scalars: int64 and float64 arrays of the sizes of COLUMN_INTS and COLUMN_REALS")
            for name, value in shape.items():
                ints[COLUMN_INTS.index(name)] = value
            return fn(ctypes.addressof(table), ints.ctypes.data, reals.ctypes.data)

        loop.keep = (arrays, table, self._library)
        return loop


# ----------------------------------------------------------------------------- DOP853 column loop

#: ``i64 lagrade_columns(i8 **buffers, i64 *ints, double *reals)``; see `Stages.bind_columns`.
_COLUMNS_SIGNATURE = ctypes.PYFUNCTYPE(ctypes.c_int64, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p)
#: The buffers of `Stages.bind_columns`, in the order of the pointer table the machine code reads.
COLUMN_BUFFERS = ("Z", "T", "h", "coef", "src", "out", "rates", "amax",  # the stage kernel's own
                  "F0", "t", "h_abs", "absa_old", "absa_new", "P", "t_eval", "samples", "E", "W", "limit",
                  "ynew", "t_new", "t_next", "C", "rejected", "active", "accepted", "i_eval")
#: ints: in K, n_eval, dim, max_count, nfev_limit, guard; in and out count, nfev; out column, s0, s1
COLUMN_INTS = ("K", "n_eval", "dim", "max_count", "nfev_limit", "guard", "count", "nfev", "column", "s0", "s1")
#: reals: t_end, rtol, atol / rtol, the guard's smallest limit
COLUMN_REALS = ("t_end", "rtol", "a_r", "lowest")


def _columns_ir() -> str:
    """The IR of `dop853_columns`' loop without events, every line of it (see there), calling the
    stage kernel through a pointer (the last entry of the buffer table): one call per integration
    instead of about a hundred numpy calls per step. The arithmetic is the numpy code's, element by
    element (numpy's NaN rules for maximum and minimum included); sums run in index order, where
    numpy's products may sum in another, so results agree to rounding, not bit for bit."""
    from lagrade.compare.dop853 import (ERROR_EXPONENT, LOOP_DONE, LOOP_OVER_BUDGET, LOOP_SINGULAR,
                                        LOOP_STEP_TOO_SMALL, LOOP_TOO_MANY, MAX_FACTOR, MIN_FACTOR, SAFETY)

    ir, _, _ = _llvm()
    double, i64, i8, i1 = ir.DoubleType(), ir.IntType(64), ir.IntType(8), ir.IntType(1)
    dptr, lptr, bptr = double.as_pointer(), i64.as_pointer(), i8.as_pointer()
    stage_fn = ir.FunctionType(ir.VoidType(), [dptr] * 8 + [i64] * 3).as_pointer()
    module = ir.Module(name="lagrade_columns")
    fn = ir.Function(module, ir.FunctionType(i64, [bptr.as_pointer(), lptr, dptr]), name="lagrade_columns")
    table, ints, reals = fn.args
    b = ir.IRBuilder(fn.append_basic_block("entry"))
    c = lambda x: ir.Constant(i64, x)  # noqa: E731
    f = lambda x: ir.Constant(double, x)  # noqa: E731
    fabs = module.declare_intrinsic("llvm.fabs", [double])
    sqrt = module.declare_intrinsic("llvm.sqrt", [double])
    pow_ = module.declare_intrinsic("llvm.pow", [double])

    def buf(name: str, ty=dptr):
        return b.bitcast(b.load(b.gep(table, [c(COLUMN_BUFFERS.index(name))])), ty)

    Z, T, h, coef, src, out, rates, amax = (buf(n) for n in COLUMN_BUFFERS[:8])
    F0, t, h_abs, absa_old, absa_new, P, t_eval, samples, E, W, limit, ynew, t_new, t_next, C = (
        buf(n) for n in COLUMN_BUFFERS[8:23])
    rejected, active, accepted = (buf(n, bptr) for n in ("rejected", "active", "accepted"))
    i_eval = buf("i_eval", lptr)
    stages = b.bitcast(b.load(b.gep(table, [c(len(COLUMN_BUFFERS))])), stage_fn)
    K, n_eval, dim, max_count, nfev_limit, guard = (b.load(b.gep(ints, [c(COLUMN_INTS.index(n))]))
                                                   for n in COLUMN_INTS[:6])
    t_end, rtol, a_r, lowest = (b.load(b.gep(reals, [c(i)])) for i in range(4))
    n = b.mul(dim, K)
    dim_f = b.sitofp(dim, double)

    def var(ty, init):  # a mutable scalar (in the entry block: an alloca in a loop grows the stack)
        slot = b.alloca(ty)
        b.store(init, slot)
        return slot

    count = var(i64, b.load(b.gep(ints, [c(COLUMN_INTS.index("count"))])))
    nfev = var(i64, b.load(b.gep(ints, [c(COLUMN_INTS.index("nfev"))])))
    flag = var(i1, ir.Constant(i1, 0))
    acc = var(double, f(0.0))
    acc2 = var(double, f(0.0))
    worst = var(double, f(0.0))
    worst_k = var(i64, c(-1))
    j_slot = var(i64, c(0))
    powers = b.alloca(double, c(7))  # x, x^2, ..., x^7 of a sample in its step

    def ld(ptr, i):
        return b.load(b.gep(ptr, [i]))

    def st(value, ptr, i):
        b.store(value, b.gep(ptr, [i]))

    def is_set(ptr, i):
        return b.icmp_unsigned("!=", ld(ptr, i), ir.Constant(i8, 0))

    def as_byte(bit):
        return b.zext(bit, i8)

    def np_max(x, y):  # numpy's maximum: NaN if either is
        return b.select(b.fcmp_unordered("uno", x, y), b.fadd(x, y), b.select(b.fcmp_ordered(">=", x, y), x, y))

    def np_min(x, y):
        return b.select(b.fcmp_unordered("uno", x, y), b.fadd(x, y), b.select(b.fcmp_ordered("<=", x, y), x, y))

    def ret(status: int, **outs):
        for name, value in outs.items():
            st(value, ints, c(COLUMN_INTS.index(name)))
        st(b.load(count), ints, c(COLUMN_INTS.index("count")))
        st(b.load(nfev), ints, c(COLUMN_INTS.index("nfev")))
        b.ret(c(status))

    def run_stages(s0: int, s1: int):
        """The budget checks, the stages, and the singularity guard, as `trajectory.integrate` has them."""
        with b.if_then(b.icmp_signed(">", b.add(b.load(nfev), c(s1 - s0)), nfev_limit)):
            ret(LOOP_OVER_BUDGET)
        b.store(b.add(b.load(count), c(s1 - s0)), count)
        with b.if_then(b.icmp_signed(">", b.load(count), max_count)):
            ret(LOOP_TOO_MANY)
        b.call(stages, [Z, T, h, coef, src, out, rates, amax, K, c(s0), c(s1)])
        b.store(b.add(b.load(nfev), c(s1 - s0)), nfev)
        with b.if_then(b.icmp_signed("!=", guard, c(0))):
            # the column with the largest amax / limit, the first of equals, as np.argmax
            b.store(f(-math.inf), worst)
            b.store(c(-1), worst_k)

            def check(k):
                a = ld(amax, k)
                with b.if_then(b.fcmp_ordered(">", a, ld(limit, k))):
                    ratio = b.fdiv(a, ld(limit, k))
                    with b.if_then(b.fcmp_ordered(">", ratio, b.load(worst))):
                        b.store(ratio, worst)
                        b.store(k, worst_k)
            with b.if_then(b.fcmp_ordered(">", _max_of(amax), lowest)):
                _loop(ir, b, c(0), K, check)
                with b.if_then(b.icmp_signed(">=", b.load(worst_k), c(0))):
                    ret(LOOP_SINGULAR, column=b.load(worst_k), s0=c(s0), s1=c(s1))

    def _max_of(ptr):
        b.store(f(-math.inf), acc2)
        _loop(ir, b, c(0), K, lambda k: b.store(np_max(b.load(acc2), ld(ptr, k)), acc2))
        return b.load(acc2)

    def stage_sum(table, row, width: int, i):
        """sum_j table[row, j] Z[1 + j, i] over the j < width stages, in order (a loop, not unrolled:
        the IR stays small, and so does the time to build and compile it, once per process)."""
        b.store(f(0.0), acc)
        base = b.mul(row, c(width))
        _loop(ir, b, c(0), c(width), lambda j: b.store(b.fadd(b.load(acc), b.fmul(
            ld(table, b.add(base, j)), ld(Z, b.add(b.mul(b.add(j, c(1)), n), i)))), acc))
        return b.load(acc)

    top = fn.append_basic_block("step")
    b.branch(top)
    b.position_at_end(top)

    # ---- each column's step: at least 10 ulp of its time, unless shrinking after rejections
    def step_size(k):
        tk = b.call(fabs, [ld(t, k)])
        ulp = b.fsub(b.bitcast(b.add(b.bitcast(tk, i64), c(1)), double), tk)  # np.spacing(|t|)
        min_step = b.fmul(f(10.0), ulp)
        hk = b.select(is_set(rejected, k), ld(h_abs, k), np_max(ld(h_abs, k), min_step))
        st(hk, h_abs, k)
        with b.if_then(b.and_(b.fcmp_ordered("<", hk, min_step), is_set(active, k))):
            ret(LOOP_STEP_TOO_SMALL, column=k)
        tn = b.select(is_set(active, k), np_min(b.fadd(ld(t, k), hk), t_end), ld(t, k))
        st(tn, t_new, k)
        st(b.fsub(tn, ld(t, k)), h, k)
    _loop(ir, b, c(0), K, step_size)

    def rows_by_column(body):
        _loop(ir, b, c(0), dim, lambda d: _loop(ir, b, c(0), K, lambda k: body(b.add(b.mul(d, K), k), k)))

    rows_by_column(lambda i, k: st(b.fmul(ld(F0, i), ld(h, k)), Z, b.add(n, i)))  # Z[1] = h K_0
    _loop(ir, b, c(0), c(16), lambda s: _loop(ir, b, c(0), K, lambda k: st(
        b.fadd(b.fmul(ld(C, s), ld(h, k)), ld(t, k)), T, b.add(b.mul(s, K), k))))
    _loop(ir, b, c(0), K, lambda k: st(ld(t_new, k), T, b.add(b.mul(c(12), K), k)))
    run_stages(1, 13)

    # ---- DOP853's error norm per column and its step-size control (scipy's constants)
    def control(k):
        s5, s3 = var_pair
        b.store(f(0.0), s5)
        b.store(f(0.0), s3)

        def component(d):
            i = b.add(b.mul(d, K), k)
            yn = ld(src, i)                        # the last stage's state is y_new
            st(yn, ynew, i)
            an = b.fadd(b.call(fabs, [yn]), a_r)
            st(an, absa_new, i)
            scale = np_max(ld(absa_old, i), an)
            e5 = b.fdiv(stage_sum(E, c(0), 13, i), scale)
            e3 = b.fdiv(stage_sum(E, c(1), 13, i), scale)
            b.store(b.fadd(b.load(s5), b.fmul(e5, e5)), s5)
            b.store(b.fadd(b.load(s3), b.fmul(e3, e3)), s3)
        _loop(ir, b, c(0), dim, component)
        den = b.fadd(b.load(s5), b.fmul(f(0.01), b.load(s3)))
        den = b.select(b.fcmp_ordered("==", den, f(0.0)), f(1.0), den)
        num = b.fdiv(b.fmul(b.load(s5), b.load(s5)), den)
        norm = b.fdiv(b.call(sqrt, [b.fdiv(num, dim_f)]), rtol)
        ok = b.and_(b.fcmp_ordered("<", norm, f(1.0)), is_set(active, k))
        st(as_byte(ok), accepted, k)
        factor = b.fmul(f(SAFETY), b.call(pow_, [norm, f(ERROR_EXPONENT)]))
        grow = np_min(factor, f(MAX_FACTOR))
        grow = b.select(is_set(rejected, k), np_min(grow, f(1.0)), grow)
        shrink = b.select(b.fcmp_unordered("uno", factor, factor), f(MIN_FACTOR),
                          b.select(b.fcmp_ordered(">=", factor, f(MIN_FACTOR)), factor, f(MIN_FACTOR)))  # fmax
        st(b.fmul(ld(h, k), b.select(ok, grow, shrink)), h_abs, k)
        st(as_byte(b.and_(is_set(active, k), b.not_(ok))), rejected, k)
        with b.if_then(ok):
            b.store(ir.Constant(i1, 1), flag)

    var_pair = (var(double, f(0.0)), var(double, f(0.0)))
    b.store(ir.Constant(i1, 0), flag)
    _loop(ir, b, c(0), K, control)
    with b.if_then(b.not_(b.load(flag))):
        b.branch(top)  # no column accepted its step: try again with the smaller ones

    # ---- accepted steps: FSAL, the error scale, the new times; the others keep their state
    def keep(i, k):
        with b.if_else(is_set(accepted, k)) as (yes, no):
            with yes:
                st(ld(rates, i), F0, i)
                st(ld(absa_new, i), absa_old, i)
            with no:
                st(ld(Z, i), ynew, i)
    rows_by_column(keep)
    _loop(ir, b, c(0), K, lambda k: st(b.select(is_set(accepted, k), ld(t_new, k), ld(t, k)), t_next, k))

    # ---- output samples in (t_k, t_next_k] of the accepted columns; the dense output only if some
    # sample lies inside a step
    b.store(ir.Constant(i1, 0), flag)

    def inner(k):
        j = ld(i_eval, k)
        with b.if_then(b.and_(is_set(accepted, k), b.icmp_signed("<", j, n_eval))):
            te = ld(t_eval, j)
            with b.if_then(b.and_(b.fcmp_ordered("<=", te, ld(t_next, k)), b.fcmp_ordered("<", te, ld(t_new, k)))):
                b.store(ir.Constant(i1, 1), flag)
    _loop(ir, b, c(0), K, inner)
    with b.if_then(b.load(flag)):
        run_stages(13, 16)

        _loop(ir, b, c(0), c(7), lambda p: _loop(ir, b, c(0), n, lambda i: st(
            stage_sum(W, p, 16, i), P, b.add(b.mul(p, n), i))))

    def write(k):
        tk, hk, tn = ld(t, k), ld(h, k), ld(t_new, k)
        b.store(ld(i_eval, k), j_slot)
        head, body, after = (fn.append_basic_block(x) for x in ("samples", "sample", "samples_done"))
        b.branch(head)
        b.position_at_end(head)
        j = b.load(j_slot)
        more = b.and_(is_set(accepted, k), b.icmp_signed("<", j, n_eval))
        timed = fn.append_basic_block("sample_time")
        b.cbranch(more, timed, after)
        b.position_at_end(timed)
        te = ld(t_eval, j)
        b.cbranch(b.fcmp_ordered("<=", te, ld(t_next, k)), body, after)
        b.position_at_end(body)
        x = b.fdiv(b.fsub(te, tk), hk)
        _loop(ir, b, c(0), c(7), lambda p: st(b.call(pow_, [x, b.sitofp(b.add(p, c(1)), double)]), powers, p))
        at_end = b.fcmp_unordered("uge", te, tn)  # not te < t_new: y_new itself

        def component(d):
            i = b.add(b.mul(d, K), k)
            b.store(f(0.0), acc)
            _loop(ir, b, c(0), c(7), lambda p: b.store(b.fadd(b.load(acc), b.fmul(
                ld(powers, p), ld(P, b.add(b.mul(p, n), i)))), acc))
            value = b.select(at_end, ld(ynew, i), b.fadd(b.load(acc), ld(Z, i)))
            st(value, samples, b.add(b.mul(i, n_eval), j))
        _loop(ir, b, c(0), dim, component)
        b.store(b.add(j, c(1)), j_slot)
        b.branch(head)
        b.position_at_end(after)
        st(b.load(j_slot), i_eval, k)
    _loop(ir, b, c(0), K, write)

    # ---- advance every column to its new state
    _loop(ir, b, c(0), n, lambda i: st(ld(ynew, i), Z, i))
    b.store(ir.Constant(i1, 0), flag)

    def advance(k):
        st(ld(t_next, k), t, k)
        still = b.and_(is_set(active, k), b.fcmp_ordered("<", ld(t, k), t_end))
        st(as_byte(still), active, k)
        with b.if_then(still):
            b.store(ir.Constant(i1, 1), flag)
    _loop(ir, b, c(0), K, advance)
    with b.if_then(b.load(flag)):
        b.branch(top)
    ret(LOOP_DONE)
    return str(module)


@functools.cache
def _column_loop() -> int | None:
    """The address of the column loop, compiled once per process (it does not depend on the rates)."""
    if _llvm() is None:
        return None
    text = _columns_ir()
    _llvm()[1].parse_assembly(text).verify()
    library = _Library(text, "lagrade_columns")  # at -O0 like the rest: -O2 took twice as long to
    _column_loop.library = library                # compile, for no gain measurable on this machine
    return library.address
