"""Tests of lagrade's DOP853 (lagrade.compare.dop853): K trajectories as the columns of one array,
each with its own time, step size, error control and events.

scipy is used here only as a reference; the module itself must not import it.
"""

from __future__ import annotations

import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import DOP853 as ScipyDOP853
from scipy.integrate import solve_ivp

from lagrade.compare.dop853 import ColumnEvent, ColumnResult, solve
from lagrade.compare.trajectory import ACCURACY, BatchedEvent, integrate
from lagrade.numbers.numeric import CompiledRates, compile_exprs, compile_numpy


def oscillators(w: np.ndarray):
    """x'' = -w^2 x per column, state [x, v]."""
    w2 = np.asarray(w, dtype=float) ** 2

    def fun(t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        return np.stack([Y[1], -w2 * Y[0]])

    return fun


def oscillator_exact(w, x0, v0, t) -> np.ndarray:
    """(2, K, nt) exact states of `oscillators`."""
    w, x0, v0 = (np.asarray(a, dtype=float)[:, None] for a in (w, x0, v0))
    t = np.asarray(t, dtype=float)[None, :]
    x = x0 * np.cos(w * t) + v0 / w * np.sin(w * t)
    v = -x0 * w * np.sin(w * t) + v0 * np.cos(w * t)
    return np.stack([x, v])


def pendulums(k: np.ndarray):
    """theta'' = -(g/l) sin(theta) per column, state [theta, omega]."""
    k = np.asarray(k, dtype=float)

    def fun(t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        return np.stack([Y[1], -k * np.sin(Y[0])])

    return fun


def checked(fun, K: int, dim: int = 2):
    """`fun` wrapped to check the contract of `solve`: every call gets all K columns and one time
    per column."""

    def wrapped(t, Y):
        assert isinstance(t, np.ndarray) and t.shape == (K,), t
        assert Y.shape == (dim, K), Y.shape
        return fun(t, Y)

    return wrapped


def events_of(r: ColumnResult, k: int) -> list[tuple[int, float, np.ndarray]]:
    """(event, t, y) of column k, in time order."""
    return sorted(((i, t, y) for i, kk, t, y in r.events if kk == k), key=lambda e: e[1])


# ----------------------------------------------------------------------------- 1. accuracy


def test_harmonic_oscillator_batch_matches_exact_solution():
    w = np.array([0.5, 1.0, 1.7, 2.3, 3.0])
    x0 = np.array([1.0, 2.0, 0.5, 3.0, 1.5])
    v0 = np.array([0.0, 0.3, -1.0, 0.5, 2.0])
    t_eval = np.linspace(0.0, 10.0, 41)  # includes t0 and t_end
    r = solve(checked(oscillators(w), 5), 0.0, np.vstack([x0, v0]), 10.0, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert isinstance(r, ColumnResult)
    assert r.status == 0 and r.events == [] and r.failed_column is None
    assert r.y.shape == (2, 5, 41)
    np.testing.assert_array_equal(r.t, t_eval)
    np.testing.assert_array_equal(r.t_stop, np.full(5, 10.0))
    np.testing.assert_array_equal(r.y[:, :, 0], np.vstack([x0, v0]))
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-9


def test_many_columns_match_the_exact_solution():
    K = 64
    w = np.linspace(0.5, 3.0, K)
    x0, v0 = np.linspace(-2.0, 2.0, K), np.linspace(1.0, -1.0, K)
    t_eval = np.linspace(0.0, 5.0, 11)
    r = solve(oscillators(w), 0.0, np.vstack([x0, v0]), 5.0, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert r.status == 0
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-9


def test_columns_at_rest_cost_nothing_extra():
    # a column with y = f = 0 has both error estimates exactly 0 (0/0 in the DOP853 norm)
    w = np.array([1.0, 2.0, 1.0])
    x0, v0 = np.array([1.0, 0.0, 0.5]), np.zeros(3)
    t_eval = np.linspace(0.0, 3.0, 4)
    r = solve(oscillators(w), 0.0, np.vstack([x0, v0]), 3.0, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    assert r.status == 0
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-8
    alone = solve(oscillators(w[:1]), 0.0, np.vstack([x0[:1], v0[:1]]), 3.0, rtol=1e-10, atol=1e-10,
                  t_eval=t_eval)
    assert r.nfev <= alone.nfev + 3 * 4  # at most the dense output of a few more iterations
    # everything at rest: zero error, the step grows tenfold each time
    rest = solve(oscillators(w), 0.0, np.zeros((2, 3)), 1e6, rtol=1e-10, atol=1e-10, t_eval=np.array([1e6]))
    assert rest.status == 0 and rest.nfev < 200
    np.testing.assert_array_equal(rest.y, 0.0)


# ----------------------------------------------------------------------------- 2. against scipy

K_PEND = np.array([0.5, 1.0, 1.5, 2.0, 4.0, 9.81, 3.0, 0.8])
Y0_PEND = np.vstack([[0.1, 0.5, 1.0, 1.5, 2.0, 2.5, 2.2, 0.3],
                     [0.0, 0.2, -0.3, 0.5, 0.0, -1.0, 0.1, 1.0]])


def _scipy_column(c: int, t_end: float, t_eval: np.ndarray | None):
    k = K_PEND[c]
    return solve_ivp(lambda t, y: [y[1], -k * np.sin(y[0])], (0.0, t_end), Y0_PEND[:, c], method="DOP853",
                     rtol=1e-10, atol=1e-10, t_eval=t_eval)


def test_pendulum_batch_matches_scipy_per_column_and_costs_about_the_hardest_column():
    t_end = 10.0
    t_eval = np.linspace(0.0, t_end, 101)
    r = solve(checked(pendulums(K_PEND), 8), 0.0, Y0_PEND, t_end, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    assert r.status == 0
    sols = [_scipy_column(c, t_end, t_eval) for c in range(8)]
    for c, s in enumerate(sols):
        assert s.status == 0
        assert np.abs(s.y - r.y[:, c]).max() < 1e-7, c
    # Like with like, with dense output: both runs produce the same t_eval samples, and both nfev
    # count the 3 extra dense-output evaluations of each step holding samples.
    assert r.nfev <= 1.3 * max(s.nfev for s in sols)
    # Like with like, stepping only: scipy without t_eval (no dense output), ours with samples only
    # at t0 and t_end (which need no interpolation, hence no dense output either).
    r_steps = solve(pendulums(K_PEND), 0.0, Y0_PEND, t_end, rtol=1e-10, atol=1e-10, t_eval=np.array([0.0, t_end]))
    steps_only = [_scipy_column(c, t_end, None).nfev for c in range(8)]
    assert r_steps.nfev <= 1.3 * max(steps_only)
    np.testing.assert_allclose(r_steps.y[:, :, -1], r.y[:, :, -1], rtol=0, atol=1e-12)


@pytest.mark.parametrize("c", [0, 5])
def test_single_column_takes_exactly_scipys_steps(c):
    # K = 1: the initial step, the error norm and the step-size control are scipy's DOP853
    t_end = 10.0
    r = solve(pendulums(K_PEND[c:c + 1]), 0.0, Y0_PEND[:, c:c + 1], t_end, rtol=1e-10, atol=1e-10,
              t_eval=np.array([t_end]))
    s = _scipy_column(c, t_end, None)
    assert r.nfev == s.nfev
    # same steps up to the rounding of the norm (summation order), so agreement far below the tolerance
    np.testing.assert_allclose(r.y[:, 0, -1], s.y[:, -1], rtol=0, atol=1e-11)


def test_each_column_moves_as_if_it_were_integrated_alone():
    """Each column's steps depend on that column only: in the batch it gets (up to rounding in the
    batched products) the result it gets alone, and the batch costs about its hardest column."""
    t_eval = np.linspace(0.0, 10.0, 101)
    batch = solve(pendulums(K_PEND), 0.0, Y0_PEND, 10.0, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    alone = [solve(pendulums(K_PEND[c:c + 1]), 0.0, Y0_PEND[:, c:c + 1], 10.0, rtol=1e-10, atol=1e-10,
                   t_eval=t_eval) for c in range(8)]
    for c, a in enumerate(alone):
        assert np.abs(a.y[:, 0] - batch.y[:, c]).max() < 1e-11, c
    # the only extra: the dense output of iterations where another column has a sample
    assert batch.nfev <= 1.1 * max(a.nfev for a in alone)


# ----------------------------------------------------------------------------- 3. per-column control


def test_each_column_is_held_to_its_own_tolerance():
    # 31 easy oscillators and one fast one. A norm over the flattened batch would let the easy
    # columns dilute the fast column's error (about sqrt(32)-fold larger steps^8); each column's own
    # norm gives every column at most the error it gets when integrated alone.
    K = 32
    w = np.ones(K)
    w[-1] = 20.0
    x0 = np.linspace(0.5, 2.0, K)
    v0 = np.zeros(K)
    t_eval = np.linspace(0.0, 10.0, 11)
    tol = 1e-8

    def error(cols: slice) -> np.ndarray:
        r = solve(oscillators(w[cols]), 0.0, np.vstack([x0[cols], v0[cols]]), 10.0, rtol=tol, atol=tol,
                  t_eval=t_eval)
        assert r.status == 0
        return np.abs(r.y - oscillator_exact(w[cols], x0[cols], v0[cols], t_eval)).max(axis=(0, 2))

    batch = error(slice(None))
    for c in (0, 13, K - 2, K - 1):
        alone = error(slice(c, c + 1))[0]
        assert batch[c] <= 1.2 * alone + 1e-13, (c, batch[c], alone)
    assert batch[-1] > 1e-7  # the fast column's error is well above round-off: the check has teeth


#: pendulums near the separatrix: slow near the top, fast through the bottom, with different
#: periods, so which trajectory needs the smallest step changes all the time
K_SEP = np.linspace(1.0, 4.0, 16)
Y0_SEP = np.vstack([[3.019, 3.103, 3.028, 3.093, 3.0, 3.037, 3.065, 3.047,
                     3.131, 3.112, 3.056, 3.084, 3.121, 3.075, 3.009, 3.14], np.zeros(16)])


def _shared_step(dim: int, K: int):
    """A shared step over the batch, as the removed ``dop853`` took: scipy's DOP853 on the flattened
    (dim, K) state with that integrator's error norm, the largest of the columns' own (RMS over dim)
    DOP853 norms, so one step serves every column and is as small as the hardest column needs."""

    class SharedStep(ScipyDOP853):
        def _estimate_error_norm(self, stages, h, scale):
            e5 = np.square(np.dot(stages.T, self.E5) / scale).reshape(dim, K).sum(axis=0)
            e3 = np.square(np.dot(stages.T, self.E3) / scale).reshape(dim, K).sum(axis=0)
            den = e5 + 0.01 * e3
            den[den == 0.0] = 1.0   # both estimates exactly 0: the norm is 0
            return float(np.max(np.abs(h) * e5 / np.sqrt(den * dim)))

    return SharedStep


def test_columns_cost_about_the_hardest_trajectory_not_the_shared_step():
    t_end = 10.0
    t_eval = np.linspace(0.0, t_end, 101)
    fun = pendulums(K_SEP)
    cols = solve(fun, 0.0, Y0_SEP, t_end, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    dim, K = Y0_SEP.shape
    # the removed dop853 started from the smallest of the initial steps scipy picks for each column alone
    first = min(ScipyDOP853(lambda t, y, k=k: [y[1], -k * np.sin(y[0])], 0.0, Y0_SEP[:, c], t_end, rtol=1e-10,
                            atol=1e-10).h_abs for c, k in enumerate(K_SEP))
    shared = solve_ivp(lambda t, y: fun(t, y.reshape(dim, K)).reshape(-1), (0.0, t_end), Y0_SEP.reshape(-1),
                       method=_shared_step(dim, K), rtol=1e-10, atol=1e-10, t_eval=t_eval, first_step=first)
    assert cols.status == 0 and shared.status == 0
    scipy_nfev = []
    for c in range(16):
        k = K_SEP[c]
        s = solve_ivp(lambda t, y, k=k: [y[1], -k * np.sin(y[0])], (0.0, t_end), Y0_SEP[:, c], method="DOP853",
                      rtol=1e-10, atol=1e-10, t_eval=t_eval)
        assert np.abs(s.y - cols.y[:, c]).max() < 1e-7, c
        scipy_nfev.append(s.nfev)
    print(f"\nnfev: solve {cols.nfev}, shared step {shared.nfev}, "
          f"scipy per column max {max(scipy_nfev)} mean {np.mean(scipy_nfev):.0f}")
    # like with like: same t_eval, dense output counted on both sides
    assert cols.nfev <= 1.15 * max(scipy_nfev)
    assert cols.nfev <= 0.9 * shared.nfev
    assert np.abs(cols.y - shared.y.reshape(dim, K, -1)).max() < 1e-6


def test_each_column_gets_its_own_time():
    # y' = cos(w t): y = sin(w t) / w.  A column evaluated at another column's times goes wrong.
    w = np.array([0.5, 1.0, 3.0, 7.0, 0.1])
    K = len(w)
    seen: list[np.ndarray] = []

    def fun(t, Y):
        seen.append(t.copy())
        return np.cos(w * t)[None, :]

    t_eval = np.linspace(0.0, 4.0, 41)
    r = solve(checked(fun, K, 1), 0.0, np.zeros((1, K)), 4.0, rtol=1e-12, atol=1e-12, t_eval=t_eval)
    assert r.status == 0
    exact = np.sin(w[:, None] * t_eval[None, :]) / w[:, None]
    assert np.abs(r.y[0] - exact).max() < 1e-9
    # the columns really were at different times (the fast one takes smaller steps)
    assert any(np.ptp(t) > 0.1 for t in seen)
    # columns that reached t_end are still evaluated there, without moving
    assert np.all(seen[-1] <= 4.0)


# ----------------------------------------------------------------------------- 4. events


W_EV = np.array([1.0, 2.0, 3.0, 1.5])


def _cos_batch(w=W_EV):
    """x = cos(w t): falling zero at pi/(2w), rising zero at 3pi/(2w)."""
    return oscillators(w), np.vstack([np.ones(len(w)), np.zeros(len(w))])


def _x(t: np.ndarray, Y: np.ndarray) -> np.ndarray:
    return Y[0]


def _assert_stops(r: ColumnResult, roots: np.ndarray, t_eval: np.ndarray, w=W_EV, event: int = 0) -> None:
    """Each column has exactly one event, ``event`` at its closed-form root where its state is the exact
    one; its samples are exact up to the root and its frozen state at the root after it."""
    assert r.status == 0
    np.testing.assert_allclose(r.t_stop, roots, rtol=0, atol=1e-10)
    K = len(w)
    exact = oscillator_exact(w, np.ones(K), np.zeros(K), t_eval)
    for k in range(K):
        [(i, te, yk)] = events_of(r, k)
        assert i == event and te == r.t_stop[k]
        np.testing.assert_allclose(yk, oscillator_exact(w[k:k + 1], [1.0], [0.0], [te])[:, 0, 0],
                                   rtol=0, atol=1e-10)
        before = t_eval <= te
        assert np.abs(r.y[:, k, before] - exact[:, k, before]).max(initial=0.0) < 1e-10
        np.testing.assert_array_equal(r.y[:, k, ~before], np.repeat(yk[:, None], (~before).sum(), 1))


def test_falling_event_is_located_on_the_dense_output():
    # (the removed shared step stopped the whole batch at the first root over all columns, w = 3 at
    # pi/6; now each column stops at its own first root, pi/(2w))
    fun, y0 = _cos_batch()
    t_eval = np.linspace(0.0, 2.0, 21)
    r = solve(checked(fun, 4), 0.0, y0, 2.0, rtol=1e-12, atol=1e-12, t_eval=t_eval,
              events=[ColumnEvent(_x, direction=-1)])
    np.testing.assert_array_equal(r.t, t_eval)
    assert r.y.shape == (2, 4, len(t_eval))
    _assert_stops(r, np.pi / (2 * W_EV), t_eval)
    assert abs(r.t_stop[2] - np.pi / 6) < 1e-10
    assert (t_eval > r.t_stop.max()).any()   # every column has samples after its stop: frozen ones


def test_rising_direction_ignores_falling_crossings():
    fun, y0 = _cos_batch()
    t_eval = np.linspace(0.0, 5.0, 11)
    r = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=t_eval, events=[ColumnEvent(_x, direction=+1)])
    _assert_stops(r, 3 * np.pi / (2 * W_EV), t_eval)
    assert abs(r.t_stop[2] - 3 * np.pi / 6) < 1e-10
    assert all(yk[1] > 0 for _, _, _, yk in r.events)   # rising through x = 0


def test_both_directions_fire_at_the_first_crossing():
    fun, y0 = _cos_batch()
    t_eval = np.linspace(0.0, 5.0, 11)
    r = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=t_eval, events=[ColumnEvent(_x)])
    _assert_stops(r, np.pi / (2 * W_EV), t_eval)
    assert abs(r.t_stop[2] - np.pi / 6) < 1e-10


def test_columns_mask_excludes_a_column():
    fun, y0 = _cos_batch()
    mask = np.array([True, True, False, True])  # the fastest column (w = 3) is not watched
    r = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
              events=[ColumnEvent(_x, direction=-1, columns=mask)])
    assert r.status == 0
    assert events_of(r, 2) == [] and r.t_stop[2] == 5.0
    np.testing.assert_allclose(r.y[:, 2, -1], oscillator_exact(W_EV[2:3], [1.0], [0.0], [5.0])[:, 0, 0],
                               rtol=0, atol=1e-10)
    assert abs(r.t_stop[1] - np.pi / 4) < 1e-10   # next fastest: w = 2
    np.testing.assert_allclose(r.t_stop[mask], np.pi / (2 * W_EV[mask]), rtol=0, atol=1e-10)


def test_earliest_event_over_events_wins_in_every_column():
    # (the removed shared step: the earliest over events and columns stopped the batch, event 1 of
    # column 2 at pi/9; now each column stops at its own earliest root, x = 0.5 at pi/(3w))
    fun, y0 = _cos_batch()
    t_eval = np.linspace(0, 5, 11)
    # event 0: x = -0.9 on column 0 only (late: arccos(-0.9)); event 1: x = 0.5 falling
    events = [ColumnEvent(lambda t, Y: Y[0] + 0.9, columns=np.array([True, False, False, False])),
              ColumnEvent(lambda t, Y: Y[0] - 0.5, direction=-1)]
    r = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=t_eval, events=events)
    assert r.status == 0
    assert sorted((k, i) for i, k, _, _ in r.events) == [(k, 1) for k in range(4)]
    np.testing.assert_allclose(r.t_stop, np.pi / (3 * W_EV), rtol=0, atol=1e-10)
    assert abs(r.t_stop[2] - np.pi / 9) < 1e-10
    # the same with the events in the other order, and the late one on every column
    events2 = [events[1], ColumnEvent(lambda t, Y: Y[0] + 0.9)]
    r2 = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]), events=events2)
    assert sorted((k, i) for i, k, _, _ in r2.events) == [(k, 0) for k in range(4)]
    np.testing.assert_allclose(r2.t_stop, np.pi / (3 * W_EV), rtol=0, atol=1e-10)


def test_earliest_of_several_events_in_one_column_wins():
    fun, y0 = _cos_batch()
    events = [ColumnEvent(lambda t, Y: Y[0] + 0.9),                    # x = -0.9: later
              ColumnEvent(lambda t, Y: Y[0] - 0.5, direction=-1)]      # x = 0.5: at pi / (3 w)
    r = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]), events=events)
    assert r.status == 0
    assert sorted((k, i) for i, k, _, _ in r.events) == [(k, 1) for k in range(4)]
    np.testing.assert_allclose(r.t_stop, np.pi / (3 * W_EV), rtol=0, atol=1e-10)


