"""Declared effects: what a scene says it involves, checked against what its expressions use.

A scene declares its physical effects (``effects = [...]`` in the problem file). The numerical model
is assembled from those declarations only (`lagrade.compare.scene_model`): contact events only for
unilateral contact, multiplier functions only when constraint forces are asked, an explicit time
argument only for time-dependent scenes, velocity-dependent forces (and their switching events)
only for dissipation. For that to be safe, a scene must not *use* an effect it does not declare;
`validate_effects` rejects such a scene when it is derived (``Mechanics.__init__``) with a message
that names the expression and the effect to declare.

`machinery` says which pieces of numerical machinery the declared effects call for; `lagrade bench
effects` and ``lagrade show`` print it.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from typing import Any, Protocol, get_args

import sympy as sp

from lagrade.problem.spec import Effect, SceneError
from lagrade.problem.symbols import T

class Mechanics(Protocol):
    """What the effect rules read of a derived scene (`lagrade.derive.reference.Mechanics` is one):
    a protocol, so that the rules sit below the derivation that calls them."""

    problem: Any
    system: Any
    names: list[str]
    Q: list[sp.Expr]
    L_full: sp.Expr
    constrained: dict[sp.Symbol, sp.Expr]
    s: Any          # the reduced coordinates (``.qd``: their velocities)
    full: Any       # every coordinate, constrained ones included
    multipliers: list[sp.Symbol]
    parameters: list[Any]

VOCABULARY = frozenset(get_args(Effect))

#: Effects that make the scene's equations depend on t explicitly. ``applied_force`` covers a
#: prescribed external force law F(q, t) (12.48, 12.50), which may depend on time;
#: ``time_dependent_force`` is accepted too if the vocabulary gains it.
TIME_EFFECTS = frozenset({"time_dependent_constraint", "driven_support", "time_dependent_force"})
TIME_CAPABLE = TIME_EFFECTS | {"applied_force"}
DISSIPATION = frozenset({"dissipation_drag", "dissipation_friction"})
FORCE_EFFECTS = DISSIPATION | {"applied_force", "time_dependent_force"}
CONSTRAINT_EFFECTS = frozenset({"holonomic_constraint", "time_dependent_constraint", "rolling_constraint",
                                "nonholonomic"})


@dataclass(frozen=True)
class Machinery:
    """The pieces of numerical machinery a scene's model is built with (and nothing else)."""

    explicit_time: bool = False
    velocity_forces: bool = False
    switching: tuple[str, ...] = ()        # arguments of Abs/sign in dissipative forces: switching events
    multipliers: tuple[str, ...] = ()      # constraint forces computed along the motion
    contact_events: tuple[str, ...] = ()   # multipliers whose zero ends a unilateral contact
    notes: tuple[str, ...] = field(default=(), compare=False)

    def lines(self) -> list[str]:
        out = [
            f"explicit time dependence: {'yes (t is an argument of the equations)' if self.explicit_time else 'no (autonomous)'}",
            "velocity-dependent forces: " + ("yes (dissipation)" if self.velocity_forces else "no"),
            "switching events (sign changes of dissipative forces): " + (", ".join(self.switching) or "none"),
            "constraint-force multipliers: " + (", ".join(self.multipliers) or "none"),
            "contact-loss events: " + (", ".join(f"{m} = 0" for m in self.contact_events) or "none"),
        ]
        return out + [f"note: {n}" for n in self.notes]


class EffectsError(ValueError):
    """A scene that uses an effect it does not declare."""


def _jumps(expr: sp.Expr, arg: sp.Expr, velocities: set[sp.Symbol]) -> bool:
    """Does ``expr`` jump where ``arg`` (a function of the velocities) crosses zero? Measured at a
    random point: the velocity ``arg`` is linear in is set to ``arg = +-1e-9``, the rest in [0.5, 1.5].
    v/|v| jumps by 2; v|v| (quadratic drag) does not (2e-18 against its size 1 at unit speed)."""
    import numpy as np

    v = next((x for x in sorted(arg.free_symbols & velocities, key=str)
              if sp.diff(arg, x).free_symbols.isdisjoint({x})), None)
    if v is None:
        return True  # a switch of a nonlinear velocity argument: treat it as a jump
    rng = np.random.default_rng(7)
    others = {x: float(rng.uniform(0.5, 1.5)) for x in expr.free_symbols | arg.free_symbols if x != v}
    slope = float(sp.diff(arg, v).xreplace(others))
    if slope == 0:
        return True
    at_zero = -float(arg.xreplace({**others, v: 0})) / slope

    def value(dv: float) -> float:
        return complex(expr.xreplace({**others, v: sp.Float(at_zero + dv / slope, 30)}).evalf(30)).real

    size = max(abs(value(1.0)), abs(value(-1.0)), 1e-300)
    return abs(value(1e-9) - value(-1e-9)) > 1e-6 * size


