"""The ``lagrade`` command: a package of thin commands over the library, one module each.

``check`` (cli/check.py), ``list``/``show``/``template`` (cli/problems.py), bulk grading and the LMS
(cli/bulk.py), the course server (cli/serve.py), the cache, ``doctor`` and ``bench``.
"""

from __future__ import annotations

import os

import click

from lagrade._version import __version__
from lagrade.cli import common
from lagrade.numbers.process_env import single_threaded_blas


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="lagrade")
def main() -> None:
    """Grade answers to the Lagrangian and Hamiltonian dynamics problems of chapter 12."""


def run() -> None:
    """The ``lagrade`` console script."""
    common.OWN_PROCESS = True
    single_threaded_blas(os.environ)
    main()


def _register() -> None:
    from lagrade.cli.bench import bench
    from lagrade.cli.bulk import (
        export,
        grade,
        gradescope,
        import_,
        override,
        prairielearn,
        report,
    )
    from lagrade.cli.cache import cache
    from lagrade.cli.check import check
    from lagrade.cli.doctor import doctor
    from lagrade.cli.problems import list_cmd, show, template
    from lagrade.cli.serve import serve, tokens
    from lagrade.cli.validate import validate

    for command in (list_cmd, show, template, check, grade, export, report, gradescope, prairielearn, override,
                    import_, bench, cache, doctor, serve, tokens, validate):
        main.add_command(command)


_register()
