"""`--hints` may say which term is missing or which equation is wrong, never print the reference answer.

Every wrong golden answer of the first problems is graded with hints on; no feedback may contain
the reference Lagrangian, Hamiltonian, or a reference result as written in the problem file.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import sympy as sp

import lagrade
from lagrade.grade import references
from lagrade.library import load_problem

ROOT = Path(__file__).resolve().parents[1]
IDS = ["12.1", "12.3", "12.4", "12.7", "12.10", "12.14", "12.16", "12.22", "12.43", "12.46", "ex12.3"]


def _squash(text: str) -> str:
    return re.sub(r"\s+", "", text)


def _reference_texts(pid: str) -> list[str]:
    problem = load_problem(pid)
    texts = []
    for system in problem.systems:
        mech = references(problem)[system.key]
        texts += [sp.sstr(mech.L), sp.sstr(mech.L).replace("_d", "'")]
        for raw in (system.L, system.T, system.V):
            if raw:
                texts.append(raw)
    for part in problem.parts:
        ref = part.reference
        values = ref.values() if isinstance(ref, dict) else (ref if isinstance(ref, list) else [ref])
        texts += [str(v) for v in values if isinstance(v, str) and len(v) > 8]
    return [_squash(t) for t in texts if len(_squash(t)) > 8]


CASES = [pytest.param(pid, f, id=f"{pid}/{f.name}") for pid in IDS
         for f in sorted((ROOT / "tests" / "answers" / pid).glob("wrong_*.*"))]


@pytest.mark.parametrize("pid, path", CASES)
def test_hints_do_not_print_the_reference(pid, path):
    result = lagrade.check(pid, path, hints=True)
    secrets = _reference_texts(pid)
    for part in result.parts:
        feedback = _squash(part.feedback)
        for secret in secrets:
            assert secret not in feedback, f"{part.part} feedback reveals the reference: {part.feedback}"


def test_hints_name_the_missing_term_without_its_coefficient():
    t = sp.Symbol("t")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    w1, w2 = th1.diff(t), th2.diff(t)
    L = ((m1 + m2) / 2 * l1**2 * w1**2 + m2 / 2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * sp.cos(th1 - th2)
         + (m1 + m2) * g * l1 * sp.cos(th1))  # the lower bob's potential energy is missing
    feedback = lagrade.check("12.14", L=L, hints=True).parts[0].feedback
    assert "a potential term in theta2 is missing" in feedback, feedback
    assert "m2*g*l2" not in feedback and "g*l2*m2" not in feedback
    assert "Hint" not in lagrade.check("12.14", L=L).parts[0].feedback  # only with --hints


def _L14(extra=0, factor_term=None, factor=1):
    t = sp.Symbol("t")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    w1, w2 = th1.diff(t), th2.diff(t)
    terms = [(m1 + m2) / 2 * l1**2 * w1**2, m2 / 2 * l2**2 * w2**2, m2 * l1 * l2 * w1 * w2 * sp.cos(th1 - th2),
             (m1 + m2) * g * l1 * sp.cos(th1), m2 * g * l2 * sp.cos(th2)]
    if factor_term is not None:
        terms[factor_term] *= factor
    return sp.Add(*terms) + extra


def test_hint_for_an_extra_term_quotes_the_students_term():
    t = sp.Symbol("t")
    extra = sp.Symbol("m1") * sp.Function("theta1")(t) ** 2
    feedback = lagrade.check("12.14", L=_L14(extra=extra), hints=True).parts[0].feedback
    assert "your term m1*theta1**2 should not be there" in feedback, feedback


def test_hint_for_a_wrong_factor_and_a_wrong_sign():
    feedback = lagrade.check("12.14", L=_L14(factor_term=1, factor=2), hints=True).parts[0].feedback
    assert "is 2 times what it should be" in feedback, feedback
    feedback = lagrade.check("12.14", L=_L14(factor_term=4, factor=-1), hints=True).parts[0].feedback
    assert "has the wrong sign" in feedback, feedback
