"""Trajectory evidence: integrate the student's and the reference dynamics side by side.

Both systems start from the same sampled states with the same parameter values; all K
trajectories are integrated together by lagrade's DOP853 (`compare/dop853.py`: each trajectory with
its own step size, error control and events, the K of them stepped as the columns of one array), then
compared in the tolerance-scaled norm ``|y - y_ref| / (atol + rtol*|y_ref|)``. For
a wrong answer the comparison says when the motions separate and which coordinate goes wrong first;
inside the window a separation beyond the tolerance is `decisive` and refutes an answer whose sampled
states agreed (`checkers.dynamics._decide`).

What keeps this honest on hard scenes (measurements and reasons: docs/numerics.md):

- **stiffness**: before integrating, the spectrum of the Jacobian is estimated at the initial states
  (dim+1 batched evaluations, finite differences of each trajectory's own block). A scene whose fastest
  decay or oscillation rate times the horizon exceeds ``Accuracy.stiff_index`` is stiff; a growing mode
  is not stiffness, nor is the decaying half of a conservative saddle (eigenvalues +-lambda: a pendulum
  near its separatrix), which is followed at the rate of its growing half. Decay-dominated stiffness is
  integrated with scipy's LSODA (implicit BDF there) given the batched block-diagonal Jacobian; a fast
  oscillation has to be resolved by any method, and there DOP853 is measured cheapest, so the grader
  keeps it and bounds the cost instead: when the budget ``max_rhs_evals`` cannot cover the horizon
  (about 40 evaluations per radian of the fastest mode at rtol 1e-10), the comparison window is
  shortened to what it can, and the report says so.
- **chaos**: for scenes whose phase space allows it (two or more degrees of freedom, or explicit time),
  the reference is integrated together with a slightly displaced copy of each state (still one batched
  call). The measured amplification ``A(t)`` of the displacement (its logarithm over t is the
  finite-time Lyapunov exponent) bounds how far two correct integrations of the same motion can drift
  apart: integration errors of size ``rtol`` grow to ``rtol*A(t)``. The comparison window ends where
  that reaches a tenth of the comparison tolerance, so a correct answer written differently is never
  rejected by amplified rounding; a wrong answer still separates at once.
- **events**: `integrate` takes batched event functions; each trajectory stops (is frozen) at its own
  event (contact loss) while the others go on; with switching events (sign change of a friction
  force) that trajectory goes on from the root on its new branch.
- **singularities**: if the rates of a trajectory grow a millionfold (a coordinate singularity such as
  theta -> 0 of a spherical pendulum, or a collision), the run stops and says where, instead of
  returning a silently wrong motion.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np

from lagrade.compare import dop853
from lagrade.compare.dop853 import ColumnEvent
from lagrade.numbers.numeric import CompiledRates

#: (t, y of shape (dim, K)) -> (dim, K); t is one time for the batch, or (K,) times, one per trajectory
#: (the DOP853 path steps each trajectory with its own step size)
Rates = Callable[[float | np.ndarray, np.ndarray], np.ndarray]

METHODS = ("DOP853", "RK45", "Radau", "LSODA", "BDF")


@dataclass(frozen=True)
class Accuracy:
    """Integration and comparison tolerances; the comparison is looser than the integration."""

    name: str = "default"
    rtol: float = 1e-10
    atol: float = 1e-10
    compare_rtol: float = 1e-6
    compare_atol: float = 1e-6
    trajectories: int = 4
    max_rhs_evals: int = 20000
    #: "auto": DOP853, or LSODA when stiffness is detected; or any solve_ivp method name.
    method: str = "auto"
    #: horizon * (fastest rate of the Jacobian) above which a scene counts as stiff.
    stiff_index: float = 300.0
    #: shorten the window of chaotic scenes by the measured amplification (see module doc).
    chaos_window: bool = True
    #: relative tolerance of agreement at the sampled states (the first evidence of every dynamics
    #: part): rounding of a correct answer written differently stays orders of magnitude below it
    sample_rtol: float = 1e-8

    def describe(self) -> str:
        return (f"{self.name}: integration rtol {self.rtol:g}, atol {self.atol:g}; comparison rtol "
                f"{self.compare_rtol:g}, atol {self.compare_atol:g}; sampled states within rtol {self.sample_rtol:g}; "
                f"{self.trajectories} trajectories; "
                f"at most {self.max_rhs_evals} evaluations per run")


ACCURACY = {
    "fast": Accuracy("fast", 1e-8, 1e-8, 1e-4, 1e-4, 2, 8000, sample_rtol=1e-7),
    "default": Accuracy(),
    "strict": Accuracy("strict", 1e-12, 1e-12, 1e-8, 1e-8, 6, 60000, sample_rtol=1e-10),
}

#: Rates of a trajectory growing by more than this factor mean a singularity is being approached.
SINGULAR_GROWTH = 1e6


class _TooManyEvaluations(Exception):
    pass


class _Singular(Exception):
    def __init__(self, t: float, k: int, growth: float):
        super().__init__(t, k, growth)
        self.t, self.k, self.growth = t, k, growth


@dataclass
class BatchedEvent:
    """An event function of the batch: ``fn(t, Y) -> (K,)``, one root per trajectory.

    ``action`` "stop": the trajectory ends there (frozen, and compared only up to that time), e.g.
    contact loss; "switch": ``on_event(k, t, y_k)`` is called and trajectory k goes on from there on
    its own (a branch change of a non-smooth force; the implicit methods restart the whole batch).
    ``direction`` as in `solve_ivp`.
    """

    name: str
    fn: Callable[[float, np.ndarray], np.ndarray]
    action: str = "stop"
    direction: float = 0.0
    on_event: Callable[[int, float, np.ndarray], None] | None = None
    active: Callable[[], np.ndarray] | None = None  # (K,) bool: which trajectories watch this event


@dataclass
class Run:
    """One batched integration: times, states (dim, K, len(t)), where it stopped and why."""

    t: np.ndarray
    y: np.ndarray
    ok: bool
    message: str
    rhs_evals: int
    seconds: float
    method: str = "DOP853"
    #: per trajectory, the time up to which its motion is valid (events stop trajectories early).
    t_stop: np.ndarray | None = None
    #: event name -> list of (trajectory, time, state) found.
    events: dict[str, list[tuple[int, float, np.ndarray]]] = field(default_factory=dict)
    stiffness: Stiffness | None = None
    horizon: float = 0.0
    note: str = ""
    segments: int = 1


@dataclass
class Stiffness:
    """The Jacobian's spectrum at the initial states, as seen by the step-size controller."""

    fastest: float      # max(damping, oscillation): the rate that makes a scene stiff (1/time)
    damping: float      # max over the batch of a trajectory's decay beyond its growth (see `decay_beyond_growth`)
    oscillation: float  # max |Im(lambda)| over the batch
    index: float        # horizon * fastest
    stiff: bool
    evals: int
    growth: float = 0.0  # max Re(lambda) over the batch: followed by any method, so not stiffness

    def describe(self) -> str:
        kind = "fast oscillation" if self.oscillation >= self.damping else "fast decay"
        return f"stiff ({kind}: fastest rate {self.fastest:.3g}/s, {self.index:.3g} times the horizon)"


