"""Batched DOP853: K trajectories stepped together, in numpy, with the stages in machine code where the
right-hand side allows it (``dop853_columns(stages=...)``, see `StagesHook`).

Why this exists instead of ``scipy.integrate.solve_ivp(method="DOP853")``:

* For the small systems graded here (dim 2..12, K 4..64 trajectories) the cost of a step is numpy
  call overhead, not arithmetic, so stepping K trajectories as the columns of one (dim, K) array
  costs about what one trajectory costs.  Each stage is one matrix-vector product on a
  preallocated stage array, and the dense output is one matrix product per step.
* The step size is shared, but the error norm is taken per column (RMS over the dim components)
  and then maximised over columns: every trajectory is held to the tolerance it would get if it
  were integrated alone (flattening the batch into one solve_ivp system would let the easy
  columns dilute the error of a hard one).
* It does not import scipy: ``import scipy.integrate`` costs about 0.2 s per process, and a CLI
  check should stay near the floor set by importing sympy.

Two integrators share the tableau, the dense-output matrix, the initial-step rule and Brent's method:

* `dop853`: one step size and one time for the whole batch.  Every column repeats every rejection of
  any column, and the step is always that of whichever column is hardest at the moment.
* `dop853_columns`: every column has its own time and step size, stepped in lockstep (one batched
  call of ``fun`` per stage, with a (K,) array of times), and accepts or rejects its own steps; the
  number of iterations is then about the largest number of attempts any one column needs alone.
  Measured on the double pendulum (problem 12.14, rtol = atol = 1e-10, 201 samples over 2 s):
  K = 16 takes 704 evaluations instead of 1010 (the hardest trajectory alone: 674), K = 64 1052
  instead of 1799 (alone: 998).  Its events are per column, stop it or let it continue.

The method, the step-size control, the initial step and the 7th-order dense output follow scipy's
``DOP853`` (``scipy/integrate/_ivp/rk.py``), which follows Hairer's DOP853; terminal events are
located with Brent's method on the dense output like ``solve_ivp`` does.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np

__all__ = ["ColumnEvent", "ColumnResult", "Event", "RKResult", "dop853", "dop853_columns"]

# ----------------------------------------------------------------------------- coefficients
# Tableau copied from scipy/integrate/_ivp/dop853_coefficients.py (BSD-3-Clause, (c) SciPy Developers).

N_STAGES = 12
N_STAGES_EXTENDED = 16
INTERPOLATOR_POWER = 7

C = np.array([0.0,
              0.526001519587677318785587544488e-01,
              0.789002279381515978178381316732e-01,
              0.118350341907227396726757197510,
              0.281649658092772603273242802490,
              0.333333333333333333333333333333,
              0.25,
              0.307692307692307692307692307692,
              0.651282051282051282051282051282,
              0.6,
              0.857142857142857142857142857142,
              1.0,
              1.0,
              0.1,
              0.2,
              0.777777777777777777777777777778])

A = np.zeros((N_STAGES_EXTENDED, N_STAGES_EXTENDED))
A[1, 0] = 5.26001519587677318785587544488e-2

A[2, 0] = 1.97250569845378994544595329183e-2
A[2, 1] = 5.91751709536136983633785987549e-2

A[3, 0] = 2.95875854768068491816892993775e-2
A[3, 2] = 8.87627564304205475450678981324e-2

A[4, 0] = 2.41365134159266685502369798665e-1
A[4, 2] = -8.84549479328286085344864962717e-1
A[4, 3] = 9.24834003261792003115737966543e-1

A[5, 0] = 3.7037037037037037037037037037e-2
A[5, 3] = 1.70828608729473871279604482173e-1
A[5, 4] = 1.25467687566822425016691814123e-1

A[6, 0] = 3.7109375e-2
A[6, 3] = 1.70252211019544039314978060272e-1
A[6, 4] = 6.02165389804559606850219397283e-2
A[6, 5] = -1.7578125e-2

A[7, 0] = 3.70920001185047927108779319836e-2
A[7, 3] = 1.70383925712239993810214054705e-1
A[7, 4] = 1.07262030446373284651809199168e-1
A[7, 5] = -1.53194377486244017527936158236e-2
A[7, 6] = 8.27378916381402288758473766002e-3

A[8, 0] = 6.24110958716075717114429577812e-1
A[8, 3] = -3.36089262944694129406857109825
A[8, 4] = -8.68219346841726006818189891453e-1
A[8, 5] = 2.75920996994467083049415600797e1
A[8, 6] = 2.01540675504778934086186788979e1
A[8, 7] = -4.34898841810699588477366255144e1

A[9, 0] = 4.77662536438264365890433908527e-1
A[9, 3] = -2.48811461997166764192642586468
A[9, 4] = -5.90290826836842996371446475743e-1
A[9, 5] = 2.12300514481811942347288949897e1
A[9, 6] = 1.52792336328824235832596922938e1
A[9, 7] = -3.32882109689848629194453265587e1
A[9, 8] = -2.03312017085086261358222928593e-2

A[10, 0] = -9.3714243008598732571704021658e-1
A[10, 3] = 5.18637242884406370830023853209
A[10, 4] = 1.09143734899672957818500254654
A[10, 5] = -8.14978701074692612513997267357
A[10, 6] = -1.85200656599969598641566180701e1
A[10, 7] = 2.27394870993505042818970056734e1
A[10, 8] = 2.49360555267965238987089396762
A[10, 9] = -3.0467644718982195003823669022

A[11, 0] = 2.27331014751653820792359768449
A[11, 3] = -1.05344954667372501984066689879e1
A[11, 4] = -2.00087205822486249909675718444
A[11, 5] = -1.79589318631187989172765950534e1
A[11, 6] = 2.79488845294199600508499808837e1
A[11, 7] = -2.85899827713502369474065508674
A[11, 8] = -8.87285693353062954433549289258
A[11, 9] = 1.23605671757943030647266201528e1
A[11, 10] = 6.43392746015763530355970484046e-1

A[12, 0] = 5.42937341165687622380535766363e-2
A[12, 5] = 4.45031289275240888144113950566
A[12, 6] = 1.89151789931450038304281599044
A[12, 7] = -5.8012039600105847814672114227
A[12, 8] = 3.1116436695781989440891606237e-1
A[12, 9] = -1.52160949662516078556178806805e-1
A[12, 10] = 2.01365400804030348374776537501e-1
A[12, 11] = 4.47106157277725905176885569043e-2

A[13, 0] = 5.61675022830479523392909219681e-2
A[13, 6] = 2.53500210216624811088794765333e-1
A[13, 7] = -2.46239037470802489917441475441e-1
A[13, 8] = -1.24191423263816360469010140626e-1
A[13, 9] = 1.5329179827876569731206322685e-1
A[13, 10] = 8.20105229563468988491666602057e-3
A[13, 11] = 7.56789766054569976138603589584e-3
A[13, 12] = -8.298e-3

A[14, 0] = 3.18346481635021405060768473261e-2
A[14, 5] = 2.83009096723667755288322961402e-2
A[14, 6] = 5.35419883074385676223797384372e-2
A[14, 7] = -5.49237485713909884646569340306e-2
A[14, 10] = -1.08347328697249322858509316994e-4
A[14, 11] = 3.82571090835658412954920192323e-4
A[14, 12] = -3.40465008687404560802977114492e-4
A[14, 13] = 1.41312443674632500278074618366e-1

A[15, 0] = -4.28896301583791923408573538692e-1
A[15, 5] = -4.69762141536116384314449447206
A[15, 6] = 7.68342119606259904184240953878
A[15, 7] = 4.06898981839711007970213554331
A[15, 8] = 3.56727187455281109270669543021e-1
A[15, 12] = -1.39902416515901462129418009734e-3
A[15, 13] = 2.9475147891527723389556272149
A[15, 14] = -9.15095847217987001081870187138

B = A[N_STAGES, :N_STAGES]

E3 = np.zeros(N_STAGES + 1)
E3[:-1] = B.copy()
E3[0] -= 0.244094488188976377952755905512
E3[8] -= 0.733846688281611857341361741547
E3[11] -= 0.220588235294117647058823529412e-1

E5 = np.zeros(N_STAGES + 1)
E5[0] = 0.1312004499419488073250102996e-1
E5[5] = -0.1225156446376204440720569753e+1
E5[6] = -0.4957589496572501915214079952
E5[7] = 0.1664377182454986536961530415e+1
E5[8] = -0.3503288487499736816886487290
E5[9] = 0.3341791187130174790297318841
E5[10] = 0.8192320648511571246570742613e-1
E5[11] = -0.2235530786388629525884427845e-1

# First 3 coefficients of the dense output are computed separately.
D = np.zeros((INTERPOLATOR_POWER - 3, N_STAGES_EXTENDED))
D[0, 0] = -0.84289382761090128651353491142e+1
D[0, 5] = 0.56671495351937776962531783590
D[0, 6] = -0.30689499459498916912797304727e+1
D[0, 7] = 0.23846676565120698287728149680e+1
D[0, 8] = 0.21170345824450282767155149946e+1
D[0, 9] = -0.87139158377797299206789907490
D[0, 10] = 0.22404374302607882758541771650e+1
D[0, 11] = 0.63157877876946881815570249290
D[0, 12] = -0.88990336451333310820698117400e-1
D[0, 13] = 0.18148505520854727256656404962e+2
D[0, 14] = -0.91946323924783554000451984436e+1
D[0, 15] = -0.44360363875948939664310572000e+1

D[1, 0] = 0.10427508642579134603413151009e+2
D[1, 5] = 0.24228349177525818288430175319e+3
D[1, 6] = 0.16520045171727028198505394887e+3
D[1, 7] = -0.37454675472269020279518312152e+3
D[1, 8] = -0.22113666853125306036270938578e+2
D[1, 9] = 0.77334326684722638389603898808e+1
D[1, 10] = -0.30674084731089398182061213626e+2
D[1, 11] = -0.93321305264302278729567221706e+1
D[1, 12] = 0.15697238121770843886131091075e+2
D[1, 13] = -0.31139403219565177677282850411e+2
D[1, 14] = -0.93529243588444783865713862664e+1
D[1, 15] = 0.35816841486394083752465898540e+2

D[2, 0] = 0.19985053242002433820987653617e+2
D[2, 5] = -0.38703730874935176555105901742e+3
D[2, 6] = -0.18917813819516756882830838328e+3
D[2, 7] = 0.52780815920542364900561016686e+3
D[2, 8] = -0.11573902539959630126141871134e+2
D[2, 9] = 0.68812326946963000169666922661e+1
D[2, 10] = -0.10006050966910838403183860980e+1
D[2, 11] = 0.77771377980534432092869265740
D[2, 12] = -0.27782057523535084065932004339e+1
D[2, 13] = -0.60196695231264120758267380846e+2
D[2, 14] = 0.84320405506677161018159903784e+2
D[2, 15] = 0.11992291136182789328035130030e+2

D[3, 0] = -0.25693933462703749003312586129e+2
D[3, 5] = -0.15418974869023643374053993627e+3
D[3, 6] = -0.23152937917604549567536039109e+3
D[3, 7] = 0.35763911791061412378285349910e+3
D[3, 8] = 0.93405324183624310003907691704e+2
D[3, 9] = -0.37458323136451633156875139351e+2
D[3, 10] = 0.10409964950896230045147246184e+3
D[3, 11] = 0.29840293426660503123344363579e+2
D[3, 12] = -0.43533456590011143754432175058e+2
D[3, 13] = 0.96324553959188282948394950600e+2
D[3, 14] = -0.39177261675615439165231486172e+2
D[3, 15] = -0.14972683625798562581422125276e+3

# ----------------------------------------------------------------------------- derived constants

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

_C = [float(c) for c in C]

#: Stage s (1..15) is  y + h * sum_j A[s, j] K_j.  The stacked array Z holds [y, K_0, ..., K_15], so
#: with coefficients [1, h*A[s, :s]] each stage is one dot product against Z[:s + 1].
_E = np.vstack([E5, E3])  # (2, 13): both error estimates with one product against K_0..K_12


def _horner_to_monomial() -> np.ndarray:
    """(7, 7) M with  y(x) - y_old = sum_k x^(k+1) (M @ F)[k]  for scipy's DOP853 Horner form in F."""
    poly = np.zeros((INTERPOLATOR_POWER + 1, INTERPOLATOR_POWER))  # [power, F index]
    for i in range(INTERPOLATOR_POWER):
        poly[0, INTERPOLATOR_POWER - 1 - i] += 1.0  # y += F[6 - i]
        shifted = np.zeros_like(poly)
        shifted[1:] = poly[:-1]
        poly = shifted if i % 2 == 0 else poly - shifted  # y *= x, or y *= 1 - x
    return poly[1:]


