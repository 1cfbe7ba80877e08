"""Machine code (lagrade.numbers.numeric.Compiled, symengine's LLVM Lambdify) computes what the numpy code
computes, or declines to; linear solves of 3 or more unknowns agree with LAPACK's."""

import gc
import pickle
import sys

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from lagrade.numbers import numeric
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem, problem_ids
from lagrade.numbers.numeric import (
    Compiled,
    call_blocks,
    compile_exprs,
    compile_linear_solve,
    compile_machine,
    compile_numpy,
    is_machine_code,
    solve_batch,
)
from lagrade.compare.sampling import rng_for, sample_points, state_arrays
from lagrade.compare.scene_model import scene_model

pytestmark = pytest.mark.skipif(not numeric.machine_code(), reason="symengine is not installed")

x, y, z = sp.symbols("x y z")

NODES = [
    sp.sin(x) * y**2 - 1 / x, sp.cos(x - y) / (2 + sp.sin(y)), sp.tan(x) + sp.cot(y) + sp.sec(x) - sp.csc(y),
    sp.exp(-x**2) * sp.log(1 + y**2), sp.log(x, 2), sp.sqrt(x) + 1 / sp.sqrt(1 + y**2), x ** sp.Rational(3, 2),
    sp.Abs(x - y) ** sp.Rational(-1, 3), x**-3 + y**7 - x**64, x**y, sp.pi * x + sp.E, sp.Rational(-1, 3) * x * y,
    sp.asin(y / 2) + sp.acos(y / 3) + sp.atan(x), sp.atan2(y, x), sp.sinh(y) * sp.cosh(x) - sp.tanh(y),
    sp.asinh(x) + sp.acosh(1 + x**2) + sp.atanh(y / 2), sp.floor(3 * x) + sp.ceiling(2 * y),
    sp.sign(y) * sp.Abs(y), sp.sign(x - 1), sp.Heaviside(y), sp.Heaviside(y, 1), sp.Max(x, y, 0.5), sp.Min(x, -y),
    sp.Max(sp.sin(sp.Max(x, y)), sp.Min(x, 0.3)),
    sp.Piecewise((x, x > 0.5), (-y, sp.And(y < 0, x <= 0.5)), (x * y, True)),
    sp.Piecewise((1 / x, sp.Or(sp.Eq(y, 0), sp.Ne(x, 1)))), sp.Piecewise((y, sp.Not(x > 1))),
    sp.Piecewise((1 / x, sp.Ne(x, 1)), (y, True)), sp.Piecewise((x, sp.Max(x, y) > 0.2), (y, True)),
    sp.Integer(3), sp.zoo * x, sp.nan + x, sp.oo * sp.sign(x - 1),
]


def test_every_node_kind_matches_numpy_to_rounding():
    """NaN and infinities in either argument included: numpy's rules for sign, Max, Min, != and a
    Piecewise no branch of which holds are where symengine's own code differs."""
    X = np.concatenate([np.linspace(-2, 2, 9), [0.0, 1.0, np.nan, np.inf, -np.inf, np.nan, 1.0]])
    Y = np.concatenate([np.linspace(1.5, -1.5, 9), [0.0, 0.0, 1.0, -1.0, np.nan, np.inf, np.nan]])
    made = compile_machine(NODES, [x, y])
    assert isinstance(made, Compiled)
    got, want = made(X, Y), compile_numpy(NODES, [x, y])(X, Y)
    assert got.shape == want.shape == (len(NODES), X.size)
    for i, e in enumerate(NODES):
        assert np.array_equal(np.isnan(got[i]), np.isnan(want[i])), e
        ok = ~np.isnan(want[i])
        assert np.allclose(got[i][ok], want[i][ok], rtol=1e-13, atol=1e-13), e


def test_constants_and_arrays_broadcast_in_any_shape():
    f = compile_machine([sp.sin(x) * y + z, z], [x, y, z])
    X = np.linspace(0, 1, 6).reshape(2, 3)
    got = f(X, 2.0, np.float64(0.5))
    assert got.shape == (2, 2, 3) and got.flags.c_contiguous
    assert np.allclose(got[0], np.sin(X) * 2 + 0.5) and np.all(got[1] == 0.5)
    row = f(np.array([0.1, 0.2, 0.3]), np.array([[1.0], [2.0]]), 0.0)  # shapes that need numpy's rules
    assert row.shape == (2, 2, 3) and np.allclose(row[0], np.sin([0.1, 0.2, 0.3]) * np.array([[1.0], [2.0]]))
    assert np.allclose(f(np.array([0.1, 0.2]), np.array([1.0]), np.array([0.5, 0.5]))[0], np.sin([0.1, 0.2]) + 0.5)
    assert f(np.empty(0), np.empty(0), 1.0).shape == (2, 0)
    assert np.allclose(f(0.3, 1.0, 1.0), [np.sin(0.3) + 1, 1.0])
    with pytest.raises(ValueError, match="3 expected"):
        f(X, 2.0)


