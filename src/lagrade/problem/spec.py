"""The problem file: what a problem is, as data.

A problem file is untrusted input written by instructors; it is validated here, once, so that
the engine can rely on every field. Expressions stay text until `lagrade.scene` parses them with
the same no-eval parser that reads students' text answers.
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path
from typing import Annotated, Any, Literal, NamedTuple, get_args

import sympy as sp
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

from lagrade.problem.domains import Domain, DomainError, Role, parse_domain
from lagrade.problem.symbols import T, StateSymbols

IDENT = r"^[A-Za-z][A-Za-z0-9_]*$"
#: problem ids are free (any course): letters, digits, ".", "_", "-", starting with a letter or digit
ID = r"^[A-Za-z0-9][A-Za-z0-9._-]{0,63}$"

#: The physical effects a scene may declare (the catalogue's vocabulary).
Effect = Literal[
    "gravity",
    "spring",
    "central_force",
    "rigid_body_rotation",
    "rolling_constraint",
    "holonomic_constraint",
    "constraint_force",
    "time_dependent_constraint",
    "rotating_frame",
    "driven_support",
    "dissipation_drag",
    "dissipation_friction",
    "applied_force",
    "nonholonomic",
    "velocity_dependent_potential",
    "unilateral_contact",
    "small_oscillation_linearization",
]

#: What each effect means, for the author choosing them (docs/authoring-problems.md's table): when to
#: declare it, and what it changes. Most are labels (``lagrade show`` prints them; the derivation
#: refuses a scene that visibly uses one it does not declare); a few switch numerical machinery on
#: (``lagrade.derive.effects.machinery``), and those must be declared for the scene to be integrated right.
EFFECT_MEANINGS: dict[str, str] = {
    "gravity": "a uniform gravitational field: V uses g (required then)",
    "spring": "an elastic force: V holds a spring's k*(stretch)**2/2",
    "central_force": "a force toward a fixed centre, V(r)",
    "rigid_body_rotation": "a body's rotational kinetic energy I*omega**2/2 is in T",
    "rolling_constraint": "rolling without slipping ties a rotation to a translation",
    "holonomic_constraint": "the bodies are held on a curve or surface (a rod, a hoop, a wire), or `constraints` "
                            "are given (required then)",
    "constraint_force": "a constraint's multiplier (its force) is asked: computed along the motion (required then)",
    "time_dependent_constraint": "a constraint moves with t (a support driven, a hoop or wire turned at a given "
                                 "rate): t becomes an argument of the equations (required when they or a constraint use t)",
    "rotating_frame": "coordinates measured in a turning frame or on a turning body: centrifugal (and Coriolis) "
                      "terms in T",
    "driven_support": "a support moved by a given law x_s(t): t becomes an argument of the equations",
    "dissipation_drag": "a velocity-dependent force in `Q` (drag): required then",
    "dissipation_friction": "a force in `Q` that switches sign with the velocity (dry friction): required then; "
                            "the switches are located along the motion",
    "applied_force": "a given generalized force in `Q`, possibly of t (a `Q` requires it or a dissipation effect)",
    "nonholonomic": "a constraint on the velocities that does not integrate to one on the coordinates",
    "velocity_dependent_potential": "L holds terms linear in the velocities that are not kinetic energy: "
                                    "a magnetic field's q*A.v, a rotating frame's Coriolis term",
    "unilateral_contact": "a contact that can be lost (a normal force that may reach 0): where a constraint names "
                          "its multiplier, the loss is located along the motion and ends the comparison",
    "small_oscillation_linearization": "a part is `linearized = true` about `equilibrium` (required then)",
}

class Kind(NamedTuple):
    """One kind of part: what the student gives, when it is correct, what the problem file holds."""

    expects: str                 #: shown by ``lagrade show`` and ``lagrade template``
    correct_when: str
    reference: str
    needs_reference: bool = True


#: Every kind of part. This one table drives validation (:data:`PartKind`), ``lagrade show`` and
#: ``template``, and the table of docs/authoring-problems.md; the checkers register one function per
#: kind, and a test holds their registry to this table.
KINDS: dict[str, Kind] = {
    "lagrangian": Kind(
        "expression in the coordinates q(t), their velocities q(t).diff(t), parameters and t",
        "its Euler-Lagrange equations equal the scene's (L + dF/dt ok; c*L half credit)",
        "derived from the scene", needs_reference=False),
    "eom": Kind(
        "list of Eq(lhs, rhs) (or expressions meaning = 0), one per coordinate",
        "they define the scene's accelerations; `linearized = true`: their linearization about "
        "`equilibrium` does", "derived", needs_reference=False),
    "hamiltonian": Kind(
        "expression in the coordinates and momenta p_<q> (symbols or functions of t)",
        "H - H_ref is a constant (not a function of t)", "derived (Legendre transform of the scene's L)", needs_reference=False),
    "hamilton_eqs": Kind(
        "list of 2n equations in Derivative(q(t), t) and Derivative(p_q(t), t)",
        "they define the scene's rates", "derived", needs_reference=False),
    "expression": Kind(
        "expression in the parameters (and the state where it depends on it)",
        "equal at random points (params, state)",
        "text, or a table of texts keyed by name; may use derived `q_dd`, multipliers (`lam`), "
        "momenta `p_q`, `delta_q` (virtual displacements)"),
    "expression_set": Kind("list of expressions, in any order", "same multiset of values", "list of texts"),
    "equation_root": Kind(
        "the value, or an equation it satisfies (e.g. Eq(cos(theta), 2/3))",
        "the reference value satisfies the equation (and it is not an identity)", 'text; `unknown = "theta"`'),
    "boolean": Kind("True or False", "equal", "`true` / `false`"),
    "integer": Kind("a whole number", "equal", "int"),
    "names": Kind("list of coordinate names (strings) or coordinates ([] for none)", "same set", "list of names"),
    "conserved": Kind(
        "list of expressions constant along the motion (momenta may be written p_<q>)",
        "each is conserved along the scene's motion, and together they cover the reference quantities "
        "(functional dependence)", "list of texts"),
    "trajectory": Kind(
        "dict coordinate name -> expression in t",
        "satisfies the scene's equations of motion and the `initial` values",
        'none; `initial = { theta = "theta0", theta_d = "0" }`', needs_reference=False),
    "reduced": Kind(
        "the equation(s) of motion left once the cyclic coordinates are eliminated (as for eom), or the "
        "Routhian: an expression in the remaining q, q' and the constant momenta",
        "the equations define the reduced scene's accelerations; a Routhian's Euler-Lagrange equations are "
        "the reduced scene's (R = L - p q' or p q' - L)",
        "derived from the part's `system`: the reduced scene, the constant momenta among its parameters",
        needs_reference=False),
    "numerical_solution": Kind(
        "the motion at the part's numbers: a table {'t': [times], q: [values]} (or rows [t, q...], or "
        "{time: value} for one coordinate), or a dict coordinate -> expression in t",
        "within 0.1% of the motion's scale of the reference motion integrated from `initial`, at every time "
        "given (5 times or more, reaching half the window) or on a grid",
        "the parameter values, `{ m = \"1\", k = \"1\" }`; `initial` the initial state (numbers); "
        "`domain` the time window (default [0, horizon])"),
    "conditions": Kind(
        "the conditions: a dict quantity -> value ({'param': oo}, {'coord': value}) or a list of "
        "Eq(quantity, value)",
        "limits: along them the criterion grows and the `fixed` quantities stay; conditions on the motion: "
        "it is a motion of the scene, and the named coordinate is left alone, a harmonic oscillator",
        '`{ grows = "k*l0/(m*g)", fixed = "g/l0" }` (limits of the parameters), or `{ harmonic = "r" }`; '
        '`symbols = ["oo"]` lets a text answer write oo'),
}

#: How a part is graded. Dynamics kinds are compared by their equations of motion.
PartKind = Literal[tuple(KINDS)]  # type: ignore[valid-type]

DYNAMICS_KINDS = ("lagrangian", "eom", "hamiltonian", "hamilton_eqs")


class SpecError(ValueError):
    """A problem file that cannot be used; the message names the file and what was expected."""


class SceneError(ValueError):
    """A scene whose expressions do not make a usable mechanical system (found while deriving it, or
    checking the effects it declares: both below the derivation, so the error lives here).
    ``system`` and ``field`` say where in the problem file, for a message naming its line."""

    def __init__(self, message: str, system: str | None = None, field: str | None = None):
        super().__init__(message)
        self.system, self.field = system, field


def scene_line(path: Path, system: str, field: str) -> int | None:
    """The line of ``field`` in the ``[[systems]]`` table whose key is ``system`` ("" for the only one)."""
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError):
        return None
    blocks: list[dict] = []
    inside = False
    for number, line in enumerate(lines, 1):
        text = line.strip()
        if text.startswith("["):
            inside = text == "[[systems]]"
            if inside:
                blocks.append({"key": "", "line": None})
            continue
        name, _, value = text.partition("=")
        if inside and value:
            if name.strip() == "key":
                blocks[-1]["key"] = value.strip().strip("\"'")
            elif name.strip() == field:
                blocks[-1]["line"] = number
    return next((b["line"] for b in blocks if b["key"] == system), None)


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _inside(what: str, text: str, box: tuple[float, float], name: str) -> None:
    """A symbol's domain, readable and holding its sampling box: else a one-line error naming both."""
    try:
        bounds = parse_domain(text)
    except DomainError as exc:
        raise ValueError(f"{what} {name}: domain {text!r}: {exc}") from None
    if not bounds.parameters and not bounds.encloses(box):  # with parameters: checked by the problem
        raise ValueError(f"{what} {name}: the sampling range {list(box)} is not inside its domain {text!r} "
                         f"({bounds.words(name)}): draw random values where the physics lives")