# ----------------------------------------------------------------------------- Jacobians and stiffness


def _wrap(rates: Rates, dim: int, K: int):
    def f(t: float, Y: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):
            return np.asarray(rates(t, Y), dtype=float).reshape(dim, K)
    return f


def jacobian_blocks(rates: Rates, t: float, Y: np.ndarray, f0: np.ndarray | None = None) -> tuple[np.ndarray, int]:
    """Each trajectory's Jacobian block (K, dim, dim) by forward differences: dim+1 batched evaluations,
    because the K trajectories of the batch are independent (component i is perturbed in all at once)."""
    dim, K = Y.shape
    evals = 0
    if f0 is None:
        f0 = np.asarray(rates(t, Y), dtype=float).reshape(dim, K)
        evals += 1
    J = np.empty((K, dim, dim))
    for j in range(dim):
        h = 1e-7 * np.maximum(1.0, np.abs(Y[j]))
        Yp = Y.copy()
        Yp[j] += h
        with np.errstate(all="ignore"):
            fp = np.asarray(rates(t, Yp), dtype=float).reshape(dim, K)
        evals += 1
        J[:, :, j] = ((fp - f0) / h).T
    return J, evals


def decay_beyond_growth(lam: np.ndarray) -> np.ndarray:
    """Per trajectory (rows of ``lam``, its eigenvalues): its fastest decay, max -Re(lambda), less its
    fastest growth, max Re(lambda), and at least 0.

    A decay makes explicit steps costly only where it is faster than what the solution must be followed
    at anyway. A growing mode must be followed by every method, at the accuracy asked for, so a decay
    matched by an equal growth is no stiffness: that is a saddle of conservative motion, whose
    eigenvalues come in +-lambda pairs (trace 0), e.g. a pendulum near its upright position. There
    (theta0 = pi - 1e-3, 50 periods) counting the decaying half sent the run to LSODA, 28 x less
    accurate than DOP853 at rtol 1e-12 (tests/stability/test_stiffness.py). Dissipation shows as a
    decay with no growth to match: an overdamped spring keeps all of it."""
    decay = np.maximum(-lam.real, 0.0).max(axis=-1, initial=0.0)
    growth = np.maximum(lam.real, 0.0).max(axis=-1, initial=0.0)
    return np.maximum(decay - growth, 0.0)


def estimate_stiffness(rates: Rates, y0: np.ndarray, horizon: float, acc: Accuracy, t0: float = 0.0) -> Stiffness:
    """Spectrum of the Jacobian at the initial states: is the scene stiff over ``horizon``?

    Stiff: a decay beyond growth (`decay_beyond_growth`) or an oscillation whose rate times the horizon
    exceeds ``acc.stiff_index``. A pure growth (a real lambda > 0, e.g. the upright pendulum) is not."""
    J, evals = jacobian_blocks(rates, t0, y0)
    with np.errstate(all="ignore"):
        J = np.where(np.isfinite(J), J, 0.0)
        lam = np.linalg.eigvals(J)
    damping = float(decay_beyond_growth(lam).max(initial=0.0))
    osc = float(np.abs(lam.imag).max(initial=0.0))
    growth = float(np.maximum(lam.real, 0.0).max(initial=0.0))
    fastest = max(damping, osc)
    index = fastest * horizon
    return Stiffness(fastest, damping, osc, index, index > acc.stiff_index, evals, growth)


#: Measured cost of resolving a fast oscillation with LSODA / DOP853 at rtol 1e-10: evaluations per
#: radian of the fastest mode, per batch (docs/numerics.md, "stiffness"). Scaled by tolerance below.
EVALS_PER_RADIAN = 40.0


def stiff_method(st: Stiffness) -> str:
    """Decay-dominated stiffness: LSODA (implicit BDF with the batched Jacobian) takes steps far longer
    than the fast time scale. Oscillation-dominated: the fast mode must be resolved by any method, and
    there DOP853 is measured cheaper (37 evaluations per radian against LSODA's 66 and Radau's 390 at
    k/m = 1e6, rtol 1e-10; docs/numerics.md), so it stays explicit and the window is bounded instead."""
    return "LSODA" if st.damping > st.oscillation else "DOP853"


