"""Break the integrator on purpose and show that the stability suite notices, within its timeout.

Each mutation below changes one thing in ``src/lagrade/compare/dop853.py`` or its tableau
``dop853_coefficients.py``, in a temporary copy of ``src/`` (the worktree's files are never touched),
and runs the stability suite (``tests/stability``, the slow tier) and ``tests/test_dop853.py``
against that copy (``PYTHONPATH`` points at it, ahead of the editable install) with ``-x``: the
first failing test ends the run. A mutation is *killed* when the run fails, and *survives* when it
passes (or when the run gives no verdict within ``--timeout`` seconds: a suite that hangs has not
caught anything). The script prints one line per mutation (killed or not, in how many seconds, the
first failing test) and exits 1 if any survives.

    python scripts/mutate_integrator.py                 # every mutation
    python scripts/mutate_integrator.py --only stage-time,guard-on-rejected-trials
    python scripts/mutate_integrator.py --list

Most mutations are killed by the suite's session check (``tests/stability/method_check.py``) before
its first test, in the time pytest takes to start; docs/numerics.md ("Mutations") has the table.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SUITE = ["tests/stability", "tests/test_dop853.py"]
#: what a copy of src/ needs beside it to find the problem files as a checkout does (library.data_root)
BESIDE = ["pyproject.toml", "problems", "reference_solutions"]


@dataclass(frozen=True)
class Mutation:
    name: str
    file: str      # under src/lagrade/compare/
    old: str       # must occur exactly once in the file
    new: str
    what: str


MUTATIONS = [
    Mutation("stage-time", "dop853_coefficients.py",
             "              0.281649658092772603273242802490,\n",
             "              0.281949658092772603273242802490,\n",
             "a stage time c_4 wrong in its 4th digit (read only where the rates depend on t)"),
    Mutation("guard-on-rejected-trials", "dop853.py",
             "        if accepted.any():  # only accepted ends are states of the motion (a rejected trial's is not)\n"
             "            self.watch(np.where(accepted, self.t_new, t), np.where(accepted, self.f_new, self.F0))\n",
             "        self.watch(np.where(active, self.t_new, t), np.where(active, self.f_new, self.F0))\n",
             "the singularity guard put back on rejected trial steps"),
    Mutation("event-state-fraction", "dop853.py",
             "sol.interpolate(np.array([(tt - sol.t[k]) / sol.h[k]]), np.array([k]))",
             "sol.interpolate(np.array([(tt - sol.t[k]) / sol.h_abs[k]]), np.array([k]))",
             "an event's state interpolated at the wrong fraction of its step (divided by the next step)"),
    Mutation("b-weight", "dop853_coefficients.py",
             "A[12, 7] = -5.8012039600105847814672114227\n",
             "A[12, 7] = -5.8012049600105847814672114227\n",
             "a weight of the solution (b_7) wrong in its 6th digit"),
    Mutation("error-estimate", "dop853_coefficients.py",
             "E5[7] = 0.1664377182454986536961530415e+1\n",
             "E5[7] = 0.1664377182454986536961530415e+0\n",
             "a coefficient of the 5th-order error estimate a tenth of its value"),
    Mutation("safety-exponent", "dop853.py",
             "ERROR_EXPONENT = -1.0 / 8.0",
             "ERROR_EXPONENT = -1.0 / 7.0",
             "the step-size controller's exponent -1/7 instead of -1/8"),
    Mutation("dense-output-power", "dop853.py",
             "_POWERS = np.arange(1.0, INTERPOLATOR_POWER + 1.0)",
             "_POWERS = np.arange(0.0, INTERPOLATOR_POWER)",
             "the dense output's powers off by one (x^0..x^6 instead of x^1..x^7)"),
    Mutation("swapped-stage", "dop853.py",
             "self.row_new = np.concatenate(([1.0], B))",
             "self.row_new = np.concatenate(([1.0], B[[0, 1, 2, 3, 4, 5, 7, 6, 8, 9, 10, 11]]))",
             "stages 6 and 7 swapped in the solution's weights"),
    Mutation("event-root-tolerance", "dop853.py",
             "xtol: float = 4 * EPS, rtol: float = 4 * EPS",
             "xtol: float = 1e-4, rtol: float = 4 * EPS",
             "Brent's root finder stopped at 1e-4 instead of 4 ulp"),
    Mutation("acceptance-flipped", "dop853.py",
             "accepted = (error_norm < 1.0) & active",
             "accepted = (error_norm > 1.0) & active",
             "the acceptance test's comparison flipped"),
    Mutation("no-shrink-after-rejection", "dop853.py",
             "MIN_FACTOR = 0.2",
             "MIN_FACTOR = 1.0",
             "a rejected step retried at the same size (docs/numerics.md, 'Hangs are failures')"),
    Mutation("one-digit-of-a-stage", "dop853_coefficients.py",
             "A[5, 3] = 1.70828608729473871279604482173e-1",
             "A[5, 3] = 1.70838608729473871279604482173e-1",
             "one digit of a stage coefficient (docs/numerics.md, 'Hangs are failures')"),
]
BY_NAME = {m.name: m for m in MUTATIONS}


@dataclass
class Outcome:
    mutation: Mutation
    killed: bool
    seconds: float
    first_failure: str


def mutated_copy(m: Mutation, into: Path) -> Path:
    """src/ copied under ``into`` with the mutation applied; returns the path for PYTHONPATH."""
    src = into / "src"
    shutil.copytree(ROOT / "src", src, ignore=shutil.ignore_patterns("__pycache__", "*.so"))
    for name in BESIDE:
        if (ROOT / name).exists():
            (into / name).symlink_to(ROOT / name)
    (src / "lagrade" / "compare" / m.file).write_text(mutated_text(m), encoding="utf-8")
    return src


def mutated_text(m: Mutation) -> str:
    """The mutated file's text (the worktree's file read, never written)."""
    text = (ROOT / "src" / "lagrade" / "compare" / m.file).read_text(encoding="utf-8")
    if text.count(m.old) != 1:
        raise SystemExit(f"{m.name}: the text to change occurs {text.count(m.old)} times in {m.file}, not once "
                         "(the source changed: update the mutation)")
    return text.replace(m.old, m.new)


def run(m: Mutation, timeout: float, python: str) -> Outcome:
    with tempfile.TemporaryDirectory(prefix=f"mutant-{m.name}-") as tmp:
        src = mutated_copy(m, Path(tmp))
        env = {**os.environ, "PYTHONPATH": str(src) + os.pathsep + os.environ.get("PYTHONPATH", ""),
               "PYTHONDONTWRITEBYTECODE": "1"}
        where = subprocess.run([python, "-c", "import importlib.util as u; print(u.find_spec('lagrade').origin)"],
                               env=env, capture_output=True, text=True, check=True).stdout.strip()
        if not where.startswith(str(src)):
            raise SystemExit(f"{m.name}: lagrade is imported from {where}, not from the mutated copy {src}")
        start = time.monotonic()
        try:
            proc = subprocess.run([python, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", "-m", "slow or not slow",
                                   *SUITE], cwd=ROOT, env=env, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            return Outcome(m, False, time.monotonic() - start, f"no verdict within {timeout:g} s")
        seconds = time.monotonic() - start
    if proc.returncode == 0:
        return Outcome(m, False, seconds, "every test passed")
    if proc.returncode == 1:
        check = re.search(r"the integrator is broken, so the stability suite is not run:\n(.*)", proc.stdout)
        if check:  # tests/stability/conftest.py's session check: every test of the suite errors with it
            return Outcome(m, True, seconds, f"the session check: {check.group(1).strip()[:160]}")
        failed = re.findall(r"^(?:FAILED|ERROR) (\S+)", proc.stdout, flags=re.M)
        if failed:
            return Outcome(m, True, seconds, failed[0])
        timed_out = re.search(r"Timeout \(>[\d.]+s\) from pytest-timeout", proc.stdout + proc.stderr)
        if timed_out:  # the thread method ends the whole run at a test's timeout
            return Outcome(m, True, seconds, f"a test's timeout ({timed_out.group(0)})")
    raise SystemExit(f"{m.name}: pytest exited {proc.returncode}:\n{proc.stdout[-3000:]}\n{proc.stderr[-3000:]}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", help="comma-separated mutation names (default: all)")
    ap.add_argument("--timeout", type=float, default=900.0,
                    help="seconds a mutated run may take before it counts as not caught (default 900)")
    ap.add_argument("--list", action="store_true", help="list the mutations and exit")
    args = ap.parse_args(argv)
    if args.list:
        for m in MUTATIONS:
            print(f"{m.name:28} {m.file:24} {m.what}")
        return 0
    chosen = MUTATIONS if not args.only else [BY_NAME[n] for n in args.only.split(",")]
    survivors = 0
    print(f"{'mutation':28} {'result':9} {'seconds':>8}  first failing test")
    for m in chosen:
        o = run(m, args.timeout, sys.executable)
        survivors += not o.killed
        print(f"{m.name:28} {'killed' if o.killed else 'SURVIVED':9} {o.seconds:8.1f}  {o.first_failure}", flush=True)
    print(f"{len(chosen) - survivors} of {len(chosen)} mutations killed")
    return 1 if survivors else 0


if __name__ == "__main__":
    sys.exit(main())
