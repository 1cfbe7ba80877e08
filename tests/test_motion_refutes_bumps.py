"""The bump family (issue 45, item 1): answers wrong only in a narrow region of the states or of t,
which no sampled state meets, are refused by the motion itself. From the same grading states the
student's motion separates from the true one beyond the comparison tolerance, and the separation is
re-measured at a 100x finer integration tolerance, beyond the integration's error estimate: that
evidence (the time, the separation, the error estimate, the tolerances) is the certificate, carried in
`--json` (``motion_evidence``) and the gradebook.

Why it used to pass: DOP853 sees the rates only at its stages. A bump 2e-3 wide in theta is crossed in
about a millisecond, between stages 0.05 s apart, so the student's run stepped over it and the motions
"agreed"; a kick in t was half-seen, and its separation did not survive the finer tolerance.
`trajectory.rate_scan` now finds where the rates differ along the reference motion, and the student's
run steps finely there (`dop853.solve`'s ``caps``)."""

from __future__ import annotations

from pathlib import Path

import pytest

import lagrade
from lagrade.compare import exact
from lagrade.verdicts.checkers import admit

L14 = ("(m1 + m2)*l1^2*theta1_d^2/2 + m2*l2^2*theta2_d^2/2 + m2*l1*l2*theta1_d*theta2_d*cos(theta1 - theta2)"
       " + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2)")
EOM14 = ('eom_exact = ["(m1 + m2)*l1*theta1_dd + m2*l2*(theta2_dd*cos(theta1 - theta2) + theta2_d^2*sin(theta1 - '
         'theta2)) == -(m1 + m2)*g*sin(theta1) + g*{bump}", "l2*theta2_dd + l1*(theta1_dd*cos(theta1 - theta2) - '
         'theta1_d^2*sin(theta1 - theta2)) == -g*sin(theta2)"]')


def _eom43(bump: str) -> str:
    return f'eom = "theta_dd == -g/l*sin(theta) + g/l*{bump}"'


#: name -> (problem, part, the answer file): five shapes in 12.43's eom, its H and Hamilton's
#: equations, and 12.14's eom and L
FAMILY = {
    "narrow gaussian in theta": ("12.43", "eom", _eom43("exp(-10**6*(theta - 1/3)**2)")),
    "wider gaussian / 1000": ("12.43", "eom", _eom43("exp(-10**4*(theta - 1/3)**2)/1000")),
    "kick in t": ("12.43", "eom", _eom43("exp(-10**4*(t - 3/2)**2)/100")),
    "bump in the velocity": ("12.43", "eom", _eom43("exp(-10**4*(theta_d - 1/2)**2)/1000")),
    "narrow lorentzian": ("12.43", "eom", _eom43("1/(1 + 10**8*(theta - 1/3)**2)/10")),
    "H: bump in theta": ("12.43", "H", 'H = "p_theta^2/(2*m*l^2) - m*g*l*cos(theta) + '
                                        'm*g*l*exp(-10**6*(theta - 1/3)**2)/10"'),
    "H: bump in the momentum": ("12.43", "H", 'H = "p_theta^2/(2*m*l^2) - m*g*l*cos(theta) + '
                                               'm*g*l*exp(-10**6*(p_theta/(m*l^2) - 1/2)**2)/100"'),
    "Hamilton's equations: bump": ("12.43", "hamilton", 'hamilton = ["theta_d == p_theta/(m*l^2)", "p_theta_d == '
                                   '-m*g*l*sin(theta) + m*g*l*exp(-10**6*(theta - 3217/10000)**2)"]'),
    "12.14 eom: kick in t": ("12.14", "eom_exact", EOM14.format(bump="exp(-10**6*(t - 1/2)**2)")),
    "12.14 L: kick in t": ("12.14", "L", f'L = "{L14} + m1*g*l1*theta1*exp(-10**4*(t - 1/2)**2)/100"'),
}

#: outside the exact judge's class (a power with a non-rational exponent): the motion decides them as
#: grading runs, every rule on
OUTSIDE = {
    "2**(narrow gaussian)": ("12.43", "eom", _eom43("2**(-10**6*(theta - 3217/10000)**2)")),
    "2**(kick in t)": ("12.43", "eom", _eom43("2**(-10**4*(t - 3/2)**2)/100")),
}


def _grade(tmp_path: Path, case) -> lagrade.PartResult:
    pid, name, text = case
    path = tmp_path / "answer.toml"
    path.write_text(text + "\n")
    return next(p for p in lagrade.check(pid, path, accuracy="default").parts if p.part == name)


def _refuted_by_the_motion(part) -> None:
    assert part.verdict == "incorrect" and part.score == 0, part.feedback
    assert part.method == "trajectory", (part.method, part.feedback)
    assert part.confirmed is True and part.review is None, part.trajectory_evidence
    ev = part.motion_evidence
    assert ev is not None and ev["confirmed"] is True
    # the separation beyond the tolerance, at the finer tolerance too, and beyond the error estimate
    assert ev["separation"] > 1 and ev["finer_separation"] > 1 and ev["error_estimate"] < 0.1 * ev["separation"]
    assert 0 < ev["t"] <= ev["window"] and ev["finer_rtol"] < ev["rtol"] and ev["compare_rtol"] > 0
    assert "separates from the true one at t =" in part.feedback
    assert "tolerances apart" not in part.feedback and "error estimate" not in part.feedback  # the student's words