def _affordable_window(st: Stiffness, horizon: float, acc: Accuracy) -> float:
    """The longest window whose integration fits in the evaluation budget (with a margin of 2)."""
    per_radian = EVALS_PER_RADIAN * (acc.rtol / 1e-10) ** (-1 / 8)
    # an oscillation must be resolved; a fast decay is stepped over by the implicit method, whose cost
    # then follows the slow motion (the hard cap max_rhs_evals still bounds it)
    if st.oscillation < st.damping:
        return horizon
    cost = per_radian * st.oscillation * horizon
    budget = acc.max_rhs_evals / 2
    return horizon if cost <= budget else horizon * budget / cost


# ----------------------------------------------------------------------------- integration


def integrate(rates: Rates, y0: np.ndarray, horizon: float, acc: Accuracy, samples: int = 201, *,
              method: str | None = None, events: Sequence[BatchedEvent] = (), jac: bool | None = None,
              t_eval: np.ndarray | None = None, guard: bool = True,
              caps: Sequence[tuple[int, float, float, float]] = ()) -> Run:
    """Integrate K states at once; a blow-up, a singularity or a runaway cost ends the run, not the grader.

    ``method``: None uses ``acc.method`` ("auto": DOP853, or LSODA with a batched Jacobian and, if
    needed, a window the budget can afford, when the scene is stiff). ``events``: batched events
    (contact loss stops a trajectory; a switching event moves it to a new branch, from where it goes on).
    ``caps``: windows of time where a trajectory's steps are bounded (DOP853 only: `dop853.solve`).
    """
    dim, K = y0.shape
    y0 = np.asarray(y0, dtype=float)
    count = 0
    start = time.perf_counter()
    method = method or acc.method
    stiff = None
    note = ""
    if method == "auto":
        stiff = estimate_stiffness(rates, y0, horizon, acc)
        count += stiff.evals
        method = stiff_method(stiff) if stiff.stiff else "DOP853"
        if stiff.stiff:
            window = _affordable_window(stiff, horizon, acc)
            note = f"{stiff.describe()}: integrated with {method}"
            if window < horizon:
                note += (f"; window shortened to [0, {window:.3g}] to stay within {acc.max_rhs_evals} "
                         "evaluations")
                horizon = window
    if t_eval is None:
        t_eval = np.linspace(0.0, horizon, samples)
    alive = np.ones(K, dtype=bool)
    stopped = False  # some trajectory has stopped (alive is not all True)
    t_stop = np.full(K, horizon)
    found: dict[str, list[tuple[int, float, np.ndarray]]] = {e.name: [] for e in events}

    limit: np.ndarray | None = None   # per trajectory: rates beyond this mean a singularity
    lowest = np.inf                  # the smallest of them: one comparison per call in the common case

    def watch(t: float | np.ndarray, out: np.ndarray) -> None:
        """The singularity guard: rates of a living trajectory a millionfold their first size."""
        nonlocal limit, lowest
        if not guard:
            return
        if limit is None:
            limit = SINGULAR_GROWTH * (1.0 + np.abs(out).max(axis=0))
            lowest = float(limit.min())
        elif np.abs(out).max() > lowest:  # one reduction per call; per trajectory only then
            size = np.abs(out).max(axis=0) * alive
            if np.any(size > limit):
                k = int(np.argmax(size / limit))
                raise _Singular(float(t[k]) if np.ndim(t) else t, k, float(size[k] / limit[k] * SINGULAR_GROWTH))

    def fun(t: float | np.ndarray, Y: np.ndarray) -> np.ndarray:
        # called hundreds of times per run on a few dozen numbers: every numpy call here counts
        # (floating-point warnings are silenced once around the whole integration, not per call)
        nonlocal count
        count += 1
        if count > acc.max_rhs_evals:
            raise _TooManyEvaluations
        out = rates(t, Y)
        return out * alive if stopped else out

    def flat_fun(t: float, flat: np.ndarray) -> np.ndarray:
        """`fun` as solve_ivp calls it: one flat state, the guard at every call."""
        out = np.asarray(fun(t, flat.reshape(dim, K)), dtype=float).reshape(dim, K)
        watch(t, out)
        return out.reshape(-1)

    jac_fn = None
    if (jac if jac is not None else method in ("Radau", "BDF", "LSODA")):
        def jac_fn(t: float, flat: np.ndarray) -> np.ndarray:
            nonlocal count
            Y = flat.reshape(dim, K)
            J, n = jacobian_blocks(_wrap(rates, dim, K), t, Y)
            count += n
            if count > acc.max_rhs_evals:
                raise _TooManyEvaluations
            full = np.zeros((dim * K, dim * K))
            idx = np.arange(dim)[:, None] * K
            for k in range(K):
                full[np.ix_(idx[:, 0] + k, idx[:, 0] + k)] = J[k] * alive[k]
            return full

    # One scalar event per (event, trajectory), sharing one batched evaluation per (t, y).
    cache: dict = {}

    def batched(ev: BatchedEvent, t: float, flat: np.ndarray) -> np.ndarray:
        key = (ev.name, t, flat.tobytes())
        if key not in cache:
            if len(cache) > 64:
                cache.clear()
            with np.errstate(all="ignore"):
                cache[key] = np.asarray(ev.fn(t, flat.reshape(dim, K)), dtype=float)
        return cache[key]

    def scalar_events() -> list:
        out = []
        for ev in events:
            act = ev.active() if ev.active is not None else np.ones(K, dtype=bool)
            for k in range(K):
                if not (alive[k] and act[k]):
                    continue

                def g(t, flat, ev=ev, k=k):
                    return batched(ev, t, flat)[k]
                g.terminal = True
                g.direction = ev.direction
                g.tag = (ev, k)
                out.append(g)
        return out

    def columns(t0: float, y: np.ndarray, times: np.ndarray):
        """The whole horizon in one call, each trajectory with its own time and step (compare/dop853.py):
        the batch costs about what its hardest trajectory costs alone. A stop event freezes its
        trajectory where it fires; a switching event changes that trajectory's branch and it goes on
        from there on its own, while the others go on undisturbed."""
        nonlocal stopped

        def handler(ev: BatchedEvent):
            def on_event(k: int, t: float, yk: np.ndarray) -> bool:
                nonlocal stopped
                found[ev.name].append((k, float(t), np.array(yk, dtype=float)))
                if ev.action == "stop":
                    alive[k] = False
                    stopped = True
                    t_stop[k] = t
                    return True
                if ev.on_event is not None:
                    ev.on_event(k, float(t), np.array(yk, dtype=float))
                return False
            return on_event

        # every event, even one no trajectory watches yet: the watched ones are read at every step,
        # since a switch may change them (breakaway is watched only once something sticks)
        evs = [ColumnEvent(ev.fn, ev.direction, _Watch(ev, alive), handler(ev)) for ev in events]
        res = dop853.solve(fun, t0, y.reshape(dim, K), horizon, rtol=acc.rtol, atol=acc.atol, t_eval=times,
                           events=evs, watch=watch, caps=caps)
        if res.status == -1:
            raise _Failed(res.message, res.t_failed if res.t_failed is not None else t0)
        return res.t, res.y.reshape(dim * K, -1), None

    def segment(t0: float, y: np.ndarray, times: np.ndarray):
        """One stretch up to the horizon or the first event: (t, y (dim*K, nt), hit), where hit is None
        or (t, y, [(event, trajectory), ...]) for the first crossing and any simultaneous ones."""
        if method == "DOP853":
            return columns(t0, y, times)
        from scipy.integrate import (
            solve_ivp,  # implicit methods for stiff scenes only: 0.2 s to import
        )

        evs = scalar_events()
        sol = solve_ivp(flat_fun, (t0, horizon), y, method=method, t_eval=times, rtol=acc.rtol,
                        atol=acc.atol, events=evs or None, **({"jac": jac_fn} if jac_fn else {}))
        if sol.status == -1:
            raise _Failed(sol.message, sol.t[-1] if sol.t.size else t0)
        hit = None
        if sol.status == 1 and evs:
            hits = [(te[0], ye[0], g) for g, te, ye in zip(evs, sol.t_events, sol.y_events) if len(te)]
            t_hit, y_hit, g = min(hits, key=lambda h: h[0])
            hit = (t_hit, y_hit, [g.tag])
        return np.asarray(sol.t, dtype=float).reshape(-1), np.asarray(sol.y, dtype=float).reshape(dim * K, -1), hit

    ts: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    t0, y = 0.0, y0.reshape(-1).copy()
    segments = 0
    try:
        while True:
            segments += 1
            last = t0 >= horizon
            mask = (t_eval >= t0) & (t_eval <= horizon) if segments == 1 else (t_eval > t0) & (t_eval <= horizon)
            if last:
                break
            with np.errstate(all="ignore"):
                seg_t, seg_y, hit = segment(t0, y, t_eval[mask])
            ts.append(seg_t)
            ys.append(seg_y)
            if hit is None:
                break
            # a terminal event: the first one over all events and trajectories
            t_hit, y_hit, fired = hit
            yk = np.asarray(y_hit).reshape(dim, K)
            for ev, k in fired:  # the first crossing, and any at the same time in other trajectories
                found[ev.name].append((k, float(t_hit), yk[:, k].copy()))
                if ev.action == "stop":
                    alive[k] = False
                    stopped = True
                    t_stop[k] = t_hit
                elif ev.on_event is not None:
                    ev.on_event(k, float(t_hit), yk[:, k].copy())
            t0, y = float(t_hit), y_hit.copy()
            if segments > 200:
                raise _Failed("more than 200 events (chattering between branches)", t0)
            if not alive.any():
                break
        t_all = np.concatenate(ts) if ts else t_eval[:1]
        y_all = np.concatenate(ys, axis=1).reshape(dim, K, -1) if ys else y0[..., None]
        # frozen trajectories: their samples after the stop carry the stopped state (masked by t_stop)
        ok = bool(np.all(np.isfinite(y_all)))
        message = "" if ok else "the state became infinite or undefined"
        return Run(t_all, y_all, ok, message, count, time.perf_counter() - start, method, t_stop, found,
                   stiff, horizon, note, segments)
    except _TooManyEvaluations:
        return Run(t_eval[:1], y0[..., None], False, f"needed more than {acc.max_rhs_evals} steps",
                   count, time.perf_counter() - start, method, t_stop, found, stiff, horizon, note, segments)
    except _Singular as exc:
        return Run(t_eval[:1], y0[..., None], False,
                   f"trajectory {exc.k + 1} approaches a singularity at t = {exc.t:.4g} (its rates grew "
                   f"{exc.growth:.2g}-fold): a coordinate singularity or a collision, not integrated through",
                   count, time.perf_counter() - start, method, t_stop, found, stiff, horizon, note, segments)
    except _Failed as exc:
        return Run(t_eval[:1], y0[..., None], False, f"integration failed at t = {exc.t:.4g} ({exc.reason})",
                   count, time.perf_counter() - start, method, t_stop, found, stiff, horizon, note, segments)
    except (ValueError, ZeroDivisionError, np.linalg.LinAlgError, FloatingPointError) as exc:
        if os.environ.get("LAGRADE_DEBUG"):
            raise
        return Run(t_eval[:1], y0[..., None], False, f"integration failed ({exc})", count,
                   time.perf_counter() - start, method, t_stop, found, stiff, horizon, note, segments)