_DOMAIN_HELP = ('its physical domain: "real", "positive", "nonnegative", "negative", "nonpositive", or an interval '
                'with open or closed ends in the notation, "(0, pi/2)", "[0, oo)", "(0, l)" (ends may name '
                'parameters); the sampling range must lie inside')


class Coordinate(_Strict):
    """A generalized coordinate: its physical domain and its velocity's, and the ranges its random
    states are drawn from (inside them)."""

    name: Annotated[str, Field(pattern=IDENT, description="the coordinate's name; a function of t in answers")]
    description: str = Field("", description="what it measures, as `lagrade show` prints it")
    domain: str = Field("real", description=_DOMAIN_HELP.replace("its", "the coordinate's", 1)
                        + ' (a radius "positive", an angle on a quadrant "(0, pi/2)")')
    velocity_domain: str = Field("real", description="the velocity's physical domain, written as `domain` "
                                 "(\"positive\" while the motion keeps one direction, as 12.35's ring does)")
    sample: tuple[float, float] = Field((-1.0, 1.0), description="range of random states [low, high]: keep away "
                                        "from singularities and inside the region where the model holds")
    velocity: tuple[float, float] = Field((-1.0, 1.0), description="range of random velocities [low, high]")

    @field_validator("sample", "velocity")
    @classmethod
    def _ordered(cls, v: tuple[float, float]) -> tuple[float, float]:
        if not v[0] < v[1]:
            raise ValueError(f"range {list(v)} must be [low, high] with low < high")
        return v

    @model_validator(mode="after")
    def _ranges_in_domains(self) -> Coordinate:
        _inside("coordinate", self.domain, self.sample, self.name)
        _inside("velocity", self.velocity_domain, self.velocity, f"{self.name}'")
        return self


