"""What simulating only a scene's declared effects saves (``lagrade bench effects``, benchmarks/effects.py).

For each scene, the same K sampled trajectories are integrated (DOP853, the default tolerances) three ways
in one run, side by side:

- ``declared``: `SceneModel(mech)`: only the machinery the declared effects call for;
- ``all``: `SceneModel(mech, everything=True)`: explicit time argument, the velocity-dependent force term,
  multipliers evaluated for contact events on every constraint, switching events on every Abs/sign;
- ``engine``: the grader's generic reference right-hand side (`Mechanics.accelerations`, t always passed,
  LU solve even for one coordinate).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from lagrade.research.workprecision import _timed
from lagrade.compare.trajectory import ACCURACY, integrate
from lagrade.library import load_problem
from lagrade.scene_model import SceneModel
from lagrade.reference import Mechanics
from lagrade.sampling import rng_for, sample_points, state_arrays


@dataclass
class EffectsRow:
    scene: str
    effects: list[str]
    machinery: list[str]
    ms_declared: float
    ms_all: float
    ms_engine: float
    evals_declared: int
    evals_all: int
    evals_engine: int
    K: int

    @property
    def saving(self) -> float:
        return self.ms_all / self.ms_declared


def compare_scene(pid: str, key: str | None = None, K: int = 4, repeat: int = 3) -> EffectsRow:
    problem = load_problem(pid)
    system = problem.systems[0] if key is None else problem.system(key)
    mech = Mechanics(problem, system)
    pts = sample_points(mech, K, rng_for(pid, system.key, "effects-bench"))
    q, qd, _, params = state_arrays(mech, pts)
    y0 = np.concatenate([q, qd])
    acc = replace(ACCURACY["default"], method="DOP853", max_rhs_evals=10**7)
    n = len(mech.names)

    def run_model(model: SceneModel):
        return integrate(model.rates(params), y0, system.horizon, acc, events=model.events(y0, params))

    declared, everything = SceneModel(mech), SceneModel(mech, everything=True)
    r_d, t_d = _timed(lambda: run_model(declared), repeat)
    r_a, t_a = _timed(lambda: run_model(everything), repeat)

    def engine(t, Y):
        return np.concatenate([Y[n:], mech.accelerations(Y[:n], Y[n:], np.full(Y.shape[1], t), params)])

    r_e, t_e = _timed(lambda: integrate(engine, y0, system.horizon, acc), repeat)
    return EffectsRow(f"{pid}{system.key}", list(system.effects), declared.machinery.lines(),
                      1e3 * t_d / K, 1e3 * t_a / K, 1e3 * t_e / K, r_d.rhs_evals, r_a.rhs_evals, r_e.rhs_evals, K)


def format_rows(rows: list[EffectsRow]) -> str:
    out = [f"{'scene':<7} {'declared ms/traj':>16} {'all ms/traj':>12} {'all/declared':>12} {'engine ms/traj':>15} "
           f"{'evals d/a/e':>18}"]
    for r in rows:
        out.append(f"{r.scene:<7} {r.ms_declared:16.2f} {r.ms_all:12.2f} {r.saving:12.2f}x {r.ms_engine:15.2f} "
                   f"{f'{r.evals_declared}/{r.evals_all}/{r.evals_engine}':>18}")
    out.append("")
    for r in rows:
        out.append(f"{r.scene}: effects {', '.join(r.effects) or 'none'}")
        out += [f"    {line}" for line in r.machinery]
    return "\n".join(out)