def dry_friction_form(expr: sp.Expr, velocities: set[sp.Symbol]) -> sp.Expr:
    """A force law that jumps when a velocity changes sign, written with ``sign()``: ``v/Abs(v)``,
    ``Abs(v)/v``, ``Heaviside(v)`` and a two-branch ``Piecewise`` on ``v > 0`` are dry friction
    as much as ``sign(v)`` is, and the scene model's sticking and breakaway need to see them so.
    Continuous laws (``v*Abs(v)``, quadratic drag) keep their ``Abs``."""
    expr = sp.sympify(expr)
    rep: dict[sp.Basic, sp.Basic] = {}
    for h in expr.atoms(sp.Heaviside):
        if h.args[0].free_symbols & velocities:
            rep[h] = (1 + sp.sign(h.args[0])) / 2
    for pw in expr.atoms(sp.Piecewise):
        cond = pw.args[0].cond if len(pw.args) == 2 and pw.args[1].cond == sp.true else None
        if isinstance(cond, (sp.StrictGreaterThan, sp.GreaterThan, sp.StrictLessThan, sp.LessThan)) \
                and (cond.lhs - cond.rhs).free_symbols & velocities:
            arg = cond.lhs - cond.rhs if isinstance(cond, (sp.StrictGreaterThan, sp.GreaterThan)) else cond.rhs - cond.lhs
            A, B = pw.args[0].expr, pw.args[1].expr
            rep[pw] = (A + B) / 2 + (A - B) / 2 * sp.sign(arg)
    expr = expr.xreplace(rep) if rep else expr
    for ab in sorted(expr.atoms(sp.Abs), key=sp.default_sort_key):
        arg = ab.args[0]
        if arg.free_symbols & velocities and _jumps(expr, arg, velocities):
            expr = expr.xreplace({ab: arg * sp.sign(arg)})
            # sign(a)**k away from a = 0: sign for odd k, 1 for even
            expr = expr.replace(lambda e: e.is_Pow and isinstance(e.base, sp.sign) and e.exp.is_Integer,
                                lambda e: e.base if int(e.exp) % 2 else sp.S.One)
    return expr


def _velocity_switches(expr: sp.Expr, velocities: set[sp.Symbol]) -> list[sp.Expr]:
    """Arguments of Abs and sign that depend on velocities: where a dissipative force changes branch.
    One per switch: of the forms of one function (up to sign) the first one written."""
    return [group[0][0] for group in switch_groups([expr], velocities)]


def switch_groups(exprs: list[sp.Expr], velocities: set[sp.Symbol]) -> list[list[tuple[sp.Expr, int]]]:
    """The velocity-dependent arguments of Abs and sign in ``exprs``, grouped by the function they are up
    to sign: per group [(form, +1 or -1 against the group's first form)]. A student's rows come here, so
    forms are compared by value (`same_up_to_sign`), never by ``simplify``."""
    groups: list[list[tuple[sp.Expr, int]]] = []
    for expr in exprs:
        for f in sp.preorder_traversal(expr):
            if not (isinstance(f, (sp.Abs, sp.sign)) and f.args[0].free_symbols & velocities):
                continue
            a = f.args[0]
            if any(a == form for group in groups for form, _ in group):
                continue
            for group in groups:
                relation = same_up_to_sign(a, group[0][0])
                if relation:
                    group.append((a, relation))
                    break
            else:
                groups.append([(a, 1)])
    return groups


def same_up_to_sign(a: sp.Expr, b: sp.Expr, points: int = 3) -> int:
    """+1 where ``a`` and ``b`` are one function, -1 where a = -b, 0 otherwise: by value at seeded random
    points, since ``simplify`` on a student's ``v + w (1 + x)^n - w`` takes seconds that grow with n."""
    if a == b:
        return 1
    if a == -b:
        return -1
    free = sorted((a - b).free_symbols, key=str)
    rng = random.Random(0)
    relation = None
    for _ in range(points):
        at = {x: sp.Float(rng.uniform(0.3, 1.7)) for x in free}
        try:
            va, vb = complex(a.xreplace(at).evalf(30)), complex(b.xreplace(at).evalf(30))
        except (TypeError, ValueError, ZeroDivisionError):
            return 0
        tol = 1e-12 * (1.0 + abs(va))
        here = 1 if abs(va - vb) <= tol else -1 if abs(va + vb) <= tol else 0
        if here == 0 or (relation is not None and here != relation):
            return 0
        relation = here
    return relation or 0