class Parameter(_Strict):
    """A parameter of the problem: its physical domain (positive by default: masses, lengths, g,
    spring constants), which students may rely on, and the range random values are drawn from."""

    name: Annotated[str, Field(pattern=IDENT, description="the symbol's name; answers match it by name")]
    description: str = Field("", description="what it is, as `lagrade show` prints it")
    domain: str = Field("positive", description=_DOMAIN_HELP.replace("its", "the parameter's", 1)
                        + ' (an incline\'s angle "(0, pi/2)", a charge "real")')
    positive: bool = Field(True, description="whether the domain lies in x > 0, which follows from `domain`; "
                                             "`positive = false` alone (older files) is `domain = \"real\"`")
    sample: tuple[float, float] = Field((0.5, 2.0), description="range random values are drawn from [low, high]")

    @model_validator(mode="before")
    @classmethod
    def _positive_from_domain(cls, data: Any) -> Any:
        if not isinstance(data, dict):
            return data
        data = dict(data)
        if "domain" not in data:
            data["domain"] = "real" if data.get("positive", True) is False else "positive"
            return data
        try:
            positive = parse_domain(data["domain"]).assumptions().get("positive", False)
        except (DomainError, TypeError):
            return data  # said with the parameter's name below
        if "positive" in data and data["positive"] is not positive:
            raise ValueError(f"parameter {data.get('name')}: positive = {str(data['positive']).lower()} contradicts "
                             f"domain {data['domain']!r}; give the domain alone")
        data["positive"] = positive
        return data

    @model_validator(mode="after")
    def _range_fits(self) -> Parameter:
        lo, hi = self.sample
        if not lo < hi:
            raise ValueError(f"parameter {self.name}: sample range must have low < high")
        _inside("parameter", self.domain, self.sample, self.name)
        return self


class Constraint(_Strict):
    """A holonomic constraint solved for one coordinate: ``coordinate = value(other q, t)``.

    Every constraint of the chapter can be written this way; it lets the engine reduce the
    Lagrangian by substitution and still recover the multiplier (the constraint force) when asked.
    """

    coordinate: str = Field(description="the coordinate the constraint is solved for")
    value: str = Field(description="its value: an expression in the other coordinates and t (`R`, `a*psi`, `omega*t`)")
    multiplier: Annotated[str, Field(pattern=IDENT)] | None = Field(
        None, description="name of the multiplier (the constraint force), usable in references")


