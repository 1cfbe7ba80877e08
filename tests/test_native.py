"""Machine code (lagrade.native) computes what the numpy code computes, or declines to."""

import pickle

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from lagrade import native
from lagrade.grade import references
from lagrade.library import load_problem, problem_ids
from lagrade.numeric import compile_exprs, compile_numpy
from lagrade.sampling import rng_for, sample_points, state_arrays

pytestmark = pytest.mark.skipif(not native.available(), reason="llvmlite is not installed")

x, y, z = sp.symbols("x y z")

NODES = [
    sp.sin(x) * y**2 - 1 / x, sp.cos(x - y) / (2 + sp.sin(y)), sp.tan(x) + sp.cot(y) + sp.sec(x) - sp.csc(y),
    sp.exp(-x**2) * sp.log(1 + y**2), sp.log(x, 2), sp.sqrt(x) + 1 / sp.sqrt(1 + y**2), x ** sp.Rational(3, 2),
    sp.Abs(x - y) ** sp.Rational(-1, 3), x**-3 + y**7 - x**64, x**y, sp.pi * x + sp.E, sp.Rational(-1, 3) * x * y,
    sp.asin(y / 2) + sp.acos(y / 3) + sp.atan(x), sp.atan2(y, x), sp.sinh(y) * sp.cosh(x) - sp.tanh(y),
    sp.asinh(x) + sp.acosh(1 + x**2) + sp.atanh(y / 2), sp.floor(3 * x) + sp.ceiling(2 * y),
    sp.sign(y) * sp.Abs(y), sp.Heaviside(y), sp.Heaviside(y, 1), sp.Max(x, y, 0.5), sp.Min(x, -y),
    sp.Piecewise((x, x > 0.5), (-y, sp.And(y < 0, x <= 0.5)), (x * y, True)),
    sp.Piecewise((1 / x, sp.Or(sp.Eq(y, 0), sp.Ne(x, 1)))), sp.Piecewise((y, sp.Not(x > 1))),
    sp.Integer(3), sp.zoo * x, sp.nan + x, sp.oo * sp.sign(x - 1),
]


def test_every_node_kind_matches_numpy_to_rounding():
    X = np.concatenate([np.linspace(-2, 2, 9), [0.0, 1.0, np.nan, np.inf]])
    Y = np.concatenate([np.linspace(1.5, -1.5, 9), [0.0, 0.0, 1.0, -1.0]])
    made = native.compile_native(NODES, [x, y])
    assert isinstance(made, native.Native)
    got, want = made(X, Y), compile_numpy(NODES, [x, y])(X, Y)
    assert got.shape == want.shape == (len(NODES), X.size)
    for i, e in enumerate(NODES):
        assert np.array_equal(np.isnan(got[i]), np.isnan(want[i])), e
        ok = ~np.isnan(want[i])
        assert np.allclose(got[i][ok], want[i][ok], rtol=1e-13, atol=1e-13), e


def test_constants_and_arrays_broadcast_in_any_shape():
    f = native.compile_native([sp.sin(x) * y + z, z], [x, y, z])
    X = np.linspace(0, 1, 6).reshape(2, 3)
    got = f(X, 2.0, np.float64(0.5))
    assert got.shape == (2, 2, 3)
    assert np.allclose(got[0], np.sin(X) * 2 + 0.5) and np.all(got[1] == 0.5)
    row = f(np.array([0.1, 0.2, 0.3]), np.array([[1.0], [2.0]]), 0.0)  # shapes that need numpy's rules
    assert row.shape == (2, 2, 3) and np.allclose(row[0], np.sin([0.1, 0.2, 0.3]) * np.array([[1.0], [2.0]]))
    assert f(np.empty(0), np.empty(0), 1.0).shape == (2, 0)
    assert np.allclose(f(0.3, 1.0, 1.0), [np.sin(0.3) + 1, 1.0])


