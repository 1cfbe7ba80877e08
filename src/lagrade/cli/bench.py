"""``lagrade bench``: what the numerics cost.

- ``lagrade bench accuracy [IDS...]``: the work-precision sweep (RK45, DOP853, Radau, LSODA and a symplectic
  method over tolerances 1e-3 ... 1e-12) of each scene: a table, a CSV and a work-precision PNG.
- ``lagrade bench effects [IDS...]``: which machinery each scene's declared effects compile, and what a
  trajectory costs with it and with all machinery compiled.

Registered in ``cli.py`` with ``main.add_command(bench)``.
"""

from __future__ import annotations

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
@click.option("--methods", default="RK45,DOP853,Radau,LSODA,symplectic", show_default=True,
              help="Comma-separated methods.")
@click.option("--tolerances", default="1e-3..1e-12", show_default=True,
              help="A range 1e-3..1e-12 (every decade) or a comma-separated list.")
@click.option("--trajectories", "K", default=4, show_default=True, help="Sampled states per scene (batched).")
@click.option("--repeat", default=1, show_default=True, help="Time each integration this many times (best kept).")
@click.option("--no-plot", is_flag=True, help="Skip the PNG.")
def accuracy(ids: tuple[str, ...], out_dir: Path, methods: str, tolerances: str, K: int, repeat: int,
             no_plot: bool) -> None:
    """Work-precision sweep of each scene IDS (default: 12.14 12.43); ID may be 12.8:b for a system."""
    from lagrade.research import workprecision as wp

    tols = _tolerances(tolerances)
    sweeps = []
    for pid in ids or DEFAULT_IDS:
        pid, _, key = pid.partition(":")
        sc = wp.scene(pid, key or None, K=K)
        sw = wp.sweep(sc, tols, tuple(m.strip() for m in methods.split(",") if m.strip()), repeat)
        sweeps.append(sw)
        click.echo(wp.table(sw))
        click.echo("")
    csv_path = out_dir / "accuracy.csv"
    wp.write_csv(sweeps, csv_path)
    click.echo(f"wrote {csv_path}")
    if not no_plot:
        png = out_dir / "accuracy.png"
        wp.plot(sweeps, png)
        click.echo(f"wrote {png}")


def _tolerances(text: str) -> tuple[float, ...]:
    if ".." in text:
        lo, hi = (float(x) for x in text.split(".."))
        a, b = round(-__import__("math").log10(lo)), round(-__import__("math").log10(hi))
        return tuple(10.0 ** -e for e in range(min(a, b), max(a, b) + 1))
    return tuple(float(x) for x in text.split(","))


@bench.command()
@click.argument("ids", nargs=-1)
@click.option("--repeat", default=3, show_default=True)
def effects(ids: tuple[str, ...], repeat: int) -> None:
    """The machinery each scene compiles from its declared effects, and its cost against all machinery."""
    from lagrade.research.effectsbench import compare_scene, format_rows

    rows = [compare_scene(pid, repeat=repeat) for pid in (ids or ("12.43", "12.14", "12.7", "12.4", "12.34"))]
    click.echo(format_rows(rows))
