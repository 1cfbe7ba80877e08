"""The numerical model of a scene, assembled from its declared effects only, and the switching
(Filippov) machinery that integrates dry friction for the reference and a student's equations alike.

`SceneModel(mech)` compiles exactly the machinery `lagrade.derive.effects.machinery` says the declared
effects call for, and nothing else:

- the accelerations ``M(q[, t]) qdd = f(q, qd[, t])`` with ``t`` an argument only for time-dependent
  scenes (autonomous scenes compile without it);
- velocity-dependent forces (dissipation) compiled separately, with every ``Abs``/``sign`` of a velocity
  replaced by a branch variable ``sigma = +-1`` (or 0 when a dry-friction contact sticks), so the right-hand
  side is smooth inside a branch and the sign change is located by an event, not resolved by tiny steps;
- the multipliers (constraint forces) only when ``constraint_force`` is declared;
- contact-loss events (a multiplier reaching zero) only for ``unilateral_contact``.

`scene_model(mech)` is the one model of a scene grading integrates: a scene that declares no switching
runs its `SceneModel.compiled_rates` (one compiled call of exactly these arguments) and declared events,
or `SceneModel.hamilton_rates` in (q, p) for a Hamilton-form part; a switching scene runs a fresh
`SceneModel` per run (it keeps branches).

``SceneModel(mech, everything=True)`` builds all of it regardless of the declarations: the
`benchmarks/effects.py` baseline that measures what the unused machinery costs.

`EquationsModel` builds the same switching model from any equations of motion (a student's rows,
linear in the accelerations), with no knowledge of which side they come from: grading integrates
both the reference and the student's equations this way when the scene declares switching.

Both follow Filippov's rule (`Switching`): at a zero of a switching argument h (a velocity, say)
the branch flips when one one-sided field carries the motion through; when both one-sided fields
point back into h = 0 the motion slides on it (for h = v: the coordinate sticks, which is what
"static friction holds" means for any equations), with the convex combination of the two fields
that keeps h constant; it leaves (breakaway) when that stops holding.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp

from lagrade.compare.trajectory import BatchedEvent
from lagrade.derive.effects import Machinery, _velocity_switches, dry_friction_form, machinery, switch_groups
from lagrade.numbers.numeric import (
    CompiledRates,
    Vectorized,
    as_row,
    call_blocks,
    compile_exprs,
    compile_linear_solve,
    solve_batch,
)
from lagrade.derive.reference import Mechanics, split_energy
from lagrade.problem.symbols import T


@dataclass
class Branches:
    """Switching arguments of the dissipative forces and their current branch per trajectory."""

    args: list[sp.Expr]
    sigma: np.ndarray                  # (J, K) in {-1, 0, +1}
    sign_like: list[bool]              # True: a sign() (dry friction, may stick); False: Abs (never sticks)
    coordinate: list[int | None]       # index of the coordinate whose velocity the argument is, if any


def branch_form(exprs: list[sp.Expr], velocities: set[sp.Symbol], taken: Sequence[sp.Symbol] = ()):
    """``exprs`` with each velocity ``sign``/``Abs`` (after `dry_friction_form`) replaced by a branch
    symbol: (new exprs, switching arguments, branch symbols, sign_like per argument). The same for the
    reference's forces and a student's rows, so both sides switch by the same rule. Branch symbols are
    named apart from ``taken`` (the other arguments they are compiled with) and the expressions' own."""
    forms = [dry_friction_form(e, velocities) for e in exprs]
    groups = switch_groups(forms, velocities)
    args = [group[0][0] for group in groups]
    names = {str(x) for x in taken} | {str(x) for e in forms for x in e.free_symbols}
    prefix = "sigma"
    while any(name.startswith(prefix) for name in names):
        prefix = "_" + prefix
    sig = list(sp.symbols(f"{prefix}0:{len(args)}")) if args else []
    repl: dict = {}
    sign_like = []
    for group, sg in zip(groups, sig):
        a = group[0][0]
        for f, relation in group:  # f = relation * a: |f| = sigma a, sign(f) = relation sigma
            for form, sgn in ((f, relation), (-f, -relation)):
                repl[sp.Abs(form)] = sg * a
                repl[sp.sign(form)] = sgn * sg
        sign_like.append(any(f.args[0] in (g, -g) for g, _ in group for e in forms for f in e.atoms(sp.sign)))
    out = [e.xreplace(repl) for e in forms]
    leftover = [e for e in out if any(f.args[0].free_symbols & velocities for f in e.atoms(sp.Abs, sp.sign))]
    if leftover:
        raise ValueError(f"cannot split the non-smooth forces {leftover} into branches")
    return out, args, sig, sign_like