def test_several_roots_in_one_step_the_earliest_wins():
    # x = v t: DOP853 is exact, so steps grow tenfold and one step holds all the roots below.
    # In column 0 the candidates are visited in order (event 0 at 0.54 first); the later one is
    # bracketed by the best root so far, and event 1 (root 0.3) must win. Column 1 has only event
    # 0 (root 0.18).
    # (the removed shared step: column 1's root 0.18 stopped the whole batch, and event 1 of column
    # 0 had to be dropped; now each column stops at its own earliest root)
    v = np.array([1.0, 3.0])
    seen: list[np.ndarray] = []

    def g0(t, Y):
        seen.append(np.array(t, dtype=float))
        return Y[0] - 0.54

    events = [ColumnEvent(g0), ColumnEvent(lambda t, Y: Y[0] - 0.3, columns=np.array([True, False]))]
    t_eval = np.linspace(0.0, 1.0, 11)
    r = solve(lambda t, Y: np.tile(v, (1, 1)), 0.0, np.zeros((1, 2)), 1.0, rtol=1e-10, atol=1e-10,
              t_eval=t_eval, events=events)
    assert r.status == 0
    # column 0 never moves past its stop at 0.3, yet its event function was read beyond 0.54: the
    # step that held its stop held both of its roots
    assert max(float(t[0]) for t in seen) > 0.54
    [(i0, t0, y0)], [(i1, t1, y1)] = events_of(r, 0), events_of(r, 1)
    assert i0 == 1 and abs(t0 - 0.3) < 1e-12
    assert i1 == 0 and abs(t1 - 0.18) < 1e-12
    np.testing.assert_allclose(r.t_stop, [0.3, 0.18], rtol=0, atol=1e-12)
    np.testing.assert_allclose([y0[0], y1[0]], [0.3, 0.54], rtol=0, atol=1e-12)
    # the samples: x = v t up to each column's stop, then its frozen state
    np.testing.assert_allclose(r.y[0], v[:, None] * np.minimum(t_eval[None, :], r.t_stop[:, None]),
                               rtol=0, atol=1e-12)


