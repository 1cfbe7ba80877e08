"""The picture of a wrong dynamics part: the student's motion against the true one.

One panel per coordinate, both motions from the same initial state, with the moment they separate
marked. Seeing where a pendulum's swing drifts away teaches more than a verdict.

The course server shows the same picture, as a PNG made in the grader process (:func:`plot_png`):
pixels only. The true motion is a curve to look at, never numbers: no text chunk, no vector path
(an SVG's path data would be the reference trajectory's samples), nothing but the axes' ticks.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np

from lagrade.compare.trajectory import integrate
from lagrade.verdicts.result import CheckResult


def plot_result(result: CheckResult, path: Path) -> bool:
    """Draw every incorrect dynamics part of ``result`` into one PNG in an existing folder; False when
    there is none."""
    fig = _figure(result)
    if fig is None:
        return False
    import matplotlib.pyplot as plt

    try:  # into a folder that exists: none is made (OSError otherwise)
        fig.savefig(Path(path), dpi=110)
    finally:
        plt.close(fig)
    return True


def plot_png(result: CheckResult, dpi: int = 90) -> bytes | None:
    """The same picture as PNG bytes with no metadata (the server's page shows it), of the incorrect
    dynamics parts whose own motion could be drawn; None when there is none."""
    import io

    fig = _figure(result, yours_only=True)
    if fig is None:
        return None
    import matplotlib.pyplot as plt

    out = io.BytesIO()
    fig.savefig(out, format="png", dpi=dpi, metadata={"Software": None})
    plt.close(fig)
    return out.getvalue()


def _figure(result: CheckResult, yours_only: bool = False):
    """The figure, or None. ``yours_only``: leave out a part whose own motion could not be drawn
    (its equations blow up at once): a picture of the true motion alone shows nothing of the answer."""
    cases = [(p, p._trajectory) for p in result.parts if p._trajectory is not None and p.verdict != "correct"]
    runs = []
    for part, case in cases:
        # the grading run's models with its events (contact loss ends a motion, friction switches)
        case.arm()
        ref = integrate(case.reference, case.y0, case.horizon, case.accuracy, events=case.events)
        case.arm()
        stu = integrate(case.student, case.y0, case.horizon, case.accuracy,
                        events=case.events if case.student_events is None else case.student_events)
        ref, stu = _until_stop(ref), _until_stop(stu)
        drawn = stu.y.shape[-1] == stu.t.size and stu.t.size > 1
        if drawn or not yours_only:
            runs.append((part, case, ref, stu, drawn))
    if not runs:
        return None
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = sum(len(case.labels) // 2 for _, case, *_ in runs)
    fig, axes = plt.subplots(rows, 1, figsize=(8, 2.4 * rows), sharex=False, squeeze=False)
    row = 0
    for part, case, ref, stu, drawn in runs:
        n = len(case.labels) // 2
        for i in range(n):
            ax = axes[row, 0]
            ax.plot(ref.t, ref.y[i, 0], color="black", lw=2, label="true motion")
            if drawn:
                ax.plot(stu.t, stu.y[i, 0], color="tab:red", lw=1.5, ls="--", label="your equations")
            sep = _separation(ref, stu, case.accuracy)
            if sep is not None:
                ax.axvline(sep, color="tab:orange", lw=1, ls=":")
                ax.annotate(f"separate at t = {sep:.3g}", (sep, ax.get_ylim()[1]), fontsize=8,
                            va="top", ha="left", color="tab:orange")
            ax.set_ylabel(case.labels[i])
            ax.set_title(f"{result.problem} {part.part}: {case.labels[i]}(t)", fontsize=9, loc="left")
            ax.legend(fontsize=8, loc="best")
            row += 1
        axes[row - 1, 0].set_xlabel("t")
    fig.tight_layout()
    return fig


def _until_stop(run):
    """The first trajectory's run up to where an event stopped it (contact lost): the scene's model
    says nothing beyond, so nothing is drawn there."""
    if run.t_stop is None or not run.t.size:
        return run
    n = min(run.t.size, run.y.shape[-1])
    keep = run.t[:n] <= float(run.t_stop[0]) + 1e-12
    return replace(run, t=run.t[:n][keep], y=run.y[..., :n][..., keep])


def _separation(ref, stu, acc) -> float | None:
    n = min(ref.t.size, stu.t.size, ref.y.shape[-1], stu.y.shape[-1])
    if n == 0:
        return None
    err = np.abs(stu.y[:, 0, :n] - ref.y[:, 0, :n]) / (acc.compare_atol + acc.compare_rtol * np.abs(ref.y[:, 0, :n]))
    bad = np.where((err > 1).any(axis=0))[0]
    return float(ref.t[bad[0]]) if bad.size else None