class _Watch:
    """Which trajectories an event watches, read by the integrator at every step: alive ones, and of
    those the ones its ``active`` says (a branch change may change them)."""

    def __init__(self, ev: BatchedEvent, alive: np.ndarray):
        self.ev, self.alive = ev, alive

    def __array__(self, dtype=None, copy=None):
        act = self.alive & (self.ev.active() if self.ev.active is not None else True)
        return np.asarray(act, dtype=dtype)


class _Failed(Exception):
    def __init__(self, reason: str, t: float):
        super().__init__(reason, t)
        self.reason, self.t = reason, float(t)


# ----------------------------------------------------------------------------- chaos


@dataclass
class Amplification:
    """How much a small displacement of each initial state grows along the reference motion."""

    t: np.ndarray
    factor: np.ndarray        # (K, len(t)): |delta(t)| / |delta(0)| in the comparison's scaled norm
    ftle: np.ndarray          # (K,): ln(factor at the end) / t_end, the finite-time Lyapunov exponents
    window: float             # where rtol * factor reaches compare_rtol / SAFETY (min over trajectories)


#: margin between the amplified integration error and the comparison tolerance
SAFETY = 10.0


def may_be_chaotic(rates: Rates, y0: np.ndarray, horizon: float) -> bool:
    """A flow can be chaotic only in a phase space of dimension 3 or more (with t counted if explicit)."""
    dim, K = y0.shape
    if dim >= 4:
        return True
    with np.errstate(all="ignore"):
        a = np.asarray(rates(0.0, y0), dtype=float)
        b = np.asarray(rates(0.5 * horizon, y0), dtype=float)
    return dim >= 2 and not np.allclose(a, b, rtol=1e-13, atol=0.0)


