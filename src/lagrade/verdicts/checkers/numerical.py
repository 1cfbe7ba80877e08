"""A solution with no closed form: q(t) given as a sampled table (or an expression), against the
reference motion integrated from the part's stated numbers.

Where the equations of motion cannot be solved in elementary functions (12.50), "solve" means a
numerical solution, so the part fixes the numbers (parameter values in ``reference``, the initial
state in ``initial``, the time window in ``domain``) and the student gives q at times of their
choice. Agreement is judged relative to the motion's own scale, so a table typed to four
significant figures passes and a wrong force does not; the feedback says where the table departs,
never what the right value is.
"""

from __future__ import annotations

import numbers

import numpy as np
import sympy as sp

from lagrade.verdicts.checkers.base import (
    Context,
    InvalidAnswer,
    as_expr,
    graded,
    keyed,
    read_sympy,
)
from lagrade.numbers.numeric import evaluate
from lagrade.derive.reference import Mechanics
from lagrade.verdicts.result import PartResult
from lagrade.problem.spec import Part
from lagrade.problem.symbols import T

#: agreement with the reference, relative to the scale of the motion (its largest value or range)
RTOL = 1e-3
#: a table must give at least this many distinct times, reaching at least half the window
MIN_TIMES = 5
#: times at which an expression answer is compared
GRID = 41
#: the longest table graded (each time is a point of the reference integration)
MAX_TIMES = 2000


def _number(value: object, what: str, part: Part) -> float:
    if isinstance(value, bool):
        raise InvalidAnswer(f"{part.name}: {what} should be a number, not {value!r}")
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, str):
        try:
            return float(value)
        except ValueError:
            pass
    if isinstance(value, sp.Basic) and value.is_number:
        try:
            return float(value)
        except (TypeError, ValueError):
            pass
    raise InvalidAnswer(f"{part.name}: {what} should be a number, not {str(value)[:40]!r}")


def _is_number(value: object) -> bool:
    try:
        float(value)  # type: ignore[arg-type]
        return not isinstance(value, bool)
    except (TypeError, ValueError):
        return False


def read_table(part: Part, mech: Mechanics, value: object) -> tuple[np.ndarray, np.ndarray] | dict[str, object]:
    """The student's solution: (times (N,), values (n, N)) for a table, or {coordinate: expression}.

    Tables: ``{"t": [...], "x": [...]}``; rows ``[[t, x], ...]`` (coordinates in the problem's order);
    ``{t: x}`` for one coordinate (what a TOML answer can write: ``{ "0.5" = "1.118" }``);
    ``{"x": {t: x}}``. Expressions: ``{"x": expr in t}`` (or the bare expression for one coordinate)."""
    names = list(mech.names)
    shape = (f"{part.name} should be a table of the motion, {{'t': [times], "
             f"{', '.join(repr(n) + ': [values]' for n in names)}}}, or rows [t, {', '.join(names)}], "
             f"or a dict coordinate -> expression in t")
    if isinstance(value, (list, tuple)):
        rows = [list(r) if isinstance(r, (list, tuple)) else None for r in value]
        if not rows or any(r is None or len(r) != len(names) + 1 for r in rows):
            raise InvalidAnswer(shape)
        data = np.array([[_number(x, f"row {i + 1}", part) for x in r] for i, r in enumerate(rows)])
        return data[:, 0], data[:, 1:].T
    if isinstance(value, sp.Basic) and not isinstance(value, sp.Equality) and len(names) == 1:
        return {names[0]: value}
    if not isinstance(value, dict) or not value:
        raise InvalidAnswer(shape)
    if len(names) == 1 and all(_is_number(k) for k in value):
        times = [_number(k, "a time", part) for k in value]
        vals = [_number(v, f"the value at t = {k}", part) for k, v in value.items()]
        return np.array(times), np.array([vals])
    given = keyed(value, part)
    unknown = sorted(set(given) - {*names, "t"})
    if unknown:
        raise InvalidAnswer(f"{part.name} has unknown keys {unknown}; " + shape)
    missing = [n for n in names if n not in given]
    if missing:
        raise InvalidAnswer(f"{part.name} is missing {', '.join(missing)}")
    if "t" in given:
        times = given["t"]
        if not isinstance(times, (list, tuple)) or any(not isinstance(given[n], (list, tuple)) for n in names):
            raise InvalidAnswer(shape)
        if any(len(given[n]) != len(times) for n in names):
            raise InvalidAnswer(f"{part.name}: each list of values must have one entry per time ({len(times)})")
        t = np.array([_number(x, f"time {i + 1}", part) for i, x in enumerate(times)])
        vals = np.array([[_number(x, f"{n} at time {i + 1}", part) for i, x in enumerate(given[n])] for n in names])
        return t, vals
    if all(isinstance(given[n], dict) for n in names):
        keys = [sorted(_number(k, "a time", part) for k in given[n]) for n in names]
        if any(k != keys[0] for k in keys):
            raise InvalidAnswer(f"{part.name}: give every coordinate at the same times")
        t = np.array(keys[0])
        vals = np.array([[_number(v, f"{n} at t = {k}", part) for k, v in
                          sorted(((_number(k, "a time", part), v) for k, v in given[n].items()), key=lambda kv: kv[0])]
                         for n in names])
        return t, vals
    return {n: given[n] for n in names}


def reads_as_motion(ctx: Context, part: Part, value: object) -> bool:
    """Whether ``value`` (bound to another part) is a motion at ``part``'s numbers: a table, or
    expressions in t and the parameters alone, with no symbol the other part's own answer needs
    (12.41's theta0). What ``also_answered_by`` grades as ``part``: the exact pendulum motion written
    under the catalogue's name ``solution_b``, while a symbolic small-angle solution stays there."""
    mech = ctx.mech(part)
    try:
        got = read_table(part, mech, value)
    except (InvalidAnswer, TypeError, ValueError):
        return False
    if not isinstance(got, dict):
        return True
    allowed = {"t", *(p.name for p in mech.parameters)}
    return all(isinstance(e, sp.Basic) and {s.name for s in e.free_symbols} <= allowed for e in got.values())


