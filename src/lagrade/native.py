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
common subexpressions computed once per column. The arithmetic is IEEE double without fast-math
(no reassociation), calling the C library for sin, cos, exp, ... Anything outside that vocabulary
(complex values, unknown functions) makes `compile_native` return None, and the caller keeps the
numpy code.
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

__all__ = ["Native", "available", "backend", "compile_native"]


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


def _module_ir(exprs: list[sp.Expr], args: Sequence[sp.Symbol]) -> str:
    """The LLVM IR of ``void lagrade_fill(double *in, double *out, i64 K)``."""
    ir, _, _ = _llvm()
    shared, reduced = sp.cse(exprs, symbols=sp.numbered_symbols("_c"), order="none")
    double, i64 = ir.DoubleType(), ir.IntType(64)
    dptr = double.as_pointer()
    module = ir.Module(name="lagrade")
    fn = ir.Function(module, ir.FunctionType(ir.VoidType(), [dptr, dptr, i64]), name="lagrade_fill")
    src, dst, K = fn.args
    entry, loop, done = fn.append_basic_block("entry"), fn.append_basic_block("loop"), fn.append_basic_block("done")
    b = ir.IRBuilder(entry)
    b.cbranch(b.icmp_signed(">", K, ir.Constant(i64, 0)), loop, done)
    b.position_at_end(loop)
    k = b.phi(i64)
    k.add_incoming(ir.Constant(i64, 0), entry)
    env = {}
    for i, a in enumerate(args):
        at = b.add(b.mul(ir.Constant(i64, i), K), k)
        env[a] = b.load(b.gep(src, [at]))
    emit = _Emitter(ir, module, b, env)
    for sym, e in shared:
        env[sym] = emit.ev(e)
    for j, e in enumerate(reduced):
        at = b.add(b.mul(ir.Constant(i64, j), K), k)
        b.store(emit.ev(e), b.gep(dst, [at]))
    nxt = b.add(k, ir.Constant(i64, 1))
    k.add_incoming(nxt, loop)
    b.cbranch(b.icmp_signed("<", nxt, K), loop, done)
    b.position_at_end(done)
    b.ret_void()
    return str(module)


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

    __slots__ = ("address", "jit", "tracker")

    def __init__(self, ir_text: str):
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
            self.tracker = (JITLibraryBuilder().add_ir(ir_text).add_current_process()
                            .export_symbol("lagrade_fill").link(self.jit, name))
        self.address = self.tracker["lagrade_fill"]

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
        self._scratch = threading.local()  # per thread: buffers filled and read around one call

    def _build(self):
        self._library = _Library(self.ir_text)
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
        ``(rows, 1)``: q, q', t and the parameters of a batch in four copies instead of one per
        argument (see `lagrade.numeric.call_blocks`)."""
        fn = self._fn or self._build()
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

    def __reduce__(self):
        return Native, (self.ir_text, self.count, self.nargs)


def compile_native(exprs: Sequence[sp.Expr], args: Sequence[sp.Symbol]) -> Native | None:
    """Machine code for ``exprs`` over the batch, or None (no llvmlite, or a node it cannot write)."""
    if _llvm() is None or not exprs:
        return None
    exprs = [sp.sympify(e) for e in exprs]
    if any(e.has(sp.I) for e in exprs):
        return None
    try:
        text = _module_ir(exprs, list(args))
    except _Unsupported:
        return None
    _llvm()[1].parse_assembly(text).verify()  # LLVM aborts on malformed IR: find out here, loudly
    made = Native(text, len(exprs), len(args))
    made._build()
    return made
