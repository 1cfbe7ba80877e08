"""`lagrade validate` (issue 46): a problem file proved before a student sees it.

The small problem files in tests/validate_problems each break one thing a validation must catch:
a wrong reference (its hand-written solution disagrees), a listed mistake equal to the reference,
a sampling box outside the physical domain; each fails with a line that says which. A valid file
passes, through the command's exit code.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp
from click.testing import CliRunner

from lagrade.cli import main
from lagrade.uses.validate.forms import half_angle_safe, right_forms
from lagrade.uses.validate.proofs import proved_equal
from lagrade.uses.validate.run import validate
from lagrade.uses.validate.slips import wrong_answers

HERE = Path(__file__).parent / "validate_problems" / "problems"
t = sp.Symbol("t")
theta = sp.Function("theta")(t)
m, g, l = sp.symbols("m g l")


def _failed(report) -> list[str]:
    return [c.detail for c in report.cases if not c.ok]


def test_a_valid_problem_file_passes_with_exit_code_0():
    result = CliRunner().invoke(main, ["validate", str(HERE / "vp-pendulum.toml"), "--count", "3", "--json"])
    assert result.exit_code == 0, result.output
    out = json.loads(result.output)
    report = out["problems"][0]
    assert out["ok"] and report["right"] > 0 and report["wrong"] > 0
    assert report["false_accepts"] == 0 and report["false_rejects"] == 0
    checks = {c["check"] for c in report["cases"]}
    assert {"schema", "render", "reference", "mistake", "right", "wrong"} <= checks


def test_a_wrong_reference_fails_and_says_which_part():
    report = validate(str(HERE / "vp-wrong-ref.toml"), count=2)
    assert not report.ok
    lines = _failed(report)
    assert any("reference solution's omega is graded incorrect" in line for line in lines), lines


def test_a_mistake_equal_to_the_reference_fails_and_says_which():
    report = validate(str(HERE / "vp-mistake-is-ref.toml"), count=2)
    lines = _failed(report)
    assert any(line.startswith("mistake 1 of L: the mistake equals the reference") for line in lines), lines


def test_a_sampling_box_outside_the_domain_fails_and_says_which():
    result = CliRunner().invoke(main, ["validate", str(HERE / "vp-box-outside.toml")])
    assert result.exit_code == 1
    text = " ".join(result.output.split())
    assert "parameter l: the sampling range [0.5, 2.0] is not inside its domain '(0, 1)'" in text, text


def test_every_generated_wrong_answer_differs_from_the_reference_or_is_proved_right():
    L = m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * sp.cos(theta) + m * g * l  # a constant term
    slips = dict(wrong_answers("lagrangian", L, ["m", "g", "l"]))
    dropped = [label for label, value in slips.items() if value != L and
               proved_equal("lagrangian", value, L, frozenset({"m", "g", "l"}), _pendulum()) is not None]
    assert dropped and all("term" in label and "g*l*m" in label for label in dropped), dropped


def test_the_half_angle_form_only_where_no_angle_reaches_pi():
    alpha = sp.Symbol("alpha")
    domains = {"theta": sp.Reals, "alpha": sp.Interval.open(0, sp.pi / 2)}
    assert half_angle_safe(sp.cos(alpha), domains) and not half_angle_safe(sp.cos(theta), domains)
    labels = [label for label, _ in right_forms("expression", m * g * sp.sin(alpha), ["m", "g"], intervals=domains)]
    assert "the tangent half-angle form" in labels


def test_a_latex_echo_of_an_inverse_function_reads_back():
    """Found by the generated answers (12.4): the LaTeX echo printed acos as \\operatorname{acos},
    which the LaTeX reader does not know; it prints \\arccos now."""
    from lagrade.answer.reading.latex import parse_latex_answer
    from lagrade.verdicts.readback import as_latex

    text = as_latex(sp.acos(sp.Rational(2, 3)))
    assert parse_latex_answer(text, []) == sp.acos(sp.Rational(2, 3))


def _pendulum():
    from lagrade.problem.library import load_problem
    from lagrade.verdicts.grade import references

    return references(load_problem(str(HERE / "vp-pendulum.toml")))[""]


@pytest.mark.slow
@pytest.mark.timeout(1800)
def test_selftest_subset_has_no_false_accept_or_reject():
    """CI's slow tier: the chapter self-test (benchmarks/selftest.py) on a fixed-seed subset."""
    ids = ["12.1", "12.14", "12.22", "12.30", "12.43", "ex12.3"]
    reports = [validate(pid, seed=0, count=4) for pid in ids]
    failed = [f"{r.problem}: {c.detail}" for r in reports for c in r.cases if not c.ok]
    assert not failed, failed
    assert sum(r.count("right") + r.count("wrong") for r in reports) >= 200