def test_blocks_of_rows_give_what_one_array_per_argument_gives():
    exprs = [sp.sin(x) * y + z**2, x - y * z]
    f = compile_machine(exprs, [x, y, z])
    g = compile_numpy(exprs, [x, y, z])
    q = np.array([[0.1, 0.2, 0.3], [1.0, 2.0, 3.0]])  # x and y: one column per state
    c = np.array([[0.5]])                               # z: a constant
    want = f(*q, 0.5)
    assert np.array_equal(f.blocks(q, c), want) and np.array_equal(call_blocks(f, q, c), want)
    assert call_blocks(f, q, c).flags.c_contiguous
    assert np.allclose(call_blocks(g, q, c), want, rtol=1e-14)  # numpy code: one row per argument
    assert np.array_equal(f.blocks(q[:1], q[1:], np.full((1, 3), 0.5)), want)
    assert np.array_equal(f.blocks(q[:1, :1], q[1:], c), f(q[0, 0], q[1], 0.5))  # a constant x broadcasts too
    strided = np.vstack([q, np.full((1, 3), 0.5)]).T.copy().T  # any strides
    assert np.array_equal(f.blocks(strided[:, ::1]), want) and np.array_equal(f.blocks(q[:, ::2], c), want[:, ::2])
    with pytest.raises(ValueError, match="3 expected"):
        f.blocks(q)
    with pytest.raises(ValueError, match="3 expected"):
        f.blocks(q, c, c)  # never written past the buffer the machine code reads


def test_blocks_of_any_float_layout_give_the_same_result():
    """Other dtypes, byte orders, array subclasses and broadcast blocks: converted, never misread."""
    f = compile_machine([x + 2 * y - z, x * z], [x, y, z])
    row = np.array([[0.5, 1.5, -2.0]])
    want = np.array([[0.5 + 2.0 + 2.0, 1.5 + 6.0 + 2.0, -2.0 - 8.0 + 2.0], [-1.0, -3.0, 4.0]])  # y = 2x, z = -2
    for blocks in [(row.astype(np.float32), 2 * row, np.array([[-2.0]])),        # another dtype
                   (row, (2 * row).astype(">f8"), np.full((1, 3), -2.0)),         # another byte order
                   (np.vstack([row, 2 * row]), np.full((1, 1), -2.0)),            # broadcast last
                   (np.vstack([row, 2 * row]), np.full((1, 3), -2.0).view(np.matrix))]:  # a subclass
        assert np.allclose(f.blocks(*blocks), want), blocks
    with pytest.raises(TypeError):
        f.blocks(row + 1j, row, row)  # complex values are not silently cut to their real part


def test_pickles_and_still_works():
    f = compile_machine([sp.cos(x) - y], [x, y])
    g = pickle.loads(pickle.dumps(f))
    assert isinstance(g, Compiled) and g.count == 1 and g.nargs == 2
    assert np.allclose(g(np.array([0.0, np.pi]), np.array([1.0, 1.0])), [[0.0, -2.0]])
    del f  # each function owns its machine code: freeing one leaves the other working
    gc.collect()
    assert np.allclose(g(np.array([0.0]), np.array([0.0])), [[1.0]])


def test_results_are_the_callers_own_and_threads_do_not_mix_their_inputs():
    f = compile_machine([x * y + sp.sin(x)], [x, y])
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
            B = rng.normal(size=(2, 3))  # one shape for every thread: buffers it could share
            if not np.allclose(f.blocks(B)[0], B[0] * B[1] + np.sin(B[0]), rtol=1e-14, atol=1e-14):
                return False
        return True

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # threads take turns between any two steps of a call
    try:
        with ThreadPoolExecutor(4) as pool:
            assert all(pool.map(work, range(8)))
    finally:
        sys.setswitchinterval(interval)


@pytest.mark.parametrize("expr", [sp.exp(sp.I * x), sp.re(x), sp.besselj(0, x), sp.Function("h")(x),
                                  sp.Derivative(sp.Function("h")(x), x), sp.Piecewise((x, sp.Xor(x > 0, x < 1)),
                                                                                       (0, True))])
def test_declines_what_it_cannot_write(expr):
    assert compile_machine([sp.sin(x), expr], [x]) is None


def test_the_numpy_code_takes_over_where_it_declines():
    f = compile_exprs([sp.sin(x), (sp.exp(sp.I * x) + sp.exp(-sp.I * x)) / 2 + sp.re(x)], [x])
    assert not is_machine_code(f)
    X = np.array([0.2, 1.3])
    assert np.allclose(f(X), [np.sin(X), np.cos(X) + X])


