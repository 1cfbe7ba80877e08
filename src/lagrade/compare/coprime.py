"""Proving that polynomials share no factor but a monomial, without their multivariate gcd.

sympy's ``gcd_list`` of a few equations' coefficients costs tens of milliseconds; almost always the
answer is a monomial (``l1``, ``l2*m2``). Restricted to a random line modulo a prime, the question is
a univariate gcd of small polynomials, which costs well under a millisecond. The test is one-sided and
exact: it says "only a monomial" only when that is proved, and otherwise nothing (the caller then asks
sympy), so a chosen point can make it slower, never wrong.

Why it is a proof. Let ``f_1..f_k`` be polynomials in ``x = (x_1..x_n)`` over Q, ``M`` the monomial of
the smallest exponents of each variable over all their terms, ``F_i = f_i / M`` (polynomials). If the
``F_i`` had a common factor ``g`` of positive total degree, take ``g`` primitive in Z[x] and scale each
``F_i`` by an integer ``d_i`` (the lcm of its denominators) into Z[x]: by Gauss's lemma
``d_i F_i = g h_i`` with ``h_i`` in Z[x]. Reduced modulo a prime ``p`` dividing no ``d_i``, ``g`` still
divides every ``F_i``, and the top-degree homogeneous parts multiply: ``top(d_j F_j) = top(g) top(h_j)``.
On the line ``x = a + b s`` the coefficient of ``s**deg(F_j)`` in ``F_j(a + b s)`` is ``top(F_j)(b)``; if
it is nonzero mod p, so is ``top(g)(b)``, hence ``g(a + b s)`` has degree ``deg g >= 1`` in ``s`` and
divides every ``F_i(a + b s)`` in F_p[s]: their gcd would have positive degree. So a constant gcd mod p
of the ``F_i(a + b s)``, with one ``F_j(a + b s)`` of full degree, proves that the gcd of the ``f_i`` is
``M`` times a constant.
"""

from __future__ import annotations

import random
from collections.abc import Sequence

#: a prime (2**61 - 1); which prime does not matter to the proof, only to how often it succeeds
P = 2**61 - 1


def _residue(c: object) -> int | None:
    """A rational coefficient (any of sympy's ZZ or QQ element types) modulo P; None if P divides its
    denominator."""
    num, den = int(c.numerator), int(c.denominator)  # type: ignore[attr-defined]
    if den % P == 0:
        return None
    return num * pow(den, -1, P) % P


def monomial_gcd(terms: Sequence[dict[tuple[int, ...], object]], seed: int = 0) -> tuple[int, ...] | None:
    """The exponents of ``M`` when the gcd of the polynomials (each ``{exponents: rational coefficient}``,
    one ring, none zero) is proved to be ``M`` times a constant (the module's docstring); None when that
    is not shown (a common factor may exist: ask sympy)."""
    if not terms or any(not t for t in terms):
        return None
    n = len(next(iter(terms[0])))
    low = tuple(min(e[k] for t in terms for e in t) for k in range(n))
    from flint import nmod_poly  # python-flint's polynomials over Z/pZ (multiplication, monic gcd)

    rng = random.Random(seed)
    a = [rng.randrange(P) for _ in range(n)]
    b = [rng.randrange(1, P) for _ in range(n)]
    top = [max((sum(e) - sum(low) for e in t), default=0) for t in terms]
    line_of = [nmod_poly([a[k], b[k]], P) for k in range(n)]  # x_k = a_k + b_k s
    lines = []
    for t in terms:
        line = nmod_poly([], P)
        for e, c in t.items():
            r = _residue(c)
            if r is None:
                return None
            term = nmod_poly([r], P)
            for k in range(n):
                if e[k] - low[k]:
                    term *= line_of[k] ** (e[k] - low[k])
            line += term
        lines.append(line)
    if not any(line.degree() == d for line, d in zip(lines, top)):  # top(F_j)(b) = 0 mod p for every j
        return None
    g = lines[0]
    for line in lines[1:]:
        g = g.gcd(line)
        if g.degree() == 0:
            return low
    return low if g.degree() == 0 else None
