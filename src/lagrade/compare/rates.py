"""The right-hand side of a trajectory run as one compiled function, so the stages can be machine code.

A trajectory run evaluates its rates about 800 times. Written as Python around compiled pieces
(slice the state, stack q' on top of the accelerations, count, guard) a batch of 4 states costs
about 15 us per evaluation, of which the arithmetic is under one. `CompiledRates` keeps the rates
as data instead, one compiled function of the argument rows [state, t, constants], so the
integrator can hand a whole DOP853 step to machine code (`lagrade.native.Stages`) and keeps
calling it from Python only where it must (first stage, restarts, event location).
"""

from __future__ import annotations

import numpy as np

from lagrade.native import Native
from lagrade.numeric import Vectorized, as_row, call_blocks


class CompiledRates:
    """Rates ``(t, Y (dim, K)) -> (dim, K)`` from ``f`` of the rows [Y, t, constants].

    ``copied``: the first ``copied`` rates are the state rows ``copied .. 2 copied - 1`` as they are
    (q' = q-dot of a second-order system, whose ``f`` gives the accelerations only); ``f`` writes
    the other ``dim - copied``. ``constants``: (C, K) per trajectory, or (C, 1) shared; they are the
    parameters (and a part's extra symbols) of each sampled state.
    """

    def __init__(self, f: Vectorized, dim: int, constants: np.ndarray, copied: int = 0):
        self.f, self.dim, self.copied = f, dim, copied
        values = np.asarray(constants, dtype=float)
        self.constants = np.ascontiguousarray(values[:, None] if values.ndim == 1 else values)

    def __call__(self, t: float | np.ndarray, Y: np.ndarray) -> np.ndarray:
        body = call_blocks(self.f, Y, as_row(t), self.constants)
        c = self.copied
        return np.concatenate([Y[c:2 * c], body]) if c else body

    def pair(self) -> CompiledRates:
        """The same rates for a batch of twice the columns: each state and a displaced copy of it."""
        return CompiledRates(self.f, self.dim, np.concatenate([self.constants, self.constants], axis=1)
                             if self.constants.shape[1] > 1 else self.constants, self.copied)

    def stages(self, Z: np.ndarray, T: np.ndarray, h: np.ndarray, coef: np.ndarray):
        """Machine code for DOP853's stages on the integrator's buffers (`lagrade.native.Stages`;
        ``coef`` the stage rows), or None (numpy code: llvmlite missing, or rates it could not compile).

        Returns ``(run, state, rates, amax, columns)``: ``run(s0, s1)`` evaluates stages s0 .. s1 - 1
        into ``Z``; then ``state`` (dim, K) is the last stage's state, ``rates`` (dim, K) its rates
        unscaled, and ``amax`` (K,) each trajectory's largest |rate| over the stages run.
        ``columns(buffers)`` binds the integrator's whole loop to the same kernel and buffers
        (`lagrade.native.Stages.bind_columns`, given the other buffers by name)."""
        if not isinstance(self.f, Native):
            return None
        dim, K = self.dim, h.shape[0]
        native = self.f.stages(dim, self.copied)
        src = np.empty((self.f.nargs, K))
        src[dim + 1:] = self.constants  # constant for the run; the kernel writes the state and t rows
        out = np.empty((self.f.count, K))
        rates = np.empty((dim, K))
        amax = np.empty(K)
        run = native.bind(Z, T, h, coef, src, out, rates, amax)
        own = {"Z": Z, "T": T, "h": h, "coef": coef, "src": src, "out": out, "rates": rates, "amax": amax}
        return run, src[:dim], rates, amax, lambda buffers: native.bind_columns({**buffers, **own})
