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
