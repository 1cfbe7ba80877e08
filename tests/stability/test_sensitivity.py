"""Every preset catches a small error in every dynamics part (issue 23): each parameter that matters,
scaled by (1 + eps), is rejected at the preset's stated resolution. The full table (the smallest eps
each preset rejects, per part) is `python benchmarks/sensitivity.py`, in docs/numerics.md."""

from __future__ import annotations

import pytest

from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem, problem_ids
from lagrade.uses.research.sensitivity import KINDS, reference_rows, rejected

#: the error every part must reject, per preset (docs/numerics.md: measured 1e-5 ... 1e-9)
RESOLUTION = {"fast": 1e-5, "default": 1e-6, "strict": 1e-8}


def _parts():
    for pid in problem_ids():
        problem = load_problem(pid)
        for part in problem.parts:
            # a scene with a general function: its concrete stand-in earns half (tests/test_general_functions.py)
            if part.kind in KINDS and not part.linearized and part.reference is None \
                    and not problem.system(part.system).functions:
                yield pytest.param(pid, part.name, id=f"{pid}:{part.name}")


@pytest.mark.parametrize(("pid", "name"), list(_parts()))
def test_every_preset_rejects_a_parameter_off_by_its_resolution(tmp_path, pid, name):
    problem = load_problem(pid)
    part = problem.part(name)
    rows = reference_rows(problem, part)
    single = part.kind in ("lagrangian", "hamiltonian")
    mech = references(problem)[part.system]
    assert not any(rejected(pid, name, rows, single, p, 0.0, "strict", tmp_path) for p in mech.params[:1]), \
        "the reference itself must pass"
    matter = [p for p in mech.params if any(r.has(p) for r in rows)
              and rejected(pid, name, rows, single, p, 0.1, "fast", tmp_path)]
    missed = [(str(p), preset) for p in matter for preset, eps in RESOLUTION.items()
              if not rejected(pid, name, rows, single, p, eps, preset, tmp_path)]
    assert not missed, f"accepted with a parameter off by the preset's resolution: {missed}"