def amplification(ref_pair: Run, K: int, acc: Accuracy) -> Amplification:
    """From a reference run over [y0, y0 + delta] (2K trajectories), the growth of each delta."""
    y = ref_pair.y
    a, b = y[:, :K], y[:, K:]
    scale = acc.compare_atol + acc.compare_rtol * np.abs(a)
    d = np.sqrt((((b - a) / scale) ** 2).sum(axis=0))  # (K, T)
    d0 = np.maximum(d[:, :1], 1e-300)
    factor = np.maximum(d / d0, 1.0)
    t = ref_pair.t
    with np.errstate(divide="ignore", invalid="ignore"):
        ftle = np.log(factor[:, -1]) / max(t[-1], 1e-300)
    limit = acc.compare_rtol / (SAFETY * acc.rtol)
    over = factor > limit
    window = float(ref_pair.horizon)
    for k in range(K):
        if over[k].any():
            i = int(np.argmax(over[k]))
            window = min(window, float(t[max(i - 1, 0)]))
    return Amplification(t, factor, ftle, window)


# ----------------------------------------------------------------------------- comparing two motions


@dataclass
class Comparison:
    """Two motions compared. ``agree``: within tolerance over the window. ``decisive`` (when they do
    not agree): both motions were followed and differ beyond the tolerance inside the window, where
    amplified rounding cannot explain it, so the difference refutes an answer; otherwise (a motion
    that could not be followed) it proves nothing either way."""

    agree: bool
    horizon: float
    separation_time: float | None = None
    component: str | None = None
    max_error: float = 0.0
    note: str = ""
    seconds: float = 0.0
    rhs_evals: int = 0
    method: str = ""
    rtol: float | None = None
    window: float | None = None          # compared over [0, window] (<= horizon)
    why_window: str = ""                 # chaos (measured FTLE) or stiffness budget
    ftle: float | None = None
    decisive: bool = False
    #: the reference motion's stored states inside the window: times (T,), states (dim, K, T), and per
    #: trajectory the time up to which it is valid; the states whose equations must agree
    #: (`checkers.dynamics`'s motion samples), not shown to anyone
    reference_t: np.ndarray | None = field(default=None, repr=False)
    reference_y: np.ndarray | None = field(default=None, repr=False)
    reference_stop: np.ndarray | None = field(default=None, repr=False)
    #: for a decisive refutation, what it rests on (`confirm_refutation`): instructors only
    student_y: np.ndarray | None = field(default=None, repr=False)
    evidence: str | None = None
    confirmed: bool | None = None
    #: ``confirm()`` (set by the checker that made the comparison): `confirm_refutation` with its inputs
    confirm: Callable[[], None] | None = field(default=None, repr=False)
    #: windows where the student's steps were bounded (`rate_scan`), and the states the scan evaluated
    caps: list = field(default_factory=list, repr=False)
    scanned: int = 0
    #: a confirmed or unconfirmed refutation's evidence as numbers (`confirm_refutation`): for `--json`
    #: and the gradebook, instructors only
    measured: dict | None = None

    def describe(self) -> str:
        at = ""
        if self.method:
            at = f" ({self.method} at rtol {self.rtol:g}" + (f"; {self.why_window}" if self.why_window else "") + ")"
        if self.agree:
            w = self.window if self.window is not None else self.horizon
            return f"trajectories agree over t in [0, {w:.3g}]{at}"
        if self.note:
            return self.note
        return (f"from the same initial state your motion separates from the true one at t = "
                f"{self.separation_time:.3g}; {self.component} goes wrong first")


def _displaced(y0: np.ndarray, seed: int = 12) -> np.ndarray:
    rng = np.random.default_rng(seed)
    d = rng.standard_normal(y0.shape)
    d /= np.linalg.norm(d, axis=0, keepdims=True)
    return y0 + 1e-7 * d * (1.0 + np.abs(y0))