def _dense_matrix() -> np.ndarray:
    """(7, 16) W: the monomial coefficients of the dense output are  h * W @ K_ext.

    scipy's DOP853 builds F = [dy, h f_old - dy, 2 dy - h (f_new + f_old), h D K] with
    dy = h B K and f_new = K_12, i.e. F = h G K with a constant G; folding the Horner form into
    monomials gives one constant matrix, so the interpolant costs one product per step.
    """
    G = np.zeros((INTERPOLATOR_POWER, N_STAGES_EXTENDED))
    G[0, :N_STAGES] = B
    G[1, :N_STAGES] = -B
    G[1, 0] += 1.0
    G[2, :N_STAGES] = 2.0 * B
    G[2, 0] -= 1.0
    G[2, N_STAGES] -= 1.0
    G[3:] = D
    return _horner_to_monomial() @ G


_W = _dense_matrix()
#: the tables as the machine-code loop reads them (`StagesHook`)
_E_FLAT, _W_FLAT, _C_FLAT = (np.ascontiguousarray(x, dtype=float).reshape(-1) for x in (_E, _W, C))
#: np.dot without the __array_function__ dispatch (a third of its cost on small arrays); only ndarrays
#: reach it here.
_dot = getattr(np.dot, "__wrapped__", np.dot)
_POWERS = np.arange(1.0, INTERPOLATOR_POWER + 1.0)


# ----------------------------------------------------------------------------- public types


@dataclass
class Event:
    """A terminal event of the batch: ``fn(t, Y) -> (K,)``, one value per column, from one call.

    ``direction``: as in ``solve_ivp`` (+1 only rising zero crossings, -1 only falling, 0 both).
    ``columns``: bool mask (K,) of the columns this event watches (None: all).
    """

    fn: Callable[[float, np.ndarray], np.ndarray]
    direction: float = 0.0
    columns: np.ndarray | None = None


