"""The problem's figure, drawn from its scene: the figure the statement refers to ("Fig. P12.14").

A system with a ``[systems.figure]`` table is drawn as its points (bodies, pivots, pulleys) at a
sample state, joined by its lines (rods, strings), fixed points as supports; each coordinate gets
an arrow at the point it moves most, in the direction that point moves when the coordinate grows:
its positive direction, measured from the model, not drawn by hand. A system without one is drawn
as its coordinates alone: one scale each, its positive direction, and the sample value marked.

Pixels only (a PNG with no text chunk), made with matplotlib's Agg canvas, as the motion plot of
:mod:`lagrade.verdicts.plot` is: no pyplot state, so the server's threads may draw at once.
"""

from __future__ import annotations

import io

import numpy as np
import sympy as sp

from lagrade.problem.spec import Problem, System


def _latex(name: str) -> str:
    from sympy.printing.latex import latex

    from lagrade.answer.reading.latex import _latex_of as latex_name

    try:
        return f"${latex_name(name)}$"
    except Exception:  # noqa: BLE001
        return f"${latex(sp.Symbol(name))}$"


def sample_state(problem: Problem, system: System) -> tuple[dict[str, float], dict[str, float]]:
    """(coordinates, parameters) of the state drawn: each coordinate a different share of its sampled
    range (so two angles do not line up), each parameter the middle of its range."""
    coords = {c.name: c.sample[0] + (0.62 + 0.17 * i) % 1.0 * (c.sample[1] - c.sample[0])
              for i, c in enumerate(system.coordinates)}
    params = {q.name: (q.sample[0] + q.sample[1]) / 2 for q in (*problem.parameters, *system.parameters)}
    return coords, params


def _positions(problem: Problem, system: System):
    """The figure's points as numeric functions of the coordinates (the parameters at their sample)."""
    from lagrade.problem.notation import parse_math

    names = [c.name for c in system.coordinates]
    coords, params = sample_state(problem, system)
    subs = {sp.Symbol(k): v for k, v in params.items()}
    plain = {sp.Function(n)(sp.Symbol("t")): sp.Symbol(n) for n in names}
    args = [sp.Symbol(n) for n in names]
    out = {}
    for point, (x, y) in system.figure.points.items():
        exprs = [parse_math(e, names).xreplace(plain).subs(subs) for e in (x, y)]
        out[point] = sp.lambdify(args, exprs, "numpy")
    return out, coords


def draw(problem: Problem, dpi: int = 90) -> bytes:
    """The PNG of every system of ``problem``, side by side."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    systems = problem.systems
    fig = Figure(figsize=(4.2 * len(systems), 4.2))
    FigureCanvasAgg(fig)
    for i, system in enumerate(systems):
        ax = fig.add_subplot(1, len(systems), i + 1)
        try:
            if system.figure is None:
                raise LookupError
            _scene(ax, problem, system)
        except Exception:  # noqa: BLE001  (no figure table, or one that cannot be drawn: the coordinates)
            ax.clear()
            _coordinates(ax, problem, system)
        if system.key or system.title:
            ax.set_title(f"({system.key}) {system.title}".strip() if system.key else system.title, fontsize=10)
    fig.tight_layout()
    out = io.BytesIO()
    fig.savefig(out, format="png", dpi=dpi, metadata={"Software": None})
    return out.getvalue()


def _scene(ax, problem: Problem, system: System) -> None:
    funcs, coords = _positions(problem, system)
    names = [c.name for c in system.coordinates]
    at = np.array([coords[n] for n in names], dtype=float)
    pts = {p: np.array(f(*at), dtype=float) for p, f in funcs.items()}
    xy = np.array(list(pts.values()))
    size = max(float(np.ptp(xy[:, 0])), float(np.ptp(xy[:, 1])), 1.0)
    for a, b in system.figure.lines:
        ax.plot([pts[a][0], pts[b][0]], [pts[a][1], pts[b][1]], color="#444", lw=2, zorder=1)
    for p, (x, y) in pts.items():
        if p in system.figure.fixed:
            ax.plot([x - 0.08 * size, x + 0.08 * size], [y, y], color="#222", lw=3, zorder=2)
            ax.scatter([x], [y], s=30, color="#222", zorder=3)
        else:
            ax.scatter([x], [y], s=140, color="#2563eb", zorder=3)
        ax.annotate(_latex(p), (x, y), xytext=(7, 7), textcoords="offset points", fontsize=11)
    # each coordinate's positive direction: where the point that moves most goes as it grows
    h = 1e-4
    for i, name in enumerate(names):
        step = at.copy()
        step[i] += h
        moved = {p: (np.array(f(*step), dtype=float) - pts[p]) / h for p, f in funcs.items()}
        most = max(float(np.linalg.norm(v)) for v in moved.values())
        if most < 1e-9:
            continue
        # the first point (in the figure's order) that moves as much as any: a rod's own bob, not the next one
        p, d = next((q, v) for q, v in moved.items() if float(np.linalg.norm(v)) >= 0.999 * most)
        d = d / np.linalg.norm(d) * 0.28 * size
        x, y = pts[p]
        ax.annotate("", xy=(x + d[0], y + d[1]), xytext=(x, y),
                    arrowprops={"arrowstyle": "-|>", "color": "#b91c1c", "lw": 1.8}, zorder=4)
        ax.annotate(f"{_latex(name)} +", (x + d[0], y + d[1]), xytext=(4, -12), textcoords="offset points",
                    color="#b91c1c", fontsize=11)
        ax.plot([x + 1.2 * d[0]], [y + 1.2 * d[1]], alpha=0)  # the arrow inside the drawn area
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.25)
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_visible(False)


def _coordinates(ax, problem: Problem, system: System) -> None:
    """No figure table: each coordinate as a scale with its positive direction and the sample value."""
    coords, _ = sample_state(problem, system)
    n = len(system.coordinates)
    for i, c in enumerate(system.coordinates):
        y = n - i
        lo, hi = c.sample
        ax.annotate("", xy=(1.05, y), xytext=(-0.05, y), arrowprops={"arrowstyle": "-|>", "color": "#444", "lw": 1.5})
        share = (coords[c.name] - lo) / (hi - lo) if hi > lo else 0.5
        ax.scatter([share], [y], s=90, color="#2563eb", zorder=3)
        ax.text(1.08, y, f"{_latex(c.name)} +", va="center", color="#b91c1c", fontsize=11)
        ax.text(0.0, y + 0.28, c.description[:60], fontsize=8, color="#444")
    ax.set_xlim(-0.15, 1.4)
    ax.set_ylim(0.4, n + 0.8)
    ax.axis("off")
