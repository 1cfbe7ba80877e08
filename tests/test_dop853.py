"""Tests of the batched pure-numpy DOP853 integrator (lagrade.compare.dop853).

scipy is used here only as a reference; the module itself must not import it.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from lagrade.compare.dop853 import ColumnEvent, ColumnResult, Event, RKResult, dop853, dop853_columns


def oscillators(w: np.ndarray):
    """x'' = -w^2 x per column, state [x, v]."""
    w2 = np.asarray(w, dtype=float) ** 2

    def fun(t: float, Y: np.ndarray) -> np.ndarray:
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

    def fun(t: float, Y: np.ndarray) -> np.ndarray:
        return np.stack([Y[1], -k * np.sin(Y[0])])

    return fun


# ----------------------------------------------------------------------------- 1. accuracy


def test_harmonic_oscillator_batch_matches_exact_solution():
    w = np.array([0.5, 1.0, 1.7, 2.3, 3.0])
    x0 = np.array([1.0, 2.0, 0.5, 3.0, 1.5])
    v0 = np.array([0.0, 0.3, -1.0, 0.5, 2.0])
    t_eval = np.linspace(0.0, 10.0, 41)  # includes t0 and t_end
    r = dop853(oscillators(w), 0.0, np.vstack([x0, v0]), 10.0, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert isinstance(r, RKResult)
    assert r.status == 0 and r.t_event is None
    assert r.y.shape == (2, 5, 41)
    np.testing.assert_array_equal(r.t, t_eval)
    np.testing.assert_array_equal(r.y[:, :, 0], np.vstack([x0, v0]))
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-9


def test_many_columns_use_the_reduction_path():
    # n * K > 4096: the per-column sums use a reduction instead of the 0/1 matrix
    K = 64
    w = np.linspace(0.5, 3.0, K)
    x0, v0 = np.linspace(-2.0, 2.0, K), np.linspace(1.0, -1.0, K)
    t_eval = np.linspace(0.0, 5.0, 11)
    r = dop853(oscillators(w), 0.0, np.vstack([x0, v0]), 5.0, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert r.status == 0
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-9


def test_columns_at_rest_do_not_stall_the_batch():
    # a column with y = f = 0 has both error estimates exactly 0 (0/0 in the DOP853 norm)
    w = np.array([1.0, 2.0, 1.0])
    x0, v0 = np.array([1.0, 0.0, 0.5]), np.array([0.0, 0.0, 0.0])
    t_eval = np.linspace(0.0, 3.0, 4)
    r = dop853(oscillators(w), 0.0, np.vstack([x0, v0]), 3.0, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    assert r.status == 0
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-8
    alone = dop853(oscillators(w[:1]), 0.0, np.vstack([x0[:1], v0[:1]]), 3.0, rtol=1e-10, atol=1e-10,
                   t_eval=t_eval)
    assert r.nfev <= alone.nfev + 12
    # everything at rest: zero error, the step grows tenfold each time
    rest = dop853(oscillators(w), 0.0, np.zeros((2, 3)), 1e6, rtol=1e-10, atol=1e-10, t_eval=np.array([1e6]))
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
    r = dop853(pendulums(K_PEND), 0.0, Y0_PEND, t_end, rtol=1e-10, atol=1e-10, t_eval=t_eval)
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
    r_steps = dop853(pendulums(K_PEND), 0.0, Y0_PEND, t_end, rtol=1e-10, atol=1e-10,
                     t_eval=np.array([0.0, t_end]))
    steps_only = [_scipy_column(c, t_end, None).nfev for c in range(8)]
    assert r_steps.nfev <= 1.3 * max(steps_only)
    np.testing.assert_allclose(r_steps.y[:, :, -1], r.y[:, :, -1], rtol=0, atol=1e-12)


@pytest.mark.parametrize("integrator", [dop853, dop853_columns])
@pytest.mark.parametrize("c", [0, 5])
def test_single_column_takes_exactly_scipys_steps(c, integrator):
    # K = 1: the initial step, the error norm and the step-size control are scipy's DOP853
    t_end = 10.0
    r = integrator(pendulums(K_PEND[c:c + 1]), 0.0, Y0_PEND[:, c:c + 1], t_end, rtol=1e-10, atol=1e-10,
               t_eval=np.array([t_end]))
    s = _scipy_column(c, t_end, None)
    assert r.nfev == s.nfev
    # same steps up to the rounding of the norm (summation order), so agreement far below the tolerance
    np.testing.assert_allclose(r.y[:, 0, -1], s.y[:, -1], rtol=0, atol=1e-11)


# ----------------------------------------------------------------------------- 3. per-column control


def test_each_column_is_held_to_its_own_tolerance():
    # 31 easy oscillators and one fast one. A norm over the flattened batch would let the easy
    # columns dilute the fast column's error (about sqrt(32)-fold larger steps^8); the per-column
    # max norm gives every column at most the error it gets when integrated alone.
    K = 32
    w = np.ones(K)
    w[-1] = 20.0
    x0 = np.linspace(0.5, 2.0, K)
    v0 = np.zeros(K)
    t_eval = np.linspace(0.0, 10.0, 11)
    tol = 1e-8

    def error(cols: slice) -> np.ndarray:
        r = dop853(oscillators(w[cols]), 0.0, np.vstack([x0[cols], v0[cols]]), 10.0, rtol=tol, atol=tol,
                   t_eval=t_eval)
        assert r.status == 0
        return np.abs(r.y - oscillator_exact(w[cols], x0[cols], v0[cols], t_eval)).max(axis=(0, 2))

    batch = error(slice(None))
    for c in (0, 13, K - 2, K - 1):
        alone = error(slice(c, c + 1))[0]
        assert batch[c] <= 1.2 * alone + 1e-13, (c, batch[c], alone)
    assert batch[-1] > 1e-7  # the fast column's error is well above round-off: the check has teeth


# ----------------------------------------------------------------------------- 4. events


W_EV = np.array([1.0, 2.0, 3.0, 1.5])


def _cos_batch(w=W_EV):
    """x = cos(w t): falling zero at pi/(2w), rising zero at 3pi/(2w)."""
    return oscillators(w), np.vstack([np.ones(len(w)), np.zeros(len(w))])


def _x(t: float, Y: np.ndarray) -> np.ndarray:
    return Y[0]


def test_falling_event_is_located_on_the_dense_output():
    fun, y0 = _cos_batch()
    t_eval = np.linspace(0.0, 2.0, 21)
    r = dop853(fun, 0.0, y0, 2.0, rtol=1e-12, atol=1e-12, t_eval=t_eval, events=[Event(_x, direction=-1)])
    assert r.status == 1
    assert r.event_index == 0 and r.event_column == 2  # w = 3 crosses first
    assert abs(r.t_event - np.pi / 6) < 1e-10
    # y_event: the state of ALL columns at t_event
    assert r.y_event.shape == (2, 4)
    exact = oscillator_exact(W_EV, np.ones(4), np.zeros(4), [r.t_event])[:, :, 0]
    np.testing.assert_allclose(r.y_event, exact, rtol=0, atol=1e-10)
    # samples after the event are not returned; those before are
    assert r.t.max() <= r.t_event
    np.testing.assert_array_equal(r.t, t_eval[t_eval <= r.t_event])
    assert r.y.shape == (2, 4, len(r.t))
    np.testing.assert_allclose(r.y, oscillator_exact(W_EV, np.ones(4), np.zeros(4), r.t), rtol=0, atol=1e-10)


def test_rising_direction_ignores_falling_crossings():
    fun, y0 = _cos_batch()
    r = dop853(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]), events=[Event(_x, direction=+1)])
    assert r.status == 1 and r.event_column == 2
    assert abs(r.t_event - 3 * np.pi / 6) < 1e-10


def test_both_directions_fire_at_the_first_crossing():
    fun, y0 = _cos_batch()
    r = dop853(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]), events=[Event(_x)])
    assert r.status == 1 and r.event_column == 2
    assert abs(r.t_event - np.pi / 6) < 1e-10


def test_columns_mask_excludes_a_column():
    fun, y0 = _cos_batch()
    mask = np.array([True, True, False, True])  # the fastest column (w = 3) is not watched
    r = dop853(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]),
               events=[Event(_x, direction=-1, columns=mask)])
    assert r.status == 1 and r.event_column == 1  # next fastest: w = 2
    assert abs(r.t_event - np.pi / 4) < 1e-10


def test_earliest_event_over_events_and_columns_wins():
    fun, y0 = _cos_batch()
    # event 0: x = 0.5 (w = 3 reaches it at pi/9); event 1: x = -0.9 on column 0 only (late)
    events = [Event(lambda t, Y: Y[0] + 0.9, columns=np.array([True, False, False, False])),
              Event(lambda t, Y: Y[0] - 0.5, direction=-1)]
    r = dop853(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.linspace(0, 5, 11), events=events)
    assert r.status == 1
    assert (r.event_index, r.event_column) == (1, 2)
    assert abs(r.t_event - np.pi / 9) < 1e-10
    # the same with the events in the other order, and the late one on every column
    events2 = [events[1], Event(lambda t, Y: Y[0] + 0.9)]
    r2 = dop853(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]), events=events2)
    assert (r2.event_index, r2.event_column) == (0, 2)
    assert abs(r2.t_event - np.pi / 9) < 1e-10


def test_several_roots_in_one_step_the_earliest_wins():
    # x = v t: DOP853 is exact, so steps grow tenfold and one step holds all the roots below.
    # Candidates are visited in order (event 0 column 0 at 0.54 first); later ones are bracketed
    # by the best root so far, and event 1 (root 0.3) must be dropped once column 1 of event 0
    # (root 0.18) has been found.
    v = np.array([1.0, 3.0])
    seen: list[float] = []

    def g0(t, Y):
        seen.append(t)
        return Y[0] - 0.54

    events = [Event(g0), Event(lambda t, Y: Y[0] - 0.3, columns=np.array([True, False]))]
    r = dop853(lambda t, Y: np.tile(v, (1, 1)), 0.0, np.zeros((1, 2)), 1.0, rtol=1e-10, atol=1e-10,
               t_eval=np.linspace(0.0, 1.0, 11), events=events)
    assert max(seen) > 0.54  # the last step ends after every root: they all were in that step
    assert r.status == 1 and (r.event_index, r.event_column) == (0, 1)
    assert abs(r.t_event - 0.18) < 1e-12
    np.testing.assert_allclose(r.y_event, [[0.18, 0.54]], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(r.t, [0.0, 0.1])


def test_event_zero_at_t0_fires_only_when_leaving_zero_in_the_watched_direction():
    """As solve_ivp: an event function that starts at 0 and moves the watched way is a root at t0
    (a friction force undecided at rest picks its branch at once); moving the other way, the next
    watched crossing fires."""
    # x = sin(w t): exactly 0 at t0, rising
    w = np.array([2.0, 1.0])
    y0 = np.vstack([np.zeros(2), w])
    falling = dop853(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([0.0]),
                     events=[Event(_x, direction=-1)])
    assert falling.status == 1 and falling.event_column == 0
    assert abs(falling.t_event - np.pi / 2) < 1e-10
    np.testing.assert_array_equal(falling.t, [0.0])
    for direction in (+1, 0):
        rising = dop853(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]),
                        events=[Event(_x, direction=direction)])
        assert rising.status == 1 and rising.t_event == 0.0
    # a column that is not watched does not fire at t0 even so
    masked = dop853(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]),
                    events=[Event(_x, direction=+1, columns=np.array([False, True]))])
    assert masked.status == 1 and masked.event_column == 1 and masked.t_event == 0.0
    # zero at both ends of the first step (a column at rest) is no crossing
    rest = dop853(oscillators(w), 0.0, np.zeros((2, 2)), 1.0, rtol=1e-12, atol=1e-12, t_eval=np.array([1.0]),
                  events=[Event(_x)])
    assert rest.status == 0


def test_no_crossing_reaches_the_end():
    fun, y0 = _cos_batch()
    r = dop853(fun, 0.0, y0, 0.4, rtol=1e-10, atol=1e-10, t_eval=np.array([0.0, 0.4]),
               events=[Event(_x, direction=-1)])
    assert r.status == 0 and r.t_event is None and len(r.t) == 2


# ----------------------------------------------------------------------------- 5. failures


class Singular(Exception):
    pass


def test_exception_from_fun_propagates_unchanged():
    w2 = W_EV ** 2

    def fun(t, Y):
        if t > 1.0:
            raise Singular(t)
        return np.stack([Y[1], -w2 * Y[0]])

    with pytest.raises(Singular) as info:
        dop853(fun, 0.0, np.ones((2, 4)), 3.0, rtol=1e-9, atol=1e-9, t_eval=np.array([3.0]))
    assert info.value.args[0] > 1.0


def test_nan_from_fun_fails_instead_of_looping():
    w2 = W_EV ** 2

    def fun(t, Y):
        out = np.stack([Y[1], -w2 * Y[0]])
        if t > 1.0:
            out[1, 2] = np.nan
        return out

    t_eval = np.linspace(0.0, 3.0, 7)
    r = dop853(fun, 0.0, np.ones((2, 4)), 3.0, rtol=1e-9, atol=1e-9, t_eval=t_eval)
    assert r.status == -1
    assert "step size too small" in r.message
    assert r.nfev < 5000
    # the samples before the failure are returned: steps get ever closer to t = 1 from below, and the
    # last may end on t = 1 itself (t + h rounds to 1), where fun is still finite, as on an AMD EPYC
    np.testing.assert_array_equal(r.t, t_eval[: r.t.size])
    assert t_eval[t_eval < 1.0].size <= r.t.size <= t_eval[t_eval <= 1.0].size
    assert np.all(np.isfinite(r.y))


def test_max_evals_stops_with_a_message():
    fun, y0 = _cos_batch()
    r = dop853(fun, 0.0, y0, 100.0, rtol=1e-10, atol=1e-10, t_eval=np.linspace(0, 100, 11), max_evals=200)
    assert r.status == -1
    assert "more than 200 evaluations" in r.message
    assert r.nfev <= 200
    # enough evaluations: no failure
    ok = dop853(fun, 0.0, y0, 1.0, rtol=1e-10, atol=1e-10, t_eval=np.array([1.0]), max_evals=10_000)
    assert ok.status == 0 and ok.nfev <= 10_000


def test_the_module_does_not_import_scipy():
    code = ("import sys; import lagrade.compare.dop853; "
            "bad = [m for m in sys.modules if m == 'scipy' or m.startswith('scipy.')]; "
            "assert not bad, bad")
    subprocess.run([sys.executable, "-c", code], check=True)


@pytest.mark.parametrize("integrator", [dop853, dop853_columns])
def test_empty_interval_and_bad_t_eval(integrator):
    y0 = np.ones((2, 3))
    r = integrator(oscillators(np.ones(3)), 1.0, y0, 1.0, rtol=1e-8, atol=1e-8, t_eval=np.array([1.0]))
    assert r.status == 0 and r.nfev == 0
    np.testing.assert_array_equal(r.y[:, :, 0], y0)
    with pytest.raises(ValueError):
        integrator(oscillators(np.ones(3)), 0.0, y0, 1.0, rtol=1e-8, atol=1e-8, t_eval=np.array([0.5, 0.2]))


# ----------------------------------------------------------------------------- 6. property


@pytest.mark.parametrize("integrator", [dop853, dop853_columns])
@settings(max_examples=40, deadline=None)
@given(a=st.lists(st.floats(-2.0, 1.0), min_size=1, max_size=8),
       scale=st.floats(0.1, 10.0),
       t_end=st.floats(0.1, 3.0))
def test_linear_systems_match_exponential(integrator, a, scale, t_end):
    a = np.array(a)
    K = len(a)
    y0 = scale * np.vstack([np.linspace(1.0, 2.0, K), -np.linspace(0.5, 1.5, K)])
    t_eval = np.linspace(0.0, t_end, 7)
    r = integrator(lambda t, Y: a * Y, 0.0, y0, t_end, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert r.status == 0
    exact = y0[:, :, None] * np.exp(a[None, :, None] * t_eval[None, None, :])
    assert np.all(np.abs(r.y - exact) <= 1e-8 * np.abs(exact))


def test_simultaneous_crossings_are_reported_together():
    """Trajectories with the same period cross together; a restart at that root could not see the
    others' crossings (their event values are already past zero by rounding), so all come at once."""
    w = np.array([2.0, 2.0, 1.0])
    y0 = np.vstack([np.ones(3), np.zeros(3)]) * np.array([1.0, 3.0, 1.0])
    r = dop853(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]),
               events=[Event(_x, direction=-1)])
    assert r.status == 1 and abs(r.t_event - np.pi / 4) < 1e-10
    assert {(r.event_index, r.event_column), *r.also} == {(0, 0), (0, 1)}