def test_blocks_of_rows_give_what_one_array_per_argument_gives():
    from lagrade.numeric import call_blocks

    exprs = [sp.sin(x) * y + z**2, x - y * z]
    f = native.compile_native(exprs, [x, y, z])
    g = compile_numpy(exprs, [x, y, z])
    q = np.array([[0.1, 0.2, 0.3], [1.0, 2.0, 3.0]])  # x and y: one column per state
    c = np.array([[0.5]])                               # z: a constant
    want = f(*q, 0.5)
    assert np.array_equal(f.blocks(q, c), want) and np.array_equal(call_blocks(f, q, c), want)
    assert np.allclose(call_blocks(g, q, c), want, rtol=1e-14)  # numpy code: one row per argument
    assert np.array_equal(f.blocks(q[:1], q[1:], np.full((1, 3), 0.5)), want)
    assert np.array_equal(f.blocks(q[:1, :1], q[1:], c), f(q[0, 0], q[1], 0.5))  # a constant x broadcasts too
    with pytest.raises(ValueError, match="3 expected"):
        f.blocks(q)


def test_pickles_as_its_ir_and_compiles_again_when_first_called():
    f = native.compile_native([sp.cos(x) - y], [x, y])
    g = pickle.loads(pickle.dumps(f))
    assert g.ir_text == f.ir_text and g._fn is None
    assert np.allclose(g(np.array([0.0, np.pi]), np.array([1.0, 1.0])), [[0.0, -2.0]])
    del f  # each function owns its machine code: freeing one leaves the other working
    assert np.allclose(g(np.array([0.0]), np.array([0.0])), [[1.0]])


def test_results_are_the_callers_own_and_threads_do_not_mix_their_inputs():
    f = native.compile_native([x * y + sp.sin(x)], [x, y])
    first = f(np.array([1.0, 2.0]), 3.0)
    f(np.array([5.0, 6.0]), 7.0)
    assert np.allclose(first, [[3 + np.sin(1), 6 + np.sin(2)]])  # not overwritten by the next call

    from concurrent.futures import ThreadPoolExecutor

    def work(seed):
        rng = np.random.default_rng(seed)
        for _ in range(300):
            X, Y = rng.normal(size=1 + seed % 5), rng.normal()
            if not np.allclose(f(X, Y)[0], X * Y + np.sin(X), rtol=1e-14, atol=1e-14):
                return False
        return True

    with ThreadPoolExecutor(4) as pool:
        assert all(pool.map(work, range(8)))


@pytest.mark.parametrize("expr", [sp.exp(sp.I * x), sp.re(x), sp.besselj(0, x), sp.Function("h")(x),
                                  sp.Derivative(sp.Function("h")(x), x)])
def test_declines_what_it_cannot_write(expr):
    assert native.compile_native([sp.sin(x), expr], [x]) is None


def test_the_numpy_code_takes_over_where_it_declines():
    f = compile_exprs([sp.sin(x), (sp.exp(sp.I * x) + sp.exp(-sp.I * x)) / 2 + sp.re(x)], [x])
    assert not isinstance(f, native.Native)
    X = np.array([0.2, 1.3])
    assert np.allclose(f(X), [np.sin(X), np.cos(X) + X])


def test_switched_off_by_the_environment(monkeypatch):
    monkeypatch.setenv("LAGRADE_NATIVE", "0")
    native._llvm.cache_clear()
    try:
        assert native.backend() == "numpy" and native.compile_native([x], [x]) is None
    finally:
        monkeypatch.delenv("LAGRADE_NATIVE")
        native._llvm.cache_clear()
    assert native.backend().startswith("llvmlite")


@pytest.mark.parametrize("pid", problem_ids())
def test_every_reference_right_hand_side_is_machine_code_and_agrees_with_numpy(pid):
    """What the trajectories integrate: the accelerations of every reference scene."""
    problem = load_problem(pid)
    refs = references(problem)
    for system in problem.systems:
        mech = refs[system.key]
        if not hasattr(mech, "accelerations_symbolic") or not mech.s.q:
            continue
        n = len(mech.s.q)
        exprs = list(mech.accelerations_symbolic)
        made = native.compile_native(exprs, mech.args)
        assert made is not None, f"{pid}: llvmlite could not write the accelerations"
        pts = sample_points(mech, 16, rng_for(pid, system.key, "native"))
        q, qd, t, params = state_arrays(mech, pts)
        args = [*q, *qd, t, *params]
        got, want = made(*args), compile_numpy(exprs, mech.args)(*args)
        assert got.shape == want.shape == (n, q.shape[1])
        assert np.allclose(got, want, rtol=1e-10, atol=1e-12, equal_nan=True), pid


# ------------------------------------------------------------------------------- random expressions

