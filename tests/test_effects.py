"""Every scene simulates exactly the effects it declares (issue: "simulate only a scene's effects").

For every problem file: the scene derives (which runs `validate_effects`: nothing used that is not
declared), the model assembled from the declared effects contains exactly the machinery they call for,
and it is still the scene's dynamics (same accelerations as the engine's generic derivation).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from lagrade.cli import main
from lagrade.derive.effects import DISSIPATION, TIME_CAPABLE, machinery
from lagrade.problem.library import load_problem, problem_ids
from lagrade.compare.scene_model import SceneModel
from lagrade.derive.reference import Mechanics, SceneError
from lagrade.compare.sampling import rng_for, sample_points, state_arrays
from lagrade.problem.spec import Problem
from lagrade.problem.symbols import T


@pytest.mark.parametrize("pid", problem_ids())
def test_compiled_dynamics_contains_exactly_the_declared_effects(pid):
    problem = load_problem(pid)
    for system in problem.systems:
        mech = Mechanics(problem, system)        # rejects a scene using an undeclared effect
        model = SceneModel(mech)
        m = machinery(mech)
        eff = set(system.effects)
        # what the compiled model holds is what the declarations call for, nothing more
        assert model.time_arg == m.explicit_time
        assert (model._Q is not None) == bool(eff & DISSIPATION) == m.velocity_forces
        assert bool(model._mult) == bool(m.multipliers or m.contact_events)
        assert not m.multipliers or "constraint_force" in eff
        assert not m.contact_events or "unilateral_contact" in eff
        # what the scene's derived dynamics use is declared
        uses_t = any(e.has(T) for e in [*mech.force, *mech.mass])
        assert not uses_t or eff & TIME_CAPABLE
        assert not any(e.free_symbols & set(mech.s.qd) for e in mech.Q) or eff & DISSIPATION
        # events: only for contact and switching of declared dissipation
        pts = sample_points(mech, 5, rng_for(pid, system.key, "effects-test"))
        q, qd, t, params = state_arrays(mech, pts)
        y0 = np.concatenate([q, qd])
        events = model.events(y0, params)
        switching = model.branches.args if model.branches else []
        sticking = sum(1 for s, c in zip(model.branches.sign_like, model.branches.coordinate)
                       if s and c is not None) if model.branches else 0
        assert len(events) == len(m.contact_events) + len(switching) + sticking
        if not eff & ({"unilateral_contact"} | DISSIPATION):
            assert events == []
        # and it is still the scene's dynamics
        t_arg = t if m.explicit_time else 0.0
        if uses_t:
            a_ref = mech.accelerations(q, qd, t, params)
        else:
            a_ref = mech.accelerations(q, qd, np.zeros_like(t), params)
        if model.branches:   # evaluate the exact non-smooth force, not a branch
            model.branches.sigma = np.zeros((len(model.branches.args), 0))
        a = model.accelerations(q, qd, t_arg, params)
        np.testing.assert_allclose(a, a_ref, rtol=1e-9, atol=1e-9)


def _problem(effects, T="m*x_d**2/2", V="k*x**2/2", Q=None, constraints=None, coords=("x",)):
    system = {"effects": effects, "T": T, "V": V, "coordinates": [{"name": c} for c in coords]}
    if Q:
        system["Q"] = Q
    if constraints:
        system["constraints"] = constraints
    return Problem.model_validate({
        "id": "12.99", "title": "test scene",
        "parameters": [{"name": "m"}, {"name": "k"}, {"name": "c"}, {"name": "g"}],
        "systems": [system], "parts": [{"name": "L", "kind": "lagrangian"}]})


@pytest.mark.parametrize("kwargs, says", [
    (dict(effects=["spring"], V="k*x**2/2*exp(-t)"), "depend(s) on t explicitly"),
    (dict(effects=["spring", "applied_force"], Q={"x": "-c*x_d"}), "velocity-dependent force"),
    (dict(effects=["spring"], Q={"x": "-c*x"}), "declare applied_force"),
    (dict(effects=["spring", "dissipation_drag"], Q={"x": "-c*sign(x_d)"}), "declare dissipation_friction"),
    (dict(effects=["spring", "holonomic_constraint"], coords=("x", "y"), T="m*(x_d**2 + y_d**2)/2",
          constraints=[{"coordinate": "y", "value": "c*x", "multiplier": "lam"}]), "declare constraint_force"),
    (dict(effects=["spring"], coords=("x", "y"), T="m*(x_d**2 + y_d**2)/2",
          constraints=[{"coordinate": "y", "value": "c*x"}]), "declare holonomic_constraint"),
    (dict(effects=["spring", "holonomic_constraint"], coords=("x", "y"), T="m*(x_d**2 + y_d**2)/2",
          constraints=[{"coordinate": "y", "value": "c*t"}]), "declare time_dependent_constraint"),
    (dict(effects=["spring"], V="k*x**2/2 + m*g*x"), "declare gravity"),
])
def test_a_scene_using_an_undeclared_effect_is_rejected_at_load_with_a_clear_message(kwargs, says):
    problem = _problem(**kwargs)
    with pytest.raises(SceneError, match="uses effects it does not declare") as err:
        Mechanics(problem, problem.systems[0])
    assert says in str(err.value)


def test_a_scene_declaring_its_effects_loads():
    problem = _problem(["spring", "dissipation_drag"], Q={"x": "-c*x_d*Abs(x_d)"})
    model = SceneModel(Mechanics(problem, problem.systems[0]))
    assert model.machinery.velocity_forces and model.machinery.switching == ("x_d",)


def test_show_lists_the_declared_effects():
    out = CliRunner().invoke(main, ["show", "12.4"]).output
    assert "effects: gravity, holonomic_constraint, constraint_force, unilateral_contact" in out


def test_bench_effects_prints_machinery_and_costs():
    from lagrade.cli.bench import bench

    res = CliRunner().invoke(bench, ["effects", "12.4", "--repeat", "1"])
    assert res.exit_code == 0, res.output
    assert "contact-loss events: lam = 0" in res.output and "all/declared" in res.output


# ----------------------------------------------------------------------------- dry friction, however written

def _friction_forms():
    import sympy as sp

    v, w, mu, N = sp.symbols("x_d y_d mu N")
    jump = {
        "sign": -mu * N * sp.sign(v),
        "v/|v|": -mu * N * v / sp.Abs(v),
        "|v|/v": -mu * N * sp.Abs(v) / v,
        "Heaviside": -mu * N * (sp.Heaviside(v) - sp.Heaviside(-v)),
        "Piecewise on v > 0": sp.Piecewise((-mu * N, v > 0), (mu * N, True)),
        "Piecewise on v < 0": sp.Piecewise((mu * N, v < 0), (-mu * N, True)),
        "relative velocity": -mu * N * (v - w) / sp.Abs(v - w),
    }
    smooth = {"quadratic drag": -mu * v * sp.Abs(v), "a speed": mu * sp.Abs(v), "linear drag": -mu * v}
    return {v, w}, v, jump, smooth


def test_every_form_of_dry_friction_is_read_as_sign_and_drag_is_not():
    import sympy as sp

    from lagrade.derive.effects import dry_friction_form

    velocities, v, jump, smooth = _friction_forms()
    for name, force in jump.items():
        canonical = dry_friction_form(force, velocities)
        assert canonical.atoms(sp.sign), name
        assert not canonical.has(sp.Abs, sp.Heaviside, sp.Piecewise), (name, canonical)
        # the same force away from zero speed
        for speed in (0.7, -1.3):
            at = {v: speed, sp.Symbol("y_d"): 0.2, sp.Symbol("mu"): 0.4, sp.Symbol("N"): 2.0}
            assert abs(float(canonical.subs(at)) - float(force.subs(at))) < 1e-12, name
    for name, force in smooth.items():
        assert dry_friction_form(force, velocities) == force, name


@pytest.mark.parametrize("law", ["-mu*m*g*x_d/Abs(x_d)", "-mu*m*g*Abs(x_d)/x_d", "-mu*m*g*sign(x_d)"])
def test_dry_friction_declared_as_drag_is_rejected(law):
    """x_d/Abs(x_d) used to pass as drag: dry friction needs dissipation_friction (sticking)."""
    from lagrade.derive.reference import Mechanics
    from lagrade.problem.spec import Problem, SceneError

    data = {"id": "t", "title": "block", "parameters": [{"name": "m"}, {"name": "mu"}, {"name": "g"}],
            "systems": [{"effects": ["gravity", "dissipation_drag"], "T": "m*x_d**2/2", "V": "0",
                         "Q": {"x": law}, "coordinates": [{"name": "x"}]}],
            "parts": [{"name": "L", "kind": "lagrangian"}]}
    problem = Problem.model_validate(data)
    with pytest.raises(SceneError, match="dry friction.*declare dissipation_friction") as info:
        Mechanics(problem, problem.systems[0])
    assert info.value.system == "" and info.value.field == "effects"
    data["systems"][0]["effects"] = ["gravity", "dissipation_friction"]
    problem = Problem.model_validate(data)
    Mechanics(problem, problem.systems[0])


def test_check_names_the_problem_file_and_line_of_an_undeclared_effect(tmp_path):
    """One line (file:line: what to declare), exit 2: never a traceback."""
    import subprocess
    import sys

    src = (Path(__file__).resolve().parents[1] / "problems" / "12.35.toml").read_text()
    old_q = next(line for line in src.splitlines() if line.startswith("Q = { theta"))
    old_effects = next(line for line in src.splitlines() if line.startswith("effects = ["))
    src = src.replace(old_q, 'Q = { theta = "-mu*m*a**2*theta_d/Abs(theta_d)" }')
    src = src.replace(old_effects, 'effects = ["holonomic_constraint", "constraint_force", "dissipation_drag"]')
    (tmp_path / "12.35.toml").write_text(src)
    line = 1 + src.splitlines().index('effects = ["holonomic_constraint", "constraint_force", "dissipation_drag"]')
    answer = Path(__file__).resolve().parents[1] / "reference_solutions" / "12.35" / "answer.py"
    r = subprocess.run([sys.executable, "-m", "lagrade", "check", "12.35", str(answer), "--problems", str(tmp_path)],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in r.stderr
    assert lines[0].startswith(f"lagrade: {tmp_path / '12.35.toml'}:{line}: ")
    assert lines[0].endswith("declare dissipation_friction")


# ------------------------------------------------------------------ the one model grading compiles

@pytest.mark.parametrize("pid", problem_ids())
def test_the_compiled_model_has_exactly_the_declared_machinery(pid):
    """Every scene's model (`scene_model`, what grading integrates) is compiled with t only when a
    declared effect makes the scene time-dependent, velocity forces kept apart only for declared
    dissipation, multipliers only for constraint forces or contact, contact events only for
    unilateral contact."""
    import numpy as np

    from lagrade.derive.effects import machinery
    from lagrade.verdicts.grade import references
    from lagrade.problem.library import load_problem
    from lagrade.numbers.numeric import Compiled
    from lagrade.compare.sampling import rng_for, sample_points, state_arrays
    from lagrade.compare.scene_model import scene_model
    from lagrade.problem.symbols import T

    problem = load_problem(pid)
    refs = references(problem)
    for system in problem.systems:
        mech = refs[system.key]
        if not mech.s.q:
            continue
        declared = machinery(mech)
        model = scene_model(mech)
        assert model.machinery == declared
        assert (T in model.args) == declared.explicit_time, f"{pid}{system.key}"
        if not declared.explicit_time:   # sound only because nothing depends on t
            assert not any(e.has(T) for e in [*mech.mass, *mech.force]), f"{pid}{system.key}"
        assert (model._Q is not None) == declared.velocity_forces
        assert (model._mult is not None) == bool(declared.multipliers or declared.contact_events)
        q, qd, _, params = state_arrays(mech, sample_points(mech, 4, rng_for(pid, system.key, "machinery")))
        rates = model.compiled_rates(params)
        assert rates.timed == declared.explicit_time
        if isinstance(rates.f, Compiled):
            assert rates.f.nargs == len(model.args) == 2 * len(mech.s.q) + declared.explicit_time + len(mech.params)
        y0 = np.concatenate([q, qd])
        assert len(model.contact_events(y0, params)) == len(declared.contact_events)


def test_grading_integrates_an_autonomous_scene_without_t_or_events():
    """12.14 (a double pendulum: no time dependence, no force, no contact): the reference grading
    integrates takes no t argument and watches no event. On main it was `Mechanics.lagrange_rates`,
    compiled with [q, q', t, params] whatever the scene declared."""
    from lagrade.verdicts.checkers.base import Context
    from lagrade.verdicts.checkers.dynamics import _lagrange_solver, lagrange_inputs
    from lagrade.verdicts.grade import references
    from lagrade.problem.library import load_problem
    from lagrade.uses.research.effectsbench import _dynamics_part

    problem = load_problem("12.14")
    system = problem.systems[0]
    part = _dynamics_part(problem, system)
    ctx = Context(problem, references(problem))
    mech = ctx.mech(part)
    run = lagrange_inputs(ctx, mech, part, lambda: _lagrange_solver(mech.L, mech, part),
                          lambda: mech.lagrange_rows(mech.L))
    assert not run.switching and run.events == []
    assert run.reference.timed is False
    assert run.reference.f.nargs == 2 * len(mech.s.q) + len(mech.params)
    generic = lagrange_inputs(ctx, mech, part, lambda: _lagrange_solver(mech.L, mech, part),
                              lambda: mech.lagrange_rows(mech.L), everything=True)
    assert generic.reference.timed is True and not generic.switching


@pytest.mark.parametrize("pid", ["12.43", "12.14", "ex12.8"])
def test_hamilton_form_rates_are_the_scene_models(pid):
    """Hamilton's equations grading integrates come from the same effect-built model as the Lagrange
    form (`SceneModel.hamilton_rates`, no t for an autonomous scene) and equal the derivation's own
    (q', p') at sampled states."""
    import numpy as np

    from lagrade.compare.sampling import rng_for, sample_points, state_arrays
    from lagrade.compare.scene_model import scene_model
    from lagrade.derive.effects import machinery
    from lagrade.problem.library import load_problem
    from lagrade.verdicts.grade import references

    problem = load_problem(pid)
    mech = references(problem)[problem.systems[0].key]
    model = scene_model(mech)
    q, qd, _, params = state_arrays(mech, sample_points(mech, 4, rng_for(pid, "hamilton-model")))
    t = np.full(q.shape[1], 0.3)
    p = mech.momenta(q, qd, t, params)
    got = model.hamilton_rates(params)(0.3, np.concatenate([q, p]))
    np.testing.assert_allclose(got, mech.hamilton_rates(q, p, t, params), rtol=1e-12, atol=1e-12)
    velocities, forces = model._hamilton
    timed = machinery(mech).explicit_time
    assert forces.nargs == len(model.args) == 2 * len(mech.s.q) + timed + len(mech.params)


def test_a_hamilton_part_integrates_the_scene_model(monkeypatch):
    """The trajectory check of a Hamilton-form part asks the scene's model for the reference rates
    (before: `Mechanics.hamilton_rates`, compiled with t whatever the scene declared)."""
    import sympy as sp

    import lagrade
    from lagrade.compare.scene_model import SceneModel

    asked = []
    original = SceneModel.hamilton_rates
    monkeypatch.setattr(SceneModel, "hamilton_rates", lambda self, params: asked.append(self) or original(self, params))
    m, g, l, t, p_theta = sp.symbols("m g l t p_theta")
    theta = sp.Function("theta")(t)
    result = lagrade.check("12.43", H=p_theta**2 / (2 * m * l**2) - sp.Rational(3, 2) * m * g * l * sp.cos(theta))
    assert asked, "the Hamilton-form trajectory check did not use the scene model"
    (H,) = [p for p in result.parts if p.part == "H"]
    assert H.verdict == "incorrect"
