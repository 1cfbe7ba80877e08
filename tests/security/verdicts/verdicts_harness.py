"""The verdict suite's data and runner, shared by test_verdicts.py and the table it prints.

Every file ``<problem>/<family>-<name>.py|.toml`` here is an answer built to fool the verdict on
one part (or an honest control), with a four-line header (README.md). :func:`run` grades it as
``lagrade check <problem> FILE --json --accuracy A --grading-seconds 60`` does, in this process
(``lagrade.check``, the function the CLI calls; an answer.py runs in the jail as in real use);
the ``hints`` family with ``--hints``, and its feedback must not match the file's ``# leak:`` line.

    python tests/security/verdicts/verdicts_harness.py [--accuracy default,strict,fast] [--path check,grade,serve]
                                                        [--markdown] [FILE...]

prints the table attack -> (verdict, score) for a before/after report. ``--path grade`` grades every
file as one class with ``lagrade grade`` (`lagrade.uses.bulk.runner.grade_folder`, the assignment's
``accuracy`` the preset) and reads each target part back from the gradebook; ``--path serve`` submits
each file to the course server's check API (`lagrade.uses.server.app.create_app` in process, through
``fastapi.testclient``: no network port) with the preset in its assignment, and reads the JSON it
answers. One column per (path, preset).
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
            "fold", "near", "beyond", "tdep",
            # issue 42, second round: shapes no rule was written for (0**u, roots and logs of exponentials,
            # principal roots that cancel only in the box, constants near integers, logs of products)
            "trick"}
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


PATHS = ("check", "grade", "serve")
#: an assignment's limits for the grade and serve paths: check's --grading-seconds, and room for the jail
LIMITS = {"cpu_seconds": 30, "wall_seconds": 60, "grading_seconds": GRADING_SECONDS}


def _assignment(todo: list[Case], accuracy: str) -> dict:
    problems = sorted({c.problem for c in todo})
    return {"name": f"verdicts-{accuracy}", "accuracy": accuracy, "limits": LIMITS,
            "problems": [{"id": pid} for pid in problems]}


def _outcome(part: dict, seconds: float) -> Outcome:
    return Outcome(part["verdict"], float(part["score"]), float(part["max_score"]), part.get("method") or "",
                   part.get("feedback") or "", seconds)


def run_grade(todo: list[Case], accuracy: str = "default", workers: int = 2) -> dict[str, Outcome | Exception]:
    """Every file graded as one class by `lagrade grade` (one student folder per file), each target
    part read back from the gradebook."""
    import sqlite3
    import tempfile

    from lagrade.uses.bulk.assignment import parse_assignment
    from lagrade.uses.bulk.runner import grade_folder

    out: dict[str, Outcome | Exception] = {}
    with tempfile.TemporaryDirectory(prefix="verdicts-grade-") as tmp:
        root, db = Path(tmp) / "submissions", Path(tmp) / "class.sqlite"
        for i, case in enumerate(todo):
            (root / f"s{i:03d}").mkdir(parents=True)
            (root / f"s{i:03d}" / f"{case.problem}{case.path.suffix}").write_text(case.path.read_text())
        start = time.monotonic()
        grade_folder(root, parse_assignment(_assignment(todo, accuracy)), db, workers=workers)
        seconds = (time.monotonic() - start) / max(1, len(todo))
        con = sqlite3.connect(db)
        con.row_factory = sqlite3.Row
        parts = {(r["student"], r["problem"], r["part"]): dict(r) for r in con.execute("SELECT * FROM parts")}
        con.close()
        for i, case in enumerate(todo):
            got = parts.get((f"s{i:03d}", case.problem, case.target))
            out[case.name] = (_outcome(got, seconds) if got is not None else
                              AssertionError(f"{case.name}: no part {case.target!r} in the gradebook"))
    return out


def run_serve(todo: list[Case], accuracy: str = "default") -> dict[str, Outcome | Exception]:
    """Every file submitted to the course server's check API (the app in process, its warm graders),
    each target part read from the JSON answer."""
    import tempfile

    from fastapi.testclient import TestClient

    from lagrade.uses.server.app import create_app
    from lagrade.uses.server.config import ServerConfig
    from lagrade.uses.server.tokens import issue

    out: dict[str, Outcome | Exception] = {}
    a = _assignment(todo, accuracy)
    with tempfile.TemporaryDirectory(prefix="verdicts-serve-") as tmp:
        hw = Path(tmp) / "hw.toml"
        hw.write_text(f'name = "{a["name"]}"\naccuracy = "{accuracy}"\n[limits]\n'
                      + "".join(f"{k} = {v}\n" for k, v in LIMITS.items())
                      + "".join(f'[[problems]]\nid = "{p["id"]}"\n' for p in a["problems"]))
        config = ServerConfig(assignment=hw, db=str(Path(tmp) / "serve.sqlite"), workers=2, spare_graders=0,
                              checks_per_minute=60000, check_burst=10000, student_in_flight=10000,
                              student_grader_seconds_per_minute=1e9)
        app = create_app(config)
        with TestClient(app) as client:
            headers = {"Authorization": f"Bearer {issue(app.state.server.secret, 'attacker')}"}
            for case in todo:
                start = time.monotonic()
                try:
                    r = client.post(f"/api/v1/problems/{case.problem}/check", headers=headers,
                                    files={"file": (f"answer{case.path.suffix}", case.path.read_bytes())})
                    while r.status_code == 202:
                        time.sleep(0.2)
                        r = client.get(f"/api/v1/submissions/{r.json()['submission_id']}", headers=headers)
                    if r.status_code != 200:
                        raise AssertionError(f"{case.name}: the server answered {r.status_code}: {r.text[:200]}")
                    parts = {p["part"]: p for p in r.json()["parts"]}
                    if case.target not in parts:
                        raise AssertionError(f"{case.name}: no part {case.target!r} in {sorted(parts)}")
                    out[case.name] = _outcome(parts[case.target], time.monotonic() - start)
                except Exception as exc:  # noqa: BLE001  (a row of its own)
                    out[case.name] = exc
    return out


def run_path(todo: list[Case], path: str, accuracy: str) -> dict[str, Outcome | Exception]:
    """Every file's target part through one path under one preset."""
    if path == "grade":
        return run_grade(todo, accuracy)
    if path == "serve":
        return run_serve(todo, accuracy)
    out: dict[str, Outcome | Exception] = {}
    for case in todo:
        try:
            out[case.name] = run(case, accuracy)
        except Exception as exc:  # noqa: BLE001  (a row of its own)
            out[case.name] = exc
    return out