class GeneralFunction(_Strict):
    """A function of the coordinates the book leaves general (``V(r)``, ``U(xp, yp)``).

    The scene and answers may use it; a part is graded by substituting several random smooth
    functions for it (the same in every derivative), or, for an answer that does not use it, with
    the ``concrete`` one the problem states."""

    name: Annotated[str, Field(pattern=IDENT, description="the function's name, as answers call it (`V`)")]
    args: list[Annotated[str, Field(pattern=IDENT)]] = Field(
        description="the coordinates it depends on, in order (`[\"r\"]` for V(r))")
    concrete: str = Field(description="the function the problem states for definiteness, in its arguments "
                                      "and the parameters (`k*r**2/2`); answers that do not use the "
                                      "function are graded with it")
    description: str = Field("", description="what it is, as `lagrade show` prints it")
    special_case: Literal["full", "partial"] = Field(
        "partial", description="what an answer written for the `concrete` function or for 0 (not the general one) "
                               "earns when right for it: `full` where the book names no force (the answer is "
                               "checked for the force it states), `partial` where the book asks the general one; "
                               "`lagrade show` says which")


class Figure(_Strict):
    """The scene's figure (the book's "Fig. P12.14"): its points as functions of the coordinates, drawn at a sample state."""

    points: dict[Annotated[str, Field(pattern=IDENT)], tuple[str, str]] = Field(
        description="each point (a body, a pivot, a pulley) and its position [x, y] in the coordinates and parameters, "
                    "y upward")
    lines: list[tuple[str, str]] = Field([], description="rods, strings and springs: pairs of points joined by a line")
    fixed: list[str] = Field([], description="points that do not move (drawn as supports)")

    @model_validator(mode="after")
    def _known_points(self) -> Figure:
        unknown = sorted(({p for pair in self.lines for p in pair} | set(self.fixed)) - set(self.points))
        if unknown:
            raise ValueError(f"figure: lines or fixed name unknown points {unknown}")
        return self


class System(_Strict):
    """One physical system (a scene). Lettered sub-problems and alternative coordinates are systems."""

    key: str = Field("", description='"" for the only system; "a", "b", ... for lettered sub-problems')
    title: str = Field("", description="the sub-problem's title")
    #: lettered systems may reuse a name that is a coordinate in another system (12.8: theta is
    #: (a)'s incline angle, (b)'s coordinate)
    parameters: list[Parameter] = Field([], description="parameters of this system only (added to the problem's)")
    coordinates: list[Coordinate] = Field(description="the generalized coordinates")
    effects: list[Effect] = Field([], description="every physical effect the scene involves (the vocabulary below)")
    L: str | None = Field(None, description="the Lagrangian (or give T and V)")
    T: str | None = Field(None, description="the kinetic energy")
    V: str | None = Field(None, description="the potential energy")
    Q: dict[str, str] = Field({}, description="generalized (non-conservative) forces, keyed by coordinate")
    constraints: list[Constraint] = Field([], description="holonomic constraints, each solved for one coordinate")
    equilibrium: dict[str, str] = Field({}, description="the equilibrium linearized parts expand about")
    horizon: float = Field(2.0, description="time window of trajectory comparisons (and of sampled t)")
    time_domain: str = Field("real", description="t's physical domain, written as a parameter's `domain`: where "
                             "the scene's model holds (\"[0, pi/(2*omega))\" while a rotating wire is a graph over "
                             "x); [0, horizon] must lie inside")
    functions: list[GeneralFunction] = Field(
        [], description="functions of the coordinates left general (`V(r)`): the scene and answers may call them")
    figure: Figure | None = Field(None, description="the scene's figure; without it the coordinates alone are drawn")

    @model_validator(mode="after")
    def _scene_is_complete(self) -> System:
        if self.L is None and self.T is None:
            raise ValueError(f"system '{self.key}': give either L, or T (and V)")
        if self.L is not None and (self.T is not None or self.V is not None):
            raise ValueError(f"system '{self.key}': give L or T and V, not both")
        names = [c.name for c in self.coordinates]
        if len(set(names)) != len(names):
            raise ValueError(f"system '{self.key}': coordinate names repeat: {names}")
        for where, keys in (("Q", self.Q), ("equilibrium", self.equilibrium)):
            unknown = set(keys) - set(names)
            if unknown:
                raise ValueError(f"system '{self.key}': {where} names unknown coordinates {sorted(unknown)}")
        for c in self.constraints:
            if c.coordinate not in names:
                raise ValueError(f"system '{self.key}': constraint on unknown coordinate '{c.coordinate}'")
        if self.horizon <= 0:
            raise ValueError("horizon must be positive")
        _inside(f"system '{self.key}': time", self.time_domain, (0.0, self.horizon), "t")
        fnames = [f.name for f in self.functions]
        if len(set(fnames)) != len(fnames):
            raise ValueError(f"system '{self.key}': function names repeat: {fnames}")
        for f in self.functions:
            if not f.args or set(f.args) - set(names) or len(set(f.args)) != len(f.args):
                raise ValueError(f"system '{self.key}': function {f.name} must depend on distinct coordinates "
                                 f"of the system ({', '.join(names)}), not {f.args}")
            if f.name in names:
                raise ValueError(f"system '{self.key}': {f.name} is both a coordinate and a function")
        return self

    @property
    def free_coordinates(self) -> list[Coordinate]:
        fixed = {c.coordinate for c in self.constraints}
        return [c for c in self.coordinates if c.name not in fixed]


