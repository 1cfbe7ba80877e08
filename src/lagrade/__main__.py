"""The ``lagrade`` console script's first lines: a check of an ``answer.py`` starts its zygote before
anything else is imported, since the zygote's own import of sympy is what a check waits for."""

from __future__ import annotations

import sys


def run() -> None:
    args = sys.argv[1:]
    if args[:1] == ["check"] and any(a.endswith((".py", ".ipynb")) for a in args[1:]):
        from lagrade.answer.jail import zygote

        zygote.start()  # 0.2 s earlier than the check command could (importing the CLI takes that)
    from lagrade.cli import run as cli_run

    cli_run()


if __name__ == "__main__":
    run()
