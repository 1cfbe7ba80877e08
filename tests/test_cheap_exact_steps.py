"""The warm grader's cheaper steps give what the costly ones gave (issue 48): the slopes of a plainly
linear row read off its terms (`compare.equations.slopes`) are sympy's derivatives, and a monomial gcd proved modulo
a prime (`compare.coprime`) is sympy's gcd up to a constant."""

from __future__ import annotations

import random

import sympy as sp

from lagrade.compare.coprime import monomial_gcd
from lagrade.compare.equations import slopes
from lagrade.verdicts.checkers.dynamics import _common_factor

a, b, c = sp.symbols("a b c", positive=True)
x, y = sp.symbols("x y", real=True)
u, v = sp.symbols("u v")


def test_slopes_are_sympys_derivatives_for_every_shape_of_row():
    rng = random.Random(3)
    atoms = [a, b, x, sp.sin(x), sp.cos(x - y), sp.Abs(x), a + b, sp.Rational(2, 3), -1, 2, sp.sqrt(a),
             1 / (a + x), sp.Float(1.5)]
    nonlinear = [u**2, sp.sin(u), u * v, 1 / u, u + a, sp.Abs(u), a * u + b, 2 * (x * v - u) + sp.sin(x),
                 (u + a) * (v + b), u * (v + 2 * x), sp.Add(u * a, b * (u + x * v), evaluate=False)]
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


def test_the_constant_split_is_sympys_as_independent():
    from lagrade.verdicts.checkers.admit import _independent

    rng = random.Random(5)
    atoms = [a, b, x, y, sp.pi, sp.sqrt(2), sp.Rational(-3, 7), 2, -1, sp.exp(-1000), sp.sin(x), sp.log(3), sp.I,
             sp.Float(0.25)]

    def tree(depth: int) -> sp.Expr:
        if depth == 0 or rng.random() < 0.3:
            return sp.sympify(rng.choice(atoms))
        op = rng.choice([sp.Add, sp.Mul, sp.Mul, lambda *z: sp.Pow(z[0], rng.choice([2, -1, sp.S.Half])),
                         lambda *z: sp.cos(z[0])])
        return sp.sympify(op(*[tree(depth - 1) for _ in range(rng.randint(2, 4))]))

    for _ in range(500):
        for node in sp.preorder_traversal(tree(4)):
            if (node.is_Add or node.is_Mul) and node.free_symbols:
                assert sp.srepr(_independent(node)) == \
                    sp.srepr(node.as_independent(*node.free_symbols, as_Add=node.is_Add)), node