class Switching:
    """Branch variables sigma (J, K) of a right-hand side and Filippov's rule at their zeros.

    A subclass gives ``dim``, ``branches`` and three hooks: ``_field(t, Y, sigma)`` the rates with the
    branches as given (a stuck branch at 0: for a force affine in sigma, the mean of both sides),
    ``_switch_values(t, Y)`` (J, K) and ``_switch_gradient(t, Y)`` (J, dim, K), the gradient in Y.
    """

    dim: int
    branches: Branches | None = None
    #: how many times each kind of switch happened (trajectory, time): for tests and reports
    switches: dict[str, list[tuple[int, float]]]

    # ------------------------------------------------------------------ hooks
    def _field(self, t, Y: np.ndarray, sigma: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def _switch_values(self, t, Y: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    def _switch_gradient(self, t, Y: np.ndarray) -> np.ndarray:  # pragma: no cover - abstract
        raise NotImplementedError

    # ------------------------------------------------------------------ rates
    def _armed(self, K: int) -> bool:
        return self.branches is not None and self.branches.sigma.shape[1] == K

    def field(self, t, Y: np.ndarray, sigma: np.ndarray | None = None) -> np.ndarray:
        """The rates with Filippov's sliding where a sign-like branch is stuck (sigma = 0). Unarmed
        (no events set up): the exact non-smooth law, sign(h), and no sticking."""
        br = self.branches
        if br is None or not br.args:
            return self._field(t, Y, np.zeros((0, Y.shape[1])))
        if sigma is None:
            if not self._armed(Y.shape[1]):
                return self._field(t, Y, np.sign(self._switch_values(t, Y)))
            sigma = br.sigma
        zero = sigma == 0
        if not zero.any():
            return self._field(t, Y, sigma)
        stuck = zero & np.array(br.sign_like, dtype=bool)[:, None]
        if not stuck.any():
            return self._field(t, Y, sigma)
        js = np.flatnonzero(stuck.any(axis=1))
        G = self._switch_gradient(t, Y)
        if len(js) == 1:
            # Filippov's sliding field: (1 - s) F- + s F+ with s such that dh/dt = 0, exactly (no
            # assumption on how sigma enters); columns not stuck have F+ = F- = their own field
            j = js[0]
            cols = stuck[j]
            sp_, sm = sigma.copy(), sigma.copy()
            sp_[j, cols], sm[j, cols] = 1.0, -1.0
            Fp, Fm = self._field(t, Y, sp_), self._field(t, Y, sm)
            gp, gm = (G[j] * Fp).sum(axis=0), (G[j] * Fm).sum(axis=0)
            den = gm - gp
            s = np.clip(np.divide(gm, den, out=np.full_like(gm, 0.5), where=den != 0), 0.0, 1.0)
            return Fm + np.where(cols, s, 1.0) * (Fp - Fm)
        # several branches stuck at once: the field taken affine in them (as sign(v)*F is)
        F = self._field(t, Y, sigma)
        B = {}
        for j in js:
            sp_, sm = sigma.copy(), sigma.copy()
            sp_[j], sm[j] = 1.0, -1.0
            B[j] = 0.5 * (self._field(t, Y, sp_) - self._field(t, Y, sm))
        for k in np.flatnonzero(stuck.any(axis=0)):
            S = [j for j in js if stuck[j, k]]
            A = np.array([[G[i, :, k] @ B[j][:, k] for j in S] for i in S])
            b = np.array([-(G[i, :, k] @ F[:, k]) for i in S])
            if not (np.isfinite(A).all() and np.isfinite(b).all()):
                F[:, k] = np.nan  # this trajectory's step is rejected, as any NaN; the others go on
                continue
            sol = np.linalg.lstsq(A, b, rcond=None)[0]
            F[:, k] += sum(np.clip(sj, -1.0, 1.0) * B[j][:, k] for sj, j in zip(sol, S))
        return F

    def exact(self, t, Y: np.ndarray) -> np.ndarray:
        """The rates with the exact non-smooth law sign(h) and no branch state (no sticking): what a
        plot integrates without events, whatever the branches were left at by a run."""
        br = self.branches
        if br is None or not br.args:
            return self._field(t, Y, np.zeros((0, Y.shape[1])))
        return self._field(t, Y, np.sign(self._switch_values(t, Y)))

    def __call__(self, t, Y: np.ndarray) -> np.ndarray:
        return self.field(t, Y)

    # ------------------------------------------------------------------ switching
    def arm(self, y0: np.ndarray) -> None:
        """Start every trajectory on the branch its initial state is on (h = 0: the positive one)."""
        br = self.branches
        if br is None or not br.args:
            return
        br.sigma = np.sign(self._switch_values(0.0, y0))
        br.sigma[br.sigma == 0] = 1.0
        self.switches = {"flip": [], "stick": [], "breakaway": []}

    def _one_sided(self, j: int, k: int, t: float, yk: np.ndarray) -> tuple[float, float]:
        """dh_j/dt on either branch of j at the state ``yk`` of trajectory k (the batch evaluated at
        copies of it: each column keeps its own parameters; column k is the one read)."""
        K = self.branches.sigma.shape[1]
        Y = np.repeat(np.asarray(yk, dtype=float)[:, None], K, axis=1)
        up, down = self._one_sided_batch(j, t, Y, self.branches.sigma)
        return float(up[k]), float(down[k])

    def _one_sided_batch(self, j: int, t, Y: np.ndarray, sigma: np.ndarray):
        sp_, sm = sigma.copy(), sigma.copy()
        sp_[j], sm[j] = 1.0, -1.0
        g = self._switch_gradient(t, Y)[j]                       # (dim, K)
        return (g * self.field(t, Y, sp_)).sum(axis=0), (g * self.field(t, Y, sm)).sum(axis=0)

    def _at_zero(self, j: int, k: int, t: float, yk: np.ndarray) -> None:
        br = self.branches
        if not br.sign_like[j]:
            br.sigma[j, k] = -br.sigma[j, k]   # Abs: the force is continuous, only the branch changes
            self.switches["flip"].append((k, t))
            return
        up, down = self._one_sided(j, k, t, yk)
        if up > 0:
            br.sigma[j, k] = 1.0
        elif down < 0:
            br.sigma[j, k] = -1.0
        else:
            br.sigma[j, k] = 0.0   # both sides point back into h = 0: static friction holds
        self.switches["stick" if br.sigma[j, k] == 0 else "flip"].append((k, t))

    def _release(self, j: int, k: int, t: float, yk: np.ndarray) -> None:
        up, _ = self._one_sided(j, k, t, yk)
        self.branches.sigma[j, k] = 1.0 if up > 0 else -1.0
        self.switches["breakaway"].append((k, t))

    def _moving(self, j: int, t, Y: np.ndarray) -> np.ndarray:
        sg = self.branches.sigma[j]
        return np.where(sg != 0, sg * self._switch_values(t, Y)[j], 1.0)

    def _margin(self, j: int, t, Y: np.ndarray) -> np.ndarray:
        sg = self.branches.sigma[j]
        if not (sg == 0).any():
            return np.ones(Y.shape[1])
        up, down = self._one_sided_batch(j, t, Y, self.branches.sigma)
        # stuck while up <= 0 <= down; the margin reaches 0 when either side can move
        return np.where(sg == 0, np.minimum(-up, down), 1.0)

    def _released(self, j: int, k: int, t: float, yk: np.ndarray) -> None:
        if self.branches.sigma[j, k] == 0:
            self._release(j, k, t, yk)

    def switching_events(self, y0: np.ndarray) -> list[BatchedEvent]:
        """Arm the branches at ``y0`` and return their events: a sign change of each argument, and for
        sign-like ones a breakaway (its margin is +1, never a root, where nothing is stuck)."""
        self.arm(y0)
        br = self.branches
        out: list[BatchedEvent] = []
        for j, arg in enumerate(br.args if br else []):
            out.append(BatchedEvent(f"sign change of {arg}", lambda t, Y, j=j: self._moving(j, t, Y), "switch",
                                    -1.0, lambda k, t, yk, j=j: self._at_zero(j, k, t, yk)))
            if br.sign_like[j]:
                out.append(BatchedEvent(f"static friction exceeded ({arg})", lambda t, Y, j=j: self._margin(j, t, Y),
                                        "switch", -1.0, lambda k, t, yk, j=j: self._released(j, k, t, yk)))
        return out


class SceneModel(Switching):
    """Rates, multipliers and events of one scene, compiled from its declared effects."""

    def __init__(self, mech: Mechanics, *, everything: bool = False):
        self.mech = mech
        self.n = n = len(mech.names)
        self.dim = 2 * n
        self.params: np.ndarray | None = None
        self.switches = {"flip": [], "stick": [], "breakaway": []}
        declared = machinery(mech)
        if everything:
            mult = tuple(c.multiplier for c in mech.system.constraints if c.multiplier)
            vel = set(mech.s.qd)
            sw = tuple(dict.fromkeys(str(a) for e in mech.Q for a in _velocity_switches(e, vel)))
            declared = Machinery(True, True, sw, mult, mult)
        self.machinery = declared
        s = mech.s
        self.time_arg = declared.explicit_time
        base = [*s.q, *s.qd] + ([T] if self.time_arg else []) + list(mech.params)
        Q = list(mech.Q)
        conservative = [f - Qi for f, Qi in zip(mech.force, Q)]
        if not declared.velocity_forces:
            # applied forces Q(q, t) are part of the force vector; validation forbids velocities here
            conservative = list(mech.force)
            Q = [sp.S.Zero] * n
        self._mass = compile_exprs(list(mech.mass), base)
        self._force = compile_exprs(conservative, base)
        self.branches: Branches | None = None
        self._solve: Vectorized | None = None
        self._hamilton: tuple[Vectorized, Vectorized] | None = None
        self._Q = None
        self._switch = None
        if declared.velocity_forces:
            Qs, args, sig, sign_like = branch_form(Q, set(s.qd), base)
            self._Q = compile_exprs(Qs, [*base, *sig])
            coord = [s.qd.index(a) if a in s.qd else None for a in args]
            self.branches = Branches(args, np.zeros((len(args), 0)), sign_like, coord)
            if args:
                self._switch = compile_exprs(args, base)
                self._grad = compile_exprs([sp.diff(a, y) for a in args for y in [*s.q, *s.qd]], base)
        self._mult = None
        if declared.multipliers or declared.contact_events:
            names = list(dict.fromkeys([*declared.multipliers, *declared.contact_events]))
            exprs = [mech.multiplier_exprs[sp.Symbol(m)] for m in names]
            self.multiplier_names = names
            self._mult = compile_exprs(exprs, [*s.q, *s.qd, *s.qdd] + ([T] if self.time_arg else [])
                                       + list(mech.params))

    # ------------------------------------------------------------------ evaluation
    def _argv(self, q, qd, t, params):
        K = q.shape[1]
        return [*q, *qd] + ([np.full(K, t) if np.ndim(t) == 0 else t] if self.time_arg else []) + [*params]

    def accelerations(self, q: np.ndarray, qd: np.ndarray, t, params: np.ndarray,
                      sigma: np.ndarray | None = None) -> np.ndarray:
        """The accelerations on the given branches (None: the armed ones, or the exact sign(h) when
        no events are armed). Sliding (a stuck coordinate) is applied by `field`, not here."""
        n, K = q.shape
        argv = self._argv(q, qd, t, params)
        M = self._mass(*argv).reshape(n, n, K)
        f = self._force(*argv)
        if self._Q is not None:
            if sigma is not None:
                sg = sigma
            elif self._armed(K):
                sg = self.branches.sigma
            elif self._switch is not None:   # no events armed: the exact non-smooth force, no sticking
                sg = np.sign(self._switch(*argv))
            else:
                sg = np.zeros((0, K))
            f = f + self._Q(*argv, *sg)
        return solve_batch(M, f)

    def _field(self, t, Y, sigma):
        n = self.n
        return np.concatenate([Y[n:], self.accelerations(Y[:n], Y[n:], t, self.params, sigma)])

    def _switch_values(self, t, Y):
        n = self.n
        return self._switch(*self._argv(Y[:n], Y[n:], t, self.params))

    def _switch_gradient(self, t, Y):
        n = self.n
        J = len(self.branches.args)
        return self._grad(*self._argv(Y[:n], Y[n:], t, self.params)).reshape(J, 2 * n, Y.shape[1])

    def rates(self, params: np.ndarray):
        """``(t, Y) -> Y'`` for `integrate`, Y = (q, qd) of shape (2n, K)."""
        self.params = params

        def f(t: float, Y: np.ndarray) -> np.ndarray:
            return self(t, Y)

        return f

    @property
    def args(self) -> list[sp.Symbol]:
        """The arguments every function of this model is compiled with: q, q', t only when the declared
        effects make the scene time-dependent, the parameters."""
        s = self.mech.s
        return [*s.q, *s.qd] + ([T] if self.time_arg else []) + list(self.mech.params)

    def compiled_rates(self, params: np.ndarray) -> CompiledRates:
        """The rates of a scene without switching as one compiled call (machine code where symengine
        compiles it), from the same declared machinery: no t argument for an autonomous scene, the
        applied forces part of the force vector. This is what grading integrates for every scene that
        declares no switching. A switching scene's compiled rates are its exact non-smooth law (sign(h)
        evaluated, no branches, no sticking): what a study of the integrator runs; grading integrates
        `rates` there (Filippov's rule needs branches)."""
        if self._solve is None:
            n = self.n
            force = list(self.mech.force)   # = conservative + Q: no branch to keep apart
            self._solve = compile_linear_solve([list(self.mech.mass.row(i)) for i in range(n)], force, self.args)
        return CompiledRates(self._solve, self.dim, params, copied=self.n, timed=self.time_arg)

    def _hamilton_parts(self) -> tuple[Vectorized, Vectorized]:
        """(q' from (q, p[, t], params); dL/dq + Q from (q, q'[, t], params)), compiled once."""
        s, L = self.mech.s, self.mech.L
        if self._hamilton is None:
            zero = {v: 0 for v in s.qd}
            A = [[sp.diff(L, a, b).xreplace(zero) for b in s.qd] for a in s.qd]
            rhs = [p - sp.diff(L, v).xreplace(zero) for p, v in zip(s.p, s.qd)]
            timed = [T] if self.time_arg else []
            self._hamilton = (compile_linear_solve(A, rhs, [*s.q, *s.p, *timed, *self.mech.params]),
                              compile_exprs([sp.diff(L, q) + Qi for q, Qi in zip(s.q, self.mech.Q)], self.args))
        return self._hamilton

    def phase_to_velocities(self, Y: np.ndarray, t, params: np.ndarray) -> np.ndarray:
        """(q, p) of shape (2n, K) -> (q, q'): the velocities from p = dL/dq' (L quadratic in them)."""
        n = self.n
        velocities, _ = self._hamilton_parts()
        timed = [np.full(Y.shape[1], t) if np.ndim(t) == 0 else t] if self.time_arg else []
        return np.concatenate([Y[:n], velocities(*Y[:n], *Y[n:], *timed, *params)])

    def hamilton_rates(self, params: np.ndarray):
        """``(t, Y) -> Y'`` of Hamilton's equations, Y = (q, p) of shape (2n, K): q' from p = dL/dq'
        solved numerically (L is quadratic in the velocities), p' = dL/dq + Q. Compiled with the same
        arguments as `compiled_rates` (no t for an autonomous scene): what grading integrates for a
        Hamilton-form part of a scene without switching (with `phase_events`)."""
        n = self.n
        velocities, forces = self._hamilton_parts()

        def f(t: float, Y: np.ndarray) -> np.ndarray:
            timed = [np.full(Y.shape[1], t) if np.ndim(t) == 0 else t] if self.time_arg else []
            qd = velocities(*Y[:n], *Y[n:], *timed, *params)
            return np.concatenate([qd, forces(*Y[:n], *qd, *timed, *params)])

        if np.ndim(params) == 2:   # the same rates on m copies of the batch (`trajectory.rate_scan`)
            f.tiled = lambda m: self.hamilton_rates(np.tile(params, (1, m)))
        return f

    def multipliers(self, Y: np.ndarray, t, params: np.ndarray) -> np.ndarray:
        """Constraint forces along the motion, (len(multiplier_names), K)."""
        if self._mult is None:
            raise ValueError("this scene declares no constraint_force or unilateral_contact: no multipliers")
        n = self.n
        q, qd = Y[:n], Y[n:]
        a = self.accelerations(q, qd, t, params)
        K = Y.shape[1]
        extra = [np.full(K, t) if np.ndim(t) == 0 else t] if self.time_arg else []
        return self._mult(*q, *qd, *a, *extra, *params)

    # ------------------------------------------------------------------ events
    def contact_events(self, y0: np.ndarray, params: np.ndarray) -> list[BatchedEvent]:
        """Contact-loss stop events: the reference's multiplier reaching zero along the motion."""
        out: list[BatchedEvent] = []
        if self.machinery.contact_events:
            idx = [self.multiplier_names.index(m) for m in self.machinery.contact_events]
            sign0 = np.sign(self.multipliers(y0, 0.0, params)[idx])
            sign0[sign0 == 0] = 1.0
            for j, name in zip(range(len(idx)), self.machinery.contact_events):
                def g(t, Y, j=j):
                    return self.multipliers(Y, t, params)[idx[j]] * sign0[j]
                out.append(BatchedEvent(f"contact lost ({name} = 0)", g, "stop", -1.0))
        return out

    def phase_contact_events(self, y0: np.ndarray, params: np.ndarray) -> list[BatchedEvent]:
        """`contact_events` for a run in (q, p): the same multipliers, at the velocities p gives. The
        Hamilton path watches these, so its comparison ends where the contact is lost, as the
        Lagrange path's does (the scene's model says nothing beyond)."""
        if not self.machinery.contact_events:
            return []
        out = []
        for ev in self.contact_events(self.phase_to_velocities(y0, 0.0, params), params):
            def g(t, Y, fn=ev.fn):
                return fn(t, self.phase_to_velocities(Y, t, params))
            out.append(BatchedEvent(ev.name, g, ev.action, ev.direction))
        return out

    def events(self, y0: np.ndarray, params: np.ndarray) -> list[BatchedEvent]:
        """Contact-loss and switching events of the declared effects (none for a smooth, bilateral scene)."""
        self.params = params
        out = self.contact_events(y0, params)
        if self.branches is not None and self.branches.args:
            out += self.switching_events(y0)
        return out

    # ------------------------------------------------------------------ conservation
    def energy(self, Y: np.ndarray, t, params: np.ndarray) -> np.ndarray:
        """E = T + V from the scene's L (terms with velocities are T): for the stability checks."""
        if not hasattr(self, "_E"):
            kin, pot = split_energy(self.mech.L, self.mech)
            self._E = compile_exprs([kin + pot], self.mech.args)
        n = self.n
        K = Y.shape[1]
        return self._E(*Y[:n], *Y[n:], np.full(K, t) if np.ndim(t) == 0 else t, *params)[0]


class PhaseModel(Switching):
    """A switching scene's model in (q, p), for the Hamilton-form parts (an H, Hamilton's equations):
    the same `SceneModel` (its declared forces, its branch variables, Filippov's rule), read in the
    momenta. q' from p = dL/dq' (linear in p), p' = dL/dq + Q(q, q', t; sigma); the switching arguments
    are the scene's, h(q, q'(q, p)), their gradient in (q, p) by the chain rule (dq'/dp exactly: q' is
    linear in p; dq'/dq by central differences). Keeps branches: one per run, as `SceneModel`."""

    def __init__(self, scene: SceneModel, params: np.ndarray):
        self.scene = scene
        self.n, self.dim = scene.n, scene.dim
        self.params = scene.params = params
        self.branches = scene.branches
        self.switches = {"flip": [], "stick": [], "breakaway": []}
        mech = scene.mech
        self._dLdq = compile_exprs([sp.diff(mech.L, q) for q in mech.s.q], scene.args)

    def _state(self, t, Y: np.ndarray) -> tuple[np.ndarray, list]:
        X = self.scene.phase_to_velocities(Y, t, self.params)
        return X, self.scene._argv(X[:self.n], X[self.n:], t, self.params)

    def _field(self, t, Y, sigma):
        X, argv = self._state(t, Y)
        pd = np.asarray(self._dLdq(*argv), dtype=float).reshape(self.n, Y.shape[1])
        if self.scene._Q is not None:
            pd = pd + np.asarray(self.scene._Q(*argv, *sigma), dtype=float).reshape(self.n, Y.shape[1])
        return np.concatenate([X[self.n:], pd])

    def _switch_values(self, t, Y):
        _, argv = self._state(t, Y)
        return np.asarray(self.scene._switch(*argv), dtype=float).reshape(-1, Y.shape[1])

    def _switch_gradient(self, t, Y):
        n, K = self.n, Y.shape[1]
        J = len(self.branches.args)
        X, argv = self._state(t, Y)
        G = np.asarray(self.scene._grad(*argv), dtype=float).reshape(J, 2 * n, K)   # in (q, q')
        v = X[n:]
        dv = np.empty((n, 2 * n, K))   # dq'_a / d(q, p)_b
        for b in range(2 * n):
            step = np.zeros_like(Y)
            if b < n:
                h = 1e-6 * (1.0 + np.abs(Y[b]))
                step[b] = h
                dv[:, b] = (self.scene.phase_to_velocities(Y + step, t, self.params)[n:]
                            - self.scene.phase_to_velocities(Y - step, t, self.params)[n:]) / (2 * h)
            else:
                step[b] = 1.0
                dv[:, b] = self.scene.phase_to_velocities(Y + step, t, self.params)[n:] - v
        out = np.einsum("jak,abk->jbk", G[:, n:], dv)
        out[:, :n] += G[:, :n]
        return out


def scene_model(mech: Mechanics, *, everything: bool = False) -> SceneModel:
    """The one model of ``mech`` grading integrates when the scene declares no switching (kept on the
    Mechanics: it holds no per-run state there, and compiling it is the slow part). A switching
    scene's model keeps its branches per run: build a `SceneModel` for each run instead."""
    kept = mech.__dict__.setdefault("_scene_models", {})
    if everything not in kept:
        kept[everything] = SceneModel(mech, everything=everything)
    return kept[everything]


def hamilton_rows(H: sp.Expr, mech: Mechanics) -> list[sp.Expr]:
    """Hamilton's equations of ``H`` with the scene's forces, as rows ``q' - dH/dp``, ``p' + dH/dq - Q``
    (the generalized forces Q(q, q', t) at q' = dH/dp)."""
    qd = [sp.diff(H, p) for p in mech.s.p]
    at_qd = dict(zip(mech.s.qd, qd))
    pd = [-sp.diff(H, q) + sp.sympify(Qi).xreplace(at_qd) for q, Qi in zip(mech.s.q, mech.Q)]
    return [*(u - e for u, e in zip(mech.s.qd, qd)), *(u - e for u, e in zip(mech.s.pd, pd))]


def phase_form(mech: Mechanics) -> dict:
    """`EquationsModel`'s keywords for rows in (q, p): unknowns (q', p'), state (q, p), the momenta
    the velocities a switch reads."""
    s = mech.s
    return {"unknowns": [*s.qd, *s.pd], "state": [*s.q, *s.p], "velocities": set(s.p), "copied": False}


def scene_motion(mech: Mechanics, y0: np.ndarray, params: np.ndarray, horizon: float, acc, *,
                 t_eval: np.ndarray | None = None, t0: float = 0.0, method: str | None = None,
                 samples: int = 201):
    """The scene's own motion from ``y0`` = (q, q') (2n, K), ``params`` (P, K): the model of its declared
    effects with its declared events (contact loss stops a trajectory, `Run.t_stop`; a friction sign
    switches its branch), integrated by `integrate` at ``acc``. ``t0``: the time ``y0`` is given at (the
    run's times are counted from it). What the motion parts (per-entry credit) and the numerical parts
    compare with, and what the benchmarks time as "the grading path": the same model the eom, L and H
    paths integrate. ``method``, ``samples``: as `integrate` takes them."""
    from lagrade.compare.trajectory import integrate

    switching = bool(machinery(mech).switching)
    model = SceneModel(mech) if switching else scene_model(mech)
    rates = model.rates(params) if switching else model.compiled_rates(params)
    events = model.events(y0, params)
    if t0:
        base = rates
        rates = lambda t, Y: base(t + t0, Y)  # noqa: E731
        events = [BatchedEvent(e.name, lambda t, Y, fn=e.fn: fn(t + t0, Y), e.action, e.direction,
                               None if e.on_event is None else (lambda k, t, y, h=e.on_event: h(k, t + t0, y)),
                               e.active) for e in events]
    return integrate(rates, y0, horizon, acc, events=events, t_eval=t_eval, method=method, samples=samples)


class EquationsModel(Switching):
    """A system given by rows linear in its unknown rates (a student's equations of motion, the
    Lagrange rows of a student's L, Hamilton's equations of an H), made a switching model the same way
    as the scene's: each sign/Abs of a velocity a branch variable, the rows solved for the rates on
    given branches.

    ``args``: the rows' other symbols, the state first ([q, q', t, constants...] by default);
    ``constants`` (C, K) the values of those after t, per trajectory. Second order (the default):
    unknowns q'', state (q, q'), the velocities q'. Hamilton's form: ``unknowns`` (q', p'), ``state``
    (q, p), ``velocities`` the momenta (a friction law there reads sign(p/m)), ``copied=False``."""

    def __init__(self, rows: list[sp.Expr], mech: Mechanics, args: list[sp.Symbol], constants: np.ndarray, *,
                 unknowns: list[sp.Symbol] | None = None, state: list[sp.Symbol] | None = None,
                 velocities: set[sp.Symbol] | None = None, copied: bool = True):
        from lagrade.compare.equations import CompiledRows

        s = mech.s
        self.n = n = len(mech.names)
        self.dim = 2 * n
        self.copied = copied
        unknowns = list(s.qdd) if unknowns is None else unknowns
        state = [*s.q, *s.qd] if state is None else state
        velocities = set(s.qd) if velocities is None else velocities
        self.switches = {"flip": [], "stick": [], "breakaway": []}
        rows_s, sw, sig, sign_like = branch_form(list(rows), velocities, args)
        self._solver: Vectorized = CompiledRows(rows_s, unknowns, [*args, *sig]).solver
        self.constants = np.ascontiguousarray(np.asarray(constants, dtype=float))
        coord = [s.qd.index(a) if a in s.qd else None for a in sw]
        self.branches = Branches(sw, np.zeros((len(sw), 0)), sign_like, coord)
        self._switch = compile_exprs(sw, args) if sw else None
        self._grad = compile_exprs([sp.diff(a, y) for a in sw for y in state], args) if sw else None

    def _field(self, t, Y, sigma):
        n, K = self.n, Y.shape[1]
        out = np.asarray(call_blocks(self._solver, Y, as_row(t), self.constants, sigma), dtype=float)
        if not self.copied:
            return out.reshape(2 * n, K)
        return np.concatenate([Y[n:], out.reshape(n, K)])

    def _switch_values(self, t, Y):
        v = call_blocks(self._switch, Y, as_row(t), self.constants)
        return np.asarray(v, dtype=float).reshape(-1, Y.shape[1])

    def _switch_gradient(self, t, Y):
        J = len(self.branches.args)
        g = np.asarray(call_blocks(self._grad, Y, as_row(t), self.constants), dtype=float)
        return g.reshape(J, 2 * self.n, Y.shape[1])
