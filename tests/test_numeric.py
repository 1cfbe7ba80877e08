"""The batched linear solve behind every right-hand side."""

import numpy as np

from lagrade.numbers.numeric import solve_batch


def test_solves_each_state_of_the_batch():
    rng = np.random.default_rng(0)
    M = rng.normal(size=(3, 3, 5)) + 3 * np.eye(3)[..., None]
    x = rng.normal(size=(3, 5))
    f = np.einsum("ijk,jk->ik", M, x)
    assert np.allclose(solve_batch(M, f), x)


def test_a_singular_state_is_nan_alone():
    M = np.stack([np.eye(2), np.zeros((2, 2)), 2 * np.eye(2)], axis=-1)
    f = np.ones((2, 3))
    x = solve_batch(M, f)
    assert np.allclose(x[:, 0], 1) and np.allclose(x[:, 2], 0.5)
    assert np.all(np.isnan(x[:, 1]))


# --------------------------------------------------------------------------- compiled expressions

import pickle  # noqa: E402

import pytest  # noqa: E402
import sympy as sp  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from lagrade.numbers.numeric import Generated, compile_exprs, compile_linear_solve, compile_numpy  # noqa: E402

x, y, z = sp.symbols("x y z")


def test_compiled_rows_broadcast_constants_and_match_sympy():
    f = compile_numpy([sp.sin(x) * y + sp.sqrt(z), sp.Integer(3), x**2 / (1 + y**2)], [x, y, z])
    assert isinstance(f, Generated)
    X, Y, Z = np.array([0.1, 0.2]), np.array([1.0, -2.0]), np.array([4.0, 9.0])
    got = f(X, Y, Z)
    assert got.shape == (3, 2)
    for k in range(2):
        subs = {x: X[k], y: Y[k], z: Z[k]}
        assert np.allclose(got[:, k], [float(sp.sympify(e).subs(subs)) for e in
                                       (sp.sin(x) * y + sp.sqrt(z), 3, x**2 / (1 + y**2))])


def test_compiled_function_pickles_as_its_source():
    f = compile_numpy([sp.cos(x) - y], [x, y])
    g = pickle.loads(pickle.dumps(f))
    assert g.source == f.source
    assert np.allclose(g(np.array([0.0, np.pi]), np.array([1.0, 1.0])), [[0.0, -2.0]])


def test_complex_intermediates_keep_the_real_part_and_zoo_is_nan():
    f = compile_exprs([(sp.exp(sp.I * x) + sp.exp(-sp.I * x)) / 2, sp.zoo * x], [x])
    got = f(np.array([0.3, 1.0]))
    assert np.allclose(got[0], np.cos([0.3, 1.0])) and not np.iscomplexobj(got)
    assert np.all(np.isnan(got[1]))


def test_unknown_functions_fall_back_to_lambdify_or_fail_loudly():
    h = sp.Function("h")
    with pytest.raises(Exception):
        compile_exprs([h(x)], [x])(np.array([1.0]))


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_linear_solve_written_out_or_batched_matches_numpy(n):
    syms = sp.symbols(f"a0:{n}")
    rng = np.random.default_rng(n)
    C = rng.normal(size=(n, n)) + 3 * np.eye(n)
    A = [[C[i, j] * (1 + syms[(i + j) % n] ** 2) for j in range(n)] for i in range(n)]
    b = [sp.sin(syms[i]) + i for i in range(n)]
    solve = compile_linear_solve(A, b, list(syms))
    pts = rng.normal(size=(n, 7))
    got = solve(*pts)
    for k in range(7):
        subs = dict(zip(syms, pts[:, k]))
        Ak = np.array([[float(e.subs(subs)) for e in row] for row in A])
        bk = np.array([float(e.subs(subs)) for e in b])
        assert np.allclose(got[:, k], np.linalg.solve(Ak, bk))
    assert np.allclose(pickle.loads(pickle.dumps(solve))(*pts), got)