def test_switched_off_by_the_environment(monkeypatch):
    exprs = [x * sp.cos(y) + 0.25]
    assert is_machine_code(compile_exprs(exprs, [x, y])) and numeric.backend().startswith("symengine")
    monkeypatch.setenv("LAGRADE_NATIVE", "0")
    assert numeric.backend() == "numpy" and compile_machine([x], [x]) is None
    f = compile_exprs(exprs, [x, y])  # the memo does not hand back the machine code made before
    assert not is_machine_code(f) and np.allclose(f(np.array([2.0]), 0.0), [[2.25]])
    assert not is_machine_code(compile_linear_solve([[x, 1, 0], [0, 1, 0], [0, 0, y]], [1, 2, 3], [x, y]))
    monkeypatch.delenv("LAGRADE_NATIVE")
    assert is_machine_code(compile_exprs(exprs, [x, y]))


@pytest.mark.parametrize("pid", problem_ids())
def test_every_reference_right_hand_side_is_machine_code_and_agrees_with_numpy(pid):
    """What the trajectories integrate: the accelerations of every reference scene, as closed forms
    and as the rates the integrator calls (a linear solve of compiled entries from 3 unknowns)."""
    problem = load_problem(pid)
    refs = references(problem)
    for system in problem.systems:
        mech = refs[system.key]
        if not hasattr(mech, "accelerations_symbolic") or not mech.s.q:
            continue
        n = len(mech.s.q)
        exprs = list(mech.accelerations_symbolic)
        made = compile_machine(exprs, mech.args)
        assert made is not None, f"{pid}: symengine could not compile the accelerations"
        pts = sample_points(mech, 16, rng_for(pid, system.key, "native"))
        q, qd, t, params = state_arrays(mech, pts)
        args = [*q, *qd, t, *params]
        got, want = made(*args), compile_numpy(exprs, mech.args)(*args)
        assert got.shape == want.shape == (n, q.shape[1])
        assert np.allclose(got, want, rtol=1e-10, atol=1e-12, equal_nan=True), pid
        rates = scene_model(mech).compiled_rates(params)
        assert is_machine_code(rates.f), f"{pid} {system.key}: the rates are not machine code"
        y0 = np.concatenate([q, qd])
        assert np.allclose(rates(t, y0)[n:], want, rtol=1e-8, atol=1e-10, equal_nan=True), pid


# ------------------------------------------------------------------------------- random expressions

_LEAVES = st.sampled_from([x, y, sp.Integer(2), sp.Rational(1, 3), sp.Float(0.7), sp.pi])
_UNARY = [sp.sin, sp.cos, sp.exp, sp.atan, sp.sqrt, sp.Abs, sp.tanh, sp.sign, lambda a: a**2, lambda a: 1 / (1 + a**2)]
_BINARY = [sp.Add, sp.Mul, lambda a, b: a - b, lambda a, b: a / (2 + sp.sin(b)), lambda a, b: sp.Max(a, b),
           lambda a, b: sp.Piecewise((a, sp.Ne(x, y)), (b, x < 2 * y), (a * b, True))]


@st.composite
def _trees(draw, depth: int = 4):
    if depth == 0 or draw(st.booleans()):
        return draw(_LEAVES)
    if draw(st.booleans()):
        return draw(st.sampled_from(_UNARY))(draw(_trees(depth - 1)))
    op, a, b = draw(st.sampled_from(_BINARY)), draw(_trees(depth - 1)), draw(_trees(depth - 1))
    try:
        return op(a, b)
    except (ValueError, TypeError):  # Max of an imaginary constant (sqrt(cos(2))): sympy refuses to build it
        assume(False)


@settings(max_examples=60, deadline=None)
@given(st.lists(_trees(), min_size=1, max_size=3))
def test_any_expression_agrees_with_numpy(exprs):
    """Property: wherever numpy's code gives a number, machine code gives the same number."""
    assume(not any(e.has(sp.I) for e in exprs))  # complex constants (sqrt(-1/3)): numpy's case
    # sympy writes Abs(exp(x)) as exp(re(x)) for a symbol that may be complex: declined, numpy's case
    assume(not any(e.has(sp.re, sp.im) for e in exprs))
    X, Y = np.linspace(-1.7, 2.3, 11), np.linspace(0.9, -1.1, 11)
    X[3], Y[5] = np.nan, np.nan
    made = compile_machine(exprs, [x, y])
    assert made is not None
    got, want = made(X, Y), compile_numpy(exprs, [x, y])(X, Y)
    assert np.array_equal(np.isnan(got), np.isnan(want))
    # absolute rounding where terms cancel: numpy's code multiplies by (1/3) where machine code divides by 3
    assert np.allclose(got, want, rtol=1e-12, atol=1e-13, equal_nan=True)


