"""Exact equality for the class the chapter's answers live in: no tolerance, no sampling box.

Two answers agree at random points of a box and still differ elsewhere, or differ by less than any
tolerance; neither can happen to the test here. An expression built from the problem's symbols,
rational numbers, ``pi``, ``E``, ``I``, ``+ - * /``, integer powers, radicals (rational powers of
radical-free, trigonometry-free bases) and ``sin cos tan cot sec csc sinh cosh tanh coth sech csch
exp`` of any such argument is mapped into a field of rational functions over independent variables,
where zero is decided exactly with high probability (Schwartz-Zippel):

- ``exp(c*M)`` and ``exp(I*c*M)`` for a rational ``c`` and a canonical term ``M`` (the argument's
  terms, each with its rational coefficient taken out) are powers ``y_M**(c*N)`` and ``z_M**(c*N)`` of
  fresh variables (``N`` the lcm of the denominators of ``M``'s coefficients, so that ``E`` must be
  planned with the rest); sin, cos, ... are rational in ``exp(I*A)``, ``sinh``, ... in
  ``exp(A)``. Exponentials of Q-linearly independent functions are algebraically independent over the
  functions they are exponentials of (the Risch structure theorem), so this is a faithful model;
- ``pi`` is transcendental, so it is a variable too; ``E`` is ``exp(1)``;
- a radical ``b**r`` is split into the irreducible factors of ``b`` (sympy's ``factor_list``), each
  a variable ``w`` with ``w**Q = f``; this is the principal branch only when all but one of the
  factors are nonnegative on the physical domain (decided from the symbols' assumptions: parameters
  positive, states real), so any other split is refused (``OutsideClass``). Distinct irreducible
  factors give independent (Kummer) extensions, in which any root is a faithful embedding;
- the value is computed modulo a random 61-bit prime ``p`` (chosen with ``i`` in ``F_p``, unique
  roots of odd degree, and the constant radicands residues) at a random point; a nonzero value
  proves the expression nonzero as a function (so, on the open physical domain, somewhere in it); a
  zero at ``POINTS`` independent points says zero, wrongly with probability at most
  ``(D/p)**POINTS`` for an expression of degree ``D`` (below 1e-20 for any answer the readers admit);
- ``log(F)`` of an ``F`` positive on the physical domain is ``sum c * log|F_i|`` over its irreducible
  factors (and the primes of its content, and ``pi``), each ``log|F_i|`` a fresh variable
  (`_log_terms`): logarithms of distinct irreducible polynomials are algebraically independent over
  the rest. A log of a function (``log(cos(u))``), in an exponent or under a root is outside.

Anything else (an inverse function, ``Abs``, ``sign``, ``Piecewise``, a special function, a power
with a symbolic exponent (``0**u``, ``2**u``), a nested root, a root whose branch the domain does not
fix) is outside the class: ``None``, and only a proof on the domain gives credit for it
(`lagrade.verdicts.checkers.values.compare_scalar`).
"""

from __future__ import annotations

import math
import random
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp
from sympy.ntheory import isprime, sqrt_mod

from lagrade.compare.symbolic import _OutOfTime, time_bound

#: independent points (each modulo its own prime) at which an expression must vanish to be zero
POINTS = 2
#: operations beyond which an expression is not mapped (no answer the readers admit comes near)
MAX_OPS = 20_000
#: the largest degree of a polynomial whose logarithm is split into the logs of its factors
LOG_DEGREE = 40
#: tries at a point before giving up (a denominator or a radicand that is not a residue there)
TRIES = 200

_TRIG = {"sin", "cos", "tan", "cot", "sec", "csc"}
_HYP = {"sinh", "cosh", "tanh", "coth", "sech", "csch"}


#: why a root of a real trigonometric radicand is outside the class (`needs_proof` lets the screen's
#: fold rules judge it, as before: sqrt(1 - cos(alpha)**2) on 0 < alpha < pi/2 is honest)
TRIG_ROOT = "a root of a trigonometric expression"
#: sin, cos, ... inside an exponent or an angle: the terms' exponentials need not be independent
#: (sin(p)**2*u + cos(p)**2*u = u), so the modular test does not decide it; but the expression stays
#: analytic (no branch, no fold), so the sampled states decide it as any analytic answer, and no proof
#: is asked (validate's tangent half-angle forms of 12.21's T, L and Q)
TRIG_IN_EXPONENT = "a trigonometric function inside an exponent or an angle"


class OutsideClass(Exception):
    """The expression has a node the exact test does not model faithfully (named in the message)."""


class _Retry(Exception):
    """This point (or prime) cannot evaluate the expression: a zero denominator, a non-residue."""


@dataclass
class _Radical:
    """``b**r`` = ``unit`` * prod ``f**s`` over irreducible factors ``f`` (sympy expressions, or prime
    integers) with rational exponents ``s``; ``unit`` a power of ``I``."""

    i_power: int
    factors: list[tuple[sp.Basic, Fraction]]


@dataclass
class _Plan:
    radicals: dict[sp.Basic, _Radical] = field(default_factory=dict)
    exps: dict[sp.Basic, list[tuple[str, sp.Basic, sp.Rational]]] = field(default_factory=dict)  # node -> [(z|y, M, c)]
    scale: dict[tuple[str, sp.Basic], int] = field(default_factory=dict)  # (z|y, M) -> N_M
    degree: dict[sp.Basic, int] = field(default_factory=dict)  # radicand f -> Q (w**Q = f)
    symbols: set[sp.Symbol] = field(default_factory=set)
    logs: dict[sp.Basic, list[tuple[sp.Basic, Fraction]]] = field(default_factory=dict)  # log node -> [(F, c)]


