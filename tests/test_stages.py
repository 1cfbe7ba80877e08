"""DOP853's stages in machine code (lagrade.native.Stages, lagrade.compare.rates.CompiledRates)
integrate what the Python stage loop integrates: same steps, same samples to rounding, same
events, same refusals (singularity, budget), and native linear solves agree with LAPACK's."""

import gc
import weakref

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade import native
from lagrade.compare.dop853 import A, N_STAGES_EXTENDED, dop853_columns
from lagrade.compare.rates import CompiledRates
from lagrade.compare.trajectory import ACCURACY, BatchedEvent, integrate
from lagrade.grade import references
from lagrade.library import load_problem, problem_ids
from lagrade.numeric import compile_exprs, compile_linear_solve, compile_numpy, solve_batch
from lagrade.sampling import rng_for, sample_points, state_arrays

pytestmark = pytest.mark.skipif(not native.available(), reason="llvmlite is not installed")

x, v, t, k = sp.symbols("x v t k")


def python_path(rates: CompiledRates):
    """The same compiled rates without the `stages` hook: the integrator's Python stage loop."""
    return lambda tt, Y: rates(tt, Y)


def _coef() -> np.ndarray:
    coef = np.zeros((N_STAGES_EXTENDED, N_STAGES_EXTENDED + 1))
    for s in range(N_STAGES_EXTENDED):
        coef[s, 0] = 1.0
        coef[s, 1:s + 1] = A[s, :s]
    return coef


def _reference_rates(pid: str, K: int = 6):
    problem = load_problem(pid)
    refs = references(problem)
    for system in problem.systems:
        mech = refs[system.key]
        if not mech.s.q:
            continue
        q, qd, _, params = state_arrays(mech, sample_points(mech, K, rng_for(pid, system.key, "stages")))
        yield system.key, mech, mech.lagrange_rates(params), np.concatenate([q, qd])


@pytest.mark.parametrize("pid", problem_ids())
def test_every_reference_scene_has_machine_code_stages_equal_to_the_python_loop(pid):
    """Every scene, 1 to 5 degrees of freedom (3 and more: the elimination in machine code)."""
    for key, mech, rates, y0 in _reference_rates(pid):
        dim, K = y0.shape
        assert isinstance(rates.f, native.Native), f"{pid} {key}: the rates are not machine code"
        h = np.linspace(1e-3, 4e-3, K)
        T = np.empty((N_STAGES_EXTENDED, K))
        Z = np.zeros((N_STAGES_EXTENDED + 1, dim * K))
        Z[0] = y0.reshape(-1)
        coef = _coef()
        T[:] = 0.3 + np.linspace(0, 1, N_STAGES_EXTENDED)[:, None] * h
        Z[1] = (rates(T[0], y0) * h).reshape(-1)
        want = Z.copy()
        for s in range(1, N_STAGES_EXTENDED):
            state = (coef[s, :s + 1] @ want[:s + 1]).reshape(dim, K)
            want[s + 1] = (rates(T[s], state) * h).reshape(-1)
        run, last_state, last_rates, amax, _ = rates.stages(Z, T, h, coef)
        run(1, N_STAGES_EXTENDED)
        scale = np.abs(want).max(axis=1, keepdims=True) + 1e-300
        assert np.all(np.abs(Z - want) <= 1e-12 * scale), f"{pid} {key}"
        assert np.allclose(last_state, state, rtol=1e-12, atol=0)
        assert np.allclose(last_rates * h, want[-1].reshape(dim, K), rtol=1e-12, atol=0)
        every = np.abs(want[2:].reshape(-1, dim, K)) / h  # |rate| of each stage run, per column
        assert np.allclose(amax, every.max(axis=(0, 1)), rtol=1e-12)