def holds(case: Case, out: Outcome) -> bool:
    if case.leak is not None and re.search(case.leak, out.feedback):
        return False
    if case.expect == "no-credit":
        return out.score == 0 and out.verdict in ("incorrect", "invalid")
    return out.score == out.max_score


def _cell(case: Case, out: Outcome | Exception) -> tuple[str, bool, str]:
    """(verdict score, as expected, feedback) of one file through one path under one preset; a grader
    crash is a row too."""
    if isinstance(out, Exception):
        return "CRASH", False, f"{type(out).__name__}: {out}"
    ok = holds(case, out)
    leaked = case.leak is not None and re.search(case.leak, out.feedback)
    cell = f"{out.verdict} {out.score:g}/{out.max_score:g}" + ("" if ok else " (hint leaks)" if leaked else " ✗")
    return cell, ok, out.feedback.replace("\n", " ").replace("|", "\\|")


def _safe_run(case: Case, accuracy: str) -> Outcome | Exception:
    try:
        return run(case, accuracy)
    except Exception as exc:  # noqa: BLE001  (a row of its own)
        return exc


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description="attack -> (verdict, score) for every file of the verdict suite; "
                                             "a cell marked ✗ is not what the file expects")
    ap.add_argument("--accuracy", default="default",
                    help="a preset, or several separated by commas (default,strict,fast): one column each")
    ap.add_argument("--path", default="check",
                    help="check, grade, serve, or several separated by commas: one column each with each preset")
    ap.add_argument("--markdown", action="store_true", help="a Markdown table (default: tab-separated)")
    ap.add_argument("--feedback", type=int, default=100, metavar="N",
                    help="the first N characters of the first preset's feedback (0: none)")
    ap.add_argument("files", nargs="*", type=Path, help="only these files (default: all)")
    args = ap.parse_args(argv)
    presets = args.accuracy.split(",")
    paths = args.path.split(",")
    if not set(presets) <= {"fast", "default", "strict"}:
        ap.error(f"unknown preset in {args.accuracy!r}")
    if not set(paths) <= set(PATHS):
        ap.error(f"unknown path in {args.path!r} (one of {', '.join(PATHS)})")
    todo = [header(f.resolve()) for f in args.files] if args.files else cases()
    columns = [(p, a) for p in paths for a in presets]
    names = [a if len(paths) == 1 else f"{p} {a}" for p, a in columns]
    cols = ["file", "target", "family", "expect", *names] + (["feedback"] if args.feedback else [])
    if len(columns) == 1 and paths == ["check"]:
        results = None  # row by row, printed as it goes
    else:
        results = {col: run_path(todo, *col) for col in columns}
    if args.markdown:
        print("| " + " | ".join(cols) + " |")
        print("|" + "---|" * len(cols))
    else:
        print("\t".join(cols))
    held = 0
    for case in todo:
        runs = [_cell(case, results[col][case.name] if results is not None else _safe_run(case, col[1]))
                for col in columns]
        held += all(ok for _, ok, _ in runs)
        row = [case.name, case.target, case.family, case.expect, *(cell for cell, _, _ in runs)]
        if args.feedback:
            row.append(runs[0][2][:args.feedback])
        if args.markdown:
            row[0] = f"`{row[0]}`"
            print("| " + " | ".join(row) + " |", flush=True)
        else:
            print("\t".join(row), flush=True)
    print(f"\n{held} of {len(todo)} files as expected through {', '.join(paths)} under {', '.join(presets)}",
          file=sys.stderr)
    return 0 if held == len(todo) else 1


if __name__ == "__main__":
    sys.exit(main())