#: the physical domain as the judge takes it: a set of the names that are positive (the rest real), or
#: name -> `lagrade.problem.domains.Domain` (its assumptions, and its interval where the ends are numbers)
DomainLike = "set[str] | frozenset[str] | Mapping[str, Domain]"


def _assumptions(domain, name: str) -> dict[str, bool]:
    if isinstance(domain, (set, frozenset)):
        return {"positive": True} if name in domain else {"real": True}
    d = domain.get(name)
    return d.assumptions() if d is not None else {"real": True}


def _interval(domain, name: str) -> sp.Interval | None:
    """The symbol's domain as an interval with numbers for ends (None: a set, or ends with parameters)."""
    if isinstance(domain, (set, frozenset)):
        return None
    d = domain.get(name)
    if d is None or d.bounds.parameters:
        return None
    return d.interval


def _assume(expr: sp.Expr, domain) -> sp.Expr:
    """Symbols with the assumptions of their physical domain (parameters positive, the state real, and
    what each problem narrows), and each ``Abs`` or ``sign`` whose argument's sign the domain fixes
    replaced (``Abs(tan(alpha))`` is ``tan(alpha)`` for 0 < alpha < pi/2)."""
    mapping = {}
    for s in expr.free_symbols:
        if isinstance(s, sp.Symbol):
            mapping[s] = sp.Symbol(s.name, **_assumptions(domain, s.name))
    out = expr.xreplace(mapping)
    if out.has(sp.Abs, sp.sign):
        fixed = {}
        for node in out.atoms(sp.Abs, sp.sign):
            sign = sign_on_domain(node.args[0], domain)
            if sign is not None:
                fixed[node] = sign * node.args[0] if isinstance(node, sp.Abs) else sp.Integer(sign)
        out = out.xreplace(fixed) if fixed else out
    return out


def on_domain(expr: sp.Expr, domain) -> sp.Expr:
    """``expr`` with its symbols' physical-domain assumptions, and the ``Abs`` and ``sign`` the domain
    fixes replaced: what a proof (`lagrade.compare.symbolic.proves_zero`) should see."""
    try:
        return _assume(sp.sympify(expr), domain)
    except Exception:  # noqa: BLE001  (the expression as it was: the proof sees less, nothing wrong)
        return expr


def sign_on_domain(f: sp.Expr, domain) -> int | None:
    """+1 or -1 when ``f`` (with assumption-carrying symbols) has that sign on the whole physical domain,
    None when that is not shown: from the assumptions, or, for a function of one symbol whose domain is
    an interval, from no root and no break in the open interval (sympy's solveset and continuous_domain)
    and its sign at one point."""
    if f.is_positive:
        return 1
    if f.is_negative:
        return -1
    free = [s for s in f.free_symbols if isinstance(s, sp.Symbol)]
    if len(free) != 1:
        return None
    x = free[0]
    interval = _interval(domain, x.name)
    if interval is None or not (interval.start.is_finite and interval.end.is_finite) or interval.measure == 0:
        return None
    inner = sp.Interval.open(interval.start, interval.end)
    try:
        with time_bound(1.0):
            if sp.solveset(f, x, inner) != sp.S.EmptySet:
                return None
            if sp.calculus.util.continuous_domain(f, x, inner) != inner:
                return None
            value = sp.N(f.xreplace({x: (interval.start + interval.end) / 2}), 30)
    except Exception:  # noqa: BLE001  (sympy gave up: no sign shown)
        return None
    if not value.is_Number or value == 0:
        return None
    return 1 if value > 0 else -1


def _exact_floats(expr: sp.Expr) -> sp.Expr:
    """A float in an expression stands for its exact (binary) value: 1.000000001 is not 1."""
    floats = expr.atoms(sp.Float)
    return expr.xreplace({f: sp.Rational(f) for f in floats}) if floats else expr


def _canonical_term(term: sp.Expr) -> tuple[sp.Rational, bool, sp.Expr]:
    """(rational coefficient, imaginary?, canonical term M) of one term of an exponent's argument."""
    c, m = term.as_coeff_Mul()
    # the terms' exponentials are independent only when the terms are Q-linearly independent, which
    # their canonical forms show for rational functions and roots alone: sin(p)**2*u, cos(p)**2*u and u
    # are three terms and one relation (validate's generated answers, 12.21: exp(u*(1 - cos(p)**2))
    # was told apart from exp(u*sin(p)**2))
    if m.has(sp.exp, sp.E, *[getattr(sp, n) for n in _HYP]):
        raise OutsideClass("a trigonometric or exponential function inside an exponent or an angle")
    if m.has(*[getattr(sp, n) for n in _TRIG]):
        raise OutsideClass(TRIG_IN_EXPONENT)
    imaginary = False
    if m.has(sp.I):
        m = sp.expand(m / sp.I)
        if m.has(sp.I):
            raise OutsideClass("a complex exponent")
        imaginary = True
        c2, m = m.as_coeff_Mul()
        c = c * c2
    roots = {x: sp.Pow(sp.factor(sp.together(x.base)), x.exp) for x in m.atoms(sp.Pow) if not x.exp.is_Integer}
    if roots:  # sqrt(k*(1/m1 + 1/m2)) and sqrt(k*(m1 + m2)/(m1*m2)): one term, the radicand factored alike
        m = m.xreplace(roots)
    if not m.free_symbols and m != 1:
        if m.has(sp.pi):
            raise OutsideClass("a rational multiple of pi in an angle that sympy does not evaluate")
        raise OutsideClass("a function of an irrational constant")
    num, den = sp.fraction(sp.cancel(m))
    cn, num = sp.factor_terms(num).as_coeff_Mul()
    cd, den = sp.factor_terms(den).as_coeff_Mul()
    pn, num = sp.Poly(num).primitive() if num.is_polynomial() and num.free_symbols else (1, num)
    pd, den = sp.Poly(den).primitive() if den.is_polynomial() and den.free_symbols else (1, den)
    num = num.as_expr() if isinstance(num, sp.Poly) else num
    den = den.as_expr() if isinstance(den, sp.Poly) else den
    coeff = sp.Rational(c) * sp.Rational(cn) * sp.Rational(pn) / (sp.Rational(cd) * sp.Rational(pd))
    if num.could_extract_minus_sign():
        num, coeff = -num, -coeff
    if den.could_extract_minus_sign():
        den, coeff = -den, -coeff
    return coeff, imaginary, sp.expand(num) / sp.expand(den)