def _uses_time(mech: Mechanics) -> list[str]:
    where = []
    if mech.L_full.has(T):
        where.append("L" if mech.system.L is not None else "T/V")
    where += [f"Q.{n}" for n, e in zip(mech.names, mech.Q) if e.has(T)]
    where += [f"constraint on {c.coordinate}" for c in mech.system.constraints
              if mech.constrained.get(sp.Symbol(c.coordinate), sp.S.Zero).has(T)]
    return where


def validate_effects(mech: Mechanics) -> None:
    """Raise `SceneError` naming every effect the scene uses but does not declare."""
    sys_ = mech.system
    eff = set(sys_.effects)
    label = f"system '{sys_.key}'" if sys_.key else "the scene"
    problems: list[str] = []
    time_where = _uses_time(mech)
    if time_where and not eff & TIME_CAPABLE:
        problems.append(f"{', '.join(time_where)} depend(s) on t explicitly: declare a time-dependent effect "
                        "(time_dependent_constraint, driven_support, or applied_force for a prescribed force law F(q, t))")
    cons_t = [c.coordinate for c in sys_.constraints if mech.constrained[sp.Symbol(c.coordinate)].has(T)]
    if cons_t and not eff & {"time_dependent_constraint", "driven_support"}:
        problems.append(f"the constraint on {', '.join(cons_t)} moves with t: declare time_dependent_constraint")
    if sys_.constraints and not eff & CONSTRAINT_EFFECTS:
        problems.append("it has constraints: declare holonomic_constraint (or time_dependent_constraint)")
    velocities = set(mech.s.qd) | set(mech.full.qd)
    q_exprs = dict(zip(mech.names, mech.Q))
    if any(e != 0 for e in q_exprs.values()) and not eff & FORCE_EFFECTS:
        problems.append(f"Q ({', '.join(n for n, e in q_exprs.items() if e != 0)}) is a generalized force: declare "
                        "applied_force, dissipation_drag or dissipation_friction")
    vel_q = [n for n, e in q_exprs.items() if e.free_symbols & velocities]
    if vel_q and not eff & DISSIPATION:
        problems.append(f"Q.{', Q.'.join(vel_q)} depend(s) on the velocities (a velocity-dependent force): declare "
                        "dissipation_drag or dissipation_friction")
    signs = [n for n, e in q_exprs.items() if any(f.args[0].free_symbols & velocities
                                                   for f in dry_friction_form(e, velocities).atoms(sp.sign))]
    if signs and "dissipation_friction" not in eff:
        problems.append(f"Q.{', Q.'.join(signs)} switch(es) sign with the velocity (dry friction): declare "
                        "dissipation_friction")
    if mech.multipliers and "constraint_force" not in eff:
        problems.append(f"multiplier(s) {', '.join(map(str, mech.multipliers))} (constraint forces) are asked: declare "
                        "constraint_force")
    if "g" in {str(s) for s in mech.L_full.free_symbols} and "g" in {p.name for p in mech.parameters} \
            and "gravity" not in eff:
        problems.append("V uses g: declare gravity")
    if any(p.linearized and p.system == sys_.key for p in mech.problem.parts) \
            and "small_oscillation_linearization" not in eff:
        problems.append("a part is linearized about equilibrium: declare small_oscillation_linearization")
    if problems:
        raise SceneError(f"{label} uses effects it does not declare (effects = {sorted(eff)}): " + "; ".join(problems),
                         system=sys_.key, field="effects")


def machinery(mech: Mechanics) -> Machinery:
    """The machinery the *declared* effects call for (validated to cover what the scene uses)."""
    eff = set(mech.system.effects)
    explicit_time = bool(eff & TIME_EFFECTS) or ("applied_force" in eff and bool(_uses_time(mech)))
    velocity_forces = bool(eff & DISSIPATION)
    switching: list[str] = []
    if velocity_forces:
        vel = set(mech.s.qd)
        for e in mech.Q:
            for arg in _velocity_switches(dry_friction_form(e, vel), vel):
                if str(arg) not in switching:
                    switching.append(str(arg))
    with_mult = [c for c in mech.system.constraints if c.multiplier]
    multipliers = tuple(c.multiplier for c in with_mult) if "constraint_force" in eff else ()
    notes: list[str] = []
    contact: tuple[str, ...] = ()
    if "unilateral_contact" in eff:
        if with_mult:
            contact = tuple(c.multiplier for c in with_mult)
        else:
            notes.append("unilateral contact is declared but no constraint carries a multiplier: contact is "
                         "assumed to hold over the sampled window (no contact-loss event can be located)")
    return Machinery(explicit_time, velocity_forces, tuple(switching), multipliers, contact, tuple(notes))
