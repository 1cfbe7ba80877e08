"""The two expression compilers issue 24 weighs, side by side on the grader's own right-hand sides.

1. **symengine** (what lagrade uses, `lagrade.numbers.numeric.compile_machine`): symengine's LLVM
   ``Lambdify`` with cse, after lagrade's NaN rewrites, reloaded from its object code; called as the
   integrator calls it (`Compiled.blocks` on the state, t and parameter rows).
2. **llvmlite + ctypes**: a small emitter of straight-line LLVM IR (one loop over the K columns, a
   row per argument, each distinct subexpression once; the expression part of the former
   ``native.py``) with the plain C signature ``void f(double *in, double *out, int64 K)``, compiled
   by llvmlite's MCJIT at -O0 and called through ctypes after ``np.concatenate`` of the same rows
   into a buffer kept between calls (as lagrade's own calls do).
3. **numpy code**, for scale: what lagrade prints where symengine declines (`compile_numpy`).

What is compiled is what `compile_linear_solve` compiles for the scene's accelerations: Cramer's
closed form for 12.14 (2 unknowns), the n*n + n entries of M and f for 12.37 (5 unknowns; LAPACK
solves them after the call, not timed here). "call" is one call from Python with its argument
packing; "kernel" is the compiled code alone on ready buffers (symengine's ``unsafe_eval``, the
ctypes function on fixed addresses). Each figure is the median of --repeats runs, the three
compilers' runs taking turns (a change of the machine's load shifts all three alike); compile
times compile the same expressions again each time; "rel diff" is the largest relative difference
from symengine's results. Needs llvmlite (``pip install llvmlite``), which lagrade no longer does.

    python benchmarks/compilers.py [--repeats 7]
"""

from __future__ import annotations

import argparse
import ctypes
import statistics
import time

import numpy as np
import sympy as sp

from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem
from lagrade.numbers.numeric import call_blocks, compile_machine, compile_numpy
from lagrade.compare.sampling import rng_for, sample_points, state_arrays

SCENES = (("12.14", ""), ("12.37", ""))
_LIBM = {"sin": "sin", "cos": "cos", "tan": "tan", "exp": "exp", "log": "log", "atan": "atan",
         "asin": "asin", "acos": "acos", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh"}


def entries(mech) -> list[sp.Expr]:
    """The expressions `compile_linear_solve` compiles for the accelerations."""
    n = len(mech.s.q)
    A, b = [list(mech.mass.row(i)) for i in range(n)], list(mech.force)
    if n == 2:
        (a, c), (d, e) = A
        det = a * e - c * d
        return [(e * b[0] - c * b[1]) / det, (a * b[1] - d * b[0]) / det]
    return [*(x for row in A for x in row), *b]


class LlvmliteCtypes:
    """The small llvmlite emitter: straight-line IR in one loop over the columns, a C ABI."""

    def __init__(self, exprs: list[sp.Expr], args: list[sp.Symbol]):
        import llvmlite.binding as llvm
        from llvmlite import ir

        try:
            llvm.initialize()  # required before llvmlite 0.45, an error after
        except RuntimeError:
            pass
        llvm.initialize_native_target()
        llvm.initialize_native_asmprinter()
        self.ir, double, i64 = ir, ir.DoubleType(), ir.IntType(64)
        module = ir.Module(name="bench")
        fn = ir.Function(module, ir.FunctionType(ir.VoidType(), [double.as_pointer()] * 2 + [i64]), name="f")
        src, out, K = fn.args
        entry, loop, done = (fn.append_basic_block(x) for x in ("entry", "loop", "done"))
        b = self.b = ir.IRBuilder(entry)
        b.cbranch(b.icmp_signed(">", K, ir.Constant(i64, 0)), loop, done)
        b.position_at_end(loop)
        k = b.phi(i64)
        k.add_incoming(ir.Constant(i64, 0), entry)
        self.module, self.double = module, double
        self.env = {a: b.load(b.gep(src, [b.add(b.mul(ir.Constant(i64, i), K), k)])) for i, a in enumerate(args)}
        for j, e in enumerate(exprs):
            b.store(self.ev(e), b.gep(out, [b.add(b.mul(ir.Constant(i64, j), K), k)]))
        nxt = b.add(k, ir.Constant(i64, 1))
        k.add_incoming(nxt, loop)
        b.cbranch(b.icmp_signed("<", nxt, K), loop, done)
        b.position_at_end(done)
        b.ret_void()
        target = llvm.Target.from_default_triple().create_target_machine(opt=0)
        parsed = llvm.parse_assembly(str(module))
        self.engine = llvm.create_mcjit_compiler(parsed, target)
        self.engine.finalize_object()
        self.fn = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int64)(
            self.engine.get_function_address("f"))
        self.count, self.src = len(exprs), None

    def const(self, x: float):
        return self.ir.Constant(self.double, x)

    def libm(self, name: str, arity: int = 1):
        fn = self.module.globals.get(name)
        return fn or self.ir.Function(self.module, self.ir.FunctionType(self.double, [self.double] * arity), name=name)

    def ev(self, e: sp.Basic):
        hit = self.env.get(e)
        if hit is None:
            hit = self.env[e] = self._emit(e)
        return hit

    def _emit(self, e: sp.Basic):
        b = self.b
        if e.is_Number or e.is_NumberSymbol:
            return self.const(float(e))
        if e.is_Add or e.is_Mul:
            op = b.fadd if e.is_Add else b.fmul
            parts = [self.ev(a) for a in e.args]
            r = parts[0]
            for x in parts[1:]:
                r = op(r, x)
            return r
        if e.is_Pow:
            base, exp = e.args
            if exp.is_Integer and 0 < abs(int(exp)) <= 64:
                x, r, n = self.ev(base), None, abs(int(exp))
                while n:  # square-and-multiply
                    if n & 1:
                        r = x if r is None else b.fmul(r, x)
                    n >>= 1
                    if n:
                        x = b.fmul(x, x)
                return b.fdiv(self.const(1.0), r) if exp < 0 else r
            if exp == sp.S.Half:
                return b.call(self.module.declare_intrinsic("llvm.sqrt", [self.double]), [self.ev(base)])
            return b.call(self.libm("pow", 2), [self.ev(base), self.ev(exp)])
        name = type(e).__name__
        if name in _LIBM and len(e.args) == 1:
            return b.call(self.libm(_LIBM[name]), [self.ev(e.args[0])])
        raise NotImplementedError(name)  # the scenes timed here need no more

    def blocks(self, *blocks: np.ndarray) -> np.ndarray:
        """As `Compiled.blocks`: the input buffer kept between calls, the output the caller's own."""
        K = blocks[0].shape[1]
        if self.src is None or self.src.shape[1] != K:
            self.src = np.empty((sum(b.shape[0] for b in blocks), K))
        np.concatenate(blocks, out=self.src)
        out = np.empty((self.count, K))
        self.fn(self.src.ctypes.data, out.ctypes.data, K)
        return out