#: (argument, kind) -> `_exponent`'s answer: a function of the argument alone, and the same few angles
#: (theta1, theta1 - theta2) come back in every answer to a problem
_EXPONENTS: dict[tuple[sp.Basic, str], list[tuple[str, sp.Basic, int]]] = {}


def _exponent(arg: sp.Expr, kind: str) -> list[tuple[str, sp.Basic, int]]:
    """``exp(arg)`` (kind "y") or ``exp(I*arg)`` (kind "z") as powers of the variables y_M, z_M."""
    known = _EXPONENTS.get((arg, kind))
    if known is None:
        known = _exponent_of(arg, kind)  # OutsideClass is raised each time, not kept
        if len(_EXPONENTS) >= 4096:
            _EXPONENTS.clear()
        _EXPONENTS[(arg, kind)] = known
    return list(known)


def _exponent_of(arg: sp.Expr, kind: str) -> list[tuple[str, sp.Basic, int]]:
    out: dict[tuple[str, sp.Basic], int] = {}
    if arg.has(sp.log):  # exp(2*log(u)) is u**2: a log in an exponent is not an independent variable
        raise OutsideClass("an exponential or trigonometric function of a logarithm")
    for term in sp.Add.make_args(sp.expand(arg)):
        if term == 0:
            continue
        c, imaginary, m = _canonical_term(term)
        which = kind if not imaginary else ("z" if kind == "y" else "y")
        if imaginary and kind == "z":  # exp(I * I*c*M) = exp(-c*M)
            c = -c
        out[(which, m)] = out.get((which, m), 0) + sp.Rational(c)
    return [(w, m, n) for (w, m), n in out.items() if n]


def _radical(base: sp.Expr, r: sp.Rational, domain=frozenset()) -> _Radical:
    """``base**r`` split into irreducible factors, where the split is the principal branch."""
    if base.has(sp.exp, sp.E, sp.log, sp.I, *[getattr(sp, n) for n in _HYP]):
        raise OutsideClass("a root of an exponential, logarithmic or complex expression")
    trig = base.has(*[getattr(sp, n) for n in _TRIG])
    if trig:  # sqrt(1 - cos(alpha)**2) is sin(alpha) where the domain makes sin(alpha) > 0: whole powers only
        base = sp.trigsimp(base)
    if _has_radical(base):
        raise OutsideClass("a nested root")
    if base.has(sp.I):
        raise OutsideClass("a root of a complex number")
    coeff, factors = sp.factor_list(sp.together(base))
    coeff = sp.Rational(coeff)
    i_power = 0
    out: list[tuple[sp.Basic, Fraction]] = []
    r = Fraction(int(r.p), int(r.q))
    unknown = 0
    for f, e in factors:
        sign = None
        if f.is_nonnegative:
            sign = 1
        elif f.is_nonpositive:
            sign = -1
        else:
            sign = sign_on_domain(f, domain)
        if sign == -1:
            f = -f
            if e % 2:
                coeff = -coeff
        elif sign is None:
            er = Fraction(e) * r
            if e % 2 == 0 and er.denominator == 1 and er.numerator % 2 == 0:
                sign = 1  # (f**2k)**r an even integer power: no branch
            elif e % 2 == 0:  # (f**2)**(1/2) is |f|, (f**2)**(1/4) the root of |f|: not f's own root where f < 0
                raise OutsideClass("a root of an even power of a quantity whose sign the physical domain does not "
                                   "fix (an absolute value)")
            elif e != 1 and not (((e - 1) * r).denominator == 1 and ((e - 1) * r).numerator % 2 == 0):
                # (f**3)**(1/2) is f*sqrt(f) only where f > 0 (it is -f*sqrt(f) where f < 0)
                raise OutsideClass("a root of a power of a quantity whose sign the physical domain does not fix")
            else:
                unknown += 1
        if trig and f.has(*[getattr(sp, n) for n in _TRIG]) and (Fraction(e) * r).denominator != 1:
            raise OutsideClass(TRIG_ROOT)
        out.append((sp.expand(f), Fraction(e) * r))
    if coeff < 0:
        if unknown or (2 * r).denominator != 1:
            raise OutsideClass("a root of a quantity whose sign the physical domain does not fix")
        i_power = int(2 * r)
        coeff = -coeff
    if unknown > 1:
        raise OutsideClass("a root of a product of factors whose signs the physical domain does not fix")
    for prime, e in sp.factorint(int(coeff.p)).items():
        out.append((sp.Integer(prime), Fraction(e) * r))
    for prime, e in sp.factorint(int(coeff.q)).items():
        out.append((sp.Integer(prime), -Fraction(e) * r))
    return _Radical(i_power, out)


def _positive_on(f: sp.Expr, domain) -> bool:
    return bool(f.is_positive) or sign_on_domain(f, domain) == 1