@dataclass
class RKResult:
    """Outcome of `dop853`: samples at the ``t_eval`` times reached, and why the run ended."""

    t: np.ndarray            # (nt,) the entries of t_eval reached (all of them if status == 0)
    y: np.ndarray            # (dim, K, nt) states at those times
    status: int              # 0: reached t_end; 1: a terminal event fired; -1: failed
    message: str
    nfev: int                # number of calls of fun (each call evaluates all K columns)
    t_event: float | None = None     # when status == 1: time of the earliest event
    event_index: int | None = None   # which entry of `events`
    event_column: int | None = None  # which trajectory (column)
    y_event: np.ndarray | None = None  # (dim, K) state of ALL columns at t_event
    #: other (event, column) pairs whose crossing lies within SIMULTANEOUS of t_event: trajectories
    #: with the same period cross together, and a restart exactly at such a root cannot see it
    also: list[tuple[int, int]] = field(default_factory=list)


@dataclass
class ColumnEvent:
    """An event of `dop853_columns`: ``fn(t, Y) -> (K,)`` with t the (K,) times of the columns.

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
    """Outcome of `dop853_columns`."""

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


# ----------------------------------------------------------------------------- helpers


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
    if direction > 0:
        return up
    if direction < 0:
        return down
    return up or down


def _col_rms(v: np.ndarray, dim: int, K: int) -> np.ndarray:
    """RMS over the dim components of each column of a flat (dim*K,) array."""
    return np.sqrt(np.mean(np.square(v.reshape(dim, K)), axis=0))


def _initial_probe(y0: np.ndarray, f0: np.ndarray, interval: float, rtol: float, atol: float,
                   dim: int, K: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """First half of scipy's ``select_initial_step`` per column: (scale, d1, h0 per column)."""
    scale = atol + np.abs(y0) * rtol
    d0 = _col_rms(y0 / scale, dim, K)
    d1 = _col_rms(f0 / scale, dim, K)
    h0_col = np.where((d0 < 1e-5) | (d1 < 1e-5), 1e-6, 0.01 * d0 / np.where(d1 > 0, d1, 1.0))
    return scale, d1, np.minimum(h0_col, interval)


def _initial_from_probe(f0: np.ndarray, f1: np.ndarray, scale: np.ndarray, d1: np.ndarray, h0,
                        dim: int, K: int) -> tuple[np.ndarray, np.ndarray]:
    """Second half: per-column steps min(100 h0, h1) from the probe f1 = f(t0 + h0, y0 + h0 f0),
    and which columns are flat (zero rates at t0 and at the probe).  ``h0``: scalar or (K,)."""
    d2 = _col_rms((f1 - f0) / scale, dim, K) / h0
    flat = (d1 <= 1e-15) & (d2 <= 1e-15)
    h1 = np.where(flat, np.maximum(1e-6, h0 * 1e-3),
                  (0.01 / np.where(flat, 1.0, np.maximum(d1, d2))) ** (1.0 / 8.0))
    return np.minimum(100.0 * h0, h1), flat


def _initial_step(fun, t0: float, y0: np.ndarray, f0: np.ndarray, t_end: float, rtol: float,
                  atol: float, dim: int, K: int) -> tuple[float, int]:
    """scipy's ``select_initial_step`` (Hairer II.4) per column; the batch takes the smallest.

    The probe step h0 is shared (the smallest per-column h0), so one extra call of fun serves all
    columns.  Columns at rest (zero rates at t0 and at the probe) set no scale of their own, so
    they are left out of both minima unless every column is at rest: otherwise one trajectory
    sitting at an equilibrium would start the whole batch at scipy's blind 1e-4 guess.  For K = 1
    this is exactly scipy's choice.  Returns (step, calls of fun).
    """
    interval = t_end - t0
    scale, d1, h0_col = _initial_probe(y0, f0, interval, rtol, atol, dim, K)
    moving = d1 > 1e-15
    h0 = float(np.min(h0_col[moving] if moving.any() else h0_col))
    f1 = np.asarray(fun(t0 + h0, (y0 + h0 * f0).reshape(dim, K)), dtype=float).reshape(-1)
    h_col, flat = _initial_from_probe(f0, f1, scale, d1, h0, dim, K)
    h = float(np.min(h_col[~flat] if not flat.all() else h_col))
    if not math.isfinite(h):  # the probe met NaN/inf: let the step control shrink the step
        h = 100.0 * h0
    h = min(h, interval)
    if not h > 0.0:
        h = min(1e-6, interval)
    return h, 1


def _initial_steps(fun, t0: float, y0: np.ndarray, f0: np.ndarray, t_end: float, rtol: float,
                   atol: float, dim: int, K: int) -> np.ndarray:
    """scipy's ``select_initial_step`` for every column on its own (one call of fun, each column
    probed at its own t0 + h0_k): for each column exactly what scipy would choose for it alone."""
    interval = t_end - t0
    scale, d1, h0 = _initial_probe(y0, f0, interval, rtol, atol, dim, K)
    f1 = np.asarray(fun(t0 + h0, (y0.reshape(dim, K) + h0 * f0.reshape(dim, K))), dtype=float).reshape(-1)
    h, _ = _initial_from_probe(f0, f1, scale, d1, h0, dim, K)
    h = np.where(np.isfinite(h), h, 100.0 * h0)  # the probe met NaN/inf: the step control shrinks it
    h = np.minimum(h, interval)
    return np.where(h > 0.0, h, min(1e-6, interval))


def _validate(t0, y0, t_end, t_eval, rtol, atol, name: str):
    """Checked arguments: (t0, y0 (dim, K), t_end, t_eval (nt,), rtol, atol)."""
    t0 = float(t0)
    t_end = float(t_end)
    y0 = np.asarray(y0, dtype=float)
    if y0.ndim != 2:
        raise ValueError(f"y0 must have shape (dim, K), not {y0.shape}")
    t_eval = np.asarray(t_eval, dtype=float).reshape(-1)
    if t_end < t0:
        raise ValueError(f"{name} integrates forward only: t_end must be >= t0")
    if t_eval.size and (np.any(np.diff(t_eval) < 0) or t_eval[0] < t0 or t_eval[-1] > t_end):
        raise ValueError("t_eval must be sorted and inside [t0, t_end]")
    rtol = max(float(rtol), 100 * EPS)  # as scipy's validate_tol
    atol = float(atol)
    if atol < 0:
        raise ValueError("atol must be >= 0")
    return t0, y0, t_end, t_eval, rtol, atol


# ----------------------------------------------------------------------------- the integrator