def test_event_zero_at_t0_fires_only_when_leaving_zero_in_the_watched_direction():
    """As solve_ivp: an event function that starts at 0 and moves the watched way is a root at t0
    (a friction force undecided at rest picks its branch at once); moving the other way, the next
    watched crossing fires."""
    # x = sin(w t): exactly 0 at t0, rising
    w = np.array([2.0, 1.0])
    y0 = np.vstack([np.zeros(2), w])
    falling = solve(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([0.0, 5.0]),
                    events=[ColumnEvent(_x, direction=-1)])
    assert falling.status == 0
    np.testing.assert_allclose(falling.t_stop, np.pi / w, rtol=0, atol=1e-10)
    assert abs(falling.t_stop[0] - np.pi / 2) < 1e-10
    np.testing.assert_array_equal(falling.y[:, :, 0], y0)
    for direction in (+1, 0):
        rising = solve(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
                       events=[ColumnEvent(_x, direction=direction)])
        assert rising.status == 0
        np.testing.assert_array_equal(rising.t_stop, [0.0, 0.0])
        assert sorted((k, t) for _, k, t, _ in rising.events) == [(0, 0.0), (1, 0.0)]
        np.testing.assert_array_equal(rising.y[:, :, 0], y0)   # frozen at the start
    # a column that is not watched does not fire at t0 even so
    masked = solve(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
                   events=[ColumnEvent(_x, direction=+1, columns=np.array([False, True]))])
    assert masked.status == 0
    assert [(i, k, t) for i, k, t, _ in masked.events] == [(0, 1, 0.0)]
    np.testing.assert_array_equal(masked.t_stop, [5.0, 0.0])
    # zero at both ends of the first step (a column at rest) is no crossing
    rest = solve(oscillators(w), 0.0, np.zeros((2, 2)), 1.0, rtol=1e-12, atol=1e-12, t_eval=np.array([1.0]),
                 events=[ColumnEvent(_x)])
    assert rest.status == 0 and rest.events == []


