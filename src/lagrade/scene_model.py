"""The numerical model of a scene, assembled from its declared effects only.

`SceneModel(mech)` compiles exactly the machinery `lagrade.effects.machinery` says the declared
effects call for, and nothing else:

- the accelerations ``M(q[, t]) qdd = f(q, qd[, t])`` with ``t`` an argument only for time-dependent
  scenes (autonomous scenes compile without it);
- velocity-dependent forces (dissipation) compiled separately, with every ``Abs``/``sign`` of a velocity
  replaced by a branch variable ``sigma = +-1`` (or 0 when a dry-friction contact sticks), so the right-hand
  side is smooth inside a branch and the sign change is located by an event, not resolved by tiny steps;
- the multipliers (constraint forces) only when ``constraint_force`` is declared;
- contact-loss events (a multiplier reaching zero) only for ``unilateral_contact``.

``SceneModel(mech, everything=True)`` builds all of it regardless of the declarations: the
`benchmarks/effects.py` baseline that measures what the unused machinery costs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from lagrade.compare.trajectory import BatchedEvent
from lagrade.effects import Machinery, machinery
from lagrade.numeric import compile_exprs, solve_batch
from lagrade.reference import Mechanics, split_energy
from lagrade.symbols import T


@dataclass
class Branches:
    """Switching arguments of the dissipative forces and their current branch per trajectory."""

    args: list[sp.Expr]
    sigma: np.ndarray                  # (J, K) in {-1, 0, +1}
    sign_like: list[bool]              # True: a sign() (dry friction, may stick); False: Abs (never sticks)
    coordinate: list[int | None]       # index of the coordinate whose velocity the argument is, if any


class SceneModel:
    """Rates, multipliers and events of one scene, compiled from its declared effects."""

    def __init__(self, mech: Mechanics, *, everything: bool = False):
        self.mech = mech
        self.n = n = len(mech.names)
        declared = machinery(mech)
        if everything:
            mult = tuple(c.multiplier for c in mech.system.constraints if c.multiplier)
            vel = set(mech.s.qd)
            from lagrade.effects import _velocity_switches

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
        self._Q = None
        if declared.velocity_forces:
            vel = set(s.qd)
            from lagrade.effects import _velocity_switches, dry_friction_form

            Q = [dry_friction_form(e, vel) for e in Q]

            args: list[sp.Expr] = []
            for e in Q:
                for a in _velocity_switches(e, vel):
                    if not any(sp.simplify(a - b) == 0 for b in args):
                        args.append(a)
            sig = sp.symbols(f"sigma0:{len(args)}") if args else ()
            repl = {}
            sign_like = []
            for a, sg in zip(args, sig):
                repl[sp.Abs(a)] = sg * a
                repl[sp.Abs(-a)] = sg * a
                repl[sp.sign(a)] = sg
                repl[sp.sign(-a)] = -sg
                sign_like.append(any(f.args[0] in (a, -a) for e in Q for f in e.atoms(sp.sign)))
            Qs = [e.xreplace(repl) for e in Q]
            leftover = [e for e in Qs if e.has(sp.Abs, sp.sign) and any(
                f.args[0].free_symbols & vel for f in e.atoms(sp.Abs, sp.sign))]
            if leftover:
                raise ValueError(f"cannot split the non-smooth forces {leftover} into branches")
            self._Q = compile_exprs(Qs, [*base, *sig])
            coord = [s.qd.index(a) if a in s.qd else None for a in args]
            self.branches = Branches(args, np.zeros((len(args), 0)), sign_like, coord)
            self._switch = compile_exprs(args, base) if args else None
        else:
            self._switch = None
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
        n, K = q.shape
        argv = self._argv(q, qd, t, params)
        M = self._mass(*argv).reshape(n, n, K)
        f = self._force(*argv)
        if self._Q is not None:
            armed = True
            if sigma is not None:
                sg = sigma
            elif self.branches.sigma.shape[1] == K:
                sg = self.branches.sigma
            elif self._switch is not None:   # no events armed: the exact non-smooth force, no sticking
                sg, armed = np.sign(self._switch(*argv)), False
            else:
                sg = np.zeros((0, K))
            f = f + self._Q(*argv, *sg)
            stuck = self._stuck(sg) if armed else None
            if stuck is not None:
                for i, k in zip(*np.nonzero(stuck)):
                    M[i, :, k] = 0.0
                    M[i, i, k] = 1.0
                    f[i, k] = 0.0
        return solve_batch(M, f)

    def _stuck(self, sigma: np.ndarray) -> np.ndarray | None:
        """(n, K) mask of coordinates held at rest by sticking dry friction."""
        br = self.branches
        if br is None or not any(br.sign_like):
            return None
        mask = np.zeros((self.n, sigma.shape[1]), dtype=bool)
        for j, (sl, c) in enumerate(zip(br.sign_like, br.coordinate)):
            if sl and c is not None:
                mask[c] |= sigma[j] == 0
        return mask if mask.any() else None

    def rates(self, params: np.ndarray):
        """``(t, Y) -> Y'`` for `integrate`, Y = (q, qd) of shape (2n, K)."""
        n = self.n

        def f(t: float, Y: np.ndarray) -> np.ndarray:
            q, qd = Y[:n], Y[n:]
            a = self.accelerations(q, qd, t, params)
            stuck = self._stuck(self.branches.sigma) if self.branches is not None and \
                self.branches.sigma.shape[1] == Y.shape[1] else None
            v = qd if stuck is None else np.where(stuck, 0.0, qd)
            return np.concatenate([v, a])

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
    def events(self, y0: np.ndarray, params: np.ndarray) -> list[BatchedEvent]:
        """Contact-loss and switching events of the declared effects (none for a smooth, bilateral scene)."""
        out: list[BatchedEvent] = []
        n = self.n
        if self.machinery.contact_events:
            idx = [self.multiplier_names.index(m) for m in self.machinery.contact_events]
            sign0 = np.sign(self.multipliers(y0, 0.0, params)[idx])
            sign0[sign0 == 0] = 1.0
            for j, name in zip(range(len(idx)), self.machinery.contact_events):
                def g(t, Y, j=j):
                    return self.multipliers(Y, t, params)[idx[j]] * sign0[j]
                out.append(BatchedEvent(f"contact lost ({name} = 0)", g, "stop", -1.0))
        br = self.branches
        if br is not None and br.args:
            base_val = self._switch(*self._argv(y0[:n], y0[n:], 0.0, params))
            br.sigma = np.sign(base_val)
            br.sigma[br.sigma == 0] = 1.0

            for j in range(len(br.args)):
                def moving(t, Y, j=j):
                    return br.sigma[j] * self._switch(*self._argv(Y[:n], Y[n:], t, params))[j]

                def flip(k, t, yk, j=j):
                    self._on_zero_speed(j, k, t, yk, params)

                out.append(BatchedEvent(f"sign change of {br.args[j]}", moving, "switch", -1.0, flip,
                                        active=lambda j=j: br.sigma[j] != 0))
                if br.sign_like[j] and br.coordinate[j] is not None:
                    c = br.coordinate[j]

                    def breakaway(t, Y, j=j, c=c):
                        # while stuck: the acceleration the coordinate would get on either branch
                        return self._stick_margin(j, c, Y, t, params)

                    def release(k, t, yk, j=j, c=c):
                        a_plus, a_minus = self._branch_acc(j, c, yk[:, None], t, params[:, k:k + 1])
                        br.sigma[j, k] = 1.0 if a_plus > 0 else -1.0

                    out.append(BatchedEvent(f"static friction exceeded ({br.args[j]})", breakaway, "switch", -1.0,
                                            release, active=lambda j=j: br.sigma[j] == 0))
        return out

    def _branch_acc(self, j: int, c: int, Y: np.ndarray, t, params: np.ndarray):
        n = self.n
        q, qd = Y[:n], Y[n:].copy()
        qd[c] = 0.0
        sg = self.branches.sigma.copy() if self.branches.sigma.shape[1] == Y.shape[1] \
            else np.sign(self._switch(*self._argv(q, Y[n:], t, params)))
        sg_p, sg_m = sg.copy(), sg.copy()
        sg_p[j], sg_m[j] = 1.0, -1.0
        return (self.accelerations(q, qd, t, params, sg_p)[c], self.accelerations(q, qd, t, params, sg_m)[c])

    def _stick_margin(self, j, c, Y, t, params):
        a_plus, a_minus = self._branch_acc(j, c, Y, t, params)
        # stuck while a_plus <= 0 <= a_minus; the margin reaches 0 when either branch can move
        return np.minimum(-a_plus, a_minus)

    def _on_zero_speed(self, j: int, k: int, t: float, yk: np.ndarray, params: np.ndarray) -> None:
        br = self.branches
        if not br.sign_like[j] or br.coordinate[j] is None:
            br.sigma[j, k] = -br.sigma[j, k]   # Abs: the force is continuous, only the branch changes
            return
        c = br.coordinate[j]
        a_plus, a_minus = self._branch_acc(j, c, yk[:, None], t, params[:, k:k + 1])
        if a_plus[0] > 0:
            br.sigma[j, k] = 1.0
        elif a_minus[0] < 0:
            br.sigma[j, k] = -1.0
        else:
            br.sigma[j, k] = 0.0   # static friction holds: the coordinate sticks

    # ------------------------------------------------------------------ conservation
    def energy(self, Y: np.ndarray, t, params: np.ndarray) -> np.ndarray:
        """E = T + V from the scene's L (terms with velocities are T): for the stability checks."""
        if not hasattr(self, "_E"):
            kin, pot = split_energy(self.mech.L, self.mech)
            self._E = compile_exprs([kin + pot], self.mech.args)
        n = self.n
        K = Y.shape[1]
        return self._E(*Y[:n], *Y[n:], np.full(K, t) if np.ndim(t) == 0 else t, *params)[0]