class Mistake(_Strict):
    """A known wrong answer and the sentence that explains it to the student."""

    answer: Any = Field(description="the wrong answer, in the notation of references")
    message: str = Field(description="the sentence a student with this answer reads: name the physics, "
                                     "never a reference value")


class Alternative(_Strict):
    """Another admissible formulation of a part: graded in another system, against another reference, or both.

    The book leaves some choices open (a frame, a gauge, planar or 3-D coordinates, a reading of the
    question): an answer right in any admissible formulation gets full credit, and its feedback names
    the one used (`lagrade.verdicts.grade.Formulations`)."""

    system: str | None = Field(None, description="key of the system the part is graded in (default: the part's)")
    name: Annotated[str, Field(pattern=IDENT)] | None = Field(
        None, description="an alias of the part that selects this formulation: a value bound to that name is graded "
                          "in it alone, a value bound to another of the part's names in the others (12.30: `lam`, the "
                          "multiplier, a torque, answers the constraining force `N` asks)")
    reference: Any = Field(None, description="the right answer in this formulation (default: the part's), by kind")
    initial: dict[str, str] | None = Field(None, description="trajectory: initial values in this formulation "
                                                             "(default: the part's)")
    says: str = Field("", description="the formulation in a student's words, for the feedback (default: the "
                                      "system's title); never a value")
    mistakes: list[Mistake] = Field([], description="known wrong answers in this formulation (in its names), "
                                                  "each with its sentence")
    gauge: bool = Field(False, description="hamiltonian, hamilton_eqs: accept the H (or Hamilton's equations) of any "
                                           "Lagrangian L + dF(q, t)/dt of the system, whose momenta are shifted by dF/dq")
    credit: float = Field(1.0, gt=0, le=1, description="the share of the part an answer right only in this "
                                                       "formulation earns: below 1 for an approximation the question "
                                                       "does not make (small amplitudes), said in the feedback")