def compare_runs(student: Rates, reference: Rates, y0: np.ndarray, labels: list[str], horizon: float,
                 acc: Accuracy, *, chaos: bool | None = None, events: Sequence[BatchedEvent] = (),
                 student_events: Sequence[BatchedEvent] | None = None, reference_key: object = None,
                 store: dict | None = None) -> Comparison:
    """Integrate both from ``y0`` and compare; ``labels`` names each state component.

    ``chaos``: measure the amplification of small displacements along the reference and compare only
    where it keeps correct integrations within tolerance (None: when the phase space allows chaos).
    ``events`` watch the reference run; ``student_events`` the student's (None: the same ones): a
    switching model's events change that model's branches, so each run needs its own.
    ``reference_key`` and ``store``: the reference integration is made once per key and kept in
    ``store`` (the reference system's own, which the disk cache keeps): every answer to a problem is
    compared with the same reference motion.
    """
    key = (reference_key, acc, horizon) if reference_key is not None and store is not None else None
    if key is not None and key in store:
        ref, method, window, why, amp = store[key]
    else:
        ref, method, window, why, amp = _reference_run(reference, y0, horizon, acc, chaos, events)
        if key is not None:
            store[key] = (ref, method, window, why, amp)
    return _compare_to_reference(student, ref, y0, labels, horizon, acc, method, window, why, amp,
                                 events if student_events is None else student_events, reference)


def _paired(reference: Rates, K: int) -> Rates:
    """The reference's rates on 2K columns: the K states and a displaced copy of each."""
    if isinstance(reference, CompiledRates):
        return reference.pair()  # the same compiled function on twice the columns

    def pair_rates(t: float, Y: np.ndarray) -> np.ndarray:
        t1, t2 = (t, t) if np.ndim(t) == 0 else (t[:K], t[K:])  # each trajectory may have its own time
        return np.concatenate([reference(t1, Y[:, :K]), reference(t2, Y[:, K:])], axis=1)
    return pair_rates


def _reference_run(reference: Rates, y0: np.ndarray, horizon: float, acc: Accuracy, chaos: bool | None,
                   events: Sequence[BatchedEvent]):
    """The reference motion, with the method, comparison window and the reason for the window."""
    dim, K = y0.shape
    chaos = acc.chaos_window and (may_be_chaotic(reference, y0, horizon) if chaos is None else chaos)
    method = acc.method
    stiff = None
    pre = 0
    if method == "auto":
        stiff = estimate_stiffness(reference, y0, horizon, acc)
        pre = stiff.evals
        method = stiff_method(stiff) if stiff.stiff else "DOP853"
    window, why = horizon, ""
    if stiff is not None and stiff.stiff:
        window = _affordable_window(stiff, horizon, acc)
        why = stiff.describe() + (f", window shortened to fit {acc.max_rhs_evals} evaluations" if window < horizon else "")
    amp = None
    if chaos and not events:
        # the displaced copies double the batch: cheaper than a second integration
        pair = integrate(_paired(reference, K), np.concatenate([y0, _displaced(y0)], axis=1), window, acc, method=method)
        ref = Run(pair.t, pair.y[:, :K], pair.ok, pair.message, pair.rhs_evals, pair.seconds, method,
                  pair.t_stop[:K] if pair.t_stop is not None else None, {}, None, window)
        if pair.ok:
            amp = amplification(pair, K, acc)
            if amp.window < window:
                why = (f"chaotic: finite-time Lyapunov exponent {float(np.nanmax(amp.ftle)):.3g}/s measured, so "
                       f"compared over [0, {amp.window:.3g}] where the amplified integration error stays below "
                       f"a tenth of the tolerance")
                window = max(amp.window, 0.0)
    else:
        ref = integrate(reference, y0, window, acc, method=method, events=events)
    ref.rhs_evals += pre
    return ref, method, window, why, amp


#: the rate scan's spacing: consecutive states it evaluates along each reference motion are at most
#: this apart in every component (relative to the component's size, at least 1) and in t
SCAN_STEP = 2e-4
#: at most this many states per scan (the spacing grows to fit): two batched evaluations of the rates
SCAN_STATES = 40_000
#: at most this many windows per trajectory where the student's steps are bounded
SCAN_WINDOWS = 8
#: steps across a window where the rates differ: at most its width over this
SCAN_STEPS_ACROSS = 8.0


def _tiled(rates: Rates, m: int) -> Rates | None:
    """The same rates on ``m`` copies of the batch's K columns (column j*K + k is trajectory k), or
    None for rates that cannot be (a switching model keeps a branch per trajectory)."""
    if isinstance(rates, CompiledRates):
        c = rates.constants
        return CompiledRates(rates.f, rates.dim, np.tile(c, (1, m)) if c.shape[1] > 1 else c, rates.copied,
                             rates.timed)
    tile = getattr(rates, "tiled", None)
    return tile(m) if tile is not None else None