@pytest.mark.parametrize("pid", ["12.14", "12.22", "12.37", "12.2"])
def test_a_run_takes_the_same_steps_and_gives_the_same_motion(pid):
    for key, mech, rates, y0 in _reference_rates(pid):
        acc = ACCURACY["default"]
        fast = integrate(rates, y0, mech.system.horizon, acc, method="DOP853")
        slow = integrate(python_path(rates), y0, mech.system.horizon, acc, method="DOP853")
        assert fast.ok and slow.ok
        if not _constant_accelerations(mech):
            assert fast.rhs_evals == slow.rhs_evals
        assert np.allclose(fast.y, slow.y, rtol=1e-7, atol=1e-9), f"{pid} {key}"


def _constant_accelerations(mech) -> bool:
    """A scene whose motion is a quadratic in t (12.22's pulleys): DOP853 integrates it exactly, so its
    error estimate is rounding alone, and which steps it takes depends on the last bit of each stage's
    arithmetic, in which the machine-code and numpy stage loops may differ."""
    state = {*mech.s.q, *mech.s.qd}
    return not any(a.free_symbols & state for a in mech.accelerations_symbolic)


@pytest.fixture
def python_loop(monkeypatch):
    """Machine-code stages, but the integrator's own loop in Python around them (no `bind_columns`)."""
    stages = CompiledRates.stages

    def without_loop(self, *buffers):
        made = stages(self, *buffers)
        return None if made is None else (*made[:4], lambda named: None)

    def use():
        monkeypatch.setattr(CompiledRates, "stages", without_loop)

    def undo():
        monkeypatch.setattr(CompiledRates, "stages", stages)
    return use, undo


def _both_loops(pid, python_loop):
    """(scene, the run with the loop in machine code, the run with the loop in Python, whether its error
    estimate is above rounding: see `_constant_accelerations`) for every scene of ``pid``, over its
    horizon at 201 samples and over 0.7 s at 5 (a repeated one among them)."""
    use, undo = python_loop
    for key, mech, rates, y0 in _reference_rates(pid):
        acc = ACCURACY["default"]
        for horizon, t_eval in [(mech.system.horizon, None), (0.7, np.array([0.0, 0.1, 0.1, 0.35, 0.7]))]:
            undo()
            fast = integrate(rates, y0, horizon, acc, method="DOP853", t_eval=t_eval)
            use()
            slow = integrate(rates, y0, horizon, acc, method="DOP853", t_eval=t_eval)
            undo()
            yield f"{pid} {key} over {horizon}", fast, slow, not _constant_accelerations(mech)


