"""A trajectory disagreement beyond the preset's tolerance refutes; evidence that cannot decide is
flagged for review; the sampled-state tolerance follows the preset (issue 23, part 1)."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

import lagrade
from lagrade.verdicts.checkers import dynamics
from lagrade.verdicts.checkers.base import Context
from lagrade.verdicts.checkers.dynamics import _decide
from lagrade.compare import trajectory as tr
from lagrade.compare.trajectory import ACCURACY, Comparison
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem

REFERENCE = Path(__file__).resolve().parents[1] / "reference_solutions" / "12.14" / "answer.py"


def _perturbed_g(tmp_path: Path, eps: str) -> Path:
    """12.14's exact equations with g scaled by (1 + eps) in both equations; ``eps`` as written in the
    file (``Rational(1, 10**6)`` exact, ``1e-7`` a float)."""
    src = "from sympy import Rational\n" + REFERENCE.read_text()
    for old in ("-(m1 + m2) * g * sin(th1)),", "-g * sin(th2)),"):
        assert old in src
    src = src.replace("-(m1 + m2) * g * sin(th1)),", f"-(m1 + m2) * (1 + {eps})*g * sin(th1)),")
    src = src.replace("-g * sin(th2)),", f"-(1 + {eps})*g * sin(th2)),")
    path = tmp_path / f"answer_{abs(hash(eps))}.py"
    path.write_text(src)
    return path


def _eom_exact(result) -> lagrade.CheckResult:
    return next(p for p in result.parts if p.part == "eom_exact")


#: an error the numbers rule lets through (an exact simple fraction) and sampled states at 1e-3 do not see
SMALL = "Rational(1, 10**6)"


@pytest.fixture
def loose_samples(monkeypatch):
    """Presets whose sampled states let a 1e-6 error through: only the trajectories can refute it."""
    for name in ("strict", "default", "fast"):
        monkeypatch.setitem(tr.ACCURACY, f"{name}-loose",
                            dataclasses.replace(ACCURACY[name], name=f"{name}-loose", sample_rtol=1e-3))


def test_a_trajectory_beyond_tolerance_refutes(tmp_path, loose_samples, monkeypatch):
    # the exact re-check at the sampled states (`dynamics._exact_refutation`) refutes this answer before
    # any trajectory is compared, under every preset; off here, to test the trajectories' evidence alone
    monkeypatch.setattr(dynamics, "_exact_refutation", lambda *a, **k: None)
    from lagrade.compare import exact  # the exact judge refutes it first: the trajectories' own evidence here

    monkeypatch.setattr(exact, "is_zero", lambda *a, **k: None)
    monkeypatch.setattr(exact, "is_zero_given", lambda *a, **k: None)
    for accuracy in ("strict-loose", "default-loose"):
        part = _eom_exact(lagrade.check("12.14", _perturbed_g(tmp_path, SMALL), accuracy=accuracy))
        assert part.verdict == "incorrect" and part.method == "trajectory", (accuracy, part.feedback)
        assert "separates from the true one" in part.feedback
    # the fast comparison (rtol 1e-4) cannot see a 1e-6 error over the window: no refutation there
    assert _eom_exact(lagrade.check("12.14", _perturbed_g(tmp_path, SMALL), accuracy="fast-loose")).verdict == "correct"


def test_the_right_equations_pass_every_preset_and_the_loosened_ones(tmp_path, loose_samples):
    for accuracy in ("fast", "default", "strict", "default-loose", "strict-loose"):
        result = lagrade.check("12.14", REFERENCE, accuracy=accuracy)
        assert result.full_marks, (accuracy, result)
        assert not any(p.review for p in result.parts), accuracy


@pytest.mark.parametrize(("eps", "said"), [
    ("Rational(1, 10**5)", None),            # exact and simple: the sampled states refute it
    ("Rational(1, 10**6)", None),
    ("1e-7", "not exact"),                    # a float that is no simple number: the numbers rule
    ("1e-9", "not exact"),
    ("Rational(1, 10**9)", "not a simple fraction"),
])
def test_every_preset_rejects_g_off_by_a_little(tmp_path, eps, said):
    """The issue's case: g off by 1e-7 passed every preset. Now an exact error of 1e-6 is refuted by the
    sampled states under every preset, and finer ones, which no float tolerance can resolve, by the
    numbers rule (docs/answers.md)."""
    for accuracy in ("fast", "default", "strict"):
        part = _eom_exact(lagrade.check("12.14", _perturbed_g(tmp_path, eps), accuracy=accuracy))
        assert part.verdict != "correct", (eps, accuracy)
        if said is not None and accuracy == "fast":  # below fast's sample_rtol (1e-7): the rule decides
            assert said in part.feedback, (eps, accuracy, part.feedback)


def _ctx_part(accuracy: str = "default"):
    problem = load_problem("12.14")
    return Context(problem, references(problem), ACCURACY[accuracy]), problem.part("eom_exact")


def _comparison(**kw) -> Comparison:
    base = {"agree": False, "horizon": 2.0, "separation_time": 0.5, "component": "theta1", "method": "DOP853",
            "rtol": 1e-10, "window": 2.0}
    return Comparison(**{**base, **kw})


def test_a_motion_that_could_not_be_followed_is_flagged_not_refuted():
    ctx, part = _ctx_part()
    res = _decide(ctx, part, None, _comparison(note="the true motion could not be followed numerically"))
    assert res.verdict == "correct" and res.method == "numeric"
    assert res.review and "sampled states alone" in res.review
    res = _decide(ctx, part, None, None)
    assert res.verdict == "correct" and res.review


def test_a_proof_outweighs_a_disagreeing_integration_but_is_flagged():
    ctx, part = _ctx_part()
    res = _decide(ctx, part, True, _comparison(decisive=True))
    assert res.verdict == "correct" and res.method == "symbolic" and res.review


def test_a_chaotic_window_too_short_to_test_is_flagged():
    ctx, part = _ctx_part()
    short = _comparison(agree=True, window=0.05, why_window="chaotic: finite-time Lyapunov exponent 9/s measured")
    res = _decide(ctx, part, None, short)
    assert res.verdict == "correct" and res.review and "chaotic" in res.review
    assert _decide(ctx, part, None, _comparison(agree=True)).review is None


def test_review_reaches_the_json_but_no_reference():
    ctx, part = _ctx_part()
    res = _decide(ctx, part, None, None)
    assert "review" in res.model_dump(mode="json")


def test_the_exact_re_check_refutes_what_the_trajectories_would_under_every_preset(tmp_path, loose_samples):
    """The same 1e-6 error in g, with the exact re-check on (as grading runs): refuted at the sampled
    states, with a certificate, even under the fast preset whose trajectories cannot see it."""
    for accuracy in ("fast-loose", "default-loose", "strict-loose"):
        part = _eom_exact(lagrade.check("12.14", _perturbed_g(tmp_path, SMALL), accuracy=accuracy))
        assert part.verdict == "incorrect" and "exact arithmetic" in part.feedback, (accuracy, part.feedback)
        assert part.certified is True, part.review


@pytest.mark.parametrize("accuracy", ["fast", "default", "strict"])
def test_the_exact_re_check_refutes_an_H_whose_rates_are_off_below_every_tolerance(accuracy, monkeypatch):
    """12.43's H plus m*g*l*(theta + 100001)/(theta + 100000): large in value, its rates off by about
    1e-10, below every preset's sampled-state tolerance and the trajectories'. With the screen's
    negligible-part rule off, the exact re-check alone refutes the H and the Hamilton's equations it
    gives (without it both got full marks under fast and default), certified."""
    import sympy as sp

    from lagrade.verdicts.checkers import admit

    monkeypatch.setattr(admit, "_negligible", lambda *a, **k: [])
    t = sp.Symbol("t")
    m, l, g = sp.symbols("m l g", positive=True)
    theta, p = sp.Function("theta")(t), sp.Function("p_theta")(t)
    H = p**2 / (2 * m * l**2) - m * g * l * sp.cos(theta) + m * g * l * (theta + 100001) / (theta + 100000)
    hamilton = [sp.Eq(theta.diff(t), H.diff(p)), sp.Eq(p.diff(t), -H.diff(theta))]
    parts = {x.part: x for x in lagrade.check("12.43", H=H, hamilton=hamilton, accuracy=accuracy).parts}
    for name in ("H", "hamilton"):
        assert parts[name].score == 0 and parts[name].verdict == "incorrect", (name, parts[name].feedback)
    assert "at an exact state" in parts["hamilton"].feedback and parts["hamilton"].certified is True