# ------------------------------------------------------------------------------- memory stays bounded


def _rss_mb() -> float:
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4096 / 1e6


@pytest.mark.skipif(sys.platform != "linux", reason="reads /proc/self/statm")
def test_compiled_functions_are_freed_so_bulk_memory_stays_flat():
    """A bulk run compiles a few functions per answer: with each freed with its last reference, the
    memory of the next round of answers is the last round's (kept, 200 of them take 10 MB or more).
    And what is kept is small: the memo holds up to 256 (about 470 kB each as just compiled)."""
    def one_round(kept: list) -> float:
        start = _rss_mb()
        for i in range(200):
            f = compile_machine([sp.sin(x) * y + i * x, sp.cos(y) * x**2 - i], [x, y])
            assert f(np.ones(2), 2.0).shape == (2, 2)
            kept.append(f)
        held = _rss_mb() - start
        kept.clear()
        gc.collect()
        return held

    kept: list = []
    assert one_round(kept) < 40.0
    before = _rss_mb()
    for _ in range(2):
        one_round(kept)
    assert _rss_mb() - before < 5.0


def test_the_memo_of_compiled_functions_keeps_the_most_recently_used():
    reference = [sp.sin(x) * y]
    kept = compile_exprs(reference, [x, y])
    for i in range(numeric._COMPILED_MAX + 50):  # a class's worth of answers, each its own expression
        compile_exprs([sp.cos(x) + i * y], [x, y])
        assert compile_exprs(reference, [x, y]) is kept  # used for every answer: never evicted
    assert len(numeric._COMPILED) <= numeric._COMPILED_MAX


# ------------------------------------------------------------------------------- linear solves


@settings(max_examples=40, deadline=None)
@given(n=st.integers(3, 6), seed=st.integers(0, 2**32 - 1))
def test_the_elimination_agrees_with_lapack(n, seed):
    syms = sp.symbols(f"a0:{n}")
    rng = np.random.default_rng(seed)
    coeffs = rng.normal(size=(n, n + 1, n))
    A_ = [[sum(float(coeffs[i, j, m]) * syms[m] for m in range(n)) + float(rng.normal()) for j in range(n)]
          for i in range(n)]
    b_ = [sp.sin(syms[i]) + float(coeffs[i, n, 0]) for i in range(n)]
    solve = compile_linear_solve(A_, b_, syms)
    assert is_machine_code(solve)
    X = rng.normal(size=(n, 9))
    M = compile_numpy([a for row in A_ for a in row], syms)(*X).reshape(n, n, 9)
    r = compile_numpy(b_, syms)(*X)
    want = np.stack([np.linalg.solve(M[:, :, i], r[:, i]) for i in range(9)], axis=1)
    cond = np.array([np.linalg.cond(M[:, :, i]) for i in range(9)])
    ok = cond < 1e8
    for got in (solve(*X), call_blocks(solve, X[:1], X[1:])):
        assert np.allclose(got[:, ok], want[:, ok], rtol=1e-8 * 1e4, atol=1e-10 * np.abs(want[:, ok]).max())


def test_a_singular_state_gives_nan_for_that_state_only():
    a, b = sp.symbols("a b")
    A_ = [[a, 1, 0], [0, 1, 0], [0, 0, b]]
    solve = compile_linear_solve(A_, [1, 2, 3], [a, b])
    got = solve(np.array([0.0, 2.0, 1.0]), np.array([1.0, 0.0, 3.0]))
    assert np.all(np.isnan(got[:, :2]))   # a = 0 (rows dependent) and b = 0
    assert np.allclose(got[:, 2], [-1.0, 2.0, 1.0])
    M = np.stack([np.eye(3)] * 3, axis=2)
    M[:, :, 1] = 0.0
    assert np.array_equal(np.isnan(solve_batch(M, np.ones((3, 3)))), np.array([[False, True, False]] * 3))


# ------------------------------------------------------------------------------- the numpy fallback


@pytest.mark.slow
@pytest.mark.parametrize("answer", ["reference_solutions/12.14/answer.py",
                                    "tests/answers/12.14/wrong_centrifugal_sign_exact.py",
                                    "tests/answers/12.43/wrong_sign_of_V.py"])
def test_without_machine_code_the_numpy_code_grades_the_same(answer, tmp_path):
    """LAGRADE_NATIVE=0 stands for a machine where symengine cannot compile: every verdict and score the same."""
    import json
    import os
    import subprocess
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
        assert out.stdout.strip(), out.stderr[-2000:]
        data = json.loads(out.stdout)
        results[native_flag] = [(p["part"], p["verdict"], p["score"]) for p in data["parts"]]
    assert results["1"] and results["1"] == results["0"]