@pytest.mark.parametrize("pid", problem_ids())
def test_the_loop_in_machine_code_integrates_what_the_python_loop_integrates_in_every_scene(pid, python_loop):
    """Same stages kernel, the loop around it in machine code or in Python: the same outcome and
    motion, and about the same steps. Only about: the error estimate is a sum of 13 stages that
    numpy's product may add in another order (BLAS, fused multiply-adds), and where the motion is so
    smooth that the estimate is rounding noise (12.29, 12.45 on the machine this was written on), the
    step sizes follow that noise, which differs from one BLAS to another."""
    for scene, fast, slow, _ in _both_loops(pid, python_loop):
        assert fast.ok == slow.ok and fast.message == slow.message, scene
        assert np.allclose(fast.y, slow.y, rtol=1e-7, atol=1e-9), scene
        assert abs(fast.rhs_evals - slow.rhs_evals) <= max(30, slow.rhs_evals // 4), scene


@pytest.mark.parametrize("pid", ["12.14", "12.22", "12.37", "12.2", "12.25"])
def test_the_loop_in_machine_code_takes_the_python_loops_steps(pid, python_loop):
    """Where the error estimate is well above rounding (pendulums, coupled oscillators), every step
    is accepted or rejected alike: the same number of evaluations, exactly."""
    for scene, fast, slow, above_rounding in _both_loops(pid, python_loop):
        if above_rounding:
            assert fast.rhs_evals == slow.rhs_evals, scene
        assert np.allclose(fast.y, slow.y, rtol=1e-9, atol=1e-12), scene


def test_the_machine_code_loop_stops_where_the_python_loop_stops(python_loop):
    """Its three ways out besides the end: a step too small (NaN rates from t = 0.5 on in one column),
    the integrator's own evaluation budget, and the singularity guard (its column and stage times)."""
    use, undo = python_loop
    acc = ACCURACY["default"]
    f = compile_exprs([-x + sp.sqrt(0.5 - t) * k], [x, v, t, k])
    nan_later = CompiledRates(f, 2, np.array([[0.0, 1.0, 2.0]]), copied=1)   # sqrt(< 0) from t = 0.5 on
    y0 = np.array([[1.0, 0.5, 0.2], [0.0, 0.0, 1.0]])
    outs = []
    for switch in (undo, use):
        switch()
        outs.append(integrate(nan_later, y0, 1.0, acc, method="DOP853"))
    assert [o.ok for o in outs] == [False, False]
    assert all("step size too small in trajectory 0 at t = 0.49999" in o.message for o in outs), outs[0].message

    rates = CompiledRates(compile_exprs([-k * x], [x, v, t, k]), 2, np.array([[1.0, 4.0, 9.0, 16.0]]), copied=1)
    y0 = np.array([[1.0, 0.0, 0.5, 1.0], [0.0, 1.0, 0.5, 0.0]])
    fun = lambda tt, Y: rates(tt, Y)  # noqa: E731
    outs = []
    for switch in (undo, use):
        switch()
        hook = lambda *b: _with_count(rates.stages(*b))  # noqa: E731
        outs.append(dop853_columns(fun, 0.0, y0, 50.0, rtol=1e-10, atol=1e-10, t_eval=np.linspace(0, 50, 11),
                                   max_evals=300, stages=hook))
    assert outs[0].status == outs[1].status == -1 and outs[0].failed_column == outs[1].failed_column
    assert outs[0].t_failed == pytest.approx(outs[1].t_failed, rel=1e-6)
    assert all("more than 300 evaluations" in o.message for o in outs) and outs[0].nfev == outs[1].nfev
    assert np.array_equal(np.isnan(outs[0].y), np.isnan(outs[1].y))


def _with_count(made):
    """What `trajectory.integrate` hands the integrator, without its count and guard."""
    run, state, rates, amax, bind = made
    ints = np.zeros(len(native.COLUMN_INTS), dtype=np.int64)
    reals = np.zeros(len(native.COLUMN_REALS))

    def columns(buffers):
        loop = bind(buffers)
        if loop is None:
            return None

        def run_loop(nfev, nfev_limit, t_end, rtol, a_r):
            at = native.COLUMN_INTS.index
            ints[at("max_count")], ints[at("nfev_limit")], ints[at("guard")] = 2**62, nfev_limit, 0
            ints[at("count")], ints[at("nfev")] = 0, nfev
            reals[:] = (t_end, rtol, a_r, np.inf)
            status = loop(ints, reals)
            return status, int(ints[at("column")]), int(ints[at("nfev")])
        return run_loop
    return (lambda s0, s1: run(s0, s1)), state, rates, columns


def test_the_loop_refuses_buffers_it_would_read_past():
    rates, y0, _ = _ball()
    dim, K = y0.shape
    made = rates.stages(np.zeros((17, dim * K)), np.zeros((16, K)), np.full(K, 1e-3), _coef())
    n, n_eval = dim * K, 5
    good = {"F0": np.zeros((dim, K)), "t": np.zeros(K), "h_abs": np.zeros(K), "absa_old": np.zeros(n),
            "absa_new": np.zeros(n), "P": np.zeros((7, n)), "t_eval": np.linspace(0, 1, n_eval),
            "samples": np.zeros((dim, K, n_eval)), "E": np.zeros(26), "W": np.zeros(112), "limit": np.zeros(K),
            "ynew": np.zeros(n), "t_new": np.zeros(K), "t_next": np.zeros(K), "C": np.zeros(16),
            "rejected": np.zeros(K, dtype=bool), "active": np.ones(K, dtype=bool),
            "accepted": np.zeros(K, dtype=bool), "i_eval": np.zeros(K, dtype=np.int64)}
    assert made[4](good) is not None
    for name, bad in [("samples", np.zeros((dim, K, n_eval - 1))), ("P", np.zeros((6, n))),
                      ("i_eval", np.zeros(K, dtype=np.int32)), ("active", np.ones(K)),
                      ("F0", np.zeros((K, dim)).T), ("W", np.zeros(112)[::-1].copy()[:111])]:
        with pytest.raises(ValueError, match=name):
            made[4]({**good, name: bad})
    loop = made[4](good)
    with pytest.raises(ValueError):
        loop(np.zeros(3, dtype=np.int64), np.zeros(4))


def _ball():
    """x'' = -k: thrown up from x = 0 with v = 1, 2, 3, 4; the event x = 0 falling stops each column."""
    f = compile_exprs([-k + 0 * x], [x, v, t, k])
    rates = CompiledRates(f, 2, np.full((1, 4), 9.81), copied=1)
    y0 = np.array([[0.0, 0.0, 0.0, 0.0], [1.0, 2.0, 3.0, 4.0]])
    landing = BatchedEvent("landing", lambda tt, Y: Y[0] + 0 * Y[1] - 1e-3, direction=-1.0, action="stop")
    return rates, y0, landing


def test_events_stop_each_trajectory_where_the_python_loop_stops_it():
    rates, y0, landing = _ball()
    acc = ACCURACY["default"]
    fast = integrate(rates, y0, 1.0, acc, method="DOP853", events=[landing])
    slow = integrate(python_path(rates), y0, 1.0, acc, method="DOP853", events=[landing])
    assert fast.ok and slow.ok
    exact = (y0[1] + np.sqrt(y0[1] ** 2 - 2 * 9.81 * 1e-3)) / 9.81
    landed = exact < 1.0
    assert np.allclose(fast.t_stop[landed], exact[landed], rtol=1e-9)
    assert np.array_equal(fast.t_stop, slow.t_stop) or np.allclose(fast.t_stop, slow.t_stop, rtol=1e-12)
    assert np.allclose(fast.y, slow.y, rtol=1e-9, atol=1e-12)


def test_a_singularity_is_refused_with_the_python_loops_words():
    """x'' = 1/(1 - x)^2: the trajectories reach x = 1 in finite time; the guard stops the run."""
    f = compile_exprs([1 / (1 - x) ** 2 + 0 * k], [x, v, t, k])
    rates = CompiledRates(f, 2, np.ones((1, 3)), copied=1)
    y0 = np.array([[0.0, 0.2, 0.5], [1.0, 1.0, 1.0]])
    acc = ACCURACY["default"]
    fast = integrate(rates, y0, 5.0, acc, method="DOP853")
    slow = integrate(python_path(rates), y0, 5.0, acc, method="DOP853")
    assert not fast.ok and not slow.ok
    assert "approaches a singularity" in fast.message and "trajectory 3" in fast.message
    assert fast.message.split(" at t")[0] == slow.message.split(" at t")[0]


def test_the_evaluation_budget_holds_inside_machine_code():
    from dataclasses import replace

    rates, y0, _ = _ball()
    acc = replace(ACCURACY["default"], max_rhs_evals=100)
    run = integrate(rates, y0, 50.0, acc, method="DOP853")
    assert not run.ok and "needed more than 100 steps" in run.message
    assert run.rhs_evals <= 100 + 12


def test_the_stage_buffers_live_as_long_as_the_bound_code():
    """The machine code holds bare addresses: a buffer freed under it would be written after free."""
    rates, y0, _ = _ball()
    dim, K = y0.shape
    made = rates.stages(np.zeros((17, dim * K)), np.zeros((16, K)), np.full(K, 1e-3), _coef())
    run = made[0]
    watched = [weakref.ref(b) for b in run.keep[:8]]
    del made
    gc.collect()
    assert all(w() is not None for w in watched)
    run(1, 13)


def test_the_pair_of_compiled_rates_covers_twice_the_columns():
    rates, y0, _ = _ball()
    pair = rates.pair()
    Y = np.concatenate([y0, y0 + 0.1], axis=1)
    assert np.allclose(pair(0.0, Y), np.concatenate([rates(0.0, y0), rates(0.0, y0 + 0.1)], axis=1))


def test_numpy_rates_have_no_machine_code_stages_and_still_integrate():
    f = compile_numpy([-k * x], [x, v, t, k])
    rates = CompiledRates(f, 2, np.full((1, 2), 4.0), copied=1)
    T, h = np.zeros((16, 2)), np.zeros(2)
    assert rates.stages(np.zeros((17, 4)), T, h, _coef()) is None
    run = integrate(rates, np.array([[1.0, 0.5], [0.0, 0.0]]), 1.0, ACCURACY["default"], method="DOP853")
    assert run.ok and np.allclose(run.y[0, :, -1], [np.cos(2.0), 0.5 * np.cos(2.0)], rtol=1e-8)


# ------------------------------------------------------------------------------- linear solves


@settings(max_examples=40, deadline=None)
@given(n=st.integers(3, 6), seed=st.integers(0, 2**32 - 1))
def test_the_elimination_in_machine_code_agrees_with_lapack(n, seed):
    syms = sp.symbols(f"a0:{n}")
    rng = np.random.default_rng(seed)
    coeffs = rng.normal(size=(n, n + 1, n))
    A_ = [[sum(float(coeffs[i, j, m]) * syms[m] for m in range(n)) + float(rng.normal()) for j in range(n)]
          for i in range(n)]
    b_ = [sp.sin(syms[i]) + float(coeffs[i, n, 0]) for i in range(n)]
    solve = compile_linear_solve(A_, b_, syms)
    assert isinstance(solve, native.Native)
    X = rng.normal(size=(n, 9))
    M = compile_numpy([a for row in A_ for a in row], syms)(*X).reshape(n, n, 9)
    r = compile_numpy(b_, syms)(*X)
    want = solve_batch(M, r)
    cond = np.array([np.linalg.cond(M[:, :, i]) for i in range(9)])
    got = solve(*X)
    ok = cond < 1e8
    assert np.allclose(got[:, ok], want[:, ok], rtol=1e-8 * 1e4, atol=1e-10 * np.abs(want[:, ok]).max())


def test_a_singular_state_gives_nan_for_that_state_only():
    a, b = sp.symbols("a b")
    A_ = [[a, 1, 0], [0, 1, 0], [0, 0, b]]
    solve = compile_linear_solve(A_, [1, 2, 3], [a, b])
    got = solve(np.array([0.0, 2.0, 1.0]), np.array([1.0, 0.0, 3.0]))
    assert np.all(np.isnan(got[:, :2]))   # a = 0 (rows dependent) and b = 0
    assert np.allclose(got[:, 2], [-1.0, 2.0, 1.0])


def test_rates_without_constants_integrate_in_machine_code():
    """x'' = -x, no parameters at all: the argument rows are the state and t only."""
    rates = CompiledRates(compile_exprs([-x + 0 * t], [x, v, t]), 2, np.zeros((0, 3)), copied=1)
    y0 = np.array([[1.0, 0.0, 2.0], [0.0, 1.0, 0.0]])
    run = integrate(rates, y0, 2.0, ACCURACY["default"], method="DOP853")
    exact = y0[0] * np.cos(2.0) + y0[1] * np.sin(2.0)
    assert run.ok and np.allclose(run.y[0, :, -1], exact, rtol=1e-8, atol=1e-10)
    assert rates.stages(np.zeros((17, 6)), np.zeros((16, 3)), np.zeros(3), _coef()) is not None


def test_stage_ranges_outside_the_table_are_refused_before_the_machine_code_writes():
    rates, y0, _ = _ball()
    dim, K = y0.shape
    run = rates.stages(np.zeros((17, dim * K)), np.zeros((16, K)), np.full(K, 1e-3), _coef())[0]
    for s0, s1 in [(0, 3), (1, 17), (5, 4)]:
        with pytest.raises(ValueError):
            run(s0, s1)
