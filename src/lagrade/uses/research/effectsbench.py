"""What simulating only a scene's declared effects saves, on the grading path itself (``lagrade bench
effects``, benchmarks/effects.py).

For each scene, the dynamics part's trajectory check is timed as the checker runs it: the inputs
`checkers.dynamics.lagrange_inputs` builds, handed to `compare_runs` (the reference run and the
student's run, the reference not taken from a cache), with a correct answer (the reference's own
Lagrange rows standing for the student's). Two models on the *same* path, side by side, the repeats
alternated (so a load on the machine falls on both), medians of ``repeat`` runs:

- ``declared``: what grading runs: the scene's model built from its declared effects (`scene_model`):
  its compiled rates and declared events (no t argument for an autonomous scene, contact events only
  for unilateral contact), or the switching models where the scene declares switching;
- ``all``: the same path with the model built with all machinery (`scene_model(mech,
  everything=True)`): t an argument, contact events on every multiplier, switching on every velocity
  Abs/sign (so a scene with a velocity Abs/sign runs the switching models in both columns).
"""

from __future__ import annotations

import statistics
import time
from dataclasses import dataclass
from pathlib import Path

from lagrade.verdicts.checkers.base import Context
from lagrade.verdicts.checkers.dynamics import _lagrange_solver, lagrange_inputs
from lagrade.compare.trajectory import ACCURACY, compare_runs
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem
from lagrade.compare.scene_model import SceneModel
from lagrade.problem.spec import Part

#: a switching scene of the test suite (no chapter problem declares dry friction with a sign)
COULOMB = str(Path(__file__).resolve().parents[4] / "tests" / "problems_stick_slip" / "coulomb-spring.toml")


@dataclass
class EffectsRow:
    scene: str
    effects: list[str]
    machinery: list[str]
    path: str                # what grading runs for this scene
    ms_declared: float       # median ms of one compare_runs, declared machinery
    ms_all: float            # the same with all machinery
    evals_declared: int
    evals_all: int
    agree_declared: bool
    agree_all: bool
    K: int

    @property
    def saving(self) -> float:
        return self.ms_all / self.ms_declared


def _dynamics_part(problem, system):
    for part in problem.parts:
        if part.kind in ("eom", "lagrangian") and part.system == system.key and not part.linearized:
            return part
    # no dynamics part on this scene (12.4 asks for a trajectory and values): as an eom part would run
    return Part(name="eom", kind="eom", system=system.key)


def compare_scene(pid: str, key: str | None = None, K: int | None = None, repeat: int = 5) -> EffectsRow:
    problem = load_problem(pid)
    system = problem.systems[0] if key is None else problem.system(key)
    part = _dynamics_part(problem, system)
    ctx = Context(problem, references(problem))
    mech = ctx.mech(part)
    acc = ctx.accuracy

    def student_acc():
        return _lagrange_solver(mech.L, mech, part)

    def student_rows():
        return mech.lagrange_rows(mech.L)

    def one(everything: bool):
        inputs = lagrange_inputs(ctx, mech, part, student_acc, student_rows, everything=everything)
        start = time.perf_counter()
        out = compare_runs(inputs.student, inputs.reference, inputs.y0, inputs.labels, system.horizon, acc,
                           events=inputs.events, student_events=inputs.student_events)
        return time.perf_counter() - start, out, inputs

    runs: dict[bool, list] = {False: [], True: []}
    one(False), one(True)   # warm: compilation is kept on the Mechanics, and is not what is measured
    for _ in range(repeat):
        for everything in (False, True):
            runs[everything].append(one(everything))
    results = {e: (statistics.median(r[0] for r in rs), rs[-1][1], rs[-1][2]) for e, rs in runs.items()}
    (t_d, c_d, in_d), (t_a, c_a, _) = results[False], results[True]
    path = "switching models" if in_d.switching else "compiled rates"
    return EffectsRow(f"{problem.id}{system.key}", list(system.effects), SceneModel(mech).machinery.lines(), path,
                      1e3 * t_d, 1e3 * t_a, c_d.rhs_evals, c_a.rhs_evals, c_d.agree, c_a.agree, in_d.y0.shape[1])


def format_rows(rows: list[EffectsRow]) -> str:
    header = (f"{'scene':<15} {'grading path':<17} {'declared ms':>11} {'all ms':>8} {'all/declared':>12} "
              f"{'evals d/a':>11} {'agree d/a':>9}")
    out = [header]
    for r in rows:
        out.append(f"{r.scene:<15} {r.path:<17} {r.ms_declared:11.2f} {r.ms_all:8.2f} {r.saving:11.2f}x "
                   f"{f'{r.evals_declared}/{r.evals_all}':>11} {f'{r.agree_declared:d}/{r.agree_all:d}':>9}")
    K = rows[0].K if rows else ACCURACY["default"].trajectories
    out.append(f"(median of the repeats of one compare_runs, reference + student run, {K} trajectories, "
               "default accuracy)")
    out.append("")
    for r in rows:
        out.append(f"{r.scene}: effects {', '.join(r.effects) or 'none'}")
        out += [f"    {line}" for line in r.machinery]
    return "\n".join(out)