_LEAVES = st.sampled_from([x, y, sp.Integer(2), sp.Rational(1, 3), sp.Float(0.7), sp.pi])
_UNARY = [sp.sin, sp.cos, sp.exp, sp.atan, sp.sqrt, sp.Abs, sp.tanh, lambda a: a**2, lambda a: 1 / (1 + a**2)]
_BINARY = [sp.Add, sp.Mul, lambda a, b: a - b, lambda a, b: a / (2 + sp.sin(b)), lambda a, b: sp.Max(a, b)]


@st.composite
def _trees(draw, depth: int = 4):
    if depth == 0 or draw(st.booleans()):
        return draw(_LEAVES)
    if draw(st.booleans()):
        return draw(st.sampled_from(_UNARY))(draw(_trees(depth - 1)))
    op, a, b = draw(st.sampled_from(_BINARY)), draw(_trees(depth - 1)), draw(_trees(depth - 1))
    try:
        return op(a, b)
    except ValueError:  # Max of an imaginary constant (sqrt(cos(2))): sympy refuses to build it
        assume(False)


@settings(max_examples=60, deadline=None)
@given(st.lists(_trees(), min_size=1, max_size=3))
def test_any_expression_agrees_with_numpy(exprs):
    """Property: wherever numpy's code gives a number, machine code gives the same number."""
    assume(not any(e.has(sp.I) for e in exprs))  # complex constants (sqrt(-1/3)): numpy's case
    # sympy writes Abs(exp(x)) as exp(re(x)) for a symbol that may be complex: declined, numpy's case
    assume(not any(e.has(sp.re, sp.im) for e in exprs))
    X, Y = np.linspace(-1.7, 2.3, 11), np.linspace(0.9, -1.1, 11)
    made = native.compile_native(exprs, [x, y])
    assert made is not None
    got, want = made(X, Y), compile_numpy(exprs, [x, y])(X, Y)
    assert np.array_equal(np.isnan(got), np.isnan(want))
    # absolute rounding where terms cancel: numpy's code multiplies by (1/3) where machine code divides by 3
    assert np.allclose(got, want, rtol=1e-12, atol=1e-13, equal_nan=True)


# ------------------------------------------------------------------------------- memory stays bounded


def test_a_jit_is_freed_with_its_last_function_so_bulk_memory_stays_flat():
    import gc
    import weakref

    native._jit.clear()  # the next function starts a JIT of its own (others may hold the current one)
    first = native.compile_native([x + 0.5], [x])
    jit = weakref.ref(first._library.jit)
    made = [native.compile_native([x + i], [x]) for i in range(native._LIBRARIES_PER_JIT + 1)]
    assert made[-1]._library.jit is not jit()  # a full JIT is not linked into any more
    assert np.allclose(first(np.array([1.0])), [[1.5]])  # and what it holds still works
    del first, made
    gc.collect()
    assert jit() is None


def test_the_memo_of_compiled_functions_keeps_the_most_recently_used():
    from lagrade import numeric

    reference = [sp.sin(x) * y]
    kept = compile_exprs(reference, [x, y])
    for i in range(numeric._COMPILED_MAX + 50):  # a class's worth of answers, each its own expression
        compile_exprs([sp.cos(x) + i * y], [x, y])
        assert compile_exprs(reference, [x, y]) is kept  # used for every answer: never evicted
    assert len(numeric._COMPILED) <= numeric._COMPILED_MAX


# ------------------------------------------------------------------------------- the numpy fallback


@pytest.mark.parametrize("answer", ["reference_solutions/12.14/answer.py",
                                    "tests/answers/12.14/wrong_centrifugal_sign_exact.py",
                                    "tests/answers/12.43/wrong_sign_of_V.py"])
def test_without_llvmlite_the_numpy_code_grades_the_same(answer, tmp_path):
    """LAGRADE_NATIVE=0 stands for a machine without llvmlite: every verdict and score the same."""
    import json
    import os
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    path = root / answer
    if not path.is_file():
        pytest.skip(f"{answer} is not in this checkout")
    pid = path.parent.name
    results = {}
    for native_flag in ("1", "0"):
        env = {**os.environ, "LAGRADE_NATIVE": native_flag, "LAGRADE_CACHE": str(tmp_path / native_flag)}
        out = subprocess.run([sys.executable, "-m", "lagrade", "check", pid, str(path), "--json"],
                             capture_output=True, text=True, env=env, check=False)
        data = json.loads(out.stdout)
        results[native_flag] = [(p["part"], p["verdict"], p["score"]) for p in data["parts"]]
    assert results["1"] and results["1"] == results["0"]


