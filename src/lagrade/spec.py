"""The problem file: what a problem is, as data.

A problem file is untrusted input written by instructors; it is validated here, once, so that
the engine can rely on every field. Expressions stay text until `lagrade.scene` parses them with
the same no-eval parser that reads students' text answers.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator

IDENT = r"^[A-Za-z][A-Za-z0-9_]*$"

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

#: How a part is graded. Dynamics kinds are compared by their equations of motion.
PartKind = Literal[
    "lagrangian",
    "eom",
    "hamiltonian",
    "hamilton_eqs",
    "expression",
    "expression_set",
    "equation_root",
    "boolean",
    "integer",
    "names",
    "conserved",
    "trajectory",
]

DYNAMICS_KINDS = ("lagrangian", "eom", "hamiltonian", "hamilton_eqs")


class SpecError(ValueError):
    """A problem file that cannot be used; the message names the file and what was expected."""


class SceneError(ValueError):
    """A scene whose expressions do not make a usable mechanical system (found while deriving it, or
    checking the effects it declares: both below the derivation, so the error lives here)."""


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class Coordinate(_Strict):
    """A generalized coordinate, with the ranges its random states are drawn from."""

    name: Annotated[str, Field(pattern=IDENT)]
    description: str = ""
    sample: tuple[float, float] = (-1.0, 1.0)
    velocity: tuple[float, float] = (-1.0, 1.0)

    @field_validator("sample", "velocity")
    @classmethod
    def _ordered(cls, v: tuple[float, float]) -> tuple[float, float]:
        if not v[0] < v[1]:
            raise ValueError(f"range {list(v)} must be [low, high] with low < high")
        return v


class Parameter(_Strict):
    """A parameter of the problem; positivity is an assumption students may rely on."""

    name: Annotated[str, Field(pattern=IDENT)]
    description: str = ""
    positive: bool = True
    sample: tuple[float, float] = (0.5, 2.0)

    @model_validator(mode="after")
    def _range_fits(self) -> Parameter:
        lo, hi = self.sample
        if not lo < hi:
            raise ValueError(f"parameter {self.name}: sample range must have low < high")
        if self.positive and lo <= 0:
            raise ValueError(f"parameter {self.name} is positive, so its sample range must be > 0")
        return self


class Constraint(_Strict):
    """A holonomic constraint solved for one coordinate: ``coordinate = value(other q, t)``.

    Every constraint of the chapter can be written this way; it lets the engine reduce the
    Lagrangian by substitution and still recover the multiplier (the constraint force) when asked.
    """

    coordinate: str
    value: str
    multiplier: Annotated[str, Field(pattern=IDENT)] | None = None


class System(_Strict):
    """One physical system (a scene). Lettered sub-problems and alternative coordinates are systems."""

    key: str = ""
    title: str = ""
    #: parameters of this system only (added to the problem's): lettered systems may reuse a name
    #: that is a coordinate in another system (12.8: theta is (a)'s incline angle, (b)'s coordinate)
    parameters: list[Parameter] = []
    coordinates: list[Coordinate]
    effects: list[Effect] = []
    L: str | None = None
    T: str | None = None
    V: str | None = None
    Q: dict[str, str] = {}
    constraints: list[Constraint] = []
    equilibrium: dict[str, str] = {}
    horizon: float = 2.0
    momenta: dict[str, str] = {}

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
        return self

    @property
    def free_coordinates(self) -> list[Coordinate]:
        fixed = {c.coordinate for c in self.constraints}
        return [c for c in self.coordinates if c.name not in fixed]


class Mistake(_Strict):
    """A known wrong answer and the sentence that explains it to the student."""

    answer: Any
    message: str


class Part(_Strict):
    """One thing the problem asks, bound to one name in the answer file."""

    name: Annotated[str, Field(pattern=IDENT)]
    kind: PartKind
    prompt: str = ""
    system: str = ""
    weight: float = Field(default=1.0, gt=0)
    reference: Any = None
    #: eom: grade the equations linearized about the system's equilibrium.
    linearized: bool = False
    #: equation_root: the unknown the student's equation is solved for (e.g. ``theta``).
    unknown: str | None = None
    #: extra symbols the answer may use (initial values like ``theta0``).
    symbols: list[str] = []
    #: trajectory: initial values, keyed ``q`` and ``q_d``.
    initial: dict[str, str] = {}
    aliases: list[str] = []
    mistakes: list[Mistake] = []

    @model_validator(mode="after")
    def _reference_present(self) -> Part:
        needs = {"expression", "expression_set", "equation_root", "boolean", "integer", "names", "conserved"}
        if self.kind in needs and self.reference is None:
            raise ValueError(f"part '{self.name}' of kind {self.kind} needs a reference")
        if self.kind == "boolean" and not isinstance(self.reference, bool):
            raise ValueError(f"part '{self.name}': a boolean reference must be true or false")
        if self.kind == "integer" and (isinstance(self.reference, bool) or not isinstance(self.reference, int)):
            raise ValueError(f"part '{self.name}': an integer reference must be a whole number")
        if self.kind == "equation_root" and not self.unknown:
            raise ValueError(f"part '{self.name}': equation_root needs 'unknown'")
        if self.kind == "trajectory" and not self.initial:
            raise ValueError(f"part '{self.name}': a trajectory part needs 'initial' values")
        return self


class Problem(_Strict):
    """A problem (or exercise) of the chapter: its systems and the parts it asks."""

    id: Annotated[str, Field(pattern=r"^(ex|eg)?12\.\d+$")]
    title: str
    statement: str = ""
    assumptions: list[str] = []
    parameters: list[Parameter] = []
    systems: list[System]
    parts: list[Part]

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
        for part in self.parts:
            if part.system not in keys:
                raise ValueError(f"part '{part.name}' refers to unknown system '{part.system}'")
            system = self.system(part.system)
            if part.linearized and not system.equilibrium:
                raise ValueError(f"part '{part.name}' is linearized but system '{part.system}' has no equilibrium")
        return self

    def parameters_of(self, key: str) -> list[Parameter]:
        """The problem's parameters and the system's own, in that order."""
        return [*self.parameters, *self.system(key).parameters]

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
        return sum(p.weight for p in self.parts)


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