def _numbers(part: Part, mech: Mechanics) -> tuple[np.ndarray, np.ndarray, tuple[float, float]]:
    """The part's parameter values, initial state (q, q') and time window, from the problem file."""
    ref = part.reference if isinstance(part.reference, dict) else {}
    params = np.array([float(mech.parse(str(ref[p.name]))) for p in mech.parameters]) if all(
        p.name in ref for p in mech.parameters) else None
    keys = [*mech.names, *(f"{n}_d" for n in mech.names)]
    if params is None or any(k not in part.initial for k in keys):
        raise ValueError(f"part {part.name}: a numerical_solution part needs every parameter's value in "
                         "`reference` and the whole initial state in `initial`")
    y0 = np.array([float(mech.parse(part.initial[k])) for k in keys])
    window = part.domain or (0.0, mech.system.horizon)
    return params, y0, (float(window[0]), float(window[1]))


def _reference_at(ctx: Context, mech: Mechanics, params: np.ndarray, y0: np.ndarray, t0: float,
                  times: np.ndarray) -> np.ndarray:
    """q of the reference motion at ``times`` (sorted, >= t0), integrated from y0 at t0: (n, N). The
    scene's model with its declared events (`scene_motion`, as every path integrates it); a time past
    a lost contact has no reference (the scene's model ends there): NaN, said by the caller."""
    from lagrade.compare.scene_model import scene_motion

    n = len(mech.names)
    span = float(times[-1] - t0)
    grid = np.unique(np.concatenate([[0.0], times - t0]))
    run = scene_motion(mech, y0.reshape(-1, 1), params.reshape(-1, 1), max(span, 1e-12), ctx.accuracy,
                       t_eval=grid, t0=t0)
    if not run.ok or run.t.size != grid.size:
        raise RuntimeError(f"the reference motion could not be integrated: {run.message}")
    at = np.searchsorted(grid, times - t0)
    out = run.y[:n, 0, at]
    return np.where(grid[at] <= run.t_stop[0] + 1e-12, out, np.nan)


def check_numerical_solution(ctx: Context, part: Part, value: object) -> PartResult:
    mech = ctx.mech(part)
    params, y0, (t0, t1) = _numbers(part, mech)
    got = read_table(part, mech, value)
    if isinstance(got, dict):  # expressions in t, at the part's parameter values
        subs = {sp.Symbol(p.name): v for p, v in zip(mech.parameters, params)}
        times = np.linspace(t0, t1, GRID)
        exprs = [read_sympy(as_expr(got[n], part), part, mech, plain_coordinates=False, max_order=0).xreplace(subs)
                 for n in mech.names]
        stray = sorted(str(s) for e in exprs for s in e.free_symbols if s != T)
        if stray:
            raise InvalidAnswer(f"{part.name}: an expression in t only (and the parameters), not {', '.join(stray)}")
        with np.errstate(all="ignore"):
            vals = evaluate(exprs, [T], [times]).reshape(len(mech.names), -1)
        what = "your solution"
    else:
        times, vals = got
        order = np.argsort(times, kind="stable")
        times, vals = times[order], vals[:, order]
        if times.size > MAX_TIMES:
            raise InvalidAnswer(f"{part.name}: a table of {times.size} times is too long; give {MAX_TIMES} or fewer")
        if not np.all(np.isfinite(times)):
            raise InvalidAnswer(f"{part.name}: every time of the table must be a finite number")
        if np.any(np.diff(times) == 0):
            raise InvalidAnswer(f"{part.name}: a time appears twice in the table")
        if times[0] < t0 - 1e-12 or times[-1] > t1 + 1e-9 * max(abs(t1), 1.0):
            raise InvalidAnswer(f"{part.name}: give times between {t0:g} and {t1:g} (the window the part asks)")
        if times.size < MIN_TIMES or times[-1] < t0 + (t1 - t0) / 2:
            raise InvalidAnswer(f"{part.name}: give the motion at {MIN_TIMES} times or more, reaching at least "
                                f"t = {t0 + (t1 - t0) / 2:g} (the window is {t0:g} to {t1:g})")
        what = "your table"
    ref = _reference_at(ctx, mech, params, y0, t0, times)
    modelled = np.isfinite(ref).all(axis=0)   # not past a lost contact: the scene's model ends there
    if not modelled.any():
        raise RuntimeError("the scene's model ends (its contact is lost) before the first time compared")
    scale = np.maximum(np.abs(ref[:, modelled]).max(axis=1), np.ptp(ref[:, modelled], axis=1))
    scale = np.where(scale > 0, scale, 1.0)[:, None]
    off = ~(np.abs(vals - ref) <= RTOL * scale) & modelled  # NaN of the answer counts as off
    if not off.any():
        return graded(part, 1.0, "numeric", f"correct: {what} follows the motion at all {times.size} times "
                                            f"(within {RTOL:.1%} of its scale).")
    bad = np.flatnonzero(off.any(axis=0))
    coords = [n for n, row in zip(mech.names, off) if row.any()]
    which = f" ({', '.join(coords)})" if len(mech.names) > 1 else ""
    return graded(part, 0.0, "numeric",
                  f"Incorrect: {what} departs from the motion{which} from t = {times[bad[0]]:.4g} on: "
                  f"{bad.size} of the {times.size} times compared are off by more than {RTOL:.1%} of the motion's "
                  f"scale.")
