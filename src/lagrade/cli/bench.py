"""``lagrade bench``: what the numerics cost.

- ``lagrade bench accuracy [IDS...]``: the work-precision sweep of each scene: the grading path itself
  (the compiled DOP853 grading runs, at each tolerance and at the presets fast, default, strict)
  against scipy's RK45, DOP853, Radau, LSODA and BDF one trajectory at a time; a table (or Markdown),
  a CSV and a PNG with error against time and against evaluations.
- ``lagrade bench effects [IDS...]``: which machinery each scene's declared effects compile, and what a
  trajectory costs with it and with all machinery compiled.

Registered in ``cli.py`` with ``main.add_command(bench)``.
"""

from __future__ import annotations

import math
from pathlib import Path

import click

DEFAULT_IDS = ("12.14", "12.43")


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
def bench() -> None:
    """Measure the numerics: accuracy against time, and the cost of each scene's machinery."""


@bench.command()
@click.argument("ids", nargs=-1)
@click.option("--out", "out_dir", type=click.Path(path_type=Path), default=Path("bench-out"), show_default=True,
              help="Folder for accuracy.csv and accuracy.png.")
@click.option("--methods", default="grading,RK45,DOP853,Radau,LSODA,BDF", show_default=True,
              help="Comma-separated: grading (the grader's own path), RK45, DOP853, Radau, LSODA, BDF (scipy, "
                   "one trajectory per call), numpy (the grader's DOP853 on rates as numpy code), symplectic.")
@click.option("--tolerances", default="1e-3..1e-12", show_default=True,
              help="A range 1e-3..1e-12 (every decade) or a comma-separated list; the presets' own are added "
                   "to the grading path.")
@click.option("--trajectories", "K", type=click.IntRange(min=1), default=4, show_default=True,
              help="Sampled states per scene.")
@click.option("--repeat", type=click.IntRange(min=3), default=3, show_default=True,
              help="Timed runs per point (the median is kept), after one untimed run.")
@click.option("--markdown", is_flag=True, help="Print Markdown tables (for docs/numerics.md) instead of text.")
@click.option("--no-plot", is_flag=True, help="Skip the PNG.")
def accuracy(ids: tuple[str, ...], out_dir: Path, methods: str, tolerances: str, K: int, repeat: int,
             markdown: bool, no_plot: bool) -> None:
    """Work-precision sweep of each scene IDS (default: 12.14 12.43); ID may be 12.8:b for a system."""
    from lagrade.uses.research import workprecision as wp

    tols = _tolerances(tolerances)
    chosen = tuple(m.strip() for m in methods.split(",") if m.strip())
    unknown = [m for m in chosen if m not in wp.CHOICES]
    if unknown or not chosen:
        what = f"unknown method {unknown[0]!r}" if unknown else "no method given"
        raise click.BadParameter(f"{what}; expected some of {','.join(wp.CHOICES)}", param_hint="--methods")
    if min(tols) <= wp.REFERENCE_TOL or max(tols) >= 1:
        raise click.BadParameter(f"every tolerance must lie between the reference's {wp.REFERENCE_TOL:g} and 1",
                                 param_hint="--tolerances")
    sweeps = []
    for pid in ids or DEFAULT_IDS:
        pid, _, key = pid.partition(":")
        try:
            sc = wp.scene(pid, key or None, K=K)
        except (KeyError, LookupError, FileNotFoundError, ValueError) as exc:
            raise click.BadParameter(f"no scene {pid}{':' + key if key else ''} ({exc}); expected a problem id "
                                     "such as 12.43, or 12.8:b for one of its systems", param_hint="IDS") from None
        try:
            sw = wp.sweep(sc, tols, chosen, repeat)
        except (RuntimeError, ValueError) as exc:  # a reference that cannot be integrated, say
            raise click.ClickException(str(exc)) from None
        sweeps.append(sw)
        click.echo(wp.markdown(sw) if markdown else wp.table(sw))
        click.echo("")
    csv_path = out_dir / "accuracy.csv"
    wp.write_csv(sweeps, csv_path)
    click.echo(f"wrote {csv_path}")
    if not no_plot:
        png = out_dir / "accuracy.png"
        wp.plot(sweeps, png)
        click.echo(f"wrote {png}")


def _tolerances(text: str) -> tuple[float, ...]:
    """"1e-3..1e-12" (every decade between) or "1e-4,1e-10"; a clear error otherwise."""
    try:
        if ".." in text:
            lo, hi = (float(x) for x in text.split(".."))
            a, b = round(-math.log10(lo)), round(-math.log10(hi))
            return tuple(10.0 ** -e for e in range(min(a, b), max(a, b) + 1))
        tols = tuple(float(x) for x in text.split(","))
    except ValueError:
        raise click.BadParameter(f"{text!r} is not a range like 1e-3..1e-12 or a list like 1e-4,1e-10",
                                 param_hint="--tolerances") from None
    if not all(math.isfinite(t) and t > 0 for t in tols):
        raise click.BadParameter(f"{text!r}: every tolerance must be a positive number", param_hint="--tolerances")
    return tols


@bench.command()
@click.argument("ids", nargs=-1)
@click.option("--repeat", default=3, show_default=True)
def effects(ids: tuple[str, ...], repeat: int) -> None:
    """The machinery each scene compiles from its declared effects, and its cost against all machinery."""
    from lagrade.uses.research.effectsbench import compare_scene, format_rows

    rows = [compare_scene(pid, repeat=repeat) for pid in (ids or ("12.43", "12.14", "12.7", "12.4", "12.34"))]
    click.echo(format_rows(rows))