def _log_terms(arg: sp.Expr, domain=frozenset()) -> list[tuple[sp.Basic, Fraction]]:
    """``log(arg)`` as ``sum c * log|F|`` over the irreducible polynomial factors ``F`` of ``arg`` (primitive,
    sign-normalised), its rational content's primes and ``pi``, when ``arg`` is positive on the whole
    physical domain (then ``log(arg) = log|arg|``, and ``|arg|`` is the product of the factors' moduli
    to integer powers; a factor under a root must itself be positive there).

    The logarithms of distinct irreducible polynomials are algebraically independent over the rational
    functions and the exponentials of them (Ostrowski; the Risch structure theorem), so each ``log|F|`` is
    a fresh variable: a zero in the model is a zero in fact. For the constants (log 2, log 3, log pi)
    independence is Schanuel's conjecture: relied on only to reject, never to accept."""
    if arg.has(sp.I):
        raise OutsideClass("a logarithm of a complex quantity")
    if arg.has(sp.exp, sp.E, sp.log, *[getattr(sp, n) for n in (*_TRIG, *_HYP)]):
        raise OutsideClass("a logarithm of a function")
    if not _positive_on(arg, domain):
        raise OutsideClass("a logarithm of a quantity that the physical domain does not make positive")
    out: dict[sp.Basic, Fraction] = {}

    def add(key: sp.Basic, c: Fraction) -> None:
        out[key] = out.get(key, Fraction(0)) + c

    def number(n: sp.Rational, r: Fraction) -> None:
        for prime, e in sp.factorint(abs(int(n.p))).items():
            add(sp.Integer(prime), r * e)
        for prime, e in sp.factorint(int(n.q)).items():
            add(sp.Integer(prime), -r * e)

    def factor(b: sp.Expr, r: Fraction) -> None:
        if b.is_Rational:
            number(b, r)
            return
        if b is sp.pi:
            add(sp.pi, r)
            return
        if b.is_Mul:
            for x in b.args:
                factor(x, r)
            return
        if b.is_Pow:
            base, ex = b.args
            if not ex.is_Rational:
                raise OutsideClass("a logarithm of a power with a non-rational exponent")
            if not ex.is_Integer and not _positive_on(base, domain):
                raise OutsideClass("a logarithm of a root of a quantity whose sign the domain does not fix")
            factor(base, r * Fraction(int(ex.p), int(ex.q)))
            return
        if _has_radical(b) or not b.is_polynomial():
            num, den = sp.fraction(sp.together(b))
            if den != 1:
                factor(num, r)
                factor(den, -r)
                return
            raise OutsideClass("a logarithm of a sum with roots in it")
        if b.free_symbols and sp.Poly(b, *sorted(b.free_symbols, key=str)).total_degree() > LOG_DEGREE:
            raise OutsideClass(f"a logarithm of a polynomial of degree above {LOG_DEGREE} (not factored)")
        coeff, facs = sp.factor_list(b)
        number(sp.Rational(coeff), r)
        for f, e in facs:
            if f is sp.pi:
                add(sp.pi, r * e)
                continue
            f = sp.expand(f)
            if f.could_extract_minus_sign():
                f = -f
            add(f, r * e)

    factor(arg, Fraction(1))
    return [(k, c) for k, c in out.items() if c and k != 1]


def plan(expr: sp.Expr, domain=frozenset()) -> _Plan:
    """Walk ``expr`` once: every radical split, every exponential mapped; raise `OutsideClass`."""
    p = _Plan()
    seen: set[sp.Basic] = set()
    stack = [expr]
    while stack:
        e = stack.pop()
        if e in seen:
            continue
        seen.add(e)
        if e.is_Symbol:
            p.symbols.add(e)
        elif e.is_Rational or e is sp.I or e is sp.pi or e is sp.E:
            pass
        elif e.is_Add or e.is_Mul or isinstance(e, sp.Tuple):
            stack.extend(e.args)
        elif e.is_Pow:
            b, x = e.args
            if x.is_Integer:
                stack.append(b)
            elif x.is_Rational:
                rad = _radical(b, x, domain)
                p.radicals[e] = rad
                for f, s in rad.factors:
                    if s.denominator != 1:
                        p.degree[f] = math.lcm(p.degree.get(f, 1), s.denominator)
                    stack.append(f)
            else:
                raise OutsideClass("a power with a non-rational exponent")
        elif isinstance(e, sp.exp):
            p.exps[e] = _exponent(e.args[0], "y")
            stack.extend(m for _, m, _ in p.exps[e])
        elif type(e).__name__ in _TRIG:
            p.exps[e] = _exponent(e.args[0], "z")
            stack.extend(m for _, m, _ in p.exps[e])
        elif type(e).__name__ in _HYP:
            p.exps[e] = _exponent(e.args[0], "y")
            stack.extend(m for _, m, _ in p.exps[e])
        elif isinstance(e, sp.log):
            p.logs[e] = _log_terms(e.args[0], domain)
        else:
            raise OutsideClass(f"{type(e).__name__}")
    for terms in p.exps.values():  # exp(c*M) = v_M**(c*N_M), N_M the lcm of the denominators of M's c
        for which, m, c in terms:
            p.scale[(which, m)] = math.lcm(p.scale.get((which, m), 1), int(c.q))
    for f, q in p.degree.items():
        if f.is_Integer is False and f.free_symbols and _has_radical(f):
            raise OutsideClass("a nested root")
    return p


def _has_radical(f: sp.Basic) -> bool:
    return any(not x.exp.is_Integer for x in f.atoms(sp.Pow))


def _odd_part(q: int) -> tuple[int, int]:
    k = 0
    while q % 2 == 0:
        q //= 2
        k += 1
    return k, q


