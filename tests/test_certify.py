"""Rejections that are proofs (compare/certify.py): ball arithmetic at an exact rational point."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import sympy as sp

import lagrade
from lagrade.compare.certify import certify, root_between

x, y = sp.symbols("x y")
ANSWERS = Path(__file__).parent / "answers"


def test_a_difference_that_is_zero_is_never_certified_however_it_is_written():
    assert certify("d", sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1, {x: 0.7}) is None
    assert certify("d", sp.exp(sp.log(x)) - x, {x: 1.3}) is None
    assert certify("d", (x + y) ** 2 - x**2 - 2 * x * y - y**2, {x: 1e-3, y: 1e8}) is None


def test_a_nonzero_difference_is_certified_with_its_exact_point():
    cert = certify("d", sp.sin(x) - x, {x: 0.5})
    assert cert is not None and cert.point == {"x": "1/2"}
    assert "excludes 0" in cert.text()
    # a difference below any floating-point tolerance is still a difference
    assert certify("d", x * sp.Rational(10**15 + 1, 10**15) - x, {x: 0.75}) is not None


def test_a_second_root_is_certified_by_a_sign_change_over_a_finite_interval():
    assert root_between(x**2 - 2, x, 1.4, 1.5, {}, "f") is not None
    assert root_between(1 / (x - 1.45), x, 1.4, 1.5, {}, "f") is None   # a pole changes sign too: no root
    assert root_between(x**2 - 2, x, 1.5, 1.6, {}, "f") is None


def test_a_wrong_acceleration_is_certified_and_the_certificate_stays_with_the_instructor():
    m1, m2, m3, m4, g = sp.symbols("m1 m2 m3 m4 g", positive=True)
    S = 4 * g / (1 / m1 + 1 / m2 + 1 / m3 + 1 / m4)
    res = lagrade.check("12.22", a={"m1": g - S / m1, "m2": g - S / m2, "m3": g - S / m3, "m4": g - 2 * S / m4})
    a = next(p for p in res.parts if p.part == "a")
    assert a.verdict == "partial" and a.certified is True and "excludes 0" in a.certificate
    dumped = res.model_dump_json()
    assert '"certified":true' in dumped and "excludes 0" not in dumped


def _blind_wrong():
    for path in sorted(ANSWERS.glob("*/wrong_blind_*")):
        yield pytest.param(path, id=f"{path.parent.name}/{path.name}")


@pytest.mark.slow
@pytest.mark.parametrize("path", list(_blind_wrong()))
def test_every_sampled_state_rejection_of_the_blind_corpus_is_certified(path):
    res = lagrade.check(path.parent.name, path)
    for p in res.parts:
        refusal = (p.review or "").startswith("no credit without a proof")  # certified false: nothing proved wrong
        if p.verdict in ("incorrect", "partial") and p.method == "numeric" and p.certified is not None and not refusal:
            assert p.certified, f"{p.part}: {p.review}"
            assert re.search(r"excludes 0|a count|free of|finite in between|at the second|exactly 0|identically 0", p.certificate), p.certificate
