"""Run a command with some of the judge's tolerance heuristics switched off (issue 42, item 6): the
measurement of which of them a case still needs now that the exact judge and the motion decide.

    python scripts/rules_off.py negligible,three-state -- tests/security/verdicts/verdicts_harness.py --markdown
    python scripts/rules_off.py three-state -- -m pytest -q tests/test_blind_corpus.py
    python scripts/rules_off.py windows -- benchmarks/evidence.py --markdown

Rules (each replaced in this process, before the command runs):

- ``negligible``: the screen's negligible-part weighing (`admit._negligible`);
- ``three-state``: the re-check of agreeing equations at three sampled states in ball arithmetic
  (`dynamics._exact_refutation`);
- ``windows``: the number windows: a constant within 1e-9 of a simple number (`admit._near_simple`)
  and constants far from unit size (`admit.CONSTANT_SIZES`).

The wide test (the value parts' second test, positive parameters down to 1e-3 of their sampled
values) was removed after this measurement: with it off, every file of the verdict suite's tiny, near,
floats and beyond families that targets a value was still refused (by the exact judge or the
negligible-part rule), and removing a rule that only refutes rejects no honest answer.
"""

from __future__ import annotations

import runpy
import sys


def switch_off(rules: list[str]) -> None:
    from lagrade.verdicts.checkers import admit, dynamics

    for rule in rules:
        if rule == "negligible":
            admit._negligible = lambda *a, **k: []
        elif rule == "three-state":
            dynamics._exact_refutation = lambda *a, **k: None
        elif rule == "windows":
            admit._near_simple = lambda c: None
            admit.CONSTANT_SIZES = (0.0, float("inf"))
        elif rule and rule != "none":
            raise SystemExit(f"rules_off: unknown rule {rule!r}; expected negligible, three-state, windows")


def main() -> None:
    if len(sys.argv) < 4 or sys.argv[2] != "--":  # rules may be "" (none)
        raise SystemExit(__doc__)
    switch_off(sys.argv[1].split(","))
    rest = sys.argv[3:]
    if rest[0] == "-m":
        sys.argv = [rest[1], *rest[2:]]
        runpy.run_module(rest[1], run_name="__main__", alter_sys=True)
    else:
        sys.argv = rest
        runpy.run_path(rest[0], run_name="__main__")


if __name__ == "__main__":
    main()
