"""Work-precision sweep: what accuracy costs in time, per scene and per integration method.

For one scene (a problem's system) K states are sampled from its physical domain (the grader's
sampler, fixed seed); every method integrates the same batched right-hand side (the scene model
assembled from its declared effects) over the scene's horizon at each tolerance, and its error is
measured against a reference solution of much higher accuracy:

- reference: DOP853 at rtol = atol = 1e-13, cross-checked against Radau at 1e-13 (an independent,
  implicit method; their largest difference is reported as ``reference_check``) and, for the simple
  pendulum 12.43, against the closed form (Jacobi elliptic functions) for a trajectory released from rest;
- error: the largest ``|y - y_ref| / (1 + |y_ref|)`` over the sampled times, components and trajectories;
- cost: wall time (best of ``repeat``) and right-hand-side evaluations (Jacobian evaluations of the
  implicit methods counted as the evaluations their finite differences take).

Methods: scipy's RK45, DOP853, Radau, LSODA, and for conservative scenes a symplectic method (Stormer-
Verlet for a constant mass matrix, otherwise the implicit midpoint rule; both composed to order 4), whose
fixed step is chosen from the tolerance as h = horizon / ceil(2 * horizon * tol**(-1/4)).
"""

from __future__ import annotations

import csv
import math
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from lagrade.compare.trajectory import ACCURACY, Accuracy, integrate
from lagrade.library import load_problem
from lagrade.scene_model import SceneModel
from lagrade.research.symplectic import StormerVerlet, hamilton_rates, implicit_midpoint, is_conservative, is_separable
from lagrade.reference import Mechanics
from lagrade.sampling import rng_for, sample_points, state_arrays

TOLERANCES = tuple(10.0 ** -e for e in range(3, 13))
METHODS = ("RK45", "DOP853", "Radau", "LSODA", "symplectic")
SAMPLES = 41


@dataclass
class Scene:
    pid: str
    key: str
    mech: Mechanics
    model: SceneModel
    params: np.ndarray
    y0: np.ndarray
    horizon: float
    label: str = ""


def scene(pid: str, key: str | None = None, K: int = 4, horizon: float | None = None) -> Scene:
    """The states the sweep integrates: K sampled states of the scene (12.43 adds one released from rest)."""
    problem = load_problem(pid)
    system = problem.systems[0] if key is None else problem.system(key)
    mech = Mechanics(problem, system)
    pts = sample_points(mech, K, rng_for(pid, system.key, "bench"))
    q, qd, _, params = state_arrays(mech, pts)
    y0 = np.concatenate([q, qd])
    if pid == "12.43":
        y0[1, 0] = 0.0      # released from rest: the closed form (elliptic functions) checks the reference
    return Scene(pid, system.key, mech, SceneModel(mech), params, y0, horizon or system.horizon,
                 f"{pid}{system.key}: {problem.title}")


@dataclass
class Row:
    scene: str
    method: str
    tol: float
    error: float
    seconds: float
    rhs_evals: int
    ok: bool = True
    note: str = ""


@dataclass
class Sweep:
    scene: Scene
    rows: list[Row]
    reference_check: float
    closed_form_check: float | None
    reference_seconds: float
    default: Row | None = None
    notes: list[str] = field(default_factory=list)


def _acc(tol: float) -> Accuracy:
    return replace(ACCURACY["default"], name=f"tol {tol:g}", rtol=tol, atol=tol, max_rhs_evals=5_000_000,
                   method="DOP853")


def _error(y: np.ndarray, y_ref: np.ndarray) -> float:
    if y.shape != y_ref.shape or not np.all(np.isfinite(y)):
        return float("inf")
    return float((np.abs(y - y_ref) / (1.0 + np.abs(y_ref))).max())