def test_no_crossing_reaches_the_end():
    fun, y0 = _cos_batch()
    r = solve(fun, 0.0, y0, 0.4, rtol=1e-10, atol=1e-10, t_eval=np.array([0.0, 0.4]),
              events=[ColumnEvent(_x, direction=-1)])
    assert r.status == 0 and r.events == [] and len(r.t) == 2
    np.testing.assert_array_equal(r.t_stop, 0.4)


def test_simultaneous_crossings_are_reported_together():
    """Two events of one column that cross together are reported together: a restart at that root
    could not see the other crossing (its value is already past zero by rounding).
    (the removed shared step reported together the columns of equal period that crossed at the same
    time; now each column stops at its own root, and equal periods give equal stop times)"""
    w = np.array([2.0, 2.0, 1.0])
    y0 = np.vstack([np.ones(3), np.zeros(3)]) * np.array([1.0, 3.0, 1.0])
    r = solve(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]),
              events=[ColumnEvent(_x, direction=-1)])
    assert r.status == 0
    assert sorted((i, k) for i, k, _, _ in r.events) == [(0, 0), (0, 1), (0, 2)]
    np.testing.assert_allclose(r.t_stop, [np.pi / 4, np.pi / 4, np.pi / 2], rtol=0, atol=1e-10)
    # two events with the same roots (x and 2x), continuing through them: each root fires both
    both = solve(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
                 events=[ColumnEvent(_x, on_event=lambda k, t, yk: False),
                         ColumnEvent(lambda t, Y: 2 * Y[0], on_event=lambda k, t, yk: False)])
    assert both.status == 0
    for k in range(3):
        exact = [(np.pi / 2 + np.pi * n) / w[k] for n in range(10) if (np.pi / 2 + np.pi * n) / w[k] < 5.0]
        got = events_of(both, k)
        assert len(got) == 2 * len(exact), k
        for n, t_root in enumerate(exact):
            pair = [e for e in got if abs(e[1] - t_root) < 1e-9]
            assert sorted(i for i, _, _ in pair) == [0, 1], (k, n)
            assert pair[0][1] == pair[1][1]   # reported at the one root


