"""The work-precision sweep measures what grading runs, and gives scipy a fair run (one small sweep:
the pendulum 12.43, K = 2 states, tolerances 1e-4 and 1e-10)."""

from __future__ import annotations

import numpy as np
import pytest
from markdown_it import MarkdownIt

from lagrade.compare import trajectory
from lagrade.compare.trajectory import ACCURACY, compare_runs
from lagrade.numbers.numeric import CompiledRates, is_machine_code
from lagrade.uses.research import workprecision as wp
from lagrade.compare.scene_model import scene_model

TOLS = (1e-4, 1e-10)
K = 2
REPEAT = 3


@pytest.fixture(scope="module")
def spied():
    """One sweep, with every call of `integrate` and `solve_ivp` it makes recorded (the grading rows'
    through `scene_motion`, the entry every integrated path of grading shares)."""
    calls = {"integrate": [], "solve_ivp": []}
    real_integrate, real_solve = wp.integrate, wp.solve_ivp

    def integrate(rates, y0, horizon, acc, *args, **kw):
        calls["integrate"].append((rates, y0.shape, acc, kw.get("method"), kw.get("t_eval")))
        return real_integrate(rates, y0, horizon, acc, *args, **kw)

    def solve_ivp(fun, span, y0, method, **kw):
        sol = real_solve(fun, span, y0, method=method, **kw)
        calls["solve_ivp"].append((method, kw["rtol"], np.shape(y0), sol.nfev))
        return sol

    mp = pytest.MonkeyPatch()
    mp.setattr(wp, "integrate", integrate)
    # the grading row runs the grading path's entry (`scene_motion`), which calls `integrate` from there
    mp.setattr(trajectory, "integrate", integrate)
    mp.setattr(wp, "solve_ivp", solve_ivp)
    try:
        sc = wp.scene("12.43", K=K)
        sw = wp.sweep(sc, TOLS, (*wp.METHODS, "numpy"), repeat=REPEAT)
    finally:
        mp.undo()
    return sw, calls


def test_the_grading_path_is_timed_on_the_objects_grading_uses(spied):
    sw, calls = spied
    grading = [r for r in sw.rows if r.method == "grading"]
    # the swept tolerances and every preset's own
    assert sorted(r.tol for r in grading) == sorted({*TOLS, *(ACCURACY[p].rtol for p in wp.PRESETS)})
    assert {r.label for r in grading} == {"lagrade (grading path, DOP853 compiled)"}
    runs = [c for c in calls["integrate"] if is_machine_code(c[0].f)]
    assert len(runs) == len(grading) * (REPEAT + 1)   # one untimed run, then the timed ones
    for rates, shape, _acc, method, t_eval in runs:
        assert is_machine_code(rates.f), "the grading path must run the compiled rates"
        assert shape == (2, K) and method == "DOP853" and t_eval.size == 201
    # the numpy series is the same integrator on rates that are numpy code, and says so
    numpy_runs = [c for c in calls["integrate"] if not is_machine_code(c[0].f)]
    assert numpy_runs and all(isinstance(c[0], CompiledRates) for c in numpy_runs)
    assert {r.label for r in sw.rows if r.method == "numpy"} == {wp.LABELS["numpy"]}
    assert "not the grading path" in wp.LABELS["numpy"]


def test_grading_path_costs_what_compare_runs_costs(spied):
    """An answer equal to the reference, graded by `compare_runs` at the default preset: its reference
    run and its student run each cost what the sweep's default row counts (plus the stiffness estimate)."""
    sw, _ = spied
    sc = sw.scene
    row = next(r for r in sw.rows if r.preset == "default")
    rates = scene_model(sc.mech).compiled_rates(sc.params)
    cmp = compare_runs(rates, rates, sc.y0, ["theta", "theta'"], sc.horizon, ACCURACY["default"], chaos=False)
    assert cmp.agree
    dim = sc.y0.shape[0]
    assert cmp.rhs_evals == (dim + 1) + 2 * row.per_call_evals[0]
    assert row.rhs_evals == row.per_call_evals[0] * K


