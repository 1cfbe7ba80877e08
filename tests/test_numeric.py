"""The batched linear solve behind every right-hand side."""

import numpy as np

from lagrade.numeric import solve_batch


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

from lagrade.numeric import Generated, compile_exprs, compile_linear_solve  # noqa: E402

x, y, z = sp.symbols("x y z")


def test_compiled_rows_broadcast_constants_and_match_sympy():
    f = compile_exprs([sp.sin(x) * y + sp.sqrt(z), sp.Integer(3), x**2 / (1 + y**2)], [x, y, z])
    assert isinstance(f, Generated)
    X, Y, Z = np.array([0.1, 0.2]), np.array([1.0, -2.0]), np.array([4.0, 9.0])
    got = f(X, Y, Z)
    assert got.shape == (3, 2)
    for k in range(2):
        subs = {x: X[k], y: Y[k], z: Z[k]}
        assert np.allclose(got[:, k], [float(sp.sympify(e).subs(subs)) for e in
                                       (sp.sin(x) * y + sp.sqrt(z), 3, x**2 / (1 + y**2))])


def test_compiled_function_pickles_as_its_source():
    f = compile_exprs([sp.cos(x) - y], [x, y])
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