# ------------------------------------------------------------------------------- calls from Python

needs_fastcall = pytest.mark.skipif(not native._fastcall_possible(), reason="not a 64-bit CPython with the GIL")


@needs_fastcall
def test_blocks_are_read_in_place_by_a_builtin_entry_point_that_checked_itself():
    assert native._fastcall_works()
    made = native.compile_native([sp.sin(x) * y + z, x * z - y], [x, y, z])
    assert made._call is not None and type(made._call).__name__ == "builtin_function_or_method"


@needs_fastcall
@settings(max_examples=60, deadline=None)
@given(K=st.integers(1, 9), split=st.sampled_from([(3,), (1, 2), (2, 1), (1, 1, 1)]),
       column_step=st.integers(1, 3), constant=st.booleans(), seed=st.integers(0, 2**32 - 1))
def test_any_float64_blocks_give_what_the_copying_path_gives(K, split, column_step, constant, seed):
    made = native.compile_native([sp.sin(x) * y + z, x * z - y**2, sp.exp(-z) + x], [x, y, z])
    rng = np.random.default_rng(seed)
    big = rng.normal(size=(3, K * column_step))
    blocks, row = [], 0
    for rows in split:
        block = big[row:row + rows, ::column_step]  # a strided view, not a copy
        if constant and rows == split[-1] and len(split) > 1:
            block = np.ascontiguousarray(block[:, :1])  # one value for every column
        blocks.append(block)
        row += rows
    out = made.blocks(*blocks)
    call, made._call = made._call, None
    try:
        want = made.blocks(*blocks)
    finally:
        made._call = call
    assert np.array_equal(out, want)


@needs_fastcall
def test_blocks_it_must_not_read_go_the_copying_way_with_the_same_result():
    made = native.compile_native([x + 2 * y - z, x * z], [x, y, z])
    row = np.array([[0.5, 1.5, -2.0]])
    want = np.array([[0.5 + 2.0 + 2.0, 1.5 + 6.0 + 2.0, -2.0 - 8.0 + 2.0], [-1.0, -3.0, 4.0]])  # y = 2x, z = -2
    for blocks in [(row.astype(np.float32), 2 * row, np.array([[-2.0]])),        # another dtype
                   (row, (2 * row).astype(">f8"), np.full((1, 3), -2.0)),         # another byte order
                   (np.vstack([row, 2 * row]), np.full((1, 1), -2.0)),            # broadcast first
                   (np.vstack([row, 2 * row]), np.full((1, 3), -2.0).view(np.matrix))]:  # a subclass
        assert np.allclose(made.blocks(*blocks), want), blocks


def test_fastcall_switched_off_by_the_environment(monkeypatch):
    monkeypatch.setenv("LAGRADE_FASTCALL", "0")
    native._fastcall_possible.cache_clear()
    try:
        made = native.compile_native([x * y], [x, y])
        assert made._call is None
        assert np.allclose(made.blocks(np.ones((1, 2)), np.full((1, 2), 3.0)), [[3.0, 3.0]])
    finally:
        monkeypatch.delenv("LAGRADE_FASTCALL")
        native._fastcall_possible.cache_clear()


def test_an_answers_function_reuses_the_entry_and_stage_code_written_for_its_shape():
    """What does not depend on the expressions (the fast-call entry point, the Runge-Kutta stage
    loop) is written as IR once per shape: an answer pays only for its own expressions (their IR
    took 2-2.5 ms each to write, per compiled function)."""
    x, v, k = sp.symbols("x v k")
    made = []
    for c in (3, 5, 7):
        f = native.compile_native([-c * k * x, v], [x, v, k])
        f(np.ones(4), np.ones(4), np.ones(4))
        f.stages(2)._build()
        made.append(f)
    calls, stages = native._call_ir.cache_info(), native._stages_ir.cache_info()
    assert stages.hits >= 2
    assert calls.hits >= 2 or not (native._fastcall_possible() and native._fastcall_works())
    assert [f(np.full(2, 2.0), np.zeros(2), np.ones(2))[0, 0] for f in made] == [-6.0, -10.0, -14.0]
