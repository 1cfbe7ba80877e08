"""``lagrade cache``: the reference derivations kept on disk (:mod:`lagrade.derive.cache`).

- ``lagrade cache build [IDS...]``: derive, compile and integrate every reference of each problem ahead
  of time, by grading its bundled reference solution (or, without one, by deriving the scenes), so
  the first check of a class is as fast as the hundredth; and byte-compile lagrade's own modules.
- ``lagrade cache info``: where the cache is, what it holds, and whether its key is usable.
- ``lagrade cache clear``: remove every entry.

Registered in ``cli.py`` with ``main.add_command(cache)``.
"""

from __future__ import annotations

import time
from pathlib import Path

import click

from lagrade.cli.common import problems_option


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
def cache() -> None:
    """Reference derivations kept on disk: a check starts warm (LAGRADE_CACHE=off turns it off)."""


@cache.command()
@click.argument("ids", nargs=-1)
@problems_option
def build(ids: tuple[str, ...], problems_dir: tuple[Path, ...]) -> None:
    """Build the entries of IDS (default: every problem)."""
    from lagrade.derive import cache as store
    from lagrade.answer.reading.load import load_answer
    from lagrade.verdicts.grade import grade_values, keep_references, references
    from lagrade.problem.library import load_problem, problem_ids, reference_dir
    from lagrade.problem.spec import SpecError

    if store.cache_dir() is None:
        raise click.UsageError("the cache is off (LAGRADE_CACHE=off)")
    failed = 0
    for pid in ids or problem_ids(problems_dir):
        start = time.perf_counter()
        try:
            problem = load_problem(pid, problems_dir)
        except SpecError as exc:
            click.echo(f"{pid}: skipped ({exc})", err=True)
            failed += 1
            continue
        try:
            answer = reference_dir() / problem.id / "answer.py"
            if answer.is_file():
                grade_values(problem, load_answer(answer, problem), read_as=())
            else:
                refs = references(problem)
                for system in problem.systems:
                    refs[system.key]
            saved = keep_references(problem, update=True)
        except Exception as exc:  # noqa: BLE001  (one broken scene must not stop the others)
            click.echo(f"{pid}: failed ({type(exc).__name__}: {exc})", err=True)
            failed += 1
            continue
        click.echo(f"{pid}: {'built' if saved else 'up to date'} in {time.perf_counter() - start:.2f} s")
    click.echo(f"cache: {store.cache_dir()}")
    _compile_bytecode()
    raise SystemExit(1 if failed else 0)


def _compile_bytecode() -> None:
    """Byte-compile lagrade's own modules, as pip does for a regular install: after an editable
    install, or with PYTHONDONTWRITEBYTECODE set, every check would otherwise compile its ~40 modules
    from source (about 90 ms of a 1.2 s check, measured). Where the package is read-only, nothing
    is written and nothing fails."""
    import compileall

    try:
        compileall.compile_dir(Path(__file__).resolve().parents[1], quiet=2)  # the lagrade package
    except OSError:
        pass


@cache.command()
def info() -> None:
    """Where the cache is, how many entries it holds and their size."""
    from lagrade.derive import cache as store

    directory = store.cache_dir()
    if directory is None:
        click.echo("cache: off (LAGRADE_CACHE=off)")
        return
    found = store.entries(directory)
    size = sum(p.stat().st_size for p in found)
    click.echo(f"cache: {directory}\nentries: {len(found)} ({size / 1e6:.1f} MB)")
    try:
        state = "present" if store.key(directory) else "none yet (made by the first entry)"
    except store.UntrustedKey as exc:  # entries are then neither read nor written
        state = f"refused, the cache is not used: {exc}; remove it and a new one is made"
    click.echo(f"key: {state}")


@cache.command()
def clear() -> None:
    """Remove every entry."""
    from lagrade.derive import cache as store

    click.echo(f"removed {store.clear()} entries")