# ============================================================================= dop853_columns
# Every column has its own time and step size; the stages are evaluated for all columns at once.


def checked(fun, K: int, dim: int = 2):
    """`fun` wrapped to check the contract of dop853_columns: every call gets all K columns and
    one time per column."""

    def wrapped(t, Y):
        assert isinstance(t, np.ndarray) and t.shape == (K,), t
        assert Y.shape == (dim, K), Y.shape
        return fun(t, Y)

    return wrapped


# ----------------------------------------------------------------------------- C1. accuracy


def test_columns_harmonic_oscillator_batch_matches_exact_solution():
    w = np.array([0.5, 1.0, 1.7, 2.3, 3.0])
    x0 = np.array([1.0, 2.0, 0.5, 3.0, 1.5])
    v0 = np.array([0.0, 0.3, -1.0, 0.5, 2.0])
    t_eval = np.linspace(0.0, 10.0, 41)
    r = dop853_columns(checked(oscillators(w), 5), 0.0, np.vstack([x0, v0]), 10.0, rtol=1e-11, atol=1e-11,
                       t_eval=t_eval)
    assert isinstance(r, ColumnResult)
    assert r.status == 0 and r.events == [] and r.failed_column is None
    assert r.y.shape == (2, 5, 41)
    np.testing.assert_array_equal(r.t, t_eval)
    np.testing.assert_array_equal(r.t_stop, np.full(5, 10.0))
    np.testing.assert_array_equal(r.y[:, :, 0], np.vstack([x0, v0]))
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-9


