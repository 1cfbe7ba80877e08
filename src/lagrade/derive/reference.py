"""Reference derivation: from a scene (L or T and V, forces, constraints) to its dynamics.

Everything the grader compares against is derived here from the problem file, never typed in
by hand: Lagrange's equations as a mass matrix and a force vector (``M qdd = f``), the momenta,
the Hamiltonian by Legendre transform, and the multipliers of the constraints. Numerical forms
are compiled once; symbolic closed forms (which can be slow) are built only when asked for.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cached_property

import numpy as np
import sympy as sp

from lagrade.derive.general_functions import arities, random_function, substitute
from lagrade.problem.notation import parse_math
from lagrade.numbers.numeric import (
    Vectorized,
    as_row,
    call_blocks,
    compile_exprs,
    compile_linear_solve,
)
from lagrade.problem.spec import Problem, SceneError, System
from lagrade.problem.symbols import StateSymbols, T, to_state


def total_derivative(expr: sp.Expr, s: StateSymbols) -> sp.Expr:
    """d/dt of a function of (q, qd, t), introducing qdd: the chain rule, without sympy Functions."""
    out = sp.diff(expr, T)
    for q, qd, qdd in zip(s.q, s.qd, s.qdd):
        out += sp.diff(expr, q) * qd + sp.diff(expr, qd) * qdd
    return out


def euler_lagrange(L: sp.Expr, s: StateSymbols) -> list[sp.Expr]:
    """d/dt dL/dqd - dL/dq for each coordinate."""
    return [total_derivative(sp.diff(L, qd), s) - sp.diff(L, q) for q, qd in zip(s.q, s.qd)]



def split_energy(L: sp.Expr, mech: Mechanics) -> tuple[sp.Expr, sp.Expr]:
    """T and V from L: terms with velocities are kinetic, the rest is -V (for diagnostics, and for
    the energy the stability checks follow)."""
    terms = sp.Add.make_args(sp.expand(L))
    vel = set(mech.s.qd)
    kin = sp.Add(*[term for term in terms if term.free_symbols & vel])
    return kin, -(sp.expand(L) - kin)


#: the scene's fields a parse error names, for its line in the problem file
_FIELDS = {"L": "L", "T": "T", "V": "V", "Q": "Q"}


class Mechanics:
    """The dynamics of one system of a problem, in plain state symbols."""

    def __init__(self, problem: Problem, system: System, instance: int = 0):
        self.problem = problem
        self.system = system
        #: which function stands for each general function (`lagrade.derive.general_functions`): instance 0
        #: is the problem's concrete one, the others random ones
        self.instance = instance
        self.functions: dict[str, sp.Lambda] = {}
        self._parsed: dict[tuple, sp.Expr] = {}
        self._points: dict[tuple, object] = {}
        self.runs: dict[tuple, tuple] = {}  # reference integrations (lagrade.compare.trajectory)
        self.linearized: dict[tuple, tuple] = {}  # the EL rows' linear parts (checkers.dynamics)
        self._rows_of: dict[sp.Expr, list[sp.Expr]] = {}  # answers' Lagrange equations (not kept on disk)
        self.all_names = tuple(c.name for c in system.coordinates)
        self.names = tuple(c.name for c in system.free_coordinates)
        self.full = StateSymbols(self.all_names)
        self.s = StateSymbols(self.names)
        self.parameters = problem.parameters_of(system.key)
        self.params = [sp.Symbol(p.name) for p in self.parameters]
        self.multipliers = [sp.Symbol(c.multiplier) for c in system.constraints if c.multiplier]
        known = [p.name for p in self.parameters]
        parse = lambda text, what: self._parse(text, what, known)  # noqa: E731
        for f in system.functions:
            if instance:
                self.functions[f.name] = random_function(f, instance)
            else:
                body = self._parse_plain(f.concrete, f"function {f.name}", [*known, *f.args])
                self.functions[f.name] = sp.Lambda(tuple(sp.Symbol(a) for a in f.args), body)

        if system.L is not None:
            L_full = parse(system.L, "L")
        else:
            L_full = parse(system.T, "T") - (parse(system.V, "V") if system.V else 0)
        Q_full = {n: parse(system.Q.get(n, "0"), f"Q.{n}") for n in self.all_names}

        # Constraint c = v(other q, t): substitute c, c_d, c_dd everywhere.
        fixed: dict[sp.Symbol, sp.Expr] = {}
        for c in system.constraints:
            value = parse(c.value, f"constraint on {c.coordinate}")
            if value.free_symbols & {sp.Symbol(k.coordinate) for k in system.constraints}:
                raise SceneError(f"constraint on {c.coordinate} must not depend on another constrained coordinate")
            v_d = total_derivative(value, self.s)
            fixed[sp.Symbol(c.coordinate)] = value
            fixed[sp.Symbol(f"{c.coordinate}_d")] = v_d
            fixed[sp.Symbol(f"{c.coordinate}_dd")] = total_derivative(v_d, self.s)
        self.constrained = fixed
        self.L_full = L_full
        self.L = sp.expand(L_full.xreplace(fixed)) if fixed else L_full
        # Generalized forces pull back through the constraints by virtual work.
        self.Q = []
        for q, name in zip(self.s.q, self.names):
            total = Q_full[name]
            for c in system.constraints:
                total += Q_full[c.coordinate] * sp.diff(fixed[sp.Symbol(c.coordinate)], q)
            self.Q.append(total.xreplace(fixed) if fixed else total)
        # Multipliers: the constrained coordinate's own Lagrange equation, on the constrained motion.
        full_el = dict(zip(self.all_names, euler_lagrange(L_full, self.full)))
        self.multiplier_exprs = {
            sp.Symbol(c.multiplier): (full_el[c.coordinate] - Q_full[c.coordinate]).xreplace(fixed)
            for c in system.constraints if c.multiplier
        }
        self.EL = [e - Qi for e, Qi in zip(euler_lagrange(self.L, self.s), self.Q)]
        self.mass = sp.Matrix([[sp.diff(e, a) for a in self.s.qdd] for e in self.EL])
        zero_acc = {a: 0 for a in self.s.qdd}
        self.force = [-e.xreplace(zero_acc) for e in self.EL]
        if any(self.mass.has(a) for a in self.s.qdd):
            raise SceneError("Lagrange's equations are not linear in the accelerations")
        from lagrade.derive.effects import (
            validate_effects,  # a scene may only use the effects it declares
        )

        validate_effects(self)

    def __getstate__(self) -> dict:
        return {**self.__dict__, "problem": None, "_rows_of": {}, "_scene_models": {}}  # see ReferenceCache

    def lagrange_rows(self, L: sp.Expr) -> list[sp.Expr]:
        """``d/dt dL/dq' - dL/dq - Q`` of any Lagrangian on this system's coordinates, with the scene's
        forces. Differentiating is the slow part of checking an L (sympy re-derives assumptions), and
        the value check, the solver for its motion and a proof all need the same rows: made once."""
        if L == self.L:
            return self.EL
        rows = self._rows_of.get(L)
        if rows is None:
            if len(self._rows_of) >= 64:
                self._rows_of.pop(next(iter(self._rows_of)))
            rows = self._rows_of[L] = [e - Qi for e, Qi in zip(euler_lagrange(L, self.s), self.Q)]
        return rows

    def _where(self, what: str) -> str:
        return f"system '{self.system.key}', {what}" if self.system.key else what

    def _parse(self, text: str, what: str, params: Sequence[str]) -> sp.Expr:
        extra = [c.multiplier for c in self.system.constraints if c.multiplier]
        try:
            expr = parse_math(text, list(self.all_names), known_names=[*params, *extra, "t"],
                              functions=arities(self.system))
            return sp.sympify(to_state(substitute(expr, self.functions), self.all_names))
        except Exception as exc:  # a one-line reason naming the field
            raise SceneError(f"{self._where(what)}: {str(exc).replace('answer is not', 'the text is not', 1)}",
                             self.system.key, _FIELDS.get(what.split(".")[0])) from None

    def _parse_plain(self, text: str, what: str, names: Sequence[str]) -> sp.Expr:
        """An expression in plain symbols (a general function's concrete form, in its arguments)."""
        try:
            return sp.sympify(parse_math(text, [], known_names=[*names, "t"]))
        except Exception as exc:  # a one-line reason naming the field
            raise SceneError(f"{self._where(what)}: {str(exc).replace('answer is not', 'the text is not', 1)}",
                             self.system.key, _FIELDS.get(what.split(".")[0])) from None

    def parse(self, text: str, extra: Sequence[str] = ()) -> sp.Expr:
        """Parse a reference expression of this system (may use ``q_dd`` and multipliers); cached,
        since every answer to the problem is compared with the same references."""
        key = (text, tuple(extra))
        if key not in self._parsed:
            self._parsed[key] = self._parse(text, "reference", [p.name for p in self.parameters] + list(extra))
        return self._parsed[key]

    # ----- numerical forms ---------------------------------------------------------------
    @property
    def args(self) -> list[sp.Symbol]:
        """Argument order of every compiled function: q, qd, t, parameters."""
        return [*self.s.q, *self.s.qd, T, *self.params]

    @cached_property
    def _mass_f(self) -> Vectorized:
        return compile_exprs(list(self.mass), self.args)

    @cached_property
    def _accelerations_f(self) -> Vectorized:
        """M qdd = f solved in one compiled call per right-hand side (shared subexpressions)."""
        n = len(self.s.q)
        return compile_linear_solve([list(self.mass.row(i)) for i in range(n)], list(self.force), self.args)

    def accelerations(self, q: np.ndarray, qd: np.ndarray, t: np.ndarray, params: np.ndarray) -> np.ndarray:
        """qdd for a batch of states: shapes (n, K) -> (n, K); t a number or (K,), params (P,) or (P, K)."""
        params = np.asarray(params, dtype=float)
        return call_blocks(self._accelerations_f, q, qd, as_row(t),
                           params if params.ndim == 2 else params.reshape(-1, 1))

    @cached_property
    def _momentum_f(self) -> Vectorized:
        return compile_exprs([sp.diff(self.L, v) for v in self.s.qd], self.args)

    def momenta(self, q: np.ndarray, qd: np.ndarray, t: np.ndarray, params: np.ndarray) -> np.ndarray:
        return self._momentum_f(*q, *qd, t, *params)

    @cached_property
    def _lagrangian_f(self) -> Vectorized:
        return compile_exprs([self.L], self.args)

    @cached_property
    def _dLdq_f(self) -> Vectorized:
        return compile_exprs([sp.diff(self.L, q) + Qi for q, Qi in zip(self.s.q, self.Q)], self.args)

    def velocities(self, q: np.ndarray, p: np.ndarray, t: np.ndarray, params: np.ndarray) -> np.ndarray:
        """Invert p = dL/dqd numerically (L is quadratic in the velocities: p = A qd + b)."""
        return self._velocities_f(*q, *p, t, *params)

    @cached_property
    def _velocities_f(self) -> Vectorized:
        zero = {v: 0 for v in self.s.qd}
        A = [[sp.diff(self.L, a, b).xreplace(zero) for b in self.s.qd] for a in self.s.qd]
        rhs = [p - sp.diff(self.L, v).xreplace(zero) for p, v in zip(self.s.p, self.s.qd)]
        return compile_linear_solve(A, rhs, [*self.s.q, *self.s.p, T, *self.params])

    def hamiltonian(self, q: np.ndarray, p: np.ndarray, t: np.ndarray, params: np.ndarray) -> np.ndarray:
        """H(q, p, t) = p.qd - L by a numerical Legendre transform: no symbolic inversion needed."""
        qd = self.velocities(q, p, t, params)
        return (p * qd).sum(axis=0) - self._lagrangian_f(*q, *qd, t, *params)[0]

    def hamilton_rates(self, q: np.ndarray, p: np.ndarray, t: np.ndarray, params: np.ndarray) -> np.ndarray:
        """(q', p') of Hamilton's equations, using dH/dq|p = -dL/dq|qd."""
        qd = self.velocities(q, p, t, params)
        pd = self._dLdq_f(*q, *qd, t, *params)
        return np.concatenate([qd, pd])

    @cached_property
    def is_quadratic_in_velocities(self) -> bool:
        return all(sp.diff(self.L, a, b, c) == 0 for a in self.s.qd for b in self.s.qd for c in self.s.qd)

    # ----- symbolic forms (slower; built on demand) ----------------------------------------
    @cached_property
    def accelerations_symbolic(self) -> list[sp.Expr]:
        sol = self.mass.LUsolve(sp.Matrix(self.force))
        return [sp.cancel(sp.together(e)) for e in sol]

    @cached_property
    def hamiltonian_symbolic(self) -> sp.Expr:
        zero = {v: 0 for v in self.s.qd}
        b = sp.Matrix([sp.diff(self.L, v).xreplace(zero) for v in self.s.qd])
        M = sp.Matrix([[sp.diff(self.L, a, c) for c in self.s.qd] for a in self.s.qd])
        qd = M.LUsolve(sp.Matrix(self.s.p) - b)
        H = sum(pi * v for pi, v in zip(self.s.p, qd)) - self.L.xreplace(dict(zip(self.s.qd, qd)))
        return sp.cancel(sp.together(sp.expand(H)))


class ReferenceCache:
    """One `Mechanics` per system of a problem, derived once and reused by every part (and kept on
    disk between processes by :mod:`lagrade.derive.cache`)."""

    def __init__(self, problem: Problem):
        self.problem = problem
        self.systems: dict[str, Mechanics] = {}
        self.saved_size = 0

    def __getitem__(self, key: str) -> Mechanics:
        if key not in self.systems:
            self.systems[key] = Mechanics(self.problem, self.problem.system(key))
        return self.systems[key]

    def instance(self, key: str, instance: int) -> Mechanics:
        """System ``key`` with random function ``instance`` (1, 2, ...) put for its general functions;
        instance 0 is the system itself, with the problem's concrete functions."""
        if not instance:
            return self[key]
        name = f"{key}\0{instance}"  # kept with the systems, so the disk cache holds them too
        if name not in self.systems:
            self.systems[name] = Mechanics(self.problem, self.problem.system(key), instance)
        return self.systems[name]

    def size(self) -> int:
        """How much has been derived: grows whenever something new is (the disk cache's dirty check)."""
        return sum(1 + len(m.__dict__) + len(m._parsed) + len(m._points) + len(m.runs) + len(m.linearized)
                   for m in self.systems.values())

    def __getstate__(self) -> dict:
        return {**self.__dict__, "problem": None}  # the loader puts back the problem it loaded
