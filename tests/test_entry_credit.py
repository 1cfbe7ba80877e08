"""Each right entry of a dict or list earns its share (issue 22, part 2; README's promise).

Only the wrong entries beyond the expected number are surplus (and cancel a right one); where the
entries of a solution are coupled by the equations of motion the feedback says so.
"""

from __future__ import annotations

import sympy as sp

import lagrade
from lagrade.verdicts.credit import Credit

t = sp.Symbol("t")
m, M, g, phi, s0 = sp.symbols("m M g phi s0", positive=True)
D = 2 * M + m + m * sp.sin(phi) ** 2
X_TRUE = -m * g * sp.sin(phi) * sp.cos(phi) / D * t**2 / 2
S_TRUE = s0 + (M + m) * g * sp.sin(phi) / D * t**2 / 2


def part(result, name):
    return next(p for p in result.parts if p.part == name)


def test_one_right_entry_of_a_coupled_solution_earns_its_share_and_the_coupling_is_said():
    got = part(lagrade.check("12.28", solution={"X": X_TRUE, "s": s0 + g * sp.sin(phi) * t**2 / 2}), "solution")
    assert got.verdict == "partial" and got.score == 0.5, got.feedback
    assert "X(t) is right" in got.feedback and "couple" in got.feedback, got.feedback
    both = part(lagrade.check("12.28", solution={"X": X_TRUE, "s": S_TRUE}), "solution")
    assert both.verdict == "correct"
    none = part(lagrade.check("12.28", solution={"X": 2 * X_TRUE, "s": S_TRUE + t}), "solution")
    assert none.verdict == "incorrect" and none.score == 0


def test_independent_motions_earn_their_share_without_a_coupling_note():
    x0, y0, vx0, vy0 = sp.symbols("x0 y0 vx0 vy0")
    right_x = {"x": x0 + vx0 * t, "y": y0 + vy0 * t + g * t**2 / 2}
    got = part(lagrade.check("12.41", solution_a=right_x), "solution_a")
    assert got.verdict == "partial" and got.score == 0.5 and "couple" not in got.feedback, got.feedback
    right_y = {"x": x0 + 2 * vx0 * t, "y": y0 + vy0 * t - g * t**2 / 2}
    assert part(lagrade.check("12.41", solution_a=right_y), "solution_a").score == 0.5


def test_all_or_nothing_when_per_entry_credit_is_off():
    x0, y0, vx0 = sp.symbols("x0 y0 vx0")
    got = part(lagrade.check("12.41", solution_a={"x": x0 + vx0 * t, "y": y0}, credit=Credit(per_equation=False)),
               "solution_a")
    assert got.score == 0 and got.verdict == "partial"


def _omegas():
    r0, l = sp.symbols("r0 l", positive=True)
    m1, m2 = sp.symbols("m1 m2", positive=True)
    return sp.sqrt(3 * m2 * g / ((m1 + m2) * r0)), sp.sqrt(g / (l - r0)), sp.sqrt(g / r0)


def test_two_frequencies_one_right_one_wrong_earn_half():
    right, other, wrong = _omegas()
    got = part(lagrade.check("12.17", omega=[right, wrong]), "omega")
    assert got.verdict == "partial" and got.score == 0.5, got.feedback
    assert part(lagrade.check("12.17", omega=[right, other]), "omega").verdict == "correct"


def test_a_wrong_entry_beyond_the_expected_number_cancels_a_right_one():
    right, other, wrong = _omegas()
    assert part(lagrade.check("12.17", omega=[right, other, wrong]), "omega").score == 0.5
    assert part(lagrade.check("12.17", omega=[right, wrong, 2 * wrong]), "omega").score == 0
    lenient = Credit(penalize_extra_entries=False)
    assert part(lagrade.check("12.17", omega=[right, wrong, 2 * wrong], credit=lenient), "omega").score == 0.5


def test_conserved_quantities_and_cyclic_names_earn_their_share():
    R = sp.Symbol("R", positive=True)
    theta, ph = sp.Function("theta")(t), sp.Function("phi")(t)
    E = m * R**2 * (theta.diff(t) ** 2 + sp.sin(theta) ** 2 * ph.diff(t) ** 2) / 2 - m * g * R * sp.cos(theta)
    got = part(lagrade.check("12.16", conserved=[ph.diff(t), E]), "conserved")
    assert got.verdict == "partial" and got.score == 0.5, got.feedback
    X, Y, Z = sp.symbols("X Y Z")
    cyclic = part(lagrade.check("12.37", cyclic=[X, Y, Z, sp.Symbol("r")]), "cyclic")
    assert cyclic.verdict == "partial", cyclic.feedback
    assert cyclic.score == cyclic.max_score * 3 / 4


def test_each_right_entry_of_a_dict_result_earns_its_share():
    m1, m2, S = sp.symbols("m1 m2 S", positive=True)
    alpha, beta = sp.symbols("alpha beta", positive=True)
    right = g * (m1 * sp.sin(alpha) - m2 * sp.sin(beta))
    got = part(lagrade.check("12.5", Q_a={"l1": right, "l": S}), "Q_a")  # (a): l1 and l (issue 33)
    assert got.verdict == "partial" and got.score == got.max_score / 2, got.feedback


def test_coupled_dict_entries_are_said_to_be_coupled():
    m1, m2, m3, m4 = sp.symbols("m1 m2 m3 m4", positive=True)
    x, y, z = (sp.Function(n)(t) for n in "xyz")
    S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
    closed = part(lagrade.check("12.22", S_t={"S1": m1 * g, "S2": S, "S3": 2 * m1 * g}), "S_t")
    assert closed.verdict == "partial" and "S1 and S3 are coupled" in closed.feedback, closed.feedback
    assert abs(closed.score - closed.max_score / 3) < 1e-5
    # written with the accelerations, nothing was solved: the part is invalid, and says which is left
    own = part(lagrade.check("12.22", S_t={"S1": m1 * (g - x.diff(t, 2)), "S2": S,
                                          "S3": 2 * m1 * (g - y.diff(t, 2))}), "S_t")
    assert own.verdict == "invalid" and "still contains x''" in own.feedback, own.feedback