def _choose_prime(rng: random.Random, plan_: _Plan) -> int:
    """A 61-bit prime with sqrt(-1) in F_p, unique roots of every odd degree used, and each constant
    radicand a residue of the 2-power degree it needs."""
    odd = {3, 5, 7}
    for q in plan_.degree.values():
        odd |= set(sp.primefactors(_odd_part(q)[1]))
    constants = [(int(f), 2 ** _odd_part(q)[0]) for f, q in plan_.degree.items() if f.is_Integer and q % 2 == 0]
    for _ in range(20000):
        p = rng.randrange(2 ** 61, 2 ** 62) | 1
        if p % 4 != 1 or any(p % r == 1 for r in odd if r != 2):
            continue
        if not isprime(p):
            continue
        if all(pow(c, (p - 1) // math.gcd(k, p - 1), p) == 1 for c, k in constants):
            return p
    raise OutsideClass("constant roots that no prime tried takes")


def _root(a: int, q: int, p: int, rng: random.Random) -> int:
    """A q-th root of a modulo p (q's odd part has a unique root; its 2-power part needs residues)."""
    k, odd = _odd_part(q)
    if odd > 1:
        a = pow(a, pow(odd, -1, p - 1), p)
    for _ in range(k):
        roots = sqrt_mod(a, p, all_roots=False)
        if roots is None:
            raise _Retry
        a = roots if rng.random() < 0.5 else (-roots) % p
    return a


class _Evaluator:
    def __init__(self, plan_: _Plan, p: int, rng: random.Random):
        self.plan, self.p, self.rng = plan_, p, rng
        self.i = sqrt_mod(p - 1, p)
        self.memo: dict[sp.Basic, int] = {}
        self.vars: dict[object, int] = {}
        for s in sorted(plan_.symbols, key=str):
            self.vars[s] = rng.randrange(1, p)
        self.vars[sp.pi] = rng.randrange(1, p)
        self.roots: dict[sp.Basic, int] = {}
        for f, q in plan_.degree.items():  # a symbol under a root is drawn as a power: its root is known
            if f.is_Symbol:
                w = rng.randrange(1, p)
                self.vars[f], self.roots[f] = pow(w, q, p), w
        for f, q in sorted(plan_.degree.items(), key=lambda fq: sp.default_sort_key(fq[0])):
            if f not in self.roots:
                self.roots[f] = _root(self.ev(f), q, p, rng)

    def var(self, key: object) -> int:
        if key not in self.vars:
            self.vars[key] = self.rng.randrange(1, self.p)
        return self.vars[key]

    def inv(self, a: int) -> int:
        if a % self.p == 0:
            raise _Retry
        return pow(a, -1, self.p)

    def power(self, a: int, n: int) -> int:
        return pow(a, n, self.p) if n >= 0 else pow(self.inv(a), -n, self.p)

    def ev(self, e: sp.Basic) -> int:
        got = self.memo.get(e)
        if got is not None:
            return got
        p = self.p
        if e.is_Symbol or e is sp.pi:
            v = self.vars[e]
        elif e.is_Rational:
            v = int(e.p) * self.inv(int(e.q)) % p
        elif e is sp.I:
            v = self.i
        elif e is sp.E:
            v = self.power(self.var(("y", sp.S.One)), self.plan.scale.get(("y", sp.S.One), 1))
        elif e.is_Add:
            v = sum(self.ev(a) for a in e.args) % p
        elif e.is_Mul:
            v = 1
            for a in e.args:
                v = v * self.ev(a) % p
        elif e.is_Pow and e.exp.is_Integer:
            v = self.power(self.ev(e.base), int(e.exp))
        elif e.is_Pow:
            rad = self.plan.radicals[e]
            v = self.power(self.i, rad.i_power)
            for f, s in rad.factors:
                q = self.plan.degree.get(f, 1)
                whole = self.ev(f) if s.denominator == 1 else self.roots[f]
                n = s.numerator if s.denominator == 1 else int(s * q)
                v = v * self.power(whole, n) % p
        elif isinstance(e, sp.log):  # sum c * log|F|, each log|F| an independent variable
            v = 0
            for f, c in self.plan.logs[e]:
                v = (v + self.var(("log", f)) * (c.numerator * self.inv(c.denominator))) % p
        else:
            name = type(e).__name__
            x = 1
            for which, m, c in self.plan.exps[e]:
                x = x * self.power(self.var((which, m)), int(c * self.plan.scale[(which, m)])) % p
            if isinstance(e, sp.exp):
                v = x
            else:
                x2 = x * x % p
                if name in _TRIG:  # x = exp(I*A): sin = (x - 1/x)/(2I), cos = (x + 1/x)/2
                    s_num, c_num = (x2 - 1) * self.i % p, (x2 + 1) % p  # sin = (x2-1)/(2 I x) = -I(x2-1)/(2x)
                    sin_v = (-s_num) * self.inv(2 * x) % p
                    cos_v = c_num * self.inv(2 * x) % p
                    v = {"sin": sin_v, "cos": cos_v, "tan": sin_v * self.inv(cos_v), "cot": cos_v * self.inv(sin_v),
                         "sec": self.inv(cos_v), "csc": self.inv(sin_v)}[name] % p
                else:  # x = exp(A)
                    sh = (x2 - 1) * self.inv(2 * x) % p
                    ch = (x2 + 1) * self.inv(2 * x) % p
                    v = {"sinh": sh, "cosh": ch, "tanh": sh * self.inv(ch), "coth": ch * self.inv(sh),
                         "sech": self.inv(ch), "csch": self.inv(sh)}[name] % p
        self.memo[e] = v
        return v


def prepare(expr: sp.Expr, domain=frozenset()) -> tuple[sp.Expr, _Plan]:
    """``expr`` with its symbols' domain assumptions and exact floats, and its plan (or `OutsideClass`)."""
    expr = _exact_floats(_assume(sp.sympify(expr), domain))
    if sp.count_ops(expr) > MAX_OPS:
        raise OutsideClass("an expression too large to map")
    nested = [x for x in expr.atoms(sp.Pow) if not x.exp.is_Integer and not x.free_symbols and _has_radical(x.base)]
    if nested:  # a constant root that denests (sqrt(3 + 2*sqrt(2)) is 1 + sqrt(2)): sympy's denesting is exact
        expr = expr.xreplace({x: sp.sqrtdenest(x) for x in nested})
    return expr, plan(expr, domain)


@dataclass
class Witness:
    """Where an expression was found nonzero: a prime and the residues of the point's variables; the
    certificate of an exact rejection (kept for the instructor, as `lagrade.compare.certify`'s are)."""

    quantity: str
    prime: int
    value: int
    point: dict[str, int]

    def text(self) -> str:
        at = ", ".join(f"{k} = {v}" for k, v in list(self.point.items())[:6])
        more = ", ..." if len(self.point) > 6 else ""
        return (f"{self.quantity} is {self.value} (not 0) modulo the prime {self.prime} at the point {at}{more} "
                "(residues; exact arithmetic, lagrade.compare.exact)")


#: the last nonzero evaluation `is_zero` made in this thread of grading (`witness`)
_LAST: list[Witness | None] = [None]


def witness(quantity: str) -> Witness | None:
    """The point of the last exact refutation, named for ``quantity`` (None when there was none)."""
    w = _LAST[0]
    return None if w is None else Witness(quantity, w.prime, w.value, w.point)


def _name(k: object) -> str:
    """A variable of the model as the witness names it: a symbol, exp(M/N), exp(I*M/N), log|F|."""
    if not isinstance(k, tuple):
        return str(k)
    if k[0] == "log":
        return f"log|{k[1]}|"
    return f"exp({'I*' if k[0] == 'z' else ''}{k[1]}/N)"


def is_zero(expr: sp.Expr, positive=frozenset(), seconds: float = 2.0, seed: int = 0) -> bool | None:
    """True when ``expr`` is identically zero on the physical domain, False when it is not (exactly),
    None when it is outside the class or the time ran out."""
    try:
        with time_bound(seconds):
            expr, plan_ = prepare(expr, positive)
            if expr == 0:
                return True
            rng = random.Random(seed)
            for _ in range(POINTS):
                p = _choose_prime(rng, plan_)
                for _try in range(TRIES):
                    try:
                        evaluator = _Evaluator(plan_, p, rng)
                        value = evaluator.ev(expr)
                    except _Retry:
                        continue
                    break
                else:
                    return None
                if value != 0:
                    _LAST[0] = Witness("", p, value, {_name(k): v for k, v in evaluator.vars.items()})
                    return False
            return True
    except (OutsideClass, _OutOfTime):
        return None
    except (sp.PolynomialError, sp.polys.polyerrors.PolificationFailed, ValueError, TypeError,
            ZeroDivisionError, RecursionError):
        return None


def _solve_mod(A: list[list[int]], b: list[int], p: int) -> list[int]:
    """A u = b over F_p by Gaussian elimination; a singular A at this point is a `_Retry`."""
    n = len(b)
    M = [row[:] + [b[i]] for i, row in enumerate(A)]
    for c in range(n):
        pivot = next((r for r in range(c, n) if M[r][c] % p), None)
        if pivot is None:
            raise _Retry
        M[c], M[pivot] = M[pivot], M[c]
        inv = pow(M[c][c], -1, p)
        M[c] = [x * inv % p for x in M[c]]
        for r in range(n):
            if r != c and M[r][c]:
                f = M[r][c]
                M[r] = [(x - f * y) % p for x, y in zip(M[r], M[c])]
    return [M[r][n] for r in range(n)]


def is_zero_given(exprs: list[sp.Expr], unknowns: list[sp.Symbol], A: list[list[sp.Expr]], b: list[sp.Expr],
                  positive=frozenset(), seconds: float = 2.0, seed: int = 0) -> bool | None:
    """Every one of ``exprs`` identically zero on the physical domain where the ``unknowns`` are what
    ``A u = b`` makes them (the true accelerations: the mass matrix and the forces), without solving the
    system symbolically: at each random point modulo p it is solved by elimination modulo p. True, False
    (with its witness, `witness`), or None (outside the class, a singular system everywhere tried, time)."""
    try:
        with time_bound(seconds):
            whole, plan_ = prepare(sp.Tuple(*exprs, *(x for row in A for x in row), *b), positive)
            assumed = {s.name: s for s in whole.free_symbols if isinstance(s, sp.Symbol)}
            unknown = [assumed.get(u.name, sp.Symbol(u.name, real=True)) for u in unknowns]
            n, k = len(exprs), len(unknowns)
            items = list(whole.args)
            es, As, bs = items[:n], items[n:n + k * k], items[n + k * k:]
            if any(f.has(*unknown) for f in plan_.degree):
                raise OutsideClass("a root of an unknown")
            rng = random.Random(seed)
            for _ in range(POINTS):
                p = _choose_prime(rng, plan_)
                for _try in range(TRIES):
                    try:
                        ev = _Evaluator(plan_, p, rng)
                        Am = [[ev.ev(As[i * k + j]) for j in range(k)] for i in range(k)]
                        u = _solve_mod(Am, [ev.ev(x) for x in bs], p)
                        ev2 = _Evaluator.__new__(_Evaluator)  # the same point, with the unknowns solved
                        ev2.__dict__.update(ev.__dict__)
                        ev2.memo = {}
                        ev2.vars = {**ev.vars, **dict(zip(unknown, u))}
                        values = [ev2.ev(e) for e in es]
                    except _Retry:
                        continue
                    break
                else:
                    return None
                bad = next((v for v in values if v != 0), None)
                if bad is not None:
                    _LAST[0] = Witness("", p, bad, {str(x): v for x, v in ev2.vars.items() if not isinstance(x, tuple)})
                    return False
            return True
    except (OutsideClass, _OutOfTime):
        return None
    except (sp.PolynomialError, sp.polys.polyerrors.PolificationFailed, ValueError, TypeError,
            ZeroDivisionError, RecursionError, KeyError):
        return None


def outside(expr: sp.Expr, positive=frozenset()) -> str | None:
    """Why ``expr`` is outside the exact class, or None when it is inside."""
    try:
        prepare(expr, positive)
    except OutsideClass as exc:
        return str(exc)
    except Exception as exc:  # noqa: BLE001  (sympy failing to factor: outside, said so)
        return type(exc).__name__
    return None


#: nodes the reading's screen (`lagrade.verdicts.checkers.admit`) judges itself: switches, inverse
#: functions (folds), a problem's general functions and their derivatives
_SCREENED = (sp.Abs, sp.sign, sp.Piecewise, sp.Heaviside, sp.Max, sp.Min, sp.floor, sp.ceiling, sp.re, sp.im,
             sp.arg, sp.conjugate, sp.asin, sp.acos, sp.atan, sp.acot, sp.asec, sp.acsc, sp.atan2, sp.asinh,
             sp.acosh, sp.atanh, sp.acoth, sp.asech, sp.acsch, sp.Derivative, sp.Subs, sp.Integral)


def needs_proof(expr: sp.Expr, domain=frozenset()) -> str | None:
    """Why agreement at sampled points cannot accept ``expr`` (outside the exact class, in a way the screen
    does not already answer for), or None. ``0**(50 - m1)``, ``sqrt(exp(I*u/5))``, ``log(exp(I*u))``, a
    nested root, a root of a quantity whose sign the domain does not fix: each equals a right answer
    on the sampled box and not beyond it, and only a proof on the physical domain may accept it."""
    from sympy.core.function import AppliedUndef

    if isinstance(expr, sp.Equality):
        expr = expr.lhs - expr.rhs
    if not isinstance(expr, sp.Basic) or expr.has(*_SCREENED) or expr.atoms(AppliedUndef):
        return None
    why = outside(expr, domain)
    if why is None or why in (TRIG_ROOT, TRIG_IN_EXPONENT) or why.startswith("a function of an irrational constant") \
            or why.startswith("a rational multiple of pi") or why == "an expression too large to map":
        return None
    return why


def _point(symbols: list[sp.Symbol], domain) -> dict[sp.Symbol, sp.Expr] | None:
    """An exact point of the physical domain for ``symbols``: an interval's midpoint (its parameter ends at
    the point's own values), 3/4 where only positive, 1/3 where real; None where no point is found."""
    out: dict[sp.Symbol, sp.Expr] = {}
    rest = list(symbols)
    for _ in range(len(symbols) + 1):
        later = []
        for x in rest:
            d = None if isinstance(domain, (set, frozenset)) else domain.get(x.name)
            if d is not None:
                ends = d.bounds.parameters
                if not ends <= {y for y in out}:
                    later.append(x)
                    continue
                iv = d.bounds.at(out).interval
                lo, hi = iv.start, iv.end
                if lo.is_finite and hi.is_finite:
                    out[x] = (lo + hi) / 2
                elif lo.is_finite:
                    out[x] = lo + sp.Rational(3, 4)
                elif hi.is_finite:
                    out[x] = hi - sp.Rational(3, 4)
                else:
                    out[x] = sp.Rational(1, 3)
            else:
                out[x] = sp.Rational(3, 4) if x.is_positive else sp.Rational(1, 3)
        rest = later
        if not rest:
            return out
    return None


def _inside(x: sp.Symbol, value: sp.Expr, point: dict, domain) -> bool:
    d = None if isinstance(domain, (set, frozenset)) else domain.get(x.name)
    if d is None:
        return not x.is_positive or value > 0
    params = {sp.Symbol(y.name): v for y, v in point.items()}
    return d.bounds.contains(value, params if d.bounds.parameters else None) is True


def vanishes_in_domain(f: sp.Expr, domain=frozenset()) -> bool:
    """A point of the physical domain where ``f`` is exactly zero: the other symbols at a point of their
    domains (``_point``), a real root in one symbol ``f`` is polynomial in, inside that symbol's domain."""
    free = sorted(f.free_symbols, key=str)
    for x in free:
        point = _point([y for y in free if y != x], domain)
        if point is None:
            continue
        g = f.xreplace(point)
        if g.is_polynomial(x):
            if any(_inside(x, root, point, domain) for root in sp.Poly(g, x).real_roots()):
                return True
            continue
        d = None if isinstance(domain, (set, frozenset)) else domain.get(x.name)
        where = d.bounds.at({sp.Symbol(y.name): v for y, v in point.items()}).interval if d is not None else sp.S.Reals
        try:  # cos(2*alpha) on 0 < alpha < pi/2: solveset finds pi/4
            with time_bound(1.0):
                roots = sp.solveset(g, x, where)
                if isinstance(roots, sp.FiniteSet) and len(roots) > 0 or roots.is_empty is False:
                    return True
                if _sign_change(g, x, where):
                    return True
        except Exception:  # noqa: BLE001  (sympy gave up: no witness)
            continue
    return False


def _sign_change(g: sp.Expr, x: sp.Symbol, where: sp.Interval) -> bool:
    """A root by the intermediate value theorem: opposite signs at two exact points of the domain with
    ``g`` continuous between them (cos(u) on u > 0, where solveset answers with a set it cannot count)."""
    lo = where.start if where.start.is_finite else (where.end - 20 if where.end.is_finite else sp.Integer(-20))
    hi = where.end if where.end.is_finite else lo + 20
    points = [lo + (hi - lo) * sp.Rational(k, 64) for k in range(1, 64)]
    signs = []
    for a in points:
        v = sp.N(g.xreplace({x: a}), 30)
        signs.append((a, 0 if not v.is_Number else (1 if v > 0 else -1 if v < 0 else 0)))
    for (a, sa), (b, sb) in zip(signs, signs[1:]):
        if sa * sb < 0 and sp.calculus.util.continuous_domain(g, x, sp.Interval(a, b)) == sp.Interval(a, b):
            return True
    return False


def proportional(f: sp.Expr, g: sp.Expr, positive=frozenset(), seconds: float = 1.0) -> bool:
    """``f`` a constant multiple of ``g`` (decided here: every derivative of ``f/g`` zero)."""
    ratio = f / g
    return all(is_zero(sp.diff(ratio, x), positive, seconds) is True for x in f.free_symbols | g.free_symbols)


def _factors(e: sp.Expr) -> list[sp.Expr]:
    return [f for f, _ in sp.factor_list(e)[1] if f.free_symbols]


#: the quantity each of these functions divides by: tan(a) = sin(a)/cos(a) has its poles where cos(a) = 0
_DIVIDES_BY = {sp.tan: sp.cos, sp.sec: sp.cos, sp.cot: sp.sin, sp.csc: sp.sin,
               sp.tanh: sp.cosh, sp.sech: sp.cosh, sp.coth: sp.sinh, sp.csch: sp.sinh}


def poles(expr: sp.Expr) -> set[sp.Expr]:
    """Every quantity ``expr`` divides by, anywhere in it (inside a function too: exp(1/(m1 - 50)), and
    the cos(u) of a tan(u))."""
    out = {b for b, e in (x.as_base_exp() for x in expr.atoms(sp.Pow)) if e.is_negative}
    return out | {_DIVIDES_BY[type(n)](n.args[0]) for n in expr.atoms(sp.Function) if type(n) in _DIVIDES_BY}


def new_singularity(expr: sp.Expr, reference: sp.Expr, positive=frozenset(),
                    seconds: float = 2.0) -> str | None:
    """A factor of a quantity ``expr`` divides by, anywhere in it, that vanishes somewhere on the physical
    domain and is none of ``reference``'s: ``right*(m1**2 - 2500)/((m1 - 50)*(m1 + 50))`` is undefined at
    m1 = 50, ``right*tan(u)*cot(u)`` at u = 0. The witness is an exact root (``vanishes_in_domain``);
    None when there is none or the test gave up."""
    bases = [b for b in poles(_assume(expr, positive)) if not (b.is_positive or b.is_negative)]
    if not bases:  # no denominator that can vanish: the common case, at no factoring
        return None
    try:
        with time_bound(seconds):
            own = [f for b in poles(_assume(reference, positive)) for f in _factors(b)]
            for b in bases:
                for f in _factors(b):
                    if f.is_positive or f.is_negative or sign_on_domain(f, positive) is not None:
                        continue
                    if any(proportional(f, g, positive, seconds) for g in own):
                        continue
                    if vanishes_in_domain(f, positive):
                        return sp.sstr(f)
    except Exception:  # noqa: BLE001  (sympy failing to factor, or time: no witness)
        return None
    return None


#: inverse functions whose principal values lie in [-pi/2, pi/2] (where sin is one to one) and in
#: [0, pi] (where cos is)
_HALF = {"asin", "atan", "acsc"}
_UPPER = {"acos", "asec"}


def same_angle(a: sp.Expr, b: sp.Expr, positive=frozenset(), seconds: float = 2.0) -> bool | None:
    """Two inverse functions (``asin(mu/sqrt(1 + mu**2))`` and ``atan(mu)``) decided through the function
    that both invert on one interval: with both principal values in [-pi/2, pi/2], they are equal iff
    their sines are (sin is one to one there), and likewise cos on [0, pi]. None for any other pair."""
    ca, ea = a.as_coeff_Mul()
    cb, eb = b.as_coeff_Mul()
    if ca != cb or not (isinstance(ea, sp.Function) and isinstance(eb, sp.Function)):
        return None
    fa, fb = type(ea).__name__, type(eb).__name__
    if fa in _HALF and fb in _HALF:
        forward = sp.sin
    elif fa in _UPPER and fb in _UPPER:
        forward = sp.cos
    elif {fa, fb} <= _HALF | _UPPER:
        # acos(sqrt(1 - v**2)) and asin(v): the asin is in [0, pi/2] where v >= 0 on the domain, and cos is
        # one to one on [0, pi]; where v < 0 somewhere they differ there
        half = ea if fa in _HALF else eb
        if sign_on_domain(_assume(half.args[0], positive), positive) != 1:
            return None
        forward = sp.cos
    else:
        return None
    return is_zero(forward(ea) - forward(eb), positive, seconds)


def agrees_to_digits(value: sp.Float, exact_value: sp.Expr, least: int = 3) -> bool:
    """A decimal typed for a pure number (an angle, a ratio) is right when it agrees with the exact value
    to every digit typed (its shortest decimal form, at least ``least`` significant digits): within half
    a unit of its last digit (sympy's evalf, which controls its own error, at 60 digits)."""
    text = repr(float(value)) if value._prec <= 53 else sp.sstr(value)
    text = text.lower()
    mantissa, _, exp = text.partition("e")
    digits = mantissa.lstrip("-").replace(".", "").lstrip("0")
    if sp.Rational(text) == exact_value:  # 0.5 is 1/2, whatever its digits
        return True
    if len(digits) < least:
        return False
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    half_unit = sp.Rational(1, 2) * sp.Integer(10) ** (int(exp or 0) - decimals)
    gap = abs(sp.N(exact_value - sp.Rational(text), 60))
    return bool(gap.is_Number and gap < half_unit)