class Part(_Strict):
    """One thing the problem asks, bound to one name in the answer file."""

    name: Annotated[str, Field(pattern=IDENT, description="the name the answer binds (the catalogue's contract)")]
    kind: PartKind = Field(description="how it is graded (the table of kinds below)")
    prompt: str = Field("", description="what the part asks, as `lagrade show` prints it")
    system: str = Field("", description="key of the system it is about")
    weight: float = Field(default=1.0, gt=0, description="points, relative to the other parts")
    reference: Any = Field(None, description="the right answer where the scene does not derive it (by kind)")
    linearized: bool = Field(False, description="eom: grade the equations linearized about the equilibrium")
    unknown: str | None = Field(None, description="equation_root: the unknown the equation is solved for")
    domain: tuple[float, float] | None = Field(
        None, description="equation_root: the interval the unknown lives in, its ends excluded (e.g. [0, 3.14159...] "
                          "for an angle from the vertical, 0 < theta < pi); an equation with another solution inside "
                          "does not single out the answer, one whose other solutions are the ends (sin(theta) = 0 "
                          "at 0 and pi) does")
    symbols: list[str] = Field([], description="extra symbols an answer may use (initial values like theta0), "
                                                 "sampled in [0.5, 1.5]")
    symbol_ranges: dict[str, tuple[float, float]] = Field(
        {}, description="another sampling range for some of `symbols`: an initial position or velocity "
                        "that may be negative, [-1.5, 1.5]")
    symbol_domain: dict[str, str] = Field(
        {}, description="the physical domain of some of `symbols`, written as a parameter's `domain` (`{ v0 = "
                        "\"positive\" }`); the others are real. Their sampling ranges must lie inside")
    initial: dict[str, str] = Field({}, description="trajectory: initial values, keyed q and q_d")
    accelerations: bool = Field(False, description="expression parts: the answer may contain q'', evaluated on the "
                                "true motion (the solved accelerations are put for it; `lagrade show` says so); "
                                "otherwise a result with q'' in it is invalid")
    aliases: list[str] = Field([], description="other names an answer may bind for this part")
    mistakes: list[Mistake] = Field([], description="known wrong answers, each with its sentence")
    alternatives: list[Alternative] = Field(
        [], description="other admissible formulations: full credit if the answer is right in any; if in "
                        "none, the feedback is the primary formulation's")
    follows: str | None = Field(
        None, description="an earlier part whose formulation this one is judged in: the alternative with the "
                          "system the student's answer to that part was right in (else the primary)")
    version_of: Annotated[str, Field(pattern=IDENT)] | None = Field(
        None, description="a question the book asks in two (or more) versions, each graded as its own part "
                          "(ex12.6's L in theta and in y): the name they share. A value bound to that name is "
                          "graded as the version whose system's coordinates it uses (else the version that "
                          "has the name as name or alias); the other version is then missing")
    also_answered_by: list[Annotated[str, Field(pattern=IDENT)]] = Field(
        [], description="numerical_solution: other parts whose value is graded as this part when it is a motion "
                        "at this part's numbers (a table, or expressions in t and the parameters alone) and this "
                        "part is not answered itself (12.41's exact pendulum motion bound to the catalogue's "
                        "`solution_b`)")
    extra: bool = Field(False, description="a part the book does not ask: graded and shown, but not counted in "
                                           "the problem's total unless an assignment's `parts` names it")

    @model_validator(mode="after")
    def _reference_present(self) -> Part:
        if KINDS[self.kind].needs_reference and self.reference is None:
            raise ValueError(f"part '{self.name}' of kind {self.kind} needs a reference")
        if self.kind == "boolean" and not isinstance(self.reference, bool):
            raise ValueError(f"part '{self.name}': a boolean reference must be true or false")
        if self.kind == "integer" and (isinstance(self.reference, bool) or not isinstance(self.reference, int)):
            raise ValueError(f"part '{self.name}': an integer reference must be a whole number")
        if self.kind == "equation_root" and not self.unknown:
            raise ValueError(f"part '{self.name}': equation_root needs 'unknown'")
        if self.kind == "trajectory" and not self.initial:
            raise ValueError(f"part '{self.name}': a trajectory part needs 'initial' values")
        if self.domain is not None and not self.domain[0] < self.domain[1]:
            raise ValueError(f"part '{self.name}': domain must be [low, high] with low < high")
        for alt in self.alternatives:
            if alt.name is not None and alt.name not in self.aliases:
                raise ValueError(f"part '{self.name}': an alternative's name '{alt.name}' must be one of the part's "
                                 f"aliases {self.aliases}")
            if alt.system is None and alt.reference is None and alt.initial is None and not alt.gauge:
                raise ValueError(f"part '{self.name}': an alternative needs a system, a reference, initial values "
                                 f"or gauge = true")
            if alt.gauge and self.kind not in ("hamiltonian", "hamilton_eqs"):
                raise ValueError(f"part '{self.name}': gauge = true is for hamiltonian and hamilton_eqs parts, "
                                 f"not {self.kind}")
            if alt.reference is not None and self.kind in ("boolean", "integer") and type(alt.reference) is not type(self.reference):
                raise ValueError(f"part '{self.name}': an alternative's reference must be a {self.kind} like the part's")
        if self.follows == self.name:
            raise ValueError(f"part '{self.name}' cannot follow itself")
        for name, (lo, hi) in self.symbol_ranges.items():
            if name not in self.symbols:
                raise ValueError(f"part '{self.name}': symbol_ranges names '{name}', which is not in symbols")
            if not lo < hi:
                raise ValueError(f"part '{self.name}': the range of {name} must be [low, high] with low < high")
        for name in self.symbol_domain:
            if name not in self.symbols:
                raise ValueError(f"part '{self.name}': symbol_domain names '{name}', which is not in symbols")
        for name, box in self.symbol_domains.items():
            _inside(f"part '{self.name}': symbol", self.symbol_domain.get(name, "real"), box, name)
        return self

    @property
    def symbol_domains(self) -> dict[str, tuple[float, float]]:
        """Each extra symbol with the range it is sampled in."""
        return {name: self.symbol_ranges.get(name, (0.5, 1.5)) for name in self.symbols}


