"""The tolerance heuristics the exact judge and the motion did not make unnecessary (issue 42, item 6),
each with the case that needs it: switched off (as `scripts/rules_off.py` does), that wrong answer gets
full marks; on, it gets none. A rule no measured case needs was removed (the report of the change and
docs/answers.md say which).

Since the exact judge's class rule (an answer outside the exactly decided class earns nothing without a
proof), the kick and the slow ratio below are refused with the negligible-part rule or the three-state
re-check off as well: those two rules no longer have a measured case of their own on these answers;
the number window still has one."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp

import lagrade
from lagrade.verdicts.checkers import admit, dynamics


def _grade(tmp_path: Path, pid: str, part: str, text: str):
    path = tmp_path / "answer.toml"
    path.write_text(text + "\n")
    return next(p for p in lagrade.check(pid, path, accuracy="default").parts if p.part == part)


#: 12.43's eom plus a kick at t = 5, after the horizon (3): outside the exact class (a power with a
#: non-rational exponent), met by no sampled state and by no motion
KICK_AFTER_THE_HORIZON = 'eom = "theta_dd == -g/l*sin(theta) + g/l*2**(-10**6*(t - 5)**2)"'

#: 12.43's H plus a term large in value whose force is below 1e-10 of the true one: outside the exact
#: class, flagged by no other rule, too small for the motion to separate
SLOW_RATIO_H = 'H = "p_theta^2/(2*m*l^2) - m*g*l*cos(theta) + m*g*l*2**((theta + 100001)/(theta + 100000))"'


@pytest.mark.parametrize("on", [True, False])
def test_a_kick_no_state_and_no_motion_meets_is_refused_with_the_negligible_part_rule_on_or_off(tmp_path, monkeypatch, on):
    if not on:
        monkeypatch.setattr(admit, "_negligible", lambda *a, **k: [])
    part = _grade(tmp_path, "12.43", "eom", KICK_AFTER_THE_HORIZON)
    if on:
        assert part.score == 0 and "changes the whole by less than" in part.feedback, part.feedback
    else:  # since the exact judge's class rule (issue 42): outside the class, no credit without a proof
        assert part.score == 0 and "outside the class of expressions decided exactly" in part.feedback, part.feedback


@pytest.mark.parametrize("on", [True, False])
def test_a_force_below_every_tolerance_is_refused_by_the_class_rule_before_the_three_states(tmp_path, monkeypatch, on):
    if not on:
        monkeypatch.setattr(dynamics, "_exact_refutation", lambda *a, **k: None)
    part = _grade(tmp_path, "12.43", "H", SLOW_RATIO_H)
    # the class rule refuses it before the three states are weighed, with the rule on or off
    assert part.score == 0 and "outside the class of expressions decided exactly" in part.feedback, part.feedback


@pytest.mark.parametrize("on", [True, False])
def test_the_number_window_is_needed_for_a_root_the_exact_judge_does_not_take(monkeypatch, on):
    """(1 + 1/10**6)**(1/1000) is 1 + 1e-9: a root of degree 1000, beyond the exact judge's reach."""
    if not on:
        monkeypatch.setattr(admit, "_near_simple", lambda c: None)
    m1, m2, m3, m4, g = sp.symbols("m1 m2 m3 m4 g", positive=True)
    S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)     # 12.22's accelerations, as tests/test_admit.py has them
    A = {"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - S / m4}
    nearly_one = (1 + sp.Rational(1, 10**6)) ** sp.Rational(1, 1000)
    part = next(p for p in lagrade.check("12.22", a={k: nearly_one * v for k, v in A.items()}).parts if p.part == "a")
    if on:
        assert part.score == 0 and "without being equal" in part.feedback, part.feedback
    else:
        assert part.verdict == "correct", part.feedback


VERDICTS = Path(__file__).parent / "security" / "verdicts"


@pytest.mark.parametrize("on", [True, False])
def test_the_negligible_part_rule_and_the_three_states_are_still_needed_for_a_tiny_nonlinear_term(monkeypatch, on):
    """Measured on the merged judge (`python scripts/rules_off.py negligible,three-state --
    tests/security/verdicts/verdicts_harness.py`: 171 of 186 as expected, 15 wrong answers with
    credit): 12.14's linearized eom with a wrong nonlinear term that is below every tolerance at the
    sampled states is one of them. With the two rules on it earns nothing."""
    if not on:
        monkeypatch.setattr(admit, "_negligible", lambda *a, **k: [])
        monkeypatch.setattr(dynamics, "_exact_refutation", lambda *a, **k: None)
    result = lagrade.check("12.14", VERDICTS / "12.14" / "tiny-eom-wrong-nonlinear-term.py", accuracy="default")
    part = next(p for p in result.parts if p.part == "eom")
    if on:
        assert part.score == 0, part.feedback
    else:
        assert part.verdict == "correct", part.feedback   # what the two rules are kept for