def test_stop_event_freezes_one_column_and_the_others_go_on():
    fun, y0 = _cos_batch()   # x = cos(w t), w = W_EV: falling zero at pi / (2 w)
    mask = np.array([True, True, True, False])
    t_eval = np.linspace(0.0, 5.0, 51)
    r = solve(checked(fun, 4), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=t_eval,
              events=[ColumnEvent(_x, direction=-1, columns=mask)])
    assert r.status == 0
    roots = np.pi / (2 * W_EV)
    np.testing.assert_allclose(r.t_stop[:3], roots[:3], rtol=0, atol=1e-10)
    assert r.t_stop[3] == 5.0   # not watched: runs to the end
    # one event per watched column (found in iteration order, not time order: each column moves
    # at its own pace)
    assert sorted((i, k) for i, k, _, _ in r.events) == [(0, 0), (0, 1), (0, 2)]
    for i, k, te, yk in r.events:
        assert abs(te - roots[k]) < 1e-10
        np.testing.assert_allclose(yk, oscillator_exact(W_EV[k:k + 1], [1.0], [0.0], [te])[:, 0, 0],
                                   rtol=0, atol=1e-10)
    exact = oscillator_exact(W_EV, np.ones(4), np.zeros(4), t_eval)
    for k in range(4):
        before = t_eval <= r.t_stop[k]
        assert np.abs(r.y[:, k, before] - exact[:, k, before]).max() < 1e-10
        # after the stop: the frozen state at the root, exactly
        frozen = r.events[[e[1] for e in r.events].index(k)][3] if k < 3 else None
        if frozen is not None:
            assert (~before).any()
            np.testing.assert_array_equal(r.y[:, k, ~before], np.repeat(frozen[:, None], (~before).sum(), 1))


def test_callback_true_stops_false_continues():
    fun, y0 = _cos_batch()
    calls = []

    def on_event(k, t, yk):
        calls.append((k, t))
        return k == 2   # only the fastest column stops; the others go on past their roots

    r = solve(fun, 0.0, y0, 3.0, rtol=1e-12, atol=1e-12, t_eval=np.array([3.0]),
              events=[ColumnEvent(_x, direction=-1, on_event=on_event)])
    assert r.status == 0
    # falling zeros of cos(w t) at (pi/2 + 2 pi n) / w before t = 3 (column 2 stops at its first)
    expected = sorted((k, (np.pi / 2 + 2 * np.pi * n) / W_EV[k]) for k in range(4) for n in range(3)
                      if (np.pi / 2 + 2 * np.pi * n) / W_EV[k] < 3.0 and (k != 2 or n == 0))
    assert sorted(k for k, _ in calls) == [k for k, _ in expected]
    for (k, t), (k2, t2) in zip(sorted(calls), expected):
        assert k == k2 and abs(t - t2) < 1e-10
    assert abs(r.t_stop[2] - np.pi / 6) < 1e-10
    np.testing.assert_array_equal(r.t_stop[[0, 1, 3]], 3.0)
    # continuing through a root does not disturb the motion
    exact = oscillator_exact(W_EV, np.ones(4), np.zeros(4), [3.0])[:, :, 0]
    assert np.abs(r.y[:, [0, 1, 3], 0] - exact[:, [0, 1, 3]]).max() < 1e-10


def _closed_form_rest(x0, d):
    """Dry friction on a spring: each half swing ends |2d| closer to the centre (d = mu g / k); the
    block sticks once |x| <= d at a turning point (as tests/stability/test_dissipation.py)."""
    x, swings = x0, 0
    while abs(x) > d:
        x = -(x - np.sign(x) * 2 * d)
        swings += 1
    return x, swings