def test_singular_two_by_two_is_not_finite_and_never_raises():
    solve = compile_linear_solve([[x, 1], [x, 1]], [1, 2], [x])
    assert not np.any(np.isfinite(solve(np.array([1.0, 2.0]))))
    zero = compile_linear_solve([[0, 0], [0, x]], [1, 2], [x])  # a row without unknowns: det is 0 symbolically
    assert np.all(np.isnan(zero(np.array([1.0]))))


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-3, 3), min_size=4, max_size=4), st.floats(-2, 2), st.floats(-2, 2))
def test_two_by_two_written_out_solves_any_well_conditioned_system(entries, b0, b1):
    a, c, d, e = entries
    M = np.array([[a, c], [d, e]])
    if abs(np.linalg.det(M)) < 1e-3 or np.linalg.cond(M) > 1e6:
        return
    solve = compile_linear_solve([[a + 0 * x, c], [d, e]], [b0, b1], [x])
    assert np.allclose(solve(np.array([0.0]))[:, 0], np.linalg.solve(M, [b0, b1]), atol=1e-9)


# --------------------------------------------------------------------------- evaluating without compiling

from lagrade.numbers.numeric import evaluate  # noqa: E402


def test_evaluate_matches_compiled_code_on_every_node_kind():
    exprs = [sp.sin(x) * y**2 - 1 / x, sp.Piecewise((x, x > 0.5), (-y, True)),
             (sp.exp(sp.I * x) + sp.exp(-sp.I * x)) / 2, sp.Abs(x - y) ** sp.Rational(3, 2), sp.atan2(y, x),
             sp.Heaviside(x - 1), sp.Integer(3), sp.pi * x, sp.log(x, 2), sp.Max(x, y), sp.zoo * x,
             x**-3, sp.sqrt(y), sp.cosh(x) * sp.tan(y), sp.sign(y) * sp.floor(3 * x)]
    X, Y = np.linspace(0.1, 2, 7), np.linspace(-1, 1, 7)
    a, b = evaluate(exprs, [x, y], [X, Y]), compile_numpy(exprs, [x, y])(X, Y)
    assert a.shape == b.shape == (len(exprs), 7)
    assert np.array_equal(np.isnan(a), np.isnan(b))
    assert np.allclose(a[~np.isnan(a)], b[~np.isnan(b)], rtol=1e-12, atol=1e-12)


def test_evaluate_falls_back_to_compiling_what_it_does_not_know():
    f = sp.Function("f")
    with pytest.raises(Exception):
        evaluate([f(x)], [x], [np.ones(2)])
    got = evaluate([sp.Mod(x, 1)], [x], [np.array([0.25, 1.5])])  # not in the walker's table
    assert np.allclose(got[0], [0.25, 0.5])


def _systems():
    from lagrade.problem.library import load_problem, problem_ids

    for pid in problem_ids():
        for system in load_problem(pid).systems:
            yield pid, system.key


@pytest.mark.parametrize("pid, key", list(_systems()))
def test_evaluate_agrees_with_compiled_code_on_every_reference(pid, key):
    from lagrade.verdicts.grade import references
    from lagrade.problem.library import load_problem
    from lagrade.compare.sampling import rng_for, sample_points

    problem = load_problem(pid)
    mech = references(problem)[key]
    args = [*mech.s.q, *mech.s.qd, *mech.s.qdd, sp.Symbol("t"), *mech.params, *mech.multipliers]
    exprs = [mech.L, *mech.EL, *mech.multiplier_exprs.values()]
    pts = sample_points(mech, 9, rng_for("evaluate", pid, key))
    values = [pts[a] if a in pts.values else np.linspace(0.5, 1.5, 9) for a in args]
    a, b = evaluate(exprs, args, values), compile_exprs(exprs, args)(*values)
    assert np.array_equal(np.isnan(a), np.isnan(b))
    scale = np.maximum(1.0, np.abs(b))
    assert np.all(np.abs(np.nan_to_num(a) - np.nan_to_num(b)) <= 1e-10 * scale)