def test_scipy_integrates_one_trajectory_per_call(spied):
    sw, calls = spied
    for method in wp.SCIPY:
        for tol in TOLS:
            made = [c for c in calls["solve_ivp"] if c[0] == method and c[1] == tol]
            assert len(made) == K * (REPEAT + 1)
            assert all(shape == (2,) for _, _, shape, _ in made), "one state per solve_ivp call"
            row = next(r for r in sw.rows if r.method == method and r.tol == tol)
            assert row.calls == K and len(row.per_call_evals) == K
            assert row.rhs_evals == sum(row.per_call_evals)
            nfev = [n for *_, n in made[-K:]]
            if method in ("RK45", "DOP853"):   # explicit: every evaluation is scipy's nfev
                assert row.per_call_evals == nfev
            else:                               # implicit: the Jacobian's differences are counted too
                assert all(e >= n for e, n in zip(row.per_call_evals, nfev))
            assert len(row.runs) == REPEAT and row.seconds == pytest.approx(np.median(row.runs))


def test_errors_follow_the_tolerance(spied):
    sw, _ = spied
    for method in ("grading", *wp.SCIPY):
        loose, tight = (next(r for r in sw.rows if r.method == method and r.tol == t) for t in TOLS)
        assert loose.ok and tight.ok
        assert tight.error < 1e-7 < loose.error * 1e3 and tight.error < loose.error


def test_the_reference_is_not_a_candidate(spied):
    sw, calls = spied
    made = sorted(c[0] for c in calls["solve_ivp"] if c[1] == wp.REFERENCE_TOL)
    assert made == sorted([wp.REFERENCE_METHOD] * K + [wp.CHECK_METHOD] * K)   # per trajectory, untimed
    assert all((r.method, r.tol) != (wp.REFERENCE_METHOD, wp.REFERENCE_TOL) for r in sw.rows)
    assert all(r.tol > wp.REFERENCE_TOL for r in sw.rows)
    assert sw.method != wp.REFERENCE_METHOD   # the grading path does not run the reference's method
    # independent checks of the reference: another method, and 12.43's closed form
    assert sw.reference.check < 1e-10
    assert sw.reference.closed_form is not None and sw.reference.closed_form < 1e-10
    assert "Radau at rtol = atol = 1e-13" in sw.reference.describe()
    with pytest.raises(ValueError, match="reference"):
        wp.sweep(sw.scene, (1e-4, wp.REFERENCE_TOL), ("grading",), repeat=1)


def test_presets_are_marked_once_each(spied, tmp_path):
    sw, _ = spied
    marked = {r.preset: r for r in sw.rows if r.preset}
    assert set(marked) == set(wp.PRESETS) and len(sw.presets()) == len(wp.PRESETS)
    for name, r in marked.items():
        assert r.method == "grading" and r.tol == ACCURACY[name].rtol and r.ok
    wp.write_csv([sw], tmp_path / "a.csv")
    import csv

    rows = list(csv.DictReader((tmp_path / "a.csv").open()))
    assert sorted(r["preset"] for r in rows if r["preset"]) == sorted(wp.PRESETS)
    assert all(r["method"] == "grading" for r in rows if r["preset"])


def test_markdown_parses_into_one_table_of_the_rows(spied):
    sw, _ = spied
    tokens = MarkdownIt("commonmark").enable("table").parse(wp.markdown(sw))
    cells, row, head = [], None, []
    in_head = False
    for i, tok in enumerate(tokens):
        if tok.type == "thead_open":
            in_head = True
        elif tok.type == "thead_close":
            in_head = False
        elif tok.type == "tr_open":
            row = []
        elif tok.type == "tr_close":
            (head if in_head else cells).append(row)
        elif tok.type == "inline" and row is not None and tokens[i - 1].type in ("th_open", "td_open"):
            row.append(tok.content)
    assert head == [list(wp.MARKDOWN_COLUMNS)]
    assert len(cells) == len(sw.rows)
    for cell, r in zip(cells, wp.by_tolerance(sw)):
        assert len(cell) == len(wp.MARKDOWN_COLUMNS)
        assert float(cell[1]) == pytest.approx(r.tol) and float(cell[2]) == pytest.approx(r.error, rel=0.06)
        assert int(cell[4]) == r.rhs_evals and cell[6] == r.preset