def interleaved(fns: dict, reps: int, repeats: int, scale: float = 1e6) -> dict[str, float]:
    """Median time per call of each function, the repeats of all of them taking turns (a machine
    whose load changes shifts all of them alike); ``reps`` calls per repeat."""
    times: dict[str, list[float]] = {name: [] for name in fns}
    for fn in fns.values():
        fn()
    for _ in range(repeats):
        for name, fn in fns.items():
            start = time.perf_counter()
            for _ in range(reps):
                fn()
            times[name].append((time.perf_counter() - start) / reps * scale)
    return {name: statistics.median(t) for name, t in times.items()}


def scene_rows(pid: str, key: str, repeats: int) -> None:
    """The three compilers on one scene: a printed row each."""
    mech = references(load_problem(pid))[key]
    exprs, n = entries(mech), len(mech.s.q)
    makers = {"symengine": lambda: compile_machine(exprs, mech.args),
              "llvmlite + ctypes": lambda: LlvmliteCtypes(exprs, list(mech.args)),
              "numpy code": lambda: compile_numpy(exprs, mech.args)}
    compile_ms = interleaved(makers, 1, repeats, scale=1e3)
    se, ll, numpy_code = (make() for make in makers.values())
    cells = {name: [ms] for name, ms in compile_ms.items()}
    worst = dict.fromkeys(cells, 0.0)  # largest relative difference from symengine's results
    for K in (4, 64):
        q, qd, t, params = state_arrays(mech, sample_points(mech, K, rng_for(pid, key, "compilers")))
        blocks = (np.concatenate([q, qd]), t.reshape(1, -1), np.ascontiguousarray(params))
        a = se.blocks(*blocks)
        for name, made in (("llvmlite + ctypes", ll), ("numpy code", numpy_code)):
            b = call_blocks(made, *blocks)
            worst[name] = max(worst[name], float(np.max(np.abs(a - b) / (np.abs(a) + 1e-300))))
        for name, timings in call_times(se, ll, numpy_code, blocks, repeats).items():
            cells[name] += timings
    for name, (ms, call4, kern4, call64, kern64) in cells.items():
        kernel = f"{kern4:>13.2f} {kern64:>7.2f}" if name != "numpy code" else f"{'-':>13} {'-':>7}"
        print(f"{pid + key:>8} {n:>2} {len(exprs):>5} {name:>18} {ms:>10.1f} {call4:>11.2f} {call64:>7.2f} "
              f"{kernel} {worst[name]:>12.1e}")


def call_times(se, ll: LlvmliteCtypes, numpy_code, blocks: tuple, repeats: int) -> dict[str, list[float]]:
    """(call, kernel) microseconds of each compiler on these blocks of rows."""
    K = blocks[0].shape[1]
    src = np.ascontiguousarray(np.concatenate(blocks).T).reshape(-1)  # symengine: a row per point
    out = np.empty(K * se.count)
    rows = np.concatenate(blocks)
    dst = np.empty((ll.count, K))
    at_in, at_out = rows.ctypes.data, dst.ctypes.data
    us = interleaved({"se call": lambda: se.blocks(*blocks), "se kernel": lambda: se.f.unsafe_eval(src, out, K),
                      "ll call": lambda: ll.blocks(*blocks), "ll kernel": lambda: ll.fn(at_in, at_out, K),
                      "np call": lambda: call_blocks(numpy_code, *blocks)}, 1000, repeats)
    return {"symengine": [us["se call"], us["se kernel"]], "llvmlite + ctypes": [us["ll call"], us["ll kernel"]],
            "numpy code": [us["np call"], 0.0]}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    print(f"{'scene':>8} {'n':>2} {'exprs':>5} {'compiler':>18} {'compile ms':>10} "
          f"{'call us K=4':>11} {'K=64':>7} {'kernel us K=4':>13} {'K=64':>7} {'rel diff':>12}")
    for pid, key in SCENES:
        scene_rows(pid, key, args.repeats)


if __name__ == "__main__":
    main()