def test_dry_friction_branches_switch_by_callback_and_stick_in_closed_form():
    """x'' = -k x - mu g sigma with the branch sigma = sign(v) held per column and flipped by the
    callback at v = 0 (continue), or the block sticks there (stop) when the spring cannot beat
    static friction.  Each half swing is a harmonic arc of duration pi / sqrt(k), so the stop time
    and position are known in closed form; a stale first stage after a branch flip (the FSAL
    stage of the old dynamics) would spoil both."""
    k_s, g = 10.0, 9.8
    mu = np.array([0.2, 0.1, 0.3, 0.05])
    x0 = np.array([1.0, -0.8, 2.0, 1.5])
    K = len(mu)
    d = mu * g / k_s
    sigma = -np.sign(x0)   # the block starts at rest and moves towards the centre

    def fun(t, Y):
        return np.stack([Y[1], -k_s * Y[0] - mu * g * sigma])

    def moving(t, Y):      # > 0 while moving along its branch: falls to 0 at a turning point
        return sigma * Y[1]

    def turn(k, t, yk):
        if abs(k_s * yk[0]) <= mu[k] * g:
            return True    # static friction holds: the block sticks
        sigma[k] = -sigma[k]
        return False

    t_end = 12.0
    t_eval = np.linspace(0.0, t_end, 241)
    r = solve(checked(fun, K), 0.0, np.vstack([x0, np.zeros(K)]), t_end, rtol=1e-12, atol=1e-12,
              t_eval=t_eval, events=[ColumnEvent(moving, direction=-1, on_event=turn)])
    assert r.status == 0, r.message
    half = np.pi / np.sqrt(k_s)
    for c in range(K):
        rest, swings = _closed_form_rest(x0[c], d[c])
        if swings * half < t_end:
            assert abs(r.t_stop[c] - swings * half) < 1e-10, c
            assert abs(r.y[0, c, -1] - rest) < 1e-9, c
            assert abs(r.y[1, c, -1]) < 1e-9, c
            assert sum(1 for _, kk, _, _ in r.events if kk == c) == swings
        else:
            assert r.t_stop[c] == t_end
    assert np.isfinite(r.t_stop).all() and (r.t_stop < t_end).sum() >= 3
    E = 0.5 * r.y[1] ** 2 + 0.5 * k_s * r.y[0] ** 2
    assert np.all(np.diff(E, axis=1) <= 1e-10)


def test_event_mask_is_read_at_every_step():
    # the callback unwatches its column instead of stopping it: one event per column, then it runs on
    fun, y0 = _cos_batch()
    mask = np.ones(4, dtype=bool)

    def unwatch(k, t, yk):
        mask[k] = False
        return False

    r = solve(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
              events=[ColumnEvent(_x, columns=mask, on_event=unwatch)])
    assert r.status == 0
    assert sorted(k for _, k, _, _ in r.events) == [0, 1, 2, 3]
    np.testing.assert_array_equal(r.t_stop, 5.0)


def test_chattering_is_a_failure():
    """Dry friction whose callback always flips the branch, never sticks: once the spring cannot beat
    friction at a turning point, each branch at once drives the speed back through zero, and the
    column chatters between branches at one instant.  That must end the run, naming the column."""
    k_s, g = 10.0, 9.8
    mu = np.array([0.3, 0.01])   # column 0 sticks after 2 half swings; column 1 swings on
    x0 = np.array([1.0, 1.0])
    sigma = -np.sign(x0)

    def flip(k, t, yk):
        sigma[k] = -sigma[k]
        return False

    r = solve(lambda t, Y: np.stack([Y[1], -k_s * Y[0] - mu * g * sigma]), 0.0,
              np.vstack([x0, np.zeros(2)]), 5.0, rtol=1e-10, atol=1e-10, t_eval=np.array([5.0]),
              events=[ColumnEvent(lambda t, Y: sigma * Y[1], direction=-1, on_event=flip)],
              max_events_per_column=10, max_evals=20_000)   # without the limit: the budget ends it
    assert r.status == -1
    assert "more than 10 events in trajectory 0 (chattering between branches)" in r.message
    assert r.failed_column == 0
    assert abs(r.t_failed - 2 * np.pi / np.sqrt(k_s)) < 1e-8   # where it should have stuck
    assert sum(1 for _, k, _, _ in r.events if k == 0) == 11


def test_continuing_through_a_root_without_a_change_does_not_refire():
    # the callback changes nothing: the next event of that column is the next genuine crossing
    fun, y0 = _cos_batch()
    r = solve(fun, 0.0, y0, 10.0, rtol=1e-10, atol=1e-10, t_eval=np.array([10.0]),
              events=[ColumnEvent(_x, on_event=lambda k, t, yk: False)])
    assert r.status == 0
    for k in range(4):
        times = sorted(t for _, kk, t, _ in r.events if kk == k)
        exact = [(np.pi / 2 + np.pi * n) / W_EV[k] for n in range(10) if (np.pi / 2 + np.pi * n) / W_EV[k] < 10.0]
        assert len(times) == len(exact)
        np.testing.assert_allclose(times, exact, rtol=0, atol=1e-9)


# ----------------------------------------------------------------------------- 5. failures


class Singular(Exception):
    pass


def test_exception_from_fun_propagates_unchanged():
    w2 = W_EV ** 2

    def fun(t, Y):
        if np.any(t > 1.0):
            raise Singular(t)
        return np.stack([Y[1], -w2 * Y[0]])

    with pytest.raises(Singular) as info:
        solve(fun, 0.0, np.ones((2, 4)), 3.0, rtol=1e-9, atol=1e-9, t_eval=np.array([3.0]))
    assert np.max(info.value.args[0]) > 1.0


def test_nan_in_one_column_fails_naming_it_instead_of_looping():
    w2 = W_EV ** 2

    def fun(t, Y):
        out = np.stack([Y[1], -w2 * Y[0]])
        out[1, 2] = np.where(t[2] > 1.0, np.nan, out[1, 2])
        return out

    t_eval = np.linspace(0.0, 3.0, 7)
    r = solve(fun, 0.0, np.ones((2, 4)), 3.0, rtol=1e-9, atol=1e-9, t_eval=t_eval)
    assert r.status == -1
    assert "step size too small in trajectory 2" in r.message
    assert r.failed_column == 2 and abs(r.t_failed - 1.0) < 1e-6
    assert r.nfev < 5000
    np.testing.assert_array_equal(r.t, t_eval)
    assert np.all(np.isfinite(r.y[:, :, t_eval < 1.0]))   # every column reached the samples before t = 1
    assert np.isnan(r.y[:, 2, 2:]).all()                   # the failed column's later ones were not


def test_max_evals_stops_with_a_message():
    fun, y0 = _cos_batch()
    r = solve(fun, 0.0, y0, 100.0, rtol=1e-10, atol=1e-10, t_eval=np.linspace(0, 100, 11), max_evals=200)
    assert r.status == -1
    assert "more than 200 evaluations" in r.message and "trajectory" in r.message
    assert r.nfev <= 200 and r.failed_column is not None
    # enough evaluations: no failure
    ok = solve(fun, 0.0, y0, 1.0, rtol=1e-10, atol=1e-10, t_eval=np.array([1.0]), max_evals=10_000)
    assert ok.status == 0 and ok.nfev <= 10_000