@pytest.fixture
def motion_alone(monkeypatch):
    """The exact judge and the negligible-part rule off: the motion alone decides."""
    monkeypatch.setattr(exact, "is_zero", lambda *a, **k: None)
    monkeypatch.setattr(exact, "is_zero_given", lambda *a, **k: None)
    monkeypatch.setattr(admit, "_negligible", lambda *a, **k: [])


@pytest.mark.parametrize("name", list(FAMILY))
def test_the_motion_alone_refutes_the_bump(name, tmp_path, motion_alone):
    _refuted_by_the_motion(_grade(tmp_path, FAMILY[name]))


@pytest.mark.parametrize("name", list(FAMILY))
def test_with_every_rule_on_the_bump_is_still_refused(name, tmp_path):
    part = _grade(tmp_path, FAMILY[name])
    assert part.verdict == "incorrect" and part.score == 0, part.feedback


@pytest.mark.parametrize("name", list(OUTSIDE))
def test_outside_the_exact_class_the_motion_decides_as_grading_runs(name, tmp_path):
    """Before: the eom checker's own verdict was "correct, numeric" (no motion was integrated for an
    answer the screen had flagged) and only the negligible-part rule refused it, uncertified."""
    import sympy as sp

    bump = sp.sympify(name.replace("narrow gaussian", "-10**6*(theta - 3217/10000)**2")
                      .replace("kick in t", "-10**4*(t - 3/2)**2"))
    assert exact.outside(bump) is not None and exact.outside(sp.exp(bump.args[1])) is None
    _refuted_by_the_motion(_grade(tmp_path, OUTSIDE[name]))


def test_without_the_rate_scan_the_narrow_bump_passes(tmp_path, motion_alone, monkeypatch):
    """The cause, kept measurable: without the scan's windows the student's run steps over the bump and
    the motions agree."""
    from lagrade.compare import trajectory

    monkeypatch.setattr(trajectory, "rate_scan", lambda *a, **k: ([], 0))
    part = _grade(tmp_path, FAMILY["narrow gaussian in theta"])
    assert part.verdict == "correct" and part.method == "trajectory", part.feedback


@pytest.mark.parametrize("pid", ["12.43", "12.14"])
def test_the_right_answers_pass_with_the_scan(pid):
    ref = Path(__file__).resolve().parents[1] / "reference_solutions" / pid / "answer.py"
    result = lagrade.check(pid, ref, accuracy="default")
    assert result.full_marks, str(result)


def test_the_evidence_reaches_the_json(tmp_path, motion_alone):
    import json

    pid, name, text = FAMILY["kick in t"]
    path = tmp_path / "answer.toml"
    path.write_text(text + "\n")
    dumped = json.loads(lagrade.check(pid, path, accuracy="default").model_dump_json())
    ev = next(p for p in dumped["parts"] if p["part"] == name)["motion_evidence"]
    assert set(ev) >= {"t", "separation", "error_estimate", "finer_separation", "compare_rtol", "compare_atol",
                       "rtol", "finer_rtol", "method", "window"}


def test_the_gradebook_keeps_the_motion_evidence(tmp_path, motion_alone):
    """The bulk grader's row of a part refuted by the motion: its evidence in ``parts.motion_evidence``
    (JSON, the instructor's), beside the method."""
    import json

    from lagrade.uses.bulk.store import Key, Store

    part = _grade(tmp_path, FAMILY["kick in t"])
    row = part.model_dump(exclude={"read_as"})
    with Store(tmp_path / "gradebook.db", lock=True) as store:
        store.record(student="s", problem="12.43", path="s/12.43.toml", key=Key("f", "g", "v"), outcome="graded",
                     status="ok", reason="", score=0.0, max_score=1.0, problems=[], stdout="", source="",
                     seconds=0.1, parts=[row])
        got = store.db.execute("SELECT method, motion_evidence FROM parts WHERE part = 'eom'").fetchone()
    assert got[0] == "trajectory"
    ev = json.loads(got[1])
    assert ev["confirmed"] is True and ev["separation"] > 1 and ev["t"] > 0


def test_dop853_steps_through_a_capped_window():
    """The integrator's side of it: y' = exp(-10**8*(t - 1/2)**2) from 0 to 1. Unbounded, the steps
    straddle the spike and y(1) is about 0; with steps of at most 1e-5 in [0.49, 0.51] the error
    control meets it and y(1) is its integral, sqrt(pi)*1e-4."""
    import numpy as np

    from lagrade.compare import dop853

    def f(t, Y):
        return np.exp(-1e8 * (np.asarray(t) - 0.5) ** 2) * np.ones_like(Y)

    y0, times = np.zeros((1, 2)), np.array([1.0])
    free = dop853.solve(f, 0.0, y0, 1.0, rtol=1e-10, atol=1e-10, t_eval=times)
    capped = dop853.solve(f, 0.0, y0, 1.0, rtol=1e-10, atol=1e-10, t_eval=times, caps=[(1, 0.49, 0.51, 1e-5)])
    assert abs(free.y[0, 0, -1]) < 1e-6                      # the spike was stepped over
    assert abs(capped.y[0, 0, -1]) < 1e-6                    # column 0 has no cap
    assert abs(capped.y[0, 1, -1] - np.sqrt(np.pi) * 1e-4) < 1e-9