def reference(sc: Scene, t_eval: np.ndarray) -> tuple[np.ndarray, float, float | None, float]:
    """(y_ref, max difference DOP853 vs Radau at 1e-13, closed-form check or None, seconds)."""
    rates = sc.model.rates(sc.params)
    start = time.perf_counter()
    ref = integrate(rates, sc.y0, sc.horizon, _acc(1e-13), t_eval=t_eval, guard=False)
    seconds = time.perf_counter() - start
    radau = integrate(rates, sc.y0, sc.horizon, _acc(1e-13), method="Radau", t_eval=t_eval, guard=False)
    check = _error(radau.y, ref.y) if radau.ok else float("nan")
    closed = _closed_form_check(sc, t_eval, ref.y) if sc.pid == "12.43" else None
    return ref.y, check, closed, seconds


def _closed_form_check(sc: Scene, t_eval: np.ndarray, y_ref: np.ndarray) -> float | None:
    """Simple pendulum released from rest at theta0: sin(theta/2) = k cd(omega t | k^2), k = sin(theta0/2)."""
    from scipy.special import ellipj

    names = [str(p) for p in sc.mech.params]
    g, l = sc.params[names.index("g")], sc.params[names.index("l")]
    worst = None
    for k in range(sc.y0.shape[1]):
        if abs(sc.y0[1, k]) > 0 or abs(sc.y0[0, k]) >= math.pi:
            continue
        kk = math.sin(sc.y0[0, k] / 2)
        sn, cn, dn, _ = ellipj(np.sqrt(g[k] / l[k]) * t_eval, kk ** 2)
        theta = 2 * np.arcsin(kk * cn / dn)
        err = float(np.abs(theta - y_ref[0, k]).max())
        worst = err if worst is None else max(worst, err)
    return worst


def _timed(fn, repeat: int):
    best, out = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - start)
    return out, best


def sweep(sc: Scene, tolerances=TOLERANCES, methods=METHODS, repeat: int = 1) -> Sweep:
    t_eval = np.linspace(0.0, sc.horizon, SAMPLES)
    y_ref, check, closed, ref_s = reference(sc, t_eval)
    rates = sc.model.rates(sc.params)
    rows: list[Row] = []
    label = f"{sc.pid}{sc.key}"
    notes = []
    for method in methods:
        if method == "symplectic":
            if not is_conservative(sc.mech):
                notes.append("symplectic: skipped (the scene is not conservative)")
                continue
            for tol in tolerances:
                rows.append(_symplectic_row(sc, tol, t_eval, y_ref, repeat, label))
            continue
        for tol in tolerances:
            run, secs = _timed(lambda: integrate(rates, sc.y0, sc.horizon, _acc(tol), method=method,
                                                 t_eval=t_eval, guard=False), repeat)
            err = _error(run.y, y_ref) if run.ok else float("inf")
            rows.append(Row(label, method, tol, err, secs, run.rhs_evals, run.ok, "" if run.ok else run.message))
    dflt = ACCURACY["default"]
    default = next((r for r in rows if r.method == "DOP853" and r.tol == dflt.rtol), None)
    if default is None:
        run, secs = _timed(lambda: integrate(rates, sc.y0, sc.horizon, dflt, t_eval=t_eval, guard=False), repeat)
        default = Row(label, f"default ({run.method})", dflt.rtol, _error(run.y, y_ref), secs, run.rhs_evals, run.ok)
    return Sweep(sc, rows, check, closed, ref_s, default, notes)


def _symplectic_row(sc: Scene, tol: float, t_eval: np.ndarray, y_ref: np.ndarray, repeat: int, label: str) -> Row:
    mech = sc.mech
    n = len(mech.names)
    steps = math.ceil(2 * sc.horizon * tol ** (-1 / 4))
    steps = math.ceil(steps / (SAMPLES - 1)) * (SAMPLES - 1)
    h = sc.horizon / steps
    every = steps // (SAMPLES - 1)
    q0, qd0 = sc.y0[:n], sc.y0[n:]
    p0 = mech.momenta(q0, qd0, np.zeros(q0.shape[1]), sc.params)
    if is_separable(mech):
        sv = StormerVerlet(mech)
        res, secs = _timed(lambda: sv.run(q0, p0, sc.params, h, steps, every, order=4), repeat)
        q, p, evals, name = res.q, res.p, res.force_evals, "symplectic"
    else:
        rates = hamilton_rates(mech, sc.params)
        res, secs = _timed(lambda: implicit_midpoint(rates, np.concatenate([q0, p0]), h, steps, every, order=4),
                           repeat)
        _, Y, evals, _ = res
        q, p = Y[:n], Y[n:]
        name = "symplectic"
    K, Tn = q.shape[1], q.shape[2]
    qd = np.stack([mech.velocities(q[..., i], p[..., i], np.full(K, t_eval[i]), sc.params) for i in range(Tn)], -1)
    y = np.concatenate([q, qd])
    return Row(label, name, tol, _error(y, y_ref), secs, evals, True, f"h = {h:.3g}")


