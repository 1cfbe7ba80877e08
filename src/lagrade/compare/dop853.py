"""DOP853 for K independent trajectories: each with its own time, step size and error control.

The solver has scipy's `OdeSolver` shape (``scipy/integrate/_ivp/rk.py``): a tableau as data
(`lagrade.compare.dop853_coefficients`), a `DOP853.step` that attempts one step, and a dense output.
What differs is only that the state is a (dim, K) array whose K columns are independent trajectories:
for the small systems graded here (dim 2..12, K 4..64) a step costs numpy call overhead, not
arithmetic, so stepping K columns together costs about what one costs. Nothing mixes the columns:
each one's error norm (RMS over its dim components), acceptance, step size, events and restarts are
exactly scipy's DOP853 for that trajectory alone (`tests/test_dop853.py` holds it to scipy step for
step), and the batch needs about as many iterations as its hardest trajectory alone.

`solve` drives it: output at ``t_eval`` from each column's 7th-order dense output, terminal or
continuing events per column located with Brent's method on the dense output (as ``solve_ivp``
does), an evaluation budget. It does not import scipy: ``import scipy.integrate`` costs about 0.2 s
per process, and a check should stay near the floor set by importing sympy.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from lagrade.compare.dop853_coefficients import (
    E3,
    E5,
    INTERPOLATOR_POWER,
    N_STAGES,
    N_STAGES_EXTENDED,
    A,
    B,
    C,
    D,
)

__all__ = ["DOP853", "ColumnEvent", "ColumnResult", "solve"]

SAFETY = 0.9
MIN_FACTOR = 0.2   # smallest step decrease
MAX_FACTOR = 10.0  # largest step increase
ERROR_EXPONENT = -1.0 / 8.0  # -1 / (error estimator order 7 + 1)
EPS = float(np.finfo(float).eps)
#: where a column's event function is exactly 0 at the start of a step, its sign just after is read
#: this fraction of the step later: leaving zero in the watched direction is a root at the start.
_ZERO_START_OFFSET = 1e-6
#: crossings this close (relative to max(1, |t|)) to the earliest one are reported with it
SIMULTANEOUS = 1e-10

#: both error estimates (5th and 3rd order) with one product against K_0..K_12
_E = np.vstack([E5, E3])


def _dense_matrix() -> np.ndarray:
    """(7, 16) W: the monomial coefficients of the dense output are  h * W @ K_ext.

    scipy's DOP853 builds F = [dy, h f_old - dy, 2 dy - h (f_new + f_old), h D K] with dy = h B K
    and f_new = K_12, i.e. F = h G K with a constant G, and evaluates a Horner form in F with factors
    x and (1 - x) alternating; folded into monomials it is one constant matrix, so the interpolant
    costs one product per step."""
    G = np.zeros((INTERPOLATOR_POWER, N_STAGES_EXTENDED))
    G[0, :N_STAGES] = B
    G[1, :N_STAGES] = -B
    G[1, 0] += 1.0
    G[2, :N_STAGES] = 2.0 * B
    G[2, 0] -= 1.0
    G[2, N_STAGES] -= 1.0
    G[3:] = D
    poly = np.zeros((INTERPOLATOR_POWER + 1, INTERPOLATOR_POWER))  # [power, F index]
    for i in range(INTERPOLATOR_POWER):
        poly[0, INTERPOLATOR_POWER - 1 - i] += 1.0  # y += F[6 - i]
        shifted = np.zeros_like(poly)
        shifted[1:] = poly[:-1]
        poly = shifted if i % 2 == 0 else poly - shifted  # y *= x, or y *= 1 - x
    return poly[1:] @ G


_W = _dense_matrix()
#: np.dot without the __array_function__ dispatch (a third of its cost on small arrays)
_dot = getattr(np.dot, "__wrapped__", np.dot)
_POWERS = np.arange(1.0, INTERPOLATOR_POWER + 1.0)


class StepTooSmall(Exception):
    def __init__(self, column: int):
        super().__init__(column)
        self.column = column


class OverBudget(Exception):
    """The next evaluations would exceed the budget of evaluations."""


@dataclass
class ColumnEvent:
    """An event of `solve`: ``fn(t, Y) -> (K,)`` with t the (K,) times of the columns.

    ``direction``: as in ``solve_ivp``.  ``columns``: bool mask (K,) of the watched columns (None:
    all); it is read again at every step, so ``on_event`` may change it (in place or by assigning
    the attribute).  ``on_event(column, t, y_column)`` is called at the located root of that column:
    True stops the column there (frozen from then on), False lets it continue from the root (the
    callback may have changed what ``fn`` and ``fun`` depend on for that column, e.g. the branch of
    a friction force).  None: stop.
    """

    fn: Callable[[np.ndarray, np.ndarray], np.ndarray]
    direction: float = 0.0
    columns: np.ndarray | None = None
    on_event: Callable[[int, float, np.ndarray], bool] | None = None


@dataclass
class ColumnResult:
    """Outcome of `solve`."""

    t: np.ndarray            # (nt,) = t_eval
    #: (dim, K, nt); a stopped column holds its frozen state after its stop time; on failure the
    #: samples not reached are NaN
    y: np.ndarray
    t_stop: np.ndarray       # (K,) where each column stopped (t_end if it reached it; on failure: where it got)
    status: int              # 0: every column reached t_end or stopped at an event; -1: failed
    message: str
    nfev: int                # number of calls of fun (each call evaluates all K columns)
    events: list[tuple[int, int, float, np.ndarray]] = field(default_factory=list)  # (event, column, t, y)
    failed_column: int | None = None
    t_failed: float | None = None


# ----------------------------------------------------------------------------- the solver


def _col_rms(v: np.ndarray) -> np.ndarray:
    """RMS over the dim components of each column of a (dim, K) array."""
    return np.sqrt(np.mean(np.square(v), axis=0))


def _initial_steps(fun, t0: float, y0: np.ndarray, f0: np.ndarray, t_end: float, rtol: float,
                   atol: float) -> np.ndarray:
    """scipy's ``select_initial_step`` (Hairer II.4) for every column on its own, with one call of fun
    (each column probed at its own t0 + h0_k): for each column exactly what scipy would choose alone."""
    interval = t_end - t0
    scale = atol + np.abs(y0) * rtol
    d0, d1 = _col_rms(y0 / scale), _col_rms(f0 / scale)
    h0 = np.where((d0 < 1e-5) | (d1 < 1e-5), 1e-6, 0.01 * d0 / np.where(d1 > 0, d1, 1.0))
    h0 = np.minimum(h0, interval)
    f1 = np.asarray(fun(t0 + h0, y0 + h0 * f0), dtype=float)
    d2 = _col_rms((f1 - f0) / scale) / h0
    flat = (d1 <= 1e-15) & (d2 <= 1e-15)
    h1 = np.where(flat, np.maximum(1e-6, h0 * 1e-3), (0.01 / np.where(flat, 1.0, np.maximum(d1, d2))) ** (1 / 8))
    h = np.minimum(100.0 * h0, h1)
    h = np.where(np.isfinite(h), h, 100.0 * h0)  # the probe met NaN/inf: the step control shrinks it
    h = np.minimum(h, interval)
    return np.where(h > 0.0, h, min(1e-6, interval))


class DOP853:
    """The state of K trajectories and one step attempt per `step` call.

    ``fun(t, Y)``: t the (K,) times of the columns, Y (dim, K); returns (dim, K) and must not keep or
    modify its arguments (the buffers are reused). Stage s of column k is evaluated at
    t_k + c_s h_k. A column that has reached ``t_end`` or was stopped is still evaluated (``fun``
    always gets all K columns) but does not move (h_k = 0); it returns an ndarray. ``limit``: the
    most calls of ``fun`` allowed (`OverBudget` before any call beyond it). ``watch(t, f)``: called with
    the rates at the start and at the end of every step some column accepted (a column that did not
    accept carries its current time and rates), e.g. to stop at a singularity. A rejected trial step
    is never watched: its end is a state the motion does not visit (an oversized trial of a correct
    motion can reach rates a millionfold too large), and the step is retried shorter.
    """

    def __init__(self, fun, t0: float, y0: np.ndarray, t_end: float, rtol: float, atol: float,
                 limit: float = math.inf, watch: Callable[[np.ndarray, np.ndarray], None] | None = None,
                 caps: Sequence[tuple[int, float, float, float]] = ()):
        self.fun, self.t_end, self.rtol, self.limit = fun, t_end, rtol, limit
        self.caps = list(caps)
        self.watch = watch or (lambda t, f: None)
        dim, K = self.dim, self.K = y0.shape
        # The stages are stored scaled by their column's step, Z = [y, h K_0, ..., h K_15], so stage s
        # is the constant row [1, A[s, :s]] times Z[:s + 1]: one product per stage.
        # (flat rows for the products, (dim, K) views of the same memory for everything else)
        self.Zf = np.empty((N_STAGES_EXTENDED + 1, dim * K))
        self.Z = self.Zf.reshape(N_STAGES_EXTENDED + 1, dim, K)
        self.y = self.Z[0]
        self.y[...] = y0
        self.t = np.full(K, t0)
        self.T = np.empty((N_STAGES_EXTENDED, K))  # stage times
        self.rows = [np.concatenate(([1.0], A[s, :s])) for s in range(N_STAGES_EXTENDED)]
        self.row_new = np.concatenate(([1.0], B))
        # stage s as (row, the Z it reads, its times, the Z it writes): views made once, not per step
        self.plan = [(self.rows[s], self.Zf[:s + 1], self.T[s], self.Z[s + 1]) for s in range(N_STAGES_EXTENDED)]
        self.stage_f, self.y_new_f = np.empty(dim * K), np.empty(dim * K)
        self.stage, self.y_new = self.stage_f.reshape(dim, K), self.y_new_f.reshape(dim, K)
        self.Pf = np.empty((INTERPOLATOR_POWER, dim * K))  # every column's dense output (monomials)
        self.P = self.Pf.reshape(INTERPOLATOR_POWER, dim, K)
        self.a_r = atol / rtol
        self.absa = np.abs(self.y) + self.a_r
        self.h = np.zeros(K)
        self.active = np.ones(K, dtype=bool)       # neither at t_end nor stopped
        self.rejected = np.zeros(K, dtype=bool)    # rejected since the column's last accepted step
        self.need_f0 = np.zeros(K, dtype=bool)     # restarted: f must be evaluated again there
        self.nfev = 0
        self.F0 = np.array(self._f(self.t, self.y))
        self.watch(self.t, self.F0)
        self.f_new = np.empty((dim, K))
        self.h_abs = _initial_steps(self._f, t0, self.y, self.F0, t_end, rtol, atol)
        self.dense_ready = False

    def _f(self, t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        if self.nfev + 1 > self.limit:
            raise OverBudget
        self.nfev += 1
        return self.fun(t, Y)

    def step(self) -> np.ndarray:
        """Attempt one step in every active column; returns which columns accepted theirs.

        Afterwards ``t``/``y`` are still the steps' starts; ``t_new``/``y_new`` the ends (for the
        accepted columns), ``dense()`` the interpolant; `advance` moves the columns on."""
        if self.need_f0.any():  # columns restarted at an event: f at the root, maybe new dynamics
            np.copyto(self.F0, self._f(self.t, self.y), where=self.need_f0)
            self.need_f0[:] = False
        t, Z, h, active = self.t, self.Z, self.h, self.active
        min_step = 10.0 * np.spacing(np.abs(t))   # at least 10 ulp, unless shrinking after rejections
        self.h_abs = np.where(self.rejected, self.h_abs, np.maximum(self.h_abs, min_step))
        small = (self.h_abs < min_step) & active
        if small.any():
            raise StepTooSmall(int(np.argmax(small)))
        if self.nfev + N_STAGES > self.limit:
            raise OverBudget
        for k, a, b, h_max in self.caps:   # a step that reaches into a capped window enters it by h_max at most
            if t[k] < b and t[k] + self.h_abs[k] > a:
                self.h_abs[k] = min(self.h_abs[k], max(a - t[k], 0.0) + h_max)
        self.t_new = np.where(active, np.minimum(t + self.h_abs, self.t_end), t)
        np.subtract(self.t_new, t, out=h)  # 0 for the columns that do not move
        np.multiply(self.F0, h, out=Z[1])
        np.add(C[:, None] * h, t, out=self.T)
        fun, stage, stage_f, multiply = self.fun, self.stage, self.stage_f, np.multiply
        for row, Zs, Ts, Z_next in self.plan[1:N_STAGES]:  # the hot loop: 11 products and calls per attempt
            _dot(row, Zs, out=stage_f)
            multiply(fun(Ts, stage), h, out=Z_next)
        _dot(self.row_new, self.plan[N_STAGES][1], out=self.y_new_f)
        np.copyto(self.f_new, fun(self.t_new, self.y_new))  # fun may reuse its buffers
        self.nfev += N_STAGES
        np.multiply(self.f_new, h, out=Z[N_STAGES + 1])
        self.dense_ready = False

        # DOP853's error norm per column (h is already in the stages); nothing mixes columns, so a
        # NaN in one column rejects only that column's step
        self.absa_new = np.abs(self.y_new) + self.a_r
        err = _dot(_E, self.Zf[1:N_STAGES + 2]).reshape(2, self.dim, self.K)
        err /= np.maximum(self.absa, self.absa_new)
        colsum = np.add.reduce(np.square(err), axis=1)  # (2, K); not a product with a 0/1 matrix: 0 * NaN
        den = colsum[0] + 0.01 * colsum[1]
        den[den == 0.0] = 1.0                             # both estimates exactly 0: the norm is 0
        error_norm = np.sqrt(np.square(colsum[0]) / den / self.dim) / self.rtol

        # each column's step-size control (scipy's constants); NaN counts as a rejection
        accepted = (error_norm < 1.0) & active
        factor = SAFETY * error_norm ** ERROR_EXPONENT   # inf for a zero norm, NaN for NaN
        grow = np.minimum(factor, MAX_FACTOR)
        grow = np.where(self.rejected, np.minimum(grow, 1.0), grow)  # no growth right after a rejection
        self.h_abs = h * np.where(accepted, grow, np.fmax(factor, MIN_FACTOR))
        self.rejected = active & ~accepted
        if accepted.any():  # only accepted ends are states of the motion (a rejected trial's is not)
            self.watch(np.where(accepted, self.t_new, t), np.where(accepted, self.f_new, self.F0))
        return accepted

    def dense(self) -> np.ndarray:
        """The monomial coefficients (7, dim, K) of every column's dense output over its last attempt
        (the 3 extra stages, for all columns at once, only when asked for)."""
        if not self.dense_ready:
            if self.nfev + 3 > self.limit:
                raise OverBudget
            for row, Zs, Ts, Z_next in self.plan[N_STAGES + 1:]:
                _dot(row, Zs, out=self.stage_f)
                np.multiply(self._f(Ts, self.stage), self.h, out=Z_next)
            _dot(_W, self.Zf[1:], out=self.Pf)
            self.dense_ready = True
        return self.P

    def interpolate(self, x: np.ndarray, columns: np.ndarray) -> np.ndarray:
        """The dense output at fractions ``x`` (m,) of the steps of ``columns`` (m,): (dim, m)."""
        X = np.asarray(x, dtype=float)[:, None] ** _POWERS
        return np.einsum("mp,pdm->dm", X, self.dense()[:, :, columns]) + self.y[:, columns]

    def advance(self, accepted: np.ndarray) -> None:
        """Move the accepted columns to the ends of their steps (FSAL: their f is the last stage's)."""
        np.copyto(self.F0, self.f_new, where=accepted)
        np.copyto(self.absa, self.absa_new, where=accepted)
        np.copyto(self.y, self.y_new, where=accepted)
        self.t = np.where(accepted, self.t_new, self.t)
        self.active &= self.t < self.t_end

    def restart(self, k: int, t: float, y: np.ndarray, h: float) -> None:
        """Column k goes on from (t, y) with step h; f is evaluated there again (the dynamics may
        have changed: a new branch of a friction force)."""
        self.t[k], self.y[:, k], self.h_abs[k] = t, y, h
        self.absa[:, k] = np.abs(y) + self.a_r
        self.need_f0[k] = True

    def stop(self, k: int, t: float, y: np.ndarray) -> None:
        self.t[k], self.y[:, k] = t, y
        self.active[k] = False
        self.F0[:, k] = 0.0


# ----------------------------------------------------------------------------- the driver


def _brentq(f: Callable[[float], float], xa: float, xb: float, fa: float, fb: float,
            xtol: float = 4 * EPS, rtol: float = 4 * EPS, maxiter: int = 100) -> float:
    """Brent's root finder (scipy's brentq.c, in Python): a root of f in [xa, xb], f(xa) f(xb) <= 0."""
    xpre, xcur, fpre, fcur = xa, xb, fa, fb
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    xblk = fblk = spre = scur = 0.0
    for _ in range(maxiter):
        if fpre != 0.0 and fcur != 0.0 and (math.copysign(1.0, fpre) != math.copysign(1.0, fcur)):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = (xtol + rtol * abs(xcur)) / 2.0
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # secant
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:  # inverse quadratic interpolation
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        xcur += scur if abs(scur) > delta else (delta if sbis > 0 else -delta)
        fcur = f(xcur)
    return xcur


def _crosses(g_left: float, g_right: float, direction: float) -> bool:
    """A zero crossing from g_left to g_right that `direction` watches (as scipy's find_active_events)."""
    up = g_left <= 0.0 <= g_right
    down = g_left >= 0.0 >= g_right
    return up if direction > 0 else down if direction < 0 else (up or down)


def _validate(t0, y0, t_end, t_eval, rtol, atol):
    """Checked arguments: (t0, y0 (dim, K), t_end, t_eval (nt,), rtol, atol)."""
    t0, t_end = float(t0), float(t_end)
    y0 = np.array(y0, dtype=float)
    if y0.ndim != 2:
        raise ValueError(f"y0 must have shape (dim, K), not {y0.shape}")
    t_eval = np.asarray(t_eval, dtype=float).reshape(-1)
    if t_end < t0:
        raise ValueError("the integrator goes forward only: t_end must be >= t0")
    if t_eval.size and (np.any(np.diff(t_eval) < 0) or t_eval[0] < t0 or t_eval[-1] > t_end):
        raise ValueError("t_eval must be sorted and inside [t0, t_end]")
    rtol = max(float(rtol), 100 * EPS)  # as scipy's validate_tol
    atol = float(atol)
    if atol < 0:
        raise ValueError("atol must be >= 0")
    return t0, y0, t_end, t_eval, rtol, atol


class _Events:
    """The events of a run: which columns cross a root in their accepted step, and where first."""

    def __init__(self, events: Sequence[ColumnEvent], K: int, max_per_column: int):
        self.events, self.K, self.max_per_column = list(events), K, max_per_column
        self.count = np.zeros(K, dtype=np.intp)
        #: column -> the events that fired where it restarted, until its first step from there is
        #: accepted: a root of theirs at the restart time is the one just handled, not a new one (the
        #: root is only known to rounding, so the event may still sit on its old side there)
        self.handled: dict[int, list[int]] = {}

    def g(self, i: int, t: np.ndarray, Y: np.ndarray) -> np.ndarray:
        g = np.array(self.events[i].fn(t, Y), dtype=float).reshape(-1)
        if g.shape != (self.K,):
            raise ValueError(f"an event function must return shape ({self.K},), not {g.shape}")
        return g

    def watched(self, i: int) -> np.ndarray:
        cols = self.events[i].columns
        return np.ones(self.K, dtype=bool) if cols is None else np.asarray(cols, dtype=bool).reshape(self.K)

    def locate(self, sol: DOP853, accepted: np.ndarray, g_old: list, g_new: list) -> list:
        """The first root in each accepted column's step, and every event crossing with it:
        [(column, root, state, [(event, its value at the root)])]."""
        found = []
        masks = [self.watched(i) for i in range(len(self.events))]
        for k in np.flatnonzero(accepted).tolist():
            tk, hk, tk_new = float(sol.t[k]), float(sol.h[k]), float(sol.t_new[k])
            cands: list[tuple[int, float, float]] = []  # (event, g at bracket start, start)
            for i in range(len(self.events)):
                gl, gr, tl = float(g_old[i][k]), float(g_new[i][k]), tk
                if gl * gr > 0.0 or not masks[i][k] or (gl == 0.0 and gr == 0.0):
                    continue
                if gl == 0.0:
                    # zero at the step start: leaving zero in the watched direction is a root right there
                    tl = tk + _ZERO_START_OFFSET * hk
                    gl = self._g_col(sol, i, k, tl)
                    if gl == 0.0:
                        continue
                    if _crosses(0.0, gl, self.events[i].direction):
                        cands.append((i, 0.0, tk))
                        continue
                if _crosses(gl, gr, self.events[i].direction):
                    cands.append((i, gl, tl))
            if not cands:
                continue
            done_here = self.handled.get(k, ())
            t_same = tk + SIMULTANEOUS * max(1.0, abs(tk))
            best_t, hit = tk_new, None
            for i, gl, tl in cands:  # the earliest root over this column's events
                if tl >= best_t:
                    continue
                gr = float(g_new[i][k]) if best_t == tk_new else self._g_col(sol, i, k, best_t)
                if best_t != tk_new and not _crosses(gl, gr, self.events[i].direction):
                    continue
                root = _brentq(lambda tt, i=i, k=k: self._g_col(sol, i, k, tt), tl, best_t, gl, gr)
                if i in done_here and root <= t_same:
                    continue  # the crossing handled at the restart
                if hit is None or root < best_t:
                    best_t, hit = root, i
            if hit is None:
                continue
            # other events of this column crossing at (about) the same time fire with it: after a
            # restart at this root their values would already be past zero
            fired = [hit]
            t_near = min(tk_new, best_t + SIMULTANEOUS * max(1.0, abs(best_t)))
            for i, gl, tl in cands:
                if i in fired or tl > t_near or (i in done_here and best_t <= t_same):
                    continue
                if _crosses(gl, self._g_col(sol, i, k, t_near), self.events[i].direction):
                    fired.append(i)
            y_root = sol.y_new[:, k].copy() if best_t == tk_new else self._y_col(sol, k, best_t)
            # the fired events at the root before the callbacks: an event whose value the callbacks
            # leave alone has been crossed; one they change (a new branch) is watched again from zero
            found.append((k, best_t, y_root, [(i, self._g_at(i, sol, k, best_t, y_root)) for i in fired]))
        return found

    def _y_col(self, sol: DOP853, k: int, tt: float) -> np.ndarray:
        return sol.interpolate(np.array([(tt - sol.t[k]) / sol.h[k]]), np.array([k]))[:, 0]

    def _g_at(self, i: int, sol: DOP853, k: int, tt: float, yk: np.ndarray) -> float:
        T, Y = sol.t.copy(), sol.y.copy()   # other columns: their current (valid) states
        T[k], Y[:, k] = tt, yk
        return float(self.g(i, T, Y)[k])

    def _g_col(self, sol: DOP853, i: int, k: int, tt: float) -> float:
        return self._g_at(i, sol, k, tt, self._y_col(sol, k, tt))


def solve(fun: Callable[[np.ndarray, np.ndarray], np.ndarray], t0: float, y0: np.ndarray, t_end: float, *,
          rtol: float, atol: float, t_eval: np.ndarray, max_evals: int | None = None,
          events: Sequence[ColumnEvent] = (), max_events_per_column: int = 200,
          watch: Callable[[np.ndarray, np.ndarray], None] | None = None,
          caps: Sequence[tuple[int, float, float, float]] = ()) -> ColumnResult:
    """Integrate the K columns of ``y0`` (dim, K) from t0 to t_end, each with its own time and step.

    Samples at ``t_eval`` come from each column's dense output (the 3 extra stages are evaluated only
    in iterations where an accepted step holds an output time or a possible event). Events are
    located per column (see `ColumnEvent` for stop and continue); a column that continues restarts
    from the root with the step size of the step that held it. Exceptions from ``fun``, an event
    function or a callback propagate unchanged; floating-point warnings are silenced for the run.
    The run fails (status -1, the column and time in the message) when a column's step falls below
    10 ulp of its time (also after NaN/inf, which shrink the step), when ``max_evals`` would be
    exceeded, or when a column has more than ``max_events_per_column`` events. ``watch``: see `DOP853`.
    ``caps``: (column, a, b, h_max): inside [a, b] that column's steps are at most h_max, so a feature
    of the rates narrower than the steps the error control would take (a bump the stages would
    straddle unseen) is stepped through, and then resolved by the error control.
    """
    t0, y0, t_end, t_eval, rtol, atol = _validate(t0, y0, t_end, t_eval, rtol, atol)
    dim, K = y0.shape
    n_eval = t_eval.size
    out = np.full((dim, K, n_eval), np.nan)
    i_first = int(np.searchsorted(t_eval, t0, side="right"))
    out[:, :, :i_first] = y0[:, :, None]
    i_eval = np.full(K, i_first, dtype=np.intp)  # per column: its next sample not yet written
    t_stop = np.full(K, t_end)
    found: list[tuple[int, int, float, np.ndarray]] = []
    ev = _Events(events, K, max_events_per_column)
    sol: DOP853 | None = None

    def result(status: int, message: str, column: int | None = None, when: float | None = None):
        return ColumnResult(t_eval.copy(), out, t_stop, status, message, sol.nfev if sol else 0, found, column, when)

    def failure(k: int, message: str) -> ColumnResult:
        t_stop[sol.active] = sol.t[sol.active]
        return result(-1, message, k, float(sol.t[k]))

    if t_end == t0:
        return result(0, "the interval is empty")
    with np.errstate(all="ignore"):
        g_old = [ev.g(i, np.full(K, t0), y0) for i in range(len(events))]
        sol = DOP853(fun, t0, y0, t_end, rtol, atol, math.inf if max_evals is None else max_evals, watch, caps)
        try:
            while sol.active.any():
                try:
                    accepted = sol.step()
                except StepTooSmall as exc:
                    k = exc.column
                    return failure(k, f"step size too small in trajectory {k} at t = {sol.t[k]:.17g}")
                if not accepted.any():
                    continue
                t_next = np.where(accepted, sol.t_new, sol.t)
                g_new = [ev.g(i, t_next, np.where(accepted, sol.y_new, sol.y)) for i in range(len(events))]
                cuts = ev.locate(sol, accepted, g_old, g_new) if events else []
                stops: dict[int, bool] = {}
                for k, root, y_root, fired in cuts:
                    for i, _ in fired:
                        found.append((i, k, root, y_root.copy()))
                        ev.count[k] += 1
                        if ev.count[k] > max_events_per_column:
                            return failure(k, f"more than {max_events_per_column} events in trajectory {k} "
                                              f"(chattering between branches), the last at t = {root:.17g}")
                        cb = events[i].on_event
                        if cb is None or cb(k, root, y_root.copy()):
                            stops[k] = True
                    t_next[k] = root

                # output samples in (t_k, t_cut_k] of the accepted columns, all at once
                cnt = (np.searchsorted(t_eval, t_next, side="right") - i_eval) * accepted
                n_samples = int(cnt.sum())
                if n_samples:
                    cr = np.repeat(np.arange(K), cnt)      # (column, sample) of each of them
                    sidx = np.arange(n_samples) + np.repeat(i_eval - (np.cumsum(cnt) - cnt), cnt)
                    te = t_eval[sidx]
                    vals = sol.y_new[:, cr]
                    inner = te < sol.t_new[cr]            # at the step end: y_new itself
                    if inner.any():
                        vals[:, inner] = sol.interpolate(((te - sol.t[cr]) / sol.h[cr])[inner], cr[inner])
                    out[:, cr, sidx] = vals
                    i_eval += cnt

                # move every column on: to its step's end, or to its root
                sol.advance(accepted)
                for k in [k for k in ev.handled if accepted[k]]:
                    del ev.handled[k]
                for i in range(len(events)):  # only where a step was accepted: a restart's 0 must survive rejections
                    np.copyto(g_old[i], g_new[i], where=accepted)
                restarted = []
                for k, root, y_root, fired in cuts:
                    if stops.get(k):
                        sol.stop(k, root, y_root)
                        t_stop[k] = root
                        out[:, k, i_eval[k]:] = y_root[:, None]
                        i_eval[k] = n_eval
                    else:
                        sol.restart(k, root, y_root, float(sol.h[k]))  # the step size of the step that held it
                        restarted.append((k, fired))
                if restarted:
                    for i in range(len(events)):  # the callbacks may have changed the event functions too
                        now = ev.g(i, sol.t, sol.y)
                        for k, _ in restarted:
                            g_old[i][k] = now[k]
                    for k, fired in restarted:
                        for i, g_before in fired:
                            if g_old[i][k] == g_before:
                                # unchanged: the crossing is behind; a root of it at the restart time
                                # (it is only known to rounding) is this one again
                                ev.handled.setdefault(k, []).append(i)
                            else:
                                # a new branch: the event starts from zero there, so leaving zero in
                                # the watched direction fires at once (chattering shows as events)
                                g_old[i][k] = 0.0
                    sol.active[[k for k, _ in restarted]] = True
                    sol.active &= sol.t < t_end
        except OverBudget:
            k = int(np.argmin(np.where(sol.active, sol.t, np.inf)))  # the column furthest behind
            return failure(k, f"trajectory {k} stopped at t = {sol.t[k]:.17g}: integration needs more than "
                              f"{max_evals} evaluations of the rates")
    return result(0, "every trajectory reached the end of the interval or stopped at an event")