def rate_scan(student: Rates, reference: Rates, ref: Run, rtol: float) -> tuple[list[tuple[int, float, float, float]], int]:
    """Where, along each reference motion, the student's rates leave the true ones: the windows
    (trajectory, a, b, h_max) in which the student's run must step finely, and the states evaluated.

    Why: an integrator sees the rates only at its stages. A bump in a student's equations narrower
    than the steps the true motion allows (``exp(-10**6*(theta - 1/3)**2)``: 2e-3 wide in theta,
    crossed in a millisecond, between stages 0.05 s apart) is stepped over unseen, its error estimate
    blind to it, and the two motions "agree". The reference's stored states, joined by cubic Hermite
    interpolation (their rates are the reference's), are evaluated at most `SCAN_STEP` apart in every
    component and in t, both rates in two batched calls; wherever they differ beyond ``rtol`` (relative,
    the sampled states' tolerance: a correct answer written differently differs by rounding) the
    student's run gets a window of bounded steps, so its error control meets the feature and resolves
    it. Any state is a fair test of rates, so the interpolation's error does not matter; the verdict is
    still the separation of the two integrated motions (`confirm_refutation` re-checks it)."""
    t, y = ref.t, ref.y
    if t.size < 2 or y.ndim != 3:
        return [], 0
    dim, K, T = y.shape
    R, S = _tiled(reference, T), _tiled(student, T)
    if R is None or S is None or not np.isfinite(y).all():
        return [], 0
    with np.errstate(all="ignore"):
        F = np.asarray(R(np.repeat(t, K), y.transpose(0, 2, 1).reshape(dim, T * K)), dtype=float).reshape(dim, T, K)
    if not np.isfinite(F).all():
        return [], 0
    Y = y.transpose(0, 2, 1)                                             # (dim, T, K)
    dt = np.diff(t)
    dy = np.abs(np.diff(Y, axis=1)) / np.maximum(1.0, np.abs(Y[:, :-1]))  # (dim, T-1, K)
    m = np.maximum(np.ceil(np.maximum(dy.max(axis=(0, 2)), dt) / SCAN_STEP), 1.0)
    if m.sum() * K > SCAN_STATES:
        m = np.maximum(np.floor(m * SCAN_STATES / (m.sum() * K)), 1.0)
    m = m.astype(int)
    jj = np.repeat(np.arange(T - 1), m)
    s = (np.arange(jj.size) - np.repeat(np.cumsum(m) - m, m)) / np.repeat(m, m)    # fractions in [0, 1)
    M = jj.size
    h = dt[jj][None, :, None]
    s3 = s[None, :, None]
    h00, h10, h01, h11 = 2 * s3**3 - 3 * s3**2 + 1, s3**3 - 2 * s3**2 + s3, -2 * s3**3 + 3 * s3**2, s3**3 - s3**2
    D = h00 * Y[:, jj] + h10 * h * F[:, jj] + h01 * Y[:, jj + 1] + h11 * h * F[:, jj + 1]   # (dim, M, K)
    times = t[jj] + s * dt[jj]
    R, S = _tiled(reference, M), _tiled(student, M)
    cols, tcol = D.reshape(dim, M * K), np.repeat(times, K)
    with np.errstate(all="ignore"):
        fr = np.asarray(R(tcol, cols), dtype=float).reshape(dim, M, K)
        fs = np.asarray(S(tcol, cols), dtype=float).reshape(dim, M, K)
        off = (np.abs(fs - fr) > rtol * (1.0 + np.abs(fr))).any(axis=0)       # (M, K); NaN is not flagged
    caps: list[tuple[int, float, float, float]] = []
    for k in range(K):
        idx = np.flatnonzero(off[:, k])
        if idx.size == 0:
            continue
        runs = np.split(idx, np.flatnonzero(np.diff(idx) > 1) + 1)[:SCAN_WINDOWS]
        for run in runs:
            a = times[max(run[0] - 1, 0)]
            b = times[run[-1] + 1] if run[-1] + 1 < M else t[-1]
            width = max(b - a, 1e-12)
            caps.append((k, float(a - width), float(b + width), float(width / SCAN_STEPS_ACROSS)))
    return caps, 2 * (T + M) * K


def _compare_to_reference(student: Rates, ref: Run, y0: np.ndarray, labels: list[str], horizon: float,
                          acc: Accuracy, method: str, window: float, why: str, amp, events,
                          reference: Rates | None = None) -> Comparison:
    common = dict(seconds=ref.seconds, rhs_evals=ref.rhs_evals, method=method, rtol=acc.rtol, window=window,
                  why_window=why, ftle=float(np.nanmax(amp.ftle)) if amp is not None else None)
    if not ref.ok:
        common["note"] = "the true motion could not be followed numerically from these states, so no trajectory comparison"
        return Comparison(False, horizon, **common)
    keep = ref.t <= window + 1e-12
    ref = Run(ref.t[keep], ref.y[..., keep], ref.ok, ref.message, ref.rhs_evals, ref.seconds, ref.method,
              ref.t_stop, ref.events, ref.stiffness, window)
    common.update(reference_t=ref.t, reference_y=ref.y, reference_stop=ref.t_stop)
    caps: list = []
    if method == "DOP853" and reference is not None:
        caps, scanned = rate_scan(student, reference, ref, acc.sample_rtol)
        common.update(caps=caps, scanned=scanned)
    stu = integrate(student, y0, window, acc, method=method, events=events, t_eval=ref.t, caps=caps)
    common["seconds"] += stu.seconds
    common["rhs_evals"] += stu.rhs_evals
    n = min(stu.y.shape[-1], ref.y.shape[-1])
    tt = ref.t[:n]
    err = np.abs(stu.y[..., :n] - ref.y[..., :n]) / (acc.compare_atol + acc.compare_rtol * np.abs(ref.y[..., :n]))
    err = np.where(np.isfinite(err), err, np.inf)
    if ref.t_stop is not None:
        err = np.where(tt[None, None, :] <= ref.t_stop[None, :, None] + 1e-12, err, 0.0)
    bad = err > 1.0
    if not bad.any() and stu.ok:
        return Comparison(True, horizon, max_error=float(err.max(initial=0.0)), **common)
    if bad.any():
        first_t = int(np.argmax(bad.any(axis=(0, 1))))
        comp = int(np.argmax(err[:, :, first_t].max(axis=1)))
        # both motions finite where they first differ: a real difference, not a motion lost
        decisive = bool(np.isfinite(stu.y[..., first_t]).all() and np.isfinite(ref.y[..., first_t]).all())
        return Comparison(False, horizon, float(ref.t[first_t]), labels[comp], float(err.max()),
                          decisive=decisive, student_y=stu.y[..., :n], **common)
    return Comparison(False, horizon, float(stu.t[-1]) if stu.t.size else 0.0, "the motion",
                      note=cannot_integrate(student, y0, labels, stu), **common)


