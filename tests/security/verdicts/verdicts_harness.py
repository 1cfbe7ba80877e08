"""The verdict suite's data and runner, shared by test_verdicts.py and the table it prints.

Every file ``<problem>/<family>-<name>.py|.toml`` here is an answer built to fool the verdict on
one part (or an honest control), with a four-line header (README.md). :func:`run` grades it as
``lagrade check <problem> FILE --json --accuracy A --grading-seconds 60`` does, in this process
(``lagrade.check``, the function the CLI calls; an answer.py runs in the jail as in real use);
the ``hints`` family with ``--hints``, and its feedback must not match the file's ``# leak:`` line.

    python tests/security/verdicts/verdicts_harness.py [--accuracy default,strict,fast] [--markdown] [FILE...]

prints the table attack -> (verdict, score) for a before/after report.
"""

from __future__ import annotations

import argparse
import re
import sys
import time
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
FAMILIES = {"qdd", "complex", "switch", "roots", "floats", "hints", "honest", "tiny", "keys",
            # issue 42: folds built from inverse functions, algebraic numbers near simple ones, factors
            # vanishing outside the sampled box, a value of H off by a function of t
            "fold", "near", "beyond", "tdep"}
EXPECTS = {"no-credit", "full-marks"}
GRADING_SECONDS = 60.0
HEADER = re.compile(r"# target: (?P<target>\S+)\n# family: (?P<family>\S+)\n# expect: (?P<expect>\S+)\n"
                    r"# why: (?P<why>[^\n]+)\n(?:# leak: (?P<leak>[^\n]+)\n)?")


@dataclass(frozen=True)
class Case:
    path: Path
    problem: str
    target: str
    family: str
    expect: str
    why: str
    #: hints family: a regular expression the ``--hints`` feedback must not match (the exact ratio)
    leak: str | None = None

    @property
    def name(self) -> str:
        return f"{self.problem}/{self.path.name}"


def header(path: Path) -> Case:
    m = HEADER.match(path.read_text())
    if not m:
        raise ValueError(f"{path}: no '# target/family/expect/why' header on its first four lines")
    case = Case(path=path, problem=path.parent.name, **m.groupdict())
    if case.family not in FAMILIES or case.expect not in EXPECTS:
        raise ValueError(f"{path}: family {case.family!r} or expect {case.expect!r} unknown")
    if (case.family == "hints") != (case.leak is not None):
        raise ValueError(f"{path}: a '# leak: REGEX' line goes with family hints, and only there")
    if not path.stem.startswith(case.family + "-"):
        raise ValueError(f"{path}: the name must start with its family ({case.family}-)")
    return case


def cases() -> list[Case]:
    return [header(p) for p in sorted(HERE.glob("*/*")) if p.suffix in (".py", ".toml") and p.parent.name != "__pycache__"]


def preset_subset(all_cases: list[Case]) -> list[Case]:
    """The first answer.py and the first answer.toml of each family (in name order): what also runs
    under `strict` and `fast`."""
    first: dict[tuple[str, str], Case] = {}
    for c in all_cases:
        first.setdefault((c.family, c.path.suffix), c)
    return list(first.values())


@dataclass
class Outcome:
    verdict: str
    score: float
    max_score: float
    method: str
    feedback: str
    seconds: float


def run(case: Case, accuracy: str = "default") -> Outcome:
    """The target part's result, as `lagrade check <problem> FILE --json --accuracy A` reports it."""
    import lagrade

    start = time.monotonic()
    result = lagrade.check(case.problem, case.path, accuracy=accuracy, hints=case.family == "hints",
                           grading_seconds=GRADING_SECONDS)
    seconds = time.monotonic() - start
    parts = {p.part: p for p in result.parts}
    if case.target not in parts:
        raise AssertionError(f"{case.name}: no part {case.target!r} in the result ({sorted(parts)}); "
                             f"file problems: {result.problems}")
    p = parts[case.target]
    return Outcome(p.verdict, p.score, p.max_score, p.method, p.feedback, seconds)


def holds(case: Case, out: Outcome) -> bool:
    if case.leak is not None and re.search(case.leak, out.feedback):
        return False
    if case.expect == "no-credit":
        return out.score == 0 and out.verdict in ("incorrect", "invalid")
    return out.score == out.max_score


def _row(case: Case, accuracy: str) -> tuple[str, bool, str]:
    """(verdict score, as expected, feedback) of one file under one preset; a grader crash is a row too."""
    try:
        out = run(case, accuracy)
    except Exception as exc:
        return "CRASH", False, f"{type(exc).__name__}: {exc}"
    ok = holds(case, out)
    leaked = case.leak is not None and re.search(case.leak, out.feedback)
    cell = f"{out.verdict} {out.score:g}/{out.max_score:g}" + ("" if ok else " (hint leaks)" if leaked else " ✗")
    return cell, ok, out.feedback.replace("\n", " ").replace("|", "\\|")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="attack -> (verdict, score) for every file of the verdict suite; "
                                             "a cell marked ✗ is not what the file expects")
    ap.add_argument("--accuracy", default="default",
                    help="a preset, or several separated by commas (default,strict,fast): one column each")
    ap.add_argument("--markdown", action="store_true", help="a Markdown table (default: tab-separated)")
    ap.add_argument("--feedback", type=int, default=100, metavar="N",
                    help="the first N characters of the first preset's feedback (0: none)")
    ap.add_argument("files", nargs="*", type=Path, help="only these files (default: all)")
    args = ap.parse_args(argv)
    presets = args.accuracy.split(",")
    if not set(presets) <= {"fast", "default", "strict"}:
        ap.error(f"unknown preset in {args.accuracy!r}")
    todo = [header(f.resolve()) for f in args.files] if args.files else cases()
    cols = ["file", "target", "family", "expect", *presets] + (["feedback"] if args.feedback else [])
    if args.markdown:
        print("| " + " | ".join(cols) + " |")
        print("|" + "---|" * len(cols))
    else:
        print("\t".join(cols))
    held = 0
    for case in todo:
        runs = [_row(case, a) for a in presets]
        held += all(ok for _, ok, _ in runs)
        row = [case.name, case.target, case.family, case.expect, *(cell for cell, _, _ in runs)]
        if args.feedback:
            row.append(runs[0][2][:args.feedback])
        if args.markdown:
            row[0] = f"`{row[0]}`"
            print("| " + " | ".join(row) + " |", flush=True)
        else:
            print("\t".join(row), flush=True)
    print(f"\n{held} of {len(todo)} files as expected under {', '.join(presets)}", file=sys.stderr)
    return 0 if held == len(todo) else 1


if __name__ == "__main__":
    sys.exit(main())
