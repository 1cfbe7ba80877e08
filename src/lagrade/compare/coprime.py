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


def _times(u: list[int], v: list[int]) -> list[int]:
    out = [0] * (len(u) + len(v) - 1)
    for i, a in enumerate(u):
        if a:
            for j, b in enumerate(v):
                out[i + j] = (out[i + j] + a * b) % P
    return out


def _trim(u: list[int]) -> list[int]:
    while u and u[-1] == 0:
        u.pop()
    return u


def _gcd(u: list[int], v: list[int]) -> list[int]:
    """The monic gcd in F_p[s] (coefficient lists, lowest degree first; [] is 0)."""
    u, v = _trim(list(u)), _trim(list(v))
    while v:
        inv = pow(v[-1], -1, P)
        while len(u) >= len(v):
            c = u[-1] * inv % P
            shift = len(u) - len(v)
            for i, b in enumerate(v):
                u[shift + i] = (u[shift + i] - c * b) % P
            _trim(u)
            if not u:
                break
        u, v = v, u
    return u


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
    rng = random.Random(seed)
    a = [rng.randrange(P) for _ in range(n)]
    b = [rng.randrange(1, P) for _ in range(n)]
    top = [max((sum(e) - sum(low) for e in t), default=0) for t in terms]
    powers: list[list[list[int]]] = []  # powers[k][d] = (a_k + b_k s)**d
    for k in range(n):
        most = max(e[k] - low[k] for t in terms for e in t)
        row = [[1]]
        for _ in range(most):
            row.append(_times(row[-1], [a[k], b[k]]))
        powers.append(row)
    lines = []
    for t in terms:
        line = [0]
        for e, c in t.items():
            r = _residue(c)
            if r is None:
                return None
            term = [r]
            for k in range(n):
                if e[k] - low[k]:
                    term = _times(term, powers[k][e[k] - low[k]])
            if len(term) > len(line):
                line += [0] * (len(term) - len(line))
            for i, x in enumerate(term):
                line[i] = (line[i] + x) % P
        lines.append(_trim(line))
    if not any(len(line) == d + 1 for line, d in zip(lines, top)):  # top(F_j)(b) = 0 mod p for every j
        return None
    g = lines[0]
    for line in lines[1:]:
        g = _gcd(g, line)
        if len(g) == 1:
            return low
    return low if len(g) == 1 else None