def cannot_integrate(student: Rates, y0: np.ndarray, labels: list[str], run: Run) -> str:
    """Why a student's equations cannot be followed, in words (no integrator jargon): undefined
    accelerations at the initial state (the equations do not determine them: a singular mass
    matrix, a division by zero), a blow-up, or a motion too fast to follow."""
    dim, K = y0.shape
    try:
        with np.errstate(all="ignore"):
            f0 = np.asarray(student(0.0, y0), dtype=float).reshape(dim, K)
    except Exception:  # noqa: BLE001
        f0 = np.full((dim, K), np.nan)
    if not np.all(np.isfinite(f0)):
        return ("your equations cannot be integrated from the initial state: they give no finite acceleration "
                "there; they do not determine every acceleration (a singular mass matrix) or divide by zero")
    t = float(run.t[-1]) if run.t.size else 0.0
    if "singularity" in run.message or "infinite" in run.message:
        return f"the motion your equations give blows up (becomes infinite) near t = {t:.3g}"
    if "more than" in run.message and "steps" in run.message:
        return "the motion your equations give changes too fast to be followed over the time compared"
    return (f"your equations cannot be integrated beyond t = {t:.3g}: the motion they give becomes infinitely "
            "fast or undefined there")


#: the second tolerance of a refutation's confirmation: the integration's rtol and atol divided by this
CONFIRM_FACTOR = 100.0


def confirm_refutation(comparison: Comparison, student: Rates, reference: Rates, y0: np.ndarray, acc: Accuracy,
                       events: Sequence[BatchedEvent] = (), student_events: Sequence[BatchedEvent] | None = None
                       ) -> None:
    """What a decisive refutation rests on, measured: both motions integrated again at the integration
    tolerances / `CONFIRM_FACTOR` (same method, same window, same times), giving at the separation time
    the separation in units of the comparison tolerance, the integration's error estimate there (how
    far the runs at the two tolerances differ, reference and student added) and the separation at the
    finer tolerance. Confirmed when the finer comparison also separates there and the error estimate is
    below a tenth of the separation; sets ``comparison.evidence`` (instructors only: magnitudes of a
    difference from the true motion) and ``comparison.confirmed``."""
    c = comparison
    if not c.decisive or c.reference_t is None or c.student_y is None or c.separation_time is None:
        return
    fine = replace(acc, rtol=acc.rtol / CONFIRM_FACTOR, atol=acc.atol / CONFIRM_FACTOR,
                   max_rhs_evals=int(3 * acc.max_rhs_evals))
    times = c.reference_t[: c.student_y.shape[-1]]
    window = float(times[-1])
    method = c.method or "DOP853"
    try:
        ref_f = integrate(reference, y0, window, fine, method=method, events=events, t_eval=times, caps=c.caps)
        stu_f = integrate(student, y0, window, fine, method=method,
                          events=events if student_events is None else student_events, t_eval=times, caps=c.caps)
    except Exception as exc:  # noqa: BLE001  (the confirmation is evidence; its failure is said, not raised)
        c.confirmed, c.evidence = False, f"not confirmed: the integration at rtol {fine.rtol:g} failed ({exc})"
        return
    i = int(np.searchsorted(times, c.separation_time - 1e-12))
    m = min(ref_f.y.shape[-1], stu_f.y.shape[-1])
    if i >= m:
        c.confirmed = False
        c.evidence = (f"not confirmed: at rtol {fine.rtol:g} the motions could not be followed to the separation "
                      f"time t = {c.separation_time:.3g} ({ref_f.message or stu_f.message})")
        return
    live = (c.reference_stop >= c.separation_time - 1e-12) if c.reference_stop is not None \
        else np.ones(y0.shape[1], dtype=bool)   # a trajectory stopped before (an event) is not compared there
    ref_c, stu_c = c.reference_y[:, live, i], c.student_y[:, live, i]
    ref_f = replace(ref_f, y=ref_f.y[:, live])
    stu_f = replace(stu_f, y=stu_f.y[:, live])
    scale = acc.compare_atol + acc.compare_rtol * np.abs(ref_c)
    with np.errstate(all="ignore"):
        separation = float(np.nanmax(np.abs(stu_c - ref_c) / scale))
        estimate = float(np.nanmax((np.abs(ref_c - ref_f.y[..., i]) + np.abs(stu_c - stu_f.y[..., i])) / scale))
        fine_sep = float(np.nanmax(np.abs(stu_f.y[..., i] - ref_f.y[..., i]) / scale))
    c.confirmed = bool(np.isfinite(fine_sep) and fine_sep > 1.0 and np.isfinite(estimate)
                       and estimate < 0.1 * separation)
    c.measured = {"confirmed": c.confirmed, "t": c.separation_time, "component": c.component,
                  "separation": separation, "error_estimate": estimate, "finer_separation": fine_sep,
                  "compare_rtol": acc.compare_rtol, "compare_atol": acc.compare_atol, "rtol": acc.rtol,
                  "finer_rtol": fine.rtol, "method": method, "window": window,
                  "refined_windows": len(c.caps), "scanned_states": c.scanned}
    c.evidence = (f"{'confirmed' if c.confirmed else 'not confirmed'}: at t = {c.separation_time:.3g} ({c.component}) "
                  f"the motions are {separation:.3g} comparison tolerances apart (rtol {acc.compare_rtol:g}, atol "
                  f"{acc.compare_atol:g}); the integration's error estimate there (the runs at rtol {acc.rtol:g} and "
                  f"{fine.rtol:g}, reference and yours) is {estimate:.2g} of them; at integration rtol {fine.rtol:g} the "
                  f"motions are {fine_sep:.3g} apart there ({c.method or 'DOP853'}, window [0, {window:.3g}])")