def test_columns_many_columns_use_the_reduction_path():
    K = 64  # n * K > 4096
    w = np.linspace(0.5, 3.0, K)
    x0, v0 = np.linspace(-2.0, 2.0, K), np.linspace(1.0, -1.0, K)
    t_eval = np.linspace(0.0, 5.0, 11)
    r = dop853_columns(oscillators(w), 0.0, np.vstack([x0, v0]), 5.0, rtol=1e-11, atol=1e-11, t_eval=t_eval)
    assert r.status == 0
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-9


def test_columns_at_rest_cost_nothing_extra():
    # a column with y = f = 0 has both error estimates exactly 0 (0/0 in the DOP853 norm)
    w = np.array([1.0, 2.0, 1.0])
    x0, v0 = np.array([1.0, 0.0, 0.5]), np.zeros(3)
    t_eval = np.linspace(0.0, 3.0, 4)
    r = dop853_columns(oscillators(w), 0.0, np.vstack([x0, v0]), 3.0, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    assert r.status == 0
    assert np.abs(r.y - oscillator_exact(w, x0, v0, t_eval)).max() < 1e-8
    alone = dop853_columns(oscillators(w[:1]), 0.0, np.vstack([x0[:1], v0[:1]]), 3.0, rtol=1e-10, atol=1e-10,
                           t_eval=t_eval)
    assert r.nfev <= alone.nfev + 3 * 4  # at most the dense output of a few more iterations
    rest = dop853_columns(oscillators(w), 0.0, np.zeros((2, 3)), 1e6, rtol=1e-10, atol=1e-10,
                          t_eval=np.array([1e6]))
    assert rest.status == 0 and rest.nfev < 200
    np.testing.assert_array_equal(rest.y, 0.0)


def test_columns_pendulums_match_scipy_per_column():
    t_end = 10.0
    t_eval = np.linspace(0.0, t_end, 101)
    r = dop853_columns(checked(pendulums(K_PEND), 8), 0.0, Y0_PEND, t_end, rtol=1e-10, atol=1e-10,
                       t_eval=t_eval)
    assert r.status == 0
    for c in range(8):
        s = _scipy_column(c, t_end, t_eval)
        assert s.status == 0
        assert np.abs(s.y - r.y[:, c]).max() < 1e-7, c


def test_each_column_moves_as_if_it_were_integrated_alone():
    """Each column's steps depend on that column only: in the batch it gets (up to rounding in the
    batched products) the result it gets alone, and the batch costs about its hardest column."""
    t_eval = np.linspace(0.0, 10.0, 101)
    batch = dop853_columns(pendulums(K_PEND), 0.0, Y0_PEND, 10.0, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    alone = [dop853_columns(pendulums(K_PEND[c:c + 1]), 0.0, Y0_PEND[:, c:c + 1], 10.0, rtol=1e-10,
                            atol=1e-10, t_eval=t_eval) for c in range(8)]
    for c, a in enumerate(alone):
        assert np.abs(a.y[:, 0] - batch.y[:, c]).max() < 1e-11, c
    # the only extra: the dense output of iterations where another column has a sample
    assert batch.nfev <= 1.1 * max(a.nfev for a in alone)


# ----------------------------------------------------------------------------- C2. fewer evaluations

#: pendulums near the separatrix: slow near the top, fast through the bottom, with different
#: periods, so which trajectory needs the smallest step changes all the time
K_SEP = np.linspace(1.0, 4.0, 16)
Y0_SEP = np.vstack([[3.019, 3.103, 3.028, 3.093, 3.0, 3.037, 3.065, 3.047,
                     3.131, 3.112, 3.056, 3.084, 3.121, 3.075, 3.009, 3.14], np.zeros(16)])


def test_columns_cost_about_the_hardest_trajectory_not_the_shared_step():
    t_end = 10.0
    t_eval = np.linspace(0.0, t_end, 101)
    cols = dop853_columns(pendulums(K_SEP), 0.0, Y0_SEP, t_end, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    shared = dop853(pendulums(K_SEP), 0.0, Y0_SEP, t_end, rtol=1e-10, atol=1e-10, t_eval=t_eval)
    assert cols.status == 0 and shared.status == 0
    scipy_nfev = []
    for c in range(16):
        k = K_SEP[c]
        s = solve_ivp(lambda t, y: [y[1], -k * np.sin(y[0])], (0.0, t_end), Y0_SEP[:, c], method="DOP853",
                      rtol=1e-10, atol=1e-10, t_eval=t_eval)
        assert np.abs(s.y - cols.y[:, c]).max() < 1e-7, c
        scipy_nfev.append(s.nfev)
    print(f"\nnfev: dop853_columns {cols.nfev}, shared-step dop853 {shared.nfev}, "
          f"scipy per column max {max(scipy_nfev)} mean {np.mean(scipy_nfev):.0f}")
    # like with like: same t_eval, dense output counted on both sides
    assert cols.nfev <= 1.15 * max(scipy_nfev)
    assert cols.nfev <= 0.9 * shared.nfev
    assert np.abs(cols.y - shared.y).max() < 1e-6


# ----------------------------------------------------------------------------- C3. own time per column


def test_columns_each_column_gets_its_own_time():
    # y' = cos(w t): y = sin(w t) / w.  A column evaluated at another column's times goes wrong.
    w = np.array([0.5, 1.0, 3.0, 7.0, 0.1])
    K = len(w)
    seen: list[np.ndarray] = []

    def fun(t, Y):
        seen.append(t.copy())
        return np.cos(w * t)[None, :]

    t_eval = np.linspace(0.0, 4.0, 41)
    r = dop853_columns(checked(fun, K, 1), 0.0, np.zeros((1, K)), 4.0, rtol=1e-12, atol=1e-12, t_eval=t_eval)
    assert r.status == 0
    exact = np.sin(w[:, None] * t_eval[None, :]) / w[:, None]
    assert np.abs(r.y[0] - exact).max() < 1e-9
    # the columns really were at different times (the fast one takes smaller steps)
    assert any(np.ptp(t) > 0.1 for t in seen)
    # columns that reached t_end are still evaluated there, without moving
    assert np.all(seen[-1] <= 4.0)


# ----------------------------------------------------------------------------- C4. events


def _x_cols(t, Y):
    return Y[0]


def test_columns_stop_event_freezes_one_column_and_the_others_go_on():
    fun, y0 = _cos_batch()   # x = cos(w t), w = W_EV: falling zero at pi / (2 w)
    mask = np.array([True, True, True, False])
    t_eval = np.linspace(0.0, 5.0, 51)
    r = dop853_columns(checked(fun, 4), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=t_eval,
                       events=[ColumnEvent(_x_cols, direction=-1, columns=mask)])
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


def test_columns_callback_true_stops_false_continues():
    fun, y0 = _cos_batch()
    calls = []

    def on_event(k, t, yk):
        calls.append((k, t))
        return k == 2   # only the fastest column stops; the others go on past their roots

    r = dop853_columns(fun, 0.0, y0, 3.0, rtol=1e-12, atol=1e-12, t_eval=np.array([3.0]),
                       events=[ColumnEvent(_x_cols, direction=-1, on_event=on_event)])
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


def test_columns_dry_friction_branches_switch_by_callback_and_stick_in_closed_form():
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
    r = dop853_columns(checked(fun, K), 0.0, np.vstack([x0, np.zeros(K)]), t_end, rtol=1e-12, atol=1e-12,
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


def test_columns_event_zero_at_t0_fires_only_when_leaving_zero_in_the_watched_direction():
    w = np.array([2.0, 1.0])
    y0 = np.vstack([np.zeros(2), w])   # x = sin(w t): 0 at t0, rising
    falling = dop853_columns(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([0.0, 5.0]),
                             events=[ColumnEvent(_x_cols, direction=-1)])
    assert falling.status == 0
    np.testing.assert_allclose(falling.t_stop, np.pi / w, rtol=0, atol=1e-10)
    for direction in (+1, 0):
        rising = dop853_columns(oscillators(w), 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
                                events=[ColumnEvent(_x_cols, direction=direction)])
        np.testing.assert_array_equal(rising.t_stop, [0.0, 0.0])
        np.testing.assert_array_equal(rising.y[:, :, 0], y0)   # frozen at the start
    rest = dop853_columns(oscillators(w), 0.0, np.zeros((2, 2)), 1.0, rtol=1e-12, atol=1e-12,
                          t_eval=np.array([1.0]), events=[ColumnEvent(_x_cols)])
    assert rest.status == 0 and rest.events == []


def test_columns_earliest_of_several_events_in_one_column_wins():
    fun, y0 = _cos_batch()
    events = [ColumnEvent(lambda t, Y: Y[0] + 0.9),                    # x = -0.9: later
              ColumnEvent(lambda t, Y: Y[0] - 0.5, direction=-1)]      # x = 0.5: at pi / (3 w)
    r = dop853_columns(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([]), events=events)
    assert r.status == 0
    assert sorted((k, i) for i, k, _, _ in r.events) == [(k, 1) for k in range(4)]
    np.testing.assert_allclose(r.t_stop, np.pi / (3 * W_EV), rtol=0, atol=1e-10)


def test_columns_event_mask_is_read_at_every_step():
    # the callback unwatches its column instead of stopping it: one event per column, then it runs on
    fun, y0 = _cos_batch()
    mask = np.ones(4, dtype=bool)

    def unwatch(k, t, yk):
        mask[k] = False
        return False

    r = dop853_columns(fun, 0.0, y0, 5.0, rtol=1e-12, atol=1e-12, t_eval=np.array([5.0]),
                       events=[ColumnEvent(_x_cols, columns=mask, on_event=unwatch)])
    assert r.status == 0
    assert sorted(k for _, k, _, _ in r.events) == [0, 1, 2, 3]
    np.testing.assert_array_equal(r.t_stop, 5.0)


def test_columns_chattering_is_a_failure():
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

    r = dop853_columns(lambda t, Y: np.stack([Y[1], -k_s * Y[0] - mu * g * sigma]), 0.0,
                       np.vstack([x0, np.zeros(2)]), 5.0, rtol=1e-10, atol=1e-10, t_eval=np.array([5.0]),
                       events=[ColumnEvent(lambda t, Y: sigma * Y[1], direction=-1, on_event=flip)],
                       max_events_per_column=10, max_evals=20_000)   # without the limit: the budget ends it
    assert r.status == -1
    assert "more than 10 events in trajectory 0 (chattering between branches)" in r.message
    assert r.failed_column == 0
    assert abs(r.t_failed - 2 * np.pi / np.sqrt(k_s)) < 1e-8   # where it should have stuck
    assert sum(1 for _, k, _, _ in r.events if k == 0) == 11


def test_columns_continuing_through_a_root_without_a_change_does_not_refire():
    # the callback changes nothing: the next event of that column is the next genuine crossing
    fun, y0 = _cos_batch()
    r = dop853_columns(fun, 0.0, y0, 10.0, rtol=1e-10, atol=1e-10, t_eval=np.array([10.0]),
                       events=[ColumnEvent(_x_cols, on_event=lambda k, t, yk: False)])
    assert r.status == 0
    for k in range(4):
        times = sorted(t for _, kk, t, _ in r.events if kk == k)
        exact = [(np.pi / 2 + np.pi * n) / W_EV[k] for n in range(10) if (np.pi / 2 + np.pi * n) / W_EV[k] < 10.0]
        assert len(times) == len(exact)
        np.testing.assert_allclose(times, exact, rtol=0, atol=1e-9)


# ----------------------------------------------------------------------------- C5. failures


def test_columns_nan_in_one_column_fails_naming_it():
    w2 = W_EV ** 2

    def fun(t, Y):
        out = np.stack([Y[1], -w2 * Y[0]])
        out[1, 2] = np.where(t[2] > 1.0, np.nan, out[1, 2])
        return out

    r = dop853_columns(fun, 0.0, np.ones((2, 4)), 3.0, rtol=1e-9, atol=1e-9, t_eval=np.linspace(0.0, 3.0, 7))
    assert r.status == -1
    assert "step size too small in trajectory 2" in r.message
    assert r.failed_column == 2 and abs(r.t_failed - 1.0) < 1e-6
    assert r.nfev < 5000
    assert np.all(np.isfinite(r.y[:, 2, :2]))   # the samples before t = 1 were reached
    assert np.isnan(r.y[:, 2, 2:]).all()        # the others were not


def test_columns_exception_from_fun_propagates_unchanged():
    def fun(t, Y):
        if np.any(t > 1.0):
            raise Singular(t)
        return np.stack([Y[1], -Y[0]])

    with pytest.raises(Singular):
        dop853_columns(fun, 0.0, np.ones((2, 4)), 3.0, rtol=1e-9, atol=1e-9, t_eval=np.array([3.0]))


def test_columns_max_evals_stops_with_a_message():
    fun, y0 = _cos_batch()
    r = dop853_columns(fun, 0.0, y0, 100.0, rtol=1e-10, atol=1e-10, t_eval=np.linspace(0, 100, 11),
                       max_evals=200)
    assert r.status == -1
    assert "more than 200 evaluations" in r.message and "trajectory" in r.message
    assert r.nfev <= 200 and r.failed_column is not None
    ok = dop853_columns(fun, 0.0, y0, 1.0, rtol=1e-10, atol=1e-10, t_eval=np.array([1.0]), max_evals=10_000)
    assert ok.status == 0 and ok.nfev <= 10_000