# ----------------------------------------------------------------------------- output


def table(sw: Sweep) -> str:
    lines = [f"scene {sw.scene.label}",
             f"  {sw.scene.y0.shape[1]} trajectories over t in [0, {sw.scene.horizon:g}], {SAMPLES} sampled times",
             f"  reference: DOP853 at rtol = atol = 1e-13 ({sw.reference_seconds * 1e3:.0f} ms); "
             f"Radau at 1e-13 differs from it by {sw.reference_check:.1e}"
             + (f"; closed form (elliptic functions) differs by {sw.closed_form_check:.1e}"
                if sw.closed_form_check is not None else ""),
             f"  {'method':<11} {'tol':>7} {'error':>9} {'time ms':>9} {'rhs evals':>10}"]
    for r in sw.rows:
        mark = "  <- grader default" if sw.default is r else ""
        err = f"{r.error:9.1e}" if math.isfinite(r.error) else "   failed"
        lines.append(f"  {r.method:<11} {r.tol:7.0e} {err} {r.seconds * 1e3:9.1f} {r.rhs_evals:10d}{mark}")
    if sw.default is not None and sw.default not in sw.rows:
        r = sw.default
        lines.append(f"  {r.method:<11} {r.tol:7.0e} {r.error:9.1e} {r.seconds * 1e3:9.1f} {r.rhs_evals:10d}  <- grader default")
    lines += [f"  {n}" for n in sw.notes]
    return "\n".join(lines)


def write_csv(sweeps: list[Sweep], path: Path) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["scene", "method", "tol", "error", "seconds", "rhs_evals", "ok", "grader_default", "note"])
        for sw in sweeps:
            for r in sw.rows:
                w.writerow([r.scene, r.method, f"{r.tol:.0e}", f"{r.error:.3e}", f"{r.seconds:.6f}", r.rhs_evals,
                            int(r.ok), int(r is sw.default), r.note])


def plot(sweeps: list[Sweep], path: Path) -> None:
    """Work-precision diagram: error against time, log-log, one curve per method, the default marked."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(sweeps), figsize=(6.2 * len(sweeps), 4.8), squeeze=False)
    colors = {"RK45": "tab:blue", "DOP853": "tab:green", "Radau": "tab:red", "LSODA": "tab:purple",
              "symplectic": "tab:orange"}
    for ax, sw in zip(axes[0], sweeps):
        for method in dict.fromkeys(r.method for r in sw.rows):
            rs = [r for r in sw.rows if r.method == method and math.isfinite(r.error) and r.error > 0]
            if not rs:
                continue
            ax.loglog([r.seconds for r in rs], [r.error for r in rs], "o-", ms=3.5, lw=1.3,
                      color=colors.get(method), label=method)
        d = sw.default
        if d is not None and math.isfinite(d.error):
            ax.loglog([d.seconds], [max(d.error, 1e-17)], marker="*", ms=16, color="gold", mec="black",
                      ls="none", label=f"grader default (DOP853, rtol {d.tol:g})", zorder=5)
        ax.axhline(ACCURACY["default"].compare_rtol, color="gray", ls=":", lw=1)
        ax.annotate("comparison tolerance", (ax.get_xlim()[0], ACCURACY["default"].compare_rtol), fontsize=7,
                    color="gray", va="bottom")
        ax.set_xlabel("wall time per batched integration (s)")
        ax.set_ylabel("max error vs reference")
        ax.set_title(sw.scene.label, fontsize=9)
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=7, loc="best")
    fig.suptitle("Work-precision (tolerances 1e-3 ... 1e-12)", fontsize=10)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)
