"""The warm grader's cheaper steps give what the costly ones gave (issue 48): the slopes of a plainly
linear row read off its terms (`admit.slopes`) are sympy's derivatives, and a monomial gcd proved modulo
a prime (`compare.coprime`) is sympy's gcd up to a constant."""

from __future__ import annotations

import random

import sympy as sp

from lagrade.compare.coprime import monomial_gcd
from lagrade.verdicts.checkers.admit import slopes
from lagrade.verdicts.checkers.dynamics import _common_factor

a, b, c = sp.symbols("a b c", positive=True)
x, y = sp.symbols("x y", real=True)
u, v = sp.symbols("u v")


def test_slopes_are_sympys_derivatives_for_every_shape_of_row():
    rng = random.Random(3)
    atoms = [a, b, x, sp.sin(x), sp.cos(x - y), sp.Abs(x), a + b, sp.Rational(2, 3), -1, 2, sp.sqrt(a),
             1 / (a + x), sp.Float(1.5)]
    nonlinear = [u**2, sp.sin(u), u * v, 1 / u, u + a, sp.Abs(u)]
    for _ in range(400):
        terms = []
        for _ in range(rng.randint(1, 4)):
            factors = [rng.choice(atoms) for _ in range(rng.randint(0, 3))]
            r = rng.random()
            factors += [rng.choice([u, v])] if r < 0.6 else [rng.choice(nonlinear)] if r < 0.75 else []
            terms.append(sp.Mul(*factors))
        row = sp.Add(*terms)
        for unknowns in ([u, v], [u], []):
            assert slopes(row, unknowns) == {w: sp.diff(row, w) for w in unknowns}, row


def _nonconstant_factors(e: sp.Expr) -> list[str]:
    return sorted(str(f) for f, _ in sp.factor_list(e)[1] if f.free_symbols) if e.free_symbols else []


def test_the_common_factor_is_sympys_gcd_up_to_a_constant():
    rng = random.Random(1)
    atoms = [a, b, c, x, sp.sin(x), sp.cos(x - y), sp.exp(x), sp.Rational(1, 3)]
    shared = [a - 50, a * b + sp.sin(x), 1 + sp.cos(x - y), c**2 - a]
    for _ in range(150):
        common = sp.Mul(*[rng.choice(atoms) for _ in range(rng.randint(0, 2))])
        if rng.random() < 0.4:
            common *= rng.choice(shared)  # a factor the proof must not deny

        def poly() -> sp.Expr:
            return sp.Add(*[rng.randint(-3, 3) * sp.Mul(*[rng.choice(atoms) ** rng.randint(0, 2) for _ in range(3)])
                            for _ in range(rng.randint(1, 4))])

        coefficients = [e for e in (sp.expand(common * poly()) for _ in range(rng.randint(2, 3))) if e != 0]
        if len(coefficients) > 1:
            assert _nonconstant_factors(_common_factor(coefficients)) == \
                _nonconstant_factors(sp.gcd_list(coefficients)), coefficients


def test_a_shared_factor_is_never_proved_away():
    x1, x2 = sp.symbols("x1 x2")
    f = sp.Poly((x1 - 50) * (x1 * x2 + 1), x1, x2).as_dict(native=True)
    g = sp.Poly((x1 - 50) * (x2**3 + 7), x1, x2).as_dict(native=True)
    assert all(monomial_gcd([f, g], seed) is None for seed in range(20))
    h = sp.Poly(x1**2 * x2 * (x2**3 + 7) + x1**3, x1, x2).as_dict(native=True)  # gcd with f: x1 only
    assert monomial_gcd([sp.Poly(x1 * (x1 * x2 + 1), x1, x2).as_dict(native=True), h]) == (1, 0)