class Problem(_Strict):
    """A problem (or exercise) of the chapter: its systems and the parts it asks."""

    id: Annotated[str, Field(pattern=ID, description="the problem's id, also its file name: letters, digits, "
                                                      "`.`, `_`, `-` (`12.22`, `ex12.3`, `hw7-q2`)")]
    title: str = Field(description="one line")
    statement: str = Field("", description="the book's statement, paraphrased (`lagrade show` prints it)")
    assumptions: list[str] = Field([], description="what a student needs where the book's figure is missing")
    parameters: list[Parameter] = Field([], description="every symbol other than coordinates and t")
    systems: list[System] = Field(description="one scene, or several for lettered sub-problems")
    parts: list[Part] = Field(description="what the problem asks, one part per answer name")

    @model_validator(mode="after")
    def _consistent(self) -> Problem:
        keys = [s.key for s in self.systems]
        if len(set(keys)) != len(keys):
            raise ValueError(f"system keys repeat: {keys}")
        names = [p.name for p in self.parts] + [a for p in self.parts for a in p.aliases]
        if len(set(names)) != len(names):
            raise ValueError(f"part names and aliases repeat: {names}")
        for system in self.systems:
            pnames = [p.name for p in self.parameters_of(system.key)]
            if len(set(pnames)) != len(pnames):
                raise ValueError(f"parameter names repeat in system '{system.key}': {pnames}")
            clash = set(pnames) & {c.name for c in system.coordinates}
            if clash:
                raise ValueError(f"system '{system.key}': {sorted(clash)} is both a coordinate and a parameter")
            clash = set(pnames) & {f.name for f in system.functions}
            if clash:
                raise ValueError(f"system '{system.key}': {sorted(clash)} is both a function and a parameter")
        for part in self.parts:
            if part.system not in keys:
                raise ValueError(f"part '{part.name}' refers to unknown system '{part.system}'")
            system = self.system(part.system)
            if part.linearized and not system.equilibrium:
                raise ValueError(f"part '{part.name}' is linearized but system '{part.system}' has no equilibrium")
            for alt in part.alternatives:
                if alt.system is not None and alt.system not in keys:
                    raise ValueError(f"part '{part.name}': an alternative refers to unknown system '{alt.system}'")
                if alt.system is not None and part.linearized and not self.system(alt.system).equilibrium:
                    raise ValueError(f"part '{part.name}' is linearized but system '{alt.system}' has no equilibrium")
            versions = [p for p in self.parts if part.version_of is not None and p.version_of == part.version_of]
            # distinct formulations: the systems a version is graded in (its own and its alternatives'); 12.39's
            # H (either frame) and H_p (the rotating frame's) share a system but not a formulation
            formulations = {frozenset({p.system, *(a.system for a in p.alternatives if a.system)}) for p in versions}
            if part.version_of is not None and (len(versions) < 2 or len(formulations) < len(versions)
                                                or sum(part.version_of in (p.name, *p.aliases) for p in versions) != 1):
                raise ValueError(f"part '{part.name}': the versions of '{part.version_of}' must be two or more parts "
                                 f"graded in distinct systems, exactly one of them named or aliased "
                                 f"'{part.version_of}'")
            others = {p.name for p in self.parts if p is not part}
            if part.also_answered_by and (part.kind != "numerical_solution"
                                          or not set(part.also_answered_by) <= others):
                raise ValueError(f"part '{part.name}': also_answered_by is for a numerical_solution part and names "
                                 f"other parts of the problem, not {part.also_answered_by}")
            earlier = [p.name for p in self.parts[:self.parts.index(part)]]
            if part.follows is not None and part.follows not in earlier:
                raise ValueError(f"part '{part.name}' follows '{part.follows}', which is not an earlier part")
        self._domains_with_parameters()
        return self

    def _domains_with_parameters(self) -> None:
        """A domain whose ends name parameters (``(0, l)``): they must be the system's parameters, and
        the sampling range must lie inside at every corner of their ranges (the ends are monotone in
        each parameter in the chapter: a length, a time pi/(2*omega))."""
        import itertools

        for system in self.systems:
            params = {sp.Symbol(q.name): q.sample for q in self.parameters_of(system.key)}
            for part in [None, *(p.name for p in self.parts if p.system == system.key and p.symbols)]:
                for d in self.domains(system.key, part).values():
                    b = d.bounds
                    if not b.parameters:
                        continue
                    where = f"system '{system.key}': {d.role} {d.name}" if system.key else f"{d.role} {d.name}"
                    unknown = sorted(str(s) for s in b.parameters if s not in params)
                    if unknown:
                        raise ValueError(f"{where}: its domain {b.text!r} names {', '.join(unknown)}, which is not "
                                         f"a parameter of the system")
                    names = sorted(b.parameters, key=str)
                    for corner in itertools.product(*(params[s] for s in names)):
                        at = dict(zip(names, corner))
                        ends = b.at(at)
                        if not bool(ends.lo < ends.hi) or (d.sample_box is not None and not b.encloses(d.sample_box, at)):
                            shown = ", ".join(f"{s} = {v:g}" for s, v in at.items())
                            raise ValueError(f"{where}: the sampling range {list(d.sample_box or ())} is not inside "
                                             f"its domain {b.text!r} ({d.words()}) at {shown}")

    def parameters_of(self, key: str) -> list[Parameter]:
        """The problem's parameters and the system's own, in that order."""
        return [*self.parameters, *self.system(key).parameters]

    def domains(self, key: str = "", part: str | None = None) -> dict[sp.Symbol, Domain]:
        """Every symbol an answer about system ``key`` may use (its parameters, coordinates, their
        velocities, accelerations and momenta, t, and the extra `symbols` of ``part``), keyed by the
        plain sympy symbol the engine uses, with its physical domain and sampling box."""
        system = self.system(key)
        out: dict[sp.Symbol, Domain] = {}

        def put(name: str, text: str, box: tuple[float, float] | None, role: Role, words: str | None = None) -> None:
            sym = sp.Symbol(name)
            out[sym] = Domain(sym, parse_domain(text), box, role, words or name)

        for q in self.parameters_of(key):
            put(q.name, q.domain, q.sample, "parameter")
        state = StateSymbols(tuple(c.name for c in system.coordinates))
        for c, qd, qdd, p in zip(system.coordinates, state.qd, state.qdd, state.p):
            put(c.name, c.domain, c.sample, "coordinate")
            put(qd.name, c.velocity_domain, c.velocity, "velocity", f"{c.name}'")
            put(qdd.name, "real", (-1.0, 1.0), "acceleration", f"{c.name}''")  # drawn there by the sampling
            put(p.name, "real", None, "momentum")  # computed from the state, never drawn
        put(T.name, system.time_domain, (0.0, system.horizon), "time")
        if part is not None:
            asked = self.part(part)
            for name, box in asked.symbol_domains.items():
                if sp.Symbol(name) not in out or out[sp.Symbol(name)].role == "momentum":  # as the sampling does
                    put(name, asked.symbol_domain.get(name, "real"), box, "symbol")
        return out

    def system(self, key: str) -> System:
        for s in self.systems:
            if s.key == key:
                return s
        raise KeyError(key)

    def part(self, name: str) -> Part:
        for p in self.parts:
            if p.name == name or name in p.aliases:
                return p
        raise KeyError(name)

    @property
    def max_score(self) -> float:
        """The problem's total: its parts' weights, extras (parts the book does not ask) left out."""
        return sum(p.weight for p in self.parts if not p.extra)

    def versions(self, name: str) -> list[Part]:
        """The parts that are versions of the two-version question ``name`` (empty if it is none)."""
        return [p for p in self.parts if p.version_of == name]