def dop853(fun: Callable[[float, np.ndarray], np.ndarray], t0: float, y0: np.ndarray, t_end: float,
           *, rtol: float, atol: float, t_eval: np.ndarray, max_evals: int | None = None,
           events: Sequence[Event] = ()) -> RKResult:
    """Integrate the K columns of ``y0`` (dim, K) from t0 to t_end (>= t0) with one shared step.

    ``fun(t, Y)`` gets one float time and a (dim, K) state and returns (dim, K); it must not keep or
    modify Y (the buffers are reused).  Exceptions from ``fun`` or an event propagate unchanged.
    Floating-point warnings are silenced (``np.errstate(all="ignore")``, set once for the whole run,
    so also inside ``fun``): overflow or NaN shows up as rejected steps, then as status -1.

    The error norm is per column, maximised over columns, so each trajectory gets the accuracy it
    would get alone; the step sequence is otherwise scipy's DOP853 (for K = 1 it is the same).
    States at ``t_eval`` come from the 7th-order dense output, whose 3 extra calls of ``fun`` are
    spent only on steps with an output time before their end, or a possible event.  All events are
    terminal: the run stops at the earliest root over all events and watched columns.
    """
    t0, y0, t_end, t_eval, rtol, atol = _validate(t0, y0, t_end, t_eval, rtol, atol, "dop853")
    dim, K = y0.shape
    n = dim * K
    n_eval = t_eval.size
    te_list = t_eval.tolist()
    out = np.empty((n_eval, n))
    nfev = 0

    # ---- preallocated work arrays
    Z = np.empty((N_STAGES_EXTENDED + 1, n))  # [y, K_0 .. K_15]
    Z[0] = y0.reshape(-1)
    y_old = Z[0]
    Z2 = [row.reshape(dim, K) for row in Z]   # (dim, K) views handed to / filled from fun
    Kerr = Z[1:N_STAGES + 2]                  # K_0 .. K_12 for the error estimate
    Kext = Z[1:]                              # K_0 .. K_15 for the dense output
    coef = np.zeros((N_STAGES_EXTENDED, N_STAGES_EXTENDED + 1))
    coef[:, 0] = 1.0                          # stage s = [1, h A[s, :s]] @ [y, K_0 .. K_(s-1)]
    coefA = coef[:, 1:]
    ystage = np.empty(n)
    ystage2 = ystage.reshape(dim, K)
    ynew = np.empty(n)
    ynew2 = ynew.reshape(dim, K)
    C_ = _C
    stage_plan = [(coef[s, :s + 1], Z[:s + 1], Z2[s + 1], C_[s]) for s in range(1, N_STAGES)]
    dense_plan = [(coef[s, :s + 1], Z[:s + 1], Z2[s + 1], C_[s])
                  for s in range(N_STAGES + 1, N_STAGES_EXTENDED)]
    row_new = coef[N_STAGES, :N_STAGES + 1]   # [1, h B]
    Z_new = Z[:N_STAGES + 1]
    f_new2 = Z2[N_STAGES + 1]
    # error scale = rtol * (max(|y|, |y_new|) + atol/rtol); the 1/rtol goes into the final norm
    a_r = atol / rtol
    absa_old = np.empty(n)
    absa_new = np.empty(n)
    scale = np.empty(n)
    err = np.empty((2, n))
    err3 = err.reshape(2, dim, K)
    colsum = np.empty((2, K))
    cs5 = colsum[0]
    den = np.empty(K)
    num = np.empty(K)
    w_err = np.array([1.0, 0.01])
    # per-column sums of squares: one product with a 0/1 matrix while it is small, else a reduction
    S = np.tile(np.eye(K), (dim, 1)) if n * K <= 4096 else None
    P = np.empty((INTERPOLATOR_POWER, n))     # monomial coefficients of the dense output

    i_eval = bisect_right(te_list, t0)
    out[:i_eval] = y_old

    def result(status: int, message: str, m: int, **kw) -> RKResult:
        y = np.ascontiguousarray(out[:m].reshape(m, dim, K).transpose(1, 2, 0))
        return RKResult(t_eval[:m].copy(), y, status, message, nfev, **kw)

    if t_end == t0:
        return result(0, "the interval is empty", n_eval)

    limit = math.inf if max_evals is None else max_evals
    budget_message = "stopped at t = {:.17g}: integration needs more than " + f"{max_evals} evaluations of the rates"
    t = t0
    h = 0.0

    def make_dense() -> None:
        """The 3 extra stages and the monomial coefficients P of the step [t, t + h]."""
        nonlocal nfev
        if nfev + 3 > limit:
            raise _Budget
        for row, zs, dst, c in dense_plan:
            _dot(row, zs, out=ystage)
            dst[...] = fun(t + c * h, ystage2)
        nfev += 3
        _dot(_W, Kext, out=P)
        np.multiply(P, h, out=P)

    def interp(tt: float) -> np.ndarray:
        """Dense output (dim, K) at tt inside the current step (a new array)."""
        x = (tt - t) / h
        xp = [x]
        for _ in range(INTERPOLATOR_POWER - 1):
            xp.append(xp[-1] * x)
        return (np.dot(xp, P) + y_old).reshape(dim, K)

    with np.errstate(all="ignore"):
        ev_fns = [e.fn for e in events]
        ev_dir = [float(e.direction) for e in events]
        ev_watch: list[np.ndarray | None] = []
        g_old: list[np.ndarray] = []
        for e in events:
            g = np.array(e.fn(t0, Z2[0]), dtype=float).reshape(-1)
            if g.shape != (K,):
                raise ValueError(f"an event function must return shape ({K},), not {g.shape}")
            g_old.append(g)
            ev_watch.append(None if e.columns is None else np.asarray(e.columns, dtype=bool).reshape(K))
        n_events = len(ev_fns)

        Z2[1][...] = fun(t0, Z2[0])
        nfev += 1
        h_abs, calls = _initial_step(fun, t0, Z[0], Z[1].copy(), t_end, rtol, atol, dim, K)
        nfev += calls
        np.abs(y_old, out=absa_old)
        absa_old += a_r

        # local bindings: this loop is where the time goes
        dot, multiply, divide, square, maximum, absolute, add = (
            _dot, np.multiply, np.divide, np.square, np.maximum, np.absolute, np.add)
        add_reduce = np.add.reduce
        max_reduce = np.maximum.reduce
        ulp, sqrt, isfinite = math.ulp, math.sqrt, math.isfinite
        A_, E_ = A, _E
        dim_f = float(dim)

        while t < t_end:
            min_step = 10.0 * ulp(t)
            if h_abs < min_step:
                h_abs = min_step
            rejected = False
            while True:  # attempts until a step is accepted
                if h_abs < min_step:
                    return result(-1, f"step size too small at t = {t:.17g}", i_eval)
                if nfev + N_STAGES > limit:
                    return result(-1, budget_message.format(t), i_eval)
                t_new = t + h_abs
                if t_new > t_end:
                    t_new = t_end
                h = t_new - t
                h_abs = h
                multiply(A_, h, out=coefA)
                for row, zs, dst, c in stage_plan:
                    dot(row, zs, out=ystage)
                    dst[...] = fun(t + c * h, ystage2)
                dot(row_new, Z_new, out=ynew)
                f_new2[...] = fun(t_new, ynew2)
                nfev += N_STAGES

                # DOP853's 5th/3rd-order error norm per column (RMS over dim), max over columns
                absolute(ynew, out=absa_new)
                add(absa_new, a_r, out=absa_new)
                maximum(absa_old, absa_new, out=scale)
                dot(E_, Kerr, out=err)
                divide(err, scale, out=err)
                square(err, out=err)
                if S is not None:
                    dot(err, S, out=colsum)            # (2, K): |err5|^2, |err3|^2 per column
                else:
                    add_reduce(err3, axis=1, out=colsum)
                dot(w_err, colsum, out=den)            # |err5|^2 + 0.01 |err3|^2
                square(cs5, out=num)
                divide(num, den, out=num)
                q = float(max_reduce(num))
                if q != q and np.isfinite(colsum).all():
                    q = float(np.where(den > 0.0, num, 0.0).max())  # 0/0: both estimates are 0
                error_norm = h / rtol * sqrt(q / dim_f)
                if error_norm < 1.0:
                    if error_norm == 0.0:
                        factor = MAX_FACTOR
                    else:
                        factor = min(MAX_FACTOR, SAFETY * error_norm ** ERROR_EXPONENT)
                    if rejected and factor > 1.0:
                        factor = 1.0
                    h_abs *= factor
                    break
                if isfinite(error_norm):
                    h_abs *= max(MIN_FACTOR, SAFETY * error_norm ** ERROR_EXPONENT)
                else:  # NaN or inf from fun
                    h_abs *= MIN_FACTOR
                rejected = True

            # ---- accepted step [t, t_new]: y_old = Z[0], y_new = ynew, K_0..K_12 in Z[1:14]
            dense = False
            t_stop = t_new
            hit: tuple[int, int] | None = None
            also: list[tuple[int, int]] = []
            try:
                if n_events:
                    # (event, column, g at the bracket start, bracket start) with a watched crossing
                    cands: list[tuple[int, int, float, float]] = []
                    g_news = []
                    for i in range(n_events):
                        g_new = np.array(ev_fns[i](t_new, ynew2), dtype=float).reshape(-1)
                        g_news.append(g_new)
                        maybe = g_old[i] * g_new <= 0.0  # cheap superset of the sign changes
                        if ev_watch[i] is not None:
                            maybe &= ev_watch[i]
                        if not maybe.any():
                            continue
                        go = g_old[i]
                        direction = ev_dir[i]
                        g_zero = None
                        for c in np.flatnonzero(maybe).tolist():
                            gl, gr, tl = float(go[c]), float(g_new[c]), t
                            if gl == 0.0:
                                if gr == 0.0:
                                    continue  # zero at both ends: not a crossing
                                # zero at the step start (t0, or a touch at the last step end):
                                # leaving zero in the watched direction is a root right there, as in
                                # solve_ivp (a friction force whose sign is undecided at rest picks
                                # its branch at once); leaving it the other way, a later crossing
                                # in the step still counts
                                if not dense:
                                    make_dense()
                                    dense = True
                                tl = t + _ZERO_START_OFFSET * h
                                if g_zero is None:
                                    g_zero = np.array(ev_fns[i](tl, interp(tl)), dtype=float).reshape(-1)
                                gl = float(g_zero[c])
                                if gl == 0.0:
                                    continue
                                if _crosses(0.0, gl, direction):
                                    cands.append((i, c, 0.0, t))
                                    continue
                            if _crosses(gl, gr, direction):
                                cands.append((i, c, gl, tl))
                    g_old = g_news
                    if cands:
                        if not dense:
                            make_dense()
                            dense = True
                        # earliest root: each later candidate is bracketed up to the best root so far
                        best_t = t_new
                        g_best = g_news[0]
                        g_best_key = (-1, t_new)
                        for i, c, gl, tl in cands:
                            if tl >= best_t:
                                continue
                            if best_t == t_new:
                                gr = float(g_news[i][c])
                            else:
                                if g_best_key != (i, best_t):
                                    g_best = np.array(ev_fns[i](best_t, interp(best_t)), dtype=float).reshape(-1)
                                    g_best_key = (i, best_t)
                                gr = float(g_best[c])
                                if not _crosses(gl, gr, ev_dir[i]):
                                    continue  # this column's root lies after the best one

                            def g_of(tt: float, fn=ev_fns[i], c=c) -> float:
                                return float(np.asarray(fn(tt, interp(tt)), dtype=float).reshape(-1)[c])

                            root = _brentq(g_of, tl, best_t, gl, gr)
                            if hit is None or root < best_t:
                                best_t = root
                                hit = (i, c)
                        if hit is not None:
                            t_stop = best_t
                            t_near = min(t_new, best_t + SIMULTANEOUS * max(1.0, abs(best_t)))
                            g_near: dict[int, np.ndarray] = {}
                            for i, c, gl, tl in cands:
                                if (i, c) == hit or tl > t_near:
                                    continue
                                if i not in g_near:
                                    g_near[i] = np.array(ev_fns[i](t_near, interp(t_near)), dtype=float).reshape(-1)
                                if _crosses(gl, float(g_near[i][c]), ev_dir[i]):
                                    also.append((i, c))

                # ---- output samples in (t, t_stop]
                j = bisect_right(te_list, t_stop, i_eval)
                if j > i_eval:
                    k = j
                    while k > i_eval and te_list[k - 1] == t_new:
                        k -= 1
                    out[k:j] = ynew  # samples at the step end need no interpolation
                    if k > i_eval:
                        if not dense:
                            make_dense()
                            dense = True
                        if k == i_eval + 1:  # the common case: one sample in the step
                            x = (te_list[i_eval] - t) / h
                            xp = [x]
                            for _ in range(INTERPOLATOR_POWER - 1):
                                xp.append(xp[-1] * x)
                            row = out[i_eval]
                            dot(xp, P, out=row)
                            add(row, y_old, out=row)
                        else:
                            X = ((t_eval[i_eval:k] - t) / h)[:, None] ** _POWERS
                            block = out[i_eval:k]
                            dot(X, P, out=block)
                            add(block, y_old, out=block)
                    i_eval = j
                if hit is not None:
                    y_ev = ynew2.copy() if t_stop == t_new else interp(t_stop)
                    return result(1, f"event {hit[0]} of trajectory {hit[1]} at t = {t_stop:.17g}", i_eval,
                                  t_event=float(t_stop), event_index=hit[0], event_column=hit[1],
                                  y_event=y_ev, also=also)
            except _Budget:
                return result(-1, budget_message.format(t), i_eval)

            # ---- advance: y <- y_new, K_0 <- f_new
            t = t_new
            y_old[...] = ynew
            Z[1] = Z[N_STAGES + 1]
            absa_old, absa_new = absa_new, absa_old

    return result(0, "reached the end of the interval", i_eval)


