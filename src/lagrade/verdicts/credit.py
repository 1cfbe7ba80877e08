"""Partial credit: how much of a part's weight an almost-right answer earns.

The defaults below are documented in docs/answers.md; an assignment (or ``lagrade check --credit``)
may change any of them.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field, ValidationError


class Credit(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)

    #: L = c * (the right Lagrangian), c != 1: same motion, wrong momenta and H.
    scaled_lagrangian: float = Field(0.5, ge=0, le=1)
    #: eom / hamilton / dict results / lists: each right equation or entry earns its share
    #: (False: all or nothing).
    per_equation: bool = True
    #: exact nonlinear equations where the linearized ones were asked.
    nonlinear_for_linearized: float = Field(1.0, ge=0, le=1)
    #: a wrong extra entry in an order-free list (normal modes, conserved quantities, cyclic names) cancels
    #: a right one; "extra" means beyond the expected number (two asked, one right and one wrong: half).
    penalize_extra_entries: bool = True


def load_credit(path: Path) -> Credit:
    """A ``[credit]`` table (or a bare table) from a TOML file."""
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    try:
        return Credit.model_validate(data.get("credit", data))
    except ValidationError as exc:  # one line, not pydantic's dump: the first error, and how many more
        err = exc.errors()[0]
        where = ".".join(str(p) for p in err["loc"]) or "[credit]"
        more = f" (and {len(exc.errors()) - 1} more)" if len(exc.errors()) > 1 else ""
        known = ", ".join(Credit.model_fields)
        raise ValueError(f"[credit] {where}: {err['msg']}{more}; the settings are {known}") from None