def _type_name(annotation: Any) -> str:
    """A field's type in the words of a TOML file (string, list of ..., table of ...)."""
    import types
    import typing

    origin, args = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is Annotated:
        return _type_name(args[0])
    if origin in (typing.Union, types.UnionType):
        named = [_type_name(a) for a in args if a is not type(None)]
        return " or ".join(named) + (" (optional)" if type(None) in args else "")
    if origin is list:
        return f"list of {_type_name(args[0])}"
    if origin is dict:
        return f"table of {_type_name(args[1])}"
    if origin is tuple:
        return "[low, high]"
    names = {str: "string", float: "number", bool: "true/false", int: "integer"}
    if annotation in names:
        return names[annotation]
    return "any" if annotation is Any else f"`[{annotation.__name__}]`"


def markdown_tables() -> str:
    """The tables of docs/authoring-problems.md, from the models themselves (a test holds the page
    to them): every field with its type, default and description, then the kinds of part."""

    def rows(model: type[BaseModel]) -> list[str]:
        out = [f"`[{model.__name__}]`: {(model.__doc__ or '').strip().splitlines()[0]}", "",
               "| field | type | default | meaning |", "|---|---|---|---|"]
        for name, field in model.model_fields.items():
            kind = {"kind": "a kind below", "effects": "list of effects below"}.get(name) or _type_name(field.annotation)
            default = ("required" if field.is_required() else "none" if field.default is None
                       else f"`{json.dumps(field.default)}`")
            out.append(f"| `{name}` | {kind} | {default} | {field.description or ''} |")
        return out + [""]

    lines: list[str] = []
    for model in (Problem, Parameter, System, Coordinate, Constraint, GeneralFunction, Figure, Part, Alternative,
                  Mistake):
        lines += rows(model)
    lines += ["| kind | the student gives | correct when | `reference` |", "|---|---|---|---|"]
    lines += [f"| `{name}` | {k.expects} | {k.correct_when} | {k.reference} |" for name, k in KINDS.items()]
    lines += ["", "Effects (`effects = [...]` of a system): declare every one the scene involves. A scene that uses "
              "one it does not declare, where the derivation can tell (\"required then\"), is refused with a "
              "line naming the effect to add.", "", "| effect | declare it when |", "|---|---|"]
    lines += [f"| `{e}` | {EFFECT_MEANINGS[e]} |" for e in get_args(Effect)]
    return "\n".join(lines)


def _line_of(text: str, loc: tuple[Any, ...]) -> int | None:
    """Best-effort line of a validation error in a TOML file, so instructors can jump to it."""
    keys = [str(k) for k in loc if isinstance(k, str)]
    for key in reversed(keys):
        m = re.search(rf"^\s*{re.escape(key)}\s*=", text, flags=re.MULTILINE)
        if m:
            return text.count("\n", 0, m.start()) + 1
    return None


def load_problem_file(path: Path) -> Problem:
    """Read and validate one problem file; every failure is a one-line `SpecError`."""
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise SpecError(f"{path}: cannot read problem file ({exc.strerror})") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SpecError(f"{path}: not valid TOML: {exc}") from None
    try:
        return Problem.model_validate(data)
    except ValidationError as exc:
        err = exc.errors()[0]
        where = ".".join(str(p) for p in err["loc"]) or "file"
        line = _line_of(text, tuple(err["loc"]))
        at = f"{path}:{line}" if line else str(path)
        more = f" (and {len(exc.errors()) - 1} more)" if len(exc.errors()) > 1 else ""
        raise SpecError(f"{at}: {where}: {err['msg']}{more}") from None