def test_a_latex_echo_of_a_coordinate_of_several_letters_reads_back():
    """Found by the generated answers (12.9's phip): the echo printed \\dot{phip}, which the LaTeX
    reader refuses, and a bare phip reads back as a product of letters; it is \\mathrm{phip} now."""
    from lagrade.answer.reading.latex import parse_latex_answer
    from lagrade.verdicts.readback import as_latex

    phip = sp.Function("phip")(t)
    value = phip.diff(t) ** 2 * sp.sin(theta) + phip
    assert parse_latex_answer(as_latex(value), ["phip", "theta"]) == value


def test_a_scene_that_cannot_be_derived_fails_with_its_file_and_line(tmp_path):
    """12.35 with dry friction declared as drag (tests/test_check_entry.py's case): one failed check,
    the line that says where in the file."""
    root = Path(__file__).resolve().parents[1]
    src = (root / "problems" / "12.35.toml").read_text()
    old_q = next(line for line in src.splitlines() if line.startswith("Q = { theta"))
    old_effects = next(line for line in src.splitlines() if line.startswith("effects = ["))
    effects = 'effects = ["holonomic_constraint", "constraint_force", "dissipation_drag"]'
    src = src.replace(old_q, 'Q = { theta = "-mu*m*a**2*theta_d/Abs(theta_d)" }').replace(old_effects, effects)
    path = tmp_path / "12.35.toml"
    path.write_text(src)
    report = validate(str(path), count=1)
    lines = _failed(report)
    line = 1 + src.splitlines().index(effects)
    assert any(d.startswith(f"{path}:{line}: ") and d.endswith("declare dissipation_friction") for d in lines), lines


def test_exact_judge_does_not_split_an_exponent_with_trig_in_it():
    """Found by the generated answers (12.21): exp(2*u*(1 - cos(phi)**2)) and exp(2*u*sin(phi)**2)
    were two independent exponentials to the exact judge, which then proved a right T, L and Q wrong
    ("exact arithmetic shows a difference"). Such an exponent is outside its class now."""
    from lagrade.answer.reading.load import load_answer
    from lagrade.compare import exact
    from lagrade.problem.library import load_problem, reference_dir
    from lagrade.verdicts.grade import check

    u, v, phi = sp.symbols("u v phi", real=True)
    same = sp.exp(2 * (1 - sp.cos(phi) ** 2) * u) - sp.exp(2 * u * sp.sin(phi) ** 2)
    assert exact.is_zero(same, frozenset()) is not False
    problem = load_problem("12.21")
    values = load_answer(reference_dir() / "12.21" / "answer.py", problem).values
    phi = next(s for s in values["T"].free_symbols if s.name == "phi")
    rewritten = values["T"].replace(lambda x: x.is_Pow and x.exp == 2 and x.base == sp.sin(phi),
                                    lambda x: 1 - sp.cos(phi) ** 2)
    assert rewritten != values["T"]
    graded = check(problem, T=rewritten, only=["T"], read_as=()).parts[0]
    assert graded.verdict == "correct", graded.feedback


def test_a_latex_echo_of_a_parameter_of_several_letters_reads_back():
    """Found by the generated answers (12.44's eps): the echo printed eps bare, which the LaTeX
    reader reads as e*p*s; it is \\mathrm{eps} now."""
    from lagrade.answer.reading.latex import parse_latex_answer
    from lagrade.verdicts.readback import as_latex

    x = sp.Function("x")(t)
    eps, k = sp.symbols("eps k")
    value = eps * x**4 / 4 + k * x**2 / 2
    assert parse_latex_answer(as_latex(value), ["x"], known_names=["eps", "k"]) == value


def test_a_hamiltonian_of_the_same_motion_is_proved_right_where_gauges_are_allowed():
    """Found by the selftest (12.47, whose H has a gauge alternative): H with a0 and g swapped gives the
    same motion (x'' = g + a0 - k*x/m) and gets full marks, rightly; the proof covers it now."""
    from lagrade.problem.library import load_problem
    from lagrade.uses.validate.proofs import same_motion
    from lagrade.verdicts.grade import references

    x, px = sp.Function("x")(t), sp.Function("p_x")(t)
    a0, g, m, k, l0 = sp.symbols("a0 g m k l0")
    H = px**2 / (2 * m) + k * x**2 / 2 + a0 * t * px + g * m * (a0 * t**2 / 2 - l0 - x)
    mech = references(load_problem("12.47"))[""]
    positive = frozenset({"a0", "g", "m", "k", "l0"})
    assert same_motion(H.xreplace({a0: g, g: a0}), H, mech, positive) is not None
    assert same_motion(H.xreplace({k: 2 * k}), H, mech, positive) is None