#: ``stages(Z, T, h, coef) -> (run, state, rates)`` or None, called once per run on the integrator's
#: buffers: Z (17, dim*K) the scaled stages [y, h K_0, ...], T (16, K) the stage times, h (K,) the
#: steps, coef (16, 17) stage s's row [1, A[s, :s]]. ``run(s0, s1)`` writes Z[s + 1] = h K_s for the
#: stages s0 <= s < s1, reading Z, T and h as they are at the call; then ``state`` (dim, K) holds the
#: last stage's state and ``rates`` (dim, K) its K_s (`lagrade.compare.rates.CompiledRates.stages`).
StagesHook = Callable[[np.ndarray, np.ndarray, np.ndarray, np.ndarray], "tuple | None"]
#: A fourth item of what the hook returns, ``bind(buffers) -> loop | None``, runs the whole loop of
#: `dop853_columns` without events in machine code (`lagrade.native.Stages.bind_columns`):
#: ``loop(nfev, nfev_limit, t_end, rtol, atol / rtol) -> (status, column, nfev)`` on the integrator's
#: buffers, named as in `lagrade.native.COLUMN_BUFFERS`; it returns one of these statuses (the
#: column: the one whose step became too small) or raises what the hook's own checks raise.
LOOP_DONE, LOOP_STEP_TOO_SMALL, LOOP_TOO_MANY, LOOP_SINGULAR, LOOP_OVER_BUDGET = range(5)
#: nfev_limit when there is none
LOOP_NO_LIMIT = 2**62