def test_the_module_does_not_import_scipy():
    code = ("import sys; import lagrade.compare.dop853; "
            "bad = [m for m in sys.modules if m == 'scipy' or m.startswith('scipy.')]; "
            "assert not bad, bad")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_empty_interval_and_bad_t_eval():
    y0 = np.ones((2, 3))
    r = solve(oscillators(np.ones(3)), 1.0, y0, 1.0, rtol=1e-8, atol=1e-8, t_eval=np.array([1.0]))
    assert r.status == 0 and r.nfev == 0
    np.testing.assert_array_equal(r.y[:, :, 0], y0)
    with pytest.raises(ValueError):
        solve(oscillators(np.ones(3)), 0.0, y0, 1.0, rtol=1e-8, atol=1e-8, t_eval=np.array([0.5, 0.2]))


# ----------------------------------------------------------------------------- 6. property


@settings(max_examples=40, deadline=None)
@given(a=st.lists(st.floats(-2.0, 1.0), min_size=1, max_size=8),
       scale=st.floats(0.1, 10.0),
       t_end=st.floats(0.1, 3.0))
def test_linear_systems_match_exponential(a, scale, t_end):
    a = np.array(a)
    K = len(a)
    y0 = scale * np.vstack([np.linspace(1.0, 2.0, K), -np.linspace(0.5, 1.5, K)])
    t_eval = np.linspace(0.0, t_end, 7)
    r = solve(lambda t, Y: a * Y, 0.0, y0, t_end, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert r.status == 0
    exact = y0[:, :, None] * np.exp(a[None, :, None] * t_eval[None, None, :])
    assert np.all(np.abs(r.y - exact) <= 1e-8 * np.abs(exact))


# ----------------------------------------------------------------------------- 7. compiled rates
# The grader's rates (`CompiledRates`) through `trajectory.integrate`, which drives `solve`.

x, v, t, k = sp.symbols("x v t k")


def _ball():
    """x'' = -k: thrown up from x = 0 with v = 1, 2, 3, 4; the event x = 1e-3 falling stops each column."""
    f = compile_exprs([-k + 0 * x], [x, v, t, k])
    rates = CompiledRates(f, 2, np.full((1, 4), 9.81), copied=1)
    y0 = np.array([[0.0, 0.0, 0.0, 0.0], [1.0, 2.0, 3.0, 4.0]])
    landing = BatchedEvent("landing", lambda tt, Y: Y[0] + 0 * Y[1] - 1e-3, direction=-1.0, action="stop")
    return rates, y0, landing


def _plain(rates: CompiledRates):
    """The same rates as a plain function (`integrate` and `_paired` treat `CompiledRates` apart)."""
    return lambda tt, Y: rates(tt, Y)


def test_the_pair_of_compiled_rates_covers_twice_the_columns():
    rates, y0, _ = _ball()
    pair = rates.pair()
    Y = np.concatenate([y0, y0 + 0.1], axis=1)
    assert np.allclose(pair(0.0, Y), np.concatenate([rates(0.0, y0), rates(0.0, y0 + 0.1)], axis=1))


def test_numpy_rates_integrate():
    f = compile_numpy([-k * x], [x, v, t, k])
    rates = CompiledRates(f, 2, np.full((1, 2), 4.0), copied=1)
    run = integrate(rates, np.array([[1.0, 0.5], [0.0, 0.0]]), 1.0, ACCURACY["default"], method="DOP853")
    assert run.ok and np.allclose(run.y[0, :, -1], [np.cos(2.0), 0.5 * np.cos(2.0)], rtol=1e-8)


def test_rates_without_constants_integrate():
    """x'' = -x, no parameters at all: the argument rows are the state and t only."""
    rates = CompiledRates(compile_exprs([-x + 0 * t], [x, v, t]), 2, np.zeros((0, 3)), copied=1)
    y0 = np.array([[1.0, 0.0, 2.0], [0.0, 1.0, 0.0]])
    run = integrate(rates, y0, 2.0, ACCURACY["default"], method="DOP853")
    exact = y0[0] * np.cos(2.0) + y0[1] * np.sin(2.0)
    assert run.ok and np.allclose(run.y[0, :, -1], exact, rtol=1e-8, atol=1e-10)


def test_events_stop_each_trajectory_at_its_own_landing():
    rates, y0, landing = _ball()
    acc = ACCURACY["default"]
    run = integrate(rates, y0, 1.0, acc, method="DOP853", events=[landing])
    plain = integrate(_plain(rates), y0, 1.0, acc, method="DOP853", events=[landing])
    assert run.ok and plain.ok
    exact = (y0[1] + np.sqrt(y0[1] ** 2 - 2 * 9.81 * 1e-3)) / 9.81
    landed = exact < 1.0
    assert landed.all()   # every ball lands within the second (the last at 0.82 s)
    assert np.allclose(run.t_stop[landed], exact[landed], rtol=1e-9)
    assert sorted(kk for kk, _, _ in run.events["landing"]) == np.flatnonzero(landed).tolist()
    assert np.array_equal(run.t_stop, plain.t_stop) or np.allclose(run.t_stop, plain.t_stop, rtol=1e-12)
    assert np.allclose(run.y, plain.y, rtol=1e-9, atol=1e-12)


def test_a_singularity_is_refused_naming_the_trajectory():
    """x'' = 1/(1 - x)^2: the trajectories reach x = 1 in finite time; the guard stops the run."""
    f = compile_exprs([1 / (1 - x) ** 2 + 0 * k], [x, v, t, k])
    rates = CompiledRates(f, 2, np.ones((1, 3)), copied=1)
    y0 = np.array([[0.0, 0.2, 0.5], [1.0, 1.0, 1.0]])
    acc = ACCURACY["default"]
    run = integrate(rates, y0, 5.0, acc, method="DOP853")
    plain = integrate(_plain(rates), y0, 5.0, acc, method="DOP853")
    assert not run.ok and not plain.ok
    assert "approaches a singularity" in run.message and "trajectory 3" in run.message
    assert run.message.split(" at t")[0] == plain.message.split(" at t")[0]



def test_a_rejected_trial_step_is_never_watched():
    """The singularity guard (``watch``) sees only states of the motion: the start and accepted steps'
    ends. Column 1 tries one oversized step (to the end, h = 10, on x'' = -x: rates of 521 at the trial's
    end, where the motion's stay <= 1) that is rejected and retried shorter; column 0 accepts its step
    at the same time and is watched."""
    from lagrade.compare.dop853 import DOP853

    seen = []
    sol = DOP853(oscillators(np.ones(2)), 0.0, np.array([[1.0, 1.0], [0.0, 0.0]]), 10.0, 1e-10, 1e-10,
                 watch=lambda t, f: seen.append((np.array(t, dtype=float), np.abs(f).max(axis=0))))
    sol.h_abs[:] = [0.01, 50.0]
    accepted = sol.step()
    assert accepted.tolist() == [True, False]
    t, size = seen[-1]
    assert t.tolist() == [0.01, 0.0] and size.max() <= 1.0   # column 1: its current time and rates
    while sol.active.any():
        sol.advance(sol.step())
    assert max(size.max() for _, size in seen) <= 1.0 + 1e-9   # |x|, |x'| <= 1 along the motion
    assert np.allclose(sol.y, oscillator_exact(np.ones(2), [1, 1], [0, 0], [10.0])[..., 0], atol=1e-8)


def test_an_oversized_trial_after_a_switch_does_not_stop_a_correct_run():
    """A switching event restarts its trajectory with the step that held the root; on a branch 100 x
    faster that step is far too long, and its rejected trial reached rates 1e9-fold the start's. Only
    accepted steps may end a run as "approaches a singularity": this one decays, x = e^-t until x = 1/2,
    then x = exp(-100 (t - ln 2)) / 2, and it is integrated to the end."""
    rate = np.ones(2)

    def rates(t, Y):
        return -rate * Y

    def faster(k, t, yk):
        rate[k] = 100.0

    ev = BatchedEvent("switch", lambda t, Y: Y[0] - 0.5, action="switch", direction=-1, on_event=faster)
    tt = np.linspace(0.0, 2.0, 41)
    run = integrate(rates, np.array([[1.0, 2.0]]), 2.0, replace(ACCURACY["default"], method="DOP853"),
                    events=[ev], t_eval=tt)
    assert run.ok, run.message
    t_switch = np.log([2.0, 4.0])
    assert np.allclose([t for _, t, _ in sorted(run.events["switch"], key=lambda e: e[0])], t_switch, rtol=1e-9)
    exact = np.where(tt[None, :] < t_switch[:, None], np.array([[1.0], [2.0]]) * np.exp(-tt),
                     0.5 * np.exp(-100.0 * (tt[None, :] - t_switch[:, None])))
    assert np.allclose(run.y[0], exact, rtol=1e-7, atol=1e-8)   # atol 1e-10 of the integration


def test_the_evaluation_budget_holds():
    """x'' = -k x for 50 s (about 25 periods) needs hundreds of evaluations; the budget is 100.
    (A falling ball is a polynomial DOP853 crosses in a few dozen: no budget to test there.)"""
    f = compile_exprs([-k * x], [x, v, t, k])
    rates = CompiledRates(f, 2, np.full((1, 4), 9.81), copied=1)
    y0 = np.array([[0.0, 0.0, 0.0, 0.0], [1.0, 2.0, 3.0, 4.0]])
    unbounded = integrate(rates, y0, 50.0, ACCURACY["default"], method="DOP853")
    assert unbounded.ok and unbounded.rhs_evals > 300
    acc = replace(ACCURACY["default"], max_rhs_evals=100)
    run = integrate(rates, y0, 50.0, acc, method="DOP853")
    assert not run.ok and "needed more than 100 steps" in run.message
    assert run.rhs_evals <= 100 + 12


def test_a_step_too_small_and_the_budget_stop_the_run_naming_the_trajectory():
    """Two ways out besides the end: a step too small (NaN rates from t = 0.5 on in one column) and
    the integrator's own evaluation budget (the column furthest behind, the samples it did not reach
    NaN)."""
    acc = ACCURACY["default"]
    f = compile_exprs([-x + sp.sqrt(0.5 - t) * k], [x, v, t, k])
    nan_later = CompiledRates(f, 2, np.array([[0.0, 1.0, 2.0]]), copied=1)   # sqrt(< 0) from t = 0.5 on
    y0 = np.array([[1.0, 0.5, 0.2], [0.0, 0.0, 1.0]])
    outs = [integrate(r, y0, 1.0, acc, method="DOP853") for r in (nan_later, _plain(nan_later))]
    assert [o.ok for o in outs] == [False, False]
    assert all("step size too small in trajectory 0 at t = 0.49999" in o.message for o in outs), outs[0].message

    rates = CompiledRates(compile_exprs([-k * x], [x, v, t, k]), 2, np.array([[1.0, 4.0, 9.0, 16.0]]), copied=1)
    y0 = np.array([[1.0, 0.0, 0.5, 1.0], [0.0, 1.0, 0.5, 0.0]])
    t_eval = np.linspace(0, 50, 11)
    outs = [solve(fun, 0.0, y0, 50.0, rtol=1e-10, atol=1e-10, t_eval=t_eval, max_evals=300)
            for fun in (rates, _plain(rates))]
    for o in outs:
        assert o.status == -1 and "more than 300 evaluations" in o.message and o.nfev <= 300
        assert o.failed_column is not None and f"trajectory {o.failed_column} " in o.message
        # the failed column is the one furthest behind, and its samples after where it got are NaN
        assert o.t_failed == pytest.approx(o.t_stop[o.failed_column]) and o.t_failed == o.t_stop.min()
        reached = t_eval[None, :] <= o.t_stop[:, None]
        assert np.isfinite(o.y[:, reached]).all() and np.isnan(o.y[:, ~reached]).all()
    assert outs[0].failed_column == outs[1].failed_column and outs[0].nfev == outs[1].nfev
    assert outs[0].t_failed == pytest.approx(outs[1].t_failed, rel=1e-6)
    assert np.array_equal(np.isnan(outs[0].y), np.isnan(outs[1].y))