class _Budget(Exception):
    """Internal: the dense output would exceed ``max_evals``."""


# ----------------------------------------------------------------------------- one step size per column


def dop853_columns(fun: Callable[[np.ndarray, np.ndarray], np.ndarray], t0: float, y0: np.ndarray,
                   t_end: float, *, rtol: float, atol: float, t_eval: np.ndarray,
                   max_evals: int | None = None, events: Sequence[ColumnEvent] = (),
                   max_events_per_column: int = 200, stages: StagesHook | None = None) -> ColumnResult:
    """Integrate the K columns of ``y0`` (dim, K) from t0 to t_end, each with its own time and step.

    The columns are stepped in lockstep: every iteration evaluates the 12 stages once for all K
    columns, column k at its own t_k with its own h_k, so ``fun(t, Y)`` gets a (K,) array of times
    (stage s: t_k + c_s h_k) and a (dim, K) state and returns (dim, K); it must not keep or modify
    its arguments (the buffers are reused).  Each column accepts or rejects its own step with its own
    error norm and step-size control (scipy's DOP853 for that column alone), so the number of
    iterations is about the largest number of attempts any column needs alone, where `dop853`'s
    shared step repeats every column's rejections for all and follows the hardest column at each
    moment.  A column that has reached t_end or was stopped by an event is still evaluated (``fun``
    always gets all K columns) but does not move (h_k = 0).

    Samples at ``t_eval`` come from each column's 7th-order dense output; the 3 extra stages are
    evaluated (for all columns at once) only in iterations where some accepted step holds an output
    time or a possible event.  Events are located per column with Brent's method on that column's
    dense output (see `ColumnEvent` for stop and continue).  A column that continues restarts from
    the root with the step size of the step that held it, and its first stage is recomputed there
    (one extra call of fun), since the callback may have changed the dynamics.

    ``stages``: the stages of every step in one call of machine code instead of ``fun`` (see
    `StagesHook`); ``fun`` still gives the first stage, restarts and the initial step. Exceptions from
    ``fun``, ``stages``, an event function or a callback propagate unchanged; floating-point
    warnings are silenced for the run.  The whole run fails (status -1, the column and time in the
    message) when any column's step falls below 10 ulp of its time (also after NaN/inf, which
    shrink the step), when ``max_evals`` would be exceeded, or when a column has more than
    ``max_events_per_column`` events.
    """
    t0, y0, t_end, t_eval, rtol, atol = _validate(t0, y0, t_end, t_eval, rtol, atol, "dop853_columns")
    dim, K = y0.shape
    n = dim * K
    n_eval = t_eval.size
    out = np.full((dim, K, n_eval), np.nan)
    i_first = int(np.searchsorted(t_eval, t0, side="right"))
    out[:, :, :i_first] = y0[:, :, None]
    i_eval = np.full(K, i_first, dtype=np.intp)  # per column: its next sample not yet written
    columns = np.arange(K)
    t_stop = np.full(K, t_end)
    found: list[tuple[int, int, float, np.ndarray]] = []
    nfev = 0
    t = np.full(K, t0)                            # each column's time
    active = np.ones(K, dtype=bool)               # neither at t_end nor stopped by an event

    def result(status: int, message: str, column: int | None = None, when: float | None = None):
        return ColumnResult(t_eval.copy(), out, t_stop, status, message, nfev, found, column, when)

    def failure(k: int, message: str, when: float) -> ColumnResult:
        t_stop[active] = t[active]
        return result(-1, message, k, when)

    def over_budget() -> ColumnResult:
        k = int(np.argmin(np.where(active, t, np.inf)))  # the column furthest behind
        return failure(k, f"trajectory {k} stopped at t = {t[k]:.17g}: integration needs more than "
                          f"{max_evals} evaluations of the rates", float(t[k]))

    if t_end == t0:
        return result(0, "the interval is empty")
    limit = math.inf if max_evals is None else max_evals

    # ---- preallocated work arrays.  The stages are stored scaled by their column's step,
    # Z = [y, h K_0, ..., h K_15], so stage s is the constant row [1, A[s, :s]] times Z[:s + 1]:
    # one product per stage, and the per-column h costs one broadcast multiply of what fun returns
    # (which replaces the copy into the stage array).
    Z = np.empty((N_STAGES_EXTENDED + 1, n))
    Z2 = [row.reshape(dim, K) for row in Z]
    y_old, y2 = Z[0], Z2[0]
    y_old[...] = y0.reshape(-1)
    F0 = np.empty((dim, K))                       # f(t_k, y_k) unscaled: the next K_0 is h * F0
    T = np.empty((N_STAGES_EXTENDED, K))          # stage times t_k + c_s h_k
    Ccol = C[:, None]
    rows = [np.concatenate(([1.0], A[s, :s])) for s in range(N_STAGES_EXTENDED)]
    stage_plan = [(rows[s], Z[:s + 1], Z2[s + 1], T[s]) for s in range(1, N_STAGES)]
    dense_plan = [(rows[s], Z[:s + 1], Z2[s + 1], T[s]) for s in range(N_STAGES + 1, N_STAGES_EXTENDED)]
    row_new = np.concatenate(([1.0], B))
    Z_new = Z[:N_STAGES + 1]
    hf_new2 = Z2[N_STAGES + 1]
    Kerr = Z[1:N_STAGES + 2]
    Kext = Z[1:]
    ystage = np.empty(n)
    ystage2 = ystage.reshape(dim, K)
    ynew = np.empty(n)
    ynew2 = ynew.reshape(dim, K)
    a_r = atol / rtol
    absa_old = np.abs(y_old) + a_r
    absa_old2 = absa_old.reshape(dim, K)
    absa_new = np.empty(n)
    absa_new2 = absa_new.reshape(dim, K)
    scale = np.empty(n)
    err = np.empty((2, n))
    err3 = err.reshape(2, dim, K)
    colsum = np.empty((2, K))
    cs5 = colsum[0]
    den = np.empty(K)
    num = np.empty(K)
    w_err = np.array([1.0, 0.01])
    P = np.empty((INTERPOLATOR_POWER, n))         # monomial coefficients of every column's dense output
    P3 = P.reshape(INTERPOLATOR_POWER, dim, K)
    h = np.zeros(K)
    rejected = np.zeros(K, dtype=bool)            # rejected since the column's last accepted step
    need_f0 = np.zeros(K, dtype=bool)             # restarted at an event: K_0 must be recomputed
    n_ev_col = np.zeros(K, dtype=np.intp)
    coef = np.zeros((N_STAGES_EXTENDED, N_STAGES_EXTENDED + 1))  # the stage rows for `stages`
    for s, row in enumerate(rows):
        coef[s, :s + 1] = row
    fast = stages(Z, T, h, coef) if stages is not None else None
    bind_loop = None
    if fast is not None:
        run_stages, last_state, last_rates, *more = fast
        bind_loop = more[0] if more else None
    #: column -> the events that fired where it restarted, until its first step from there is
    #: accepted: a root of theirs at the restart time is the one just handled, not a new one (the
    #: root is only known to rounding, so the event may still sit on its old side there)
    handled: dict[int, list[int]] = {}

    def make_dense() -> None:
        """The 3 extra stages (all columns) and the monomial coefficients P of every column's step."""
        nonlocal nfev
        if nfev + 3 > limit:
            raise _Budget
        if fast is not None:
            run_stages(N_STAGES + 1, N_STAGES_EXTENDED)
        else:
            for row, zs, dst, ts in dense_plan:
                _dot(row, zs, out=ystage)
                np.multiply(fun(ts, ystage2), h, out=dst)
        nfev += 3
        _dot(_W, Kext, out=P)

    def interp_all(x: float) -> np.ndarray:
        """Every column's dense output at the same fraction x of its step (a new (dim, K) array)."""
        xp = [x]
        for _ in range(INTERPOLATOR_POWER - 1):
            xp.append(xp[-1] * x)
        return np.dot(xp, P).reshape(dim, K) + y2

    n_events = len(events)
    ev_fns = [e.fn for e in events]
    ev_dir = [float(e.direction) for e in events]

    def g_all(i: int, tt: np.ndarray, Y: np.ndarray) -> np.ndarray:
        g = np.array(ev_fns[i](tt, Y), dtype=float).reshape(-1)
        if g.shape != (K,):
            raise ValueError(f"an event function must return shape ({K},), not {g.shape}")
        return g

    def watched(i: int) -> np.ndarray | None:
        cols = events[i].columns
        return None if cols is None else np.asarray(cols, dtype=bool).reshape(K)

    with np.errstate(all="ignore"):
        g_old = [g_all(i, t, y2) for i in range(n_events)]
        F0[...] = fun(t, y2)
        nfev += 1
        h_abs = _initial_steps(fun, t0, y_old, F0.reshape(-1).copy(), t_end, rtol, atol, dim, K)
        nfev += 1

        if bind_loop is not None and not n_events:
            # the whole loop below, events aside, in one call of machine code (`StagesHook`)
            loop = bind_loop({
                "F0": F0, "t": t, "h_abs": np.array(h_abs, dtype=float).reshape(K), "absa_old": absa_old,
                "absa_new": absa_new, "P": P, "t_eval": t_eval, "samples": out, "E": _E_FLAT, "W": _W_FLAT,
                "limit": np.empty(K), "ynew": ynew, "t_new": np.empty(K), "t_next": np.empty(K), "C": _C_FLAT,
                "rejected": rejected, "active": active, "accepted": np.zeros(K, dtype=bool), "i_eval": i_eval})
            if loop is not None:
                status, k, nfev = loop(nfev, LOOP_NO_LIMIT if max_evals is None else max_evals, t_end, rtol, a_r)
                if status == LOOP_STEP_TOO_SMALL:
                    return failure(k, f"step size too small in trajectory {k} at t = {t[k]:.17g}", float(t[k]))
                if status == LOOP_OVER_BUDGET:
                    return over_budget()
                return result(0, "every trajectory reached the end of the interval or stopped at an event")

        dot, multiply, divide, square, maximum, minimum, absolute, add, where, copyto = (
            _dot, np.multiply, np.divide, np.square, np.maximum, np.minimum, np.absolute, np.add,
            np.where, np.copyto)
        spacing, sqrt, fmax = np.spacing, np.sqrt, np.fmax
        add_reduce = np.add.reduce
        E_ = _E
        restarted = False

        while True:
            if restarted:  # K_0 of the columns restarted at an event: f at the root, new dynamics
                if nfev + 1 > limit:
                    return over_budget()
                copyto(F0, fun(t, y2), where=need_f0)
                nfev += 1
                need_f0[:] = False
                restarted = False

            # ---- each column's step: at least 10 ulp of its time, unless shrinking after rejections
            min_step = 10.0 * spacing(absolute(t))
            h_abs = where(rejected, h_abs, maximum(h_abs, min_step))
            small = (h_abs < min_step) & active
            if small.any():
                k = int(np.argmax(small))
                return failure(k, f"step size too small in trajectory {k} at t = {t[k]:.17g}", float(t[k]))
            if nfev + N_STAGES > limit:
                return over_budget()
            t_new = where(active, minimum(t + h_abs, t_end), t)
            np.subtract(t_new, t, out=h)      # 0 for the columns that do not move (in place: `fast` reads it)

            multiply(F0, h, out=Z2[1])
            multiply(Ccol, h, out=T)
            add(T, t, out=T)
            if fast is not None:
                T[N_STAGES] = t_new           # the last stage is f(t_new, y_new), as below
                run_stages(1, N_STAGES + 1)
                copyto(ynew2, last_state)
                f_new = last_rates
            else:
                for row, zs, dst, ts in stage_plan:
                    dot(row, zs, out=ystage)
                    multiply(fun(ts, ystage2), h, out=dst)
                dot(row_new, Z_new, out=ynew)
                f_new = fun(t_new, ynew2)
                multiply(f_new, h, out=hf_new2)
            nfev += N_STAGES

            # ---- DOP853's error norm per column (RMS over dim); h is already in the stages.  Nothing
            # here mixes columns, so a NaN in one column rejects only that column's step.
            absolute(ynew, out=absa_new)
            add(absa_new, a_r, out=absa_new)
            maximum(absa_old, absa_new, out=scale)
            dot(E_, Kerr, out=err)
            divide(err, scale, out=err)
            square(err, out=err)
            add_reduce(err3, axis=1, out=colsum)   # not a product with a 0/1 matrix: 0 * NaN = NaN
            dot(w_err, colsum, out=den)
            square(cs5, out=num)
            copyto(den, 1.0, where=den == 0.0)   # both estimates exactly 0: the norm is 0
            divide(num, den, out=num)
            error_norm = sqrt(num / dim) / rtol

            # ---- each column's step-size control (scipy's constants); NaN counts as a rejection
            accepted = error_norm < 1.0
            accepted &= active
            factor = SAFETY * error_norm ** ERROR_EXPONENT   # inf for a zero norm, NaN for NaN
            grow = minimum(factor, MAX_FACTOR)
            grow = where(rejected, minimum(grow, 1.0), grow)  # no growth right after a rejection
            h_abs = h * where(accepted, grow, fmax(factor, MIN_FACTOR))
            rejected = active & ~accepted
            if not accepted.any():
                continue

            # ---- accepted steps [t_k, t_new_k]
            copyto(F0, f_new, where=accepted)   # FSAL: before fun is called again for the dense output
            copyto(absa_old2, absa_new2, where=accepted)
            t_next = where(accepted, t_new, t)
            copyto(ynew2, y2, where=~accepted)   # ynew: every column's state after this iteration
            dense = False
            # (column, root, state there, stop, [(fired event, its value at the root before the callbacks)])
            cuts: list[tuple[int, float, np.ndarray, bool, list[tuple[int, float]]]] = []
            try:
                if n_events:
                    g_new = [g_all(i, t_next, ynew2) for i in range(n_events)]
                    per_col: dict[int, list[int]] = {}
                    for i in range(n_events):
                        maybe = g_old[i] * g_new[i] <= 0.0  # cheap superset of the sign changes
                        maybe &= accepted
                        w = watched(i)
                        if w is not None:
                            maybe &= w
                        if maybe.any():
                            for k in np.flatnonzero(maybe).tolist():
                                per_col.setdefault(k, []).append(i)
                    g_zero: dict[int, np.ndarray] = {}
                    for k in sorted(per_col):
                        tk, hk, tk_new = float(t[k]), float(h[k]), float(t_new[k])
                        cands: list[tuple[int, float, float]] = []  # (event, g at bracket start, start)
                        for i in per_col[k]:
                            gl, gr, tl = float(g_old[i][k]), float(g_new[i][k]), tk
                            if gl == 0.0:
                                if gr == 0.0:
                                    continue  # zero at both ends: not a crossing
                                # zero at the step start: leaving zero in the watched direction is a
                                # root right there (as in solve_ivp and `dop853`)
                                if not dense:
                                    make_dense()
                                    dense = True
                                if i not in g_zero:
                                    g_zero[i] = g_all(i, t + _ZERO_START_OFFSET * h, interp_all(_ZERO_START_OFFSET))
                                tl = tk + _ZERO_START_OFFSET * hk
                                gl = float(g_zero[i][k])
                                if gl == 0.0:
                                    continue
                                if _crosses(0.0, gl, ev_dir[i]):
                                    cands.append((i, 0.0, tk))
                                    continue
                            if _crosses(gl, gr, ev_dir[i]):
                                cands.append((i, gl, tl))
                        if not cands:
                            continue
                        if not dense:
                            make_dense()
                            dense = True
                        Pk = P3[:, :, k].copy()
                        yk = y2[:, k].copy()
                        T_try = t.copy()    # other columns: their current (valid) states
                        Y_try = y2.copy()

                        def interp_k(tt: float, Pk=Pk, yk=yk, tk=tk, hk=hk) -> np.ndarray:
                            x = (tt - tk) / hk
                            xp = [x]
                            for _ in range(INTERPOLATOR_POWER - 1):
                                xp.append(xp[-1] * x)
                            return np.dot(xp, Pk) + yk

                        def g_col(i: int, tt: float, k=k, T_try=T_try, Y_try=Y_try, interp_k=interp_k) -> float:
                            T_try[k] = tt
                            Y_try[:, k] = interp_k(tt)
                            return float(np.asarray(ev_fns[i](T_try, Y_try), dtype=float).reshape(-1)[k])

                        # earliest root over this column's events (as `dop853` over all columns)
                        best_t = tk_new
                        hit = None
                        done_here = handled.get(k, ())
                        t_same = tk + SIMULTANEOUS * max(1.0, abs(tk))
                        for i, gl, tl in cands:
                            if tl >= best_t:
                                continue
                            if best_t == tk_new:
                                gr = float(g_new[i][k])
                            else:
                                gr = g_col(i, best_t)
                                if not _crosses(gl, gr, ev_dir[i]):
                                    continue
                            root = _brentq(lambda tt, i=i: g_col(i, tt), tl, best_t, gl, gr)
                            if i in done_here and root <= t_same:
                                continue  # the crossing handled at the restart
                            if hit is None or root < best_t:
                                best_t = root
                                hit = i
                        if hit is None:
                            continue
                        # other events of this column crossing at (about) the same time fire with it:
                        # after a restart at this root their values would already be past zero
                        fired = [hit]
                        t_near = min(tk_new, best_t + SIMULTANEOUS * max(1.0, abs(best_t)))
                        for i, gl, tl in cands:
                            if i in fired or tl > t_near or (i in done_here and best_t <= t_same):
                                continue
                            if _crosses(gl, g_col(i, t_near), ev_dir[i]):
                                fired.append(i)
                        y_root = ynew2[:, k].copy() if best_t == tk_new else interp_k(best_t)
                        # the fired events at the root before the callbacks: an event whose value
                        # the callbacks leave alone has been crossed; one they change (a new branch)
                        # is watched again from zero there
                        T_try[k] = best_t
                        Y_try[:, k] = y_root
                        g_pre = [float(np.asarray(ev_fns[i](T_try, Y_try), dtype=float).reshape(-1)[k])
                                 for i in fired]
                        stop = False
                        for i in fired:
                            found.append((i, k, best_t, y_root.copy()))
                            n_ev_col[k] += 1
                            if n_ev_col[k] > max_events_per_column:
                                return failure(k, f"more than {max_events_per_column} events in trajectory {k} "
                                                  f"(chattering between branches), the last at t = {best_t:.17g}",
                                               best_t)
                            cb = events[i].on_event
                            if cb is None or cb(k, best_t, y_root.copy()):
                                stop = True
                        cuts.append((k, best_t, y_root, stop, list(zip(fired, g_pre))))

                # ---- output samples in (t_k, t_cut_k] of the accepted columns, all at once
                if cuts:
                    t_cut = t_next.copy()
                    for k, root, *_ in cuts:
                        t_cut[k] = root
                else:
                    t_cut = t_next
                cnt = np.searchsorted(t_eval, t_cut, side="right")
                cnt -= i_eval
                cnt *= accepted                       # samples per column in its step
                n_samples = int(cnt.sum())
                if n_samples:
                    cr = np.repeat(columns, cnt)      # (column, sample) of each of them
                    sidx = np.arange(n_samples) + np.repeat(i_eval - (np.cumsum(cnt) - cnt), cnt)
                    te = t_eval[sidx]
                    inner = te < t_new[cr]            # at the step end: y_new itself
                    if inner.any():
                        if not dense:
                            make_dense()
                            dense = True
                        X = ((te - t[cr]) / h[cr])[:, None] ** _POWERS
                        vals = np.einsum("mp,pdm->dm", X, P3[:, :, cr]) + y2[:, cr]
                        at_end = ~inner
                        if at_end.any():
                            vals[:, at_end] = ynew2[:, cr[at_end]]
                    else:
                        vals = ynew2[:, cr]
                    out[:, cr, sidx] = vals
                    i_eval += cnt
            except _Budget:
                return over_budget()

            # ---- advance every column to its new state
            y_old[...] = ynew
            t = t_next
            if handled:
                for k in [k for k in handled if accepted[k]]:
                    del handled[k]
            for i in range(n_events):   # only where a step was accepted: a restart's 0 must survive rejections
                copyto(g_old[i], g_new[i], where=accepted)
            if cuts:
                restart = np.zeros(K, dtype=bool)
                for k, root, y_root, stop, fired in cuts:
                    y2[:, k] = y_root
                    t[k] = root
                    absa_old2[:, k] = np.abs(y_root) + a_r
                    if stop:
                        active[k] = False
                        t_stop[k] = root
                        F0[:, k] = 0.0
                        out[:, k, i_eval[k]:] = y_root[:, None]
                        i_eval[k] = n_eval
                    else:
                        restart[k] = True
                        h_abs[k] = h[k]   # the step size of the step that held the root
                if restart.any():
                    need_f0 |= restart
                    restarted = True
                    for i in range(n_events):   # the callbacks may have changed the event functions too
                        copyto(g_old[i], g_all(i, t, y2), where=restart)
                    for k, root, y_root, stop, fired in cuts:
                        if stop:
                            continue
                        for i, g_before in fired:
                            if g_old[i][k] == g_before:
                                # unchanged: the crossing is behind; a root of it at the restart
                                # time (it is only known to rounding) is this one again
                                handled.setdefault(k, []).append(i)
                            else:
                                # a new branch: the event starts from zero there, so leaving zero in
                                # the watched direction fires at once (chattering shows as events)
                                g_old[i][k] = 0.0
            active &= t < t_end
            if not active.any():
                break

    return result(0, "every trajectory reached the end of the interval or stopped at an event")
