"""Which evidence decides which class of mistake, per preset, measured on the chapter (issue 34):
the table of docs/numerics.md section 2.

    python benchmarks/evidence.py                    # every eom part of the chapter (a few minutes)
    python benchmarks/evidence.py 12.14 12.22        # some
    python benchmarks/evidence.py --markdown         # the table

For every equations-of-motion part (not linearized, no switching declared), the derived reference rows
are written as an answer three ways and graded under fast, default and strict:

- **beyond the box**: the first row's force terms (the row at zero accelerations) times
  ``1 + exp(8*(s - n) - 30)``, ``s`` the sum of (q'_i / v_i)**2 with v_i the largest speed of the
  coordinate's sampling range and n the number of coordinates: analytic, exact simple numbers, at most
  e**-30 (1e-13) of the force inside the sampling box, and growing fast at speeds the motion reaches
  beyond it;
- **small parameter error**: one parameter p -> (1 + 1/10**6) p (the finest exact fraction the numbers
  rule lets through), the first parameter (in the problem's order) whose 10 % change is rejected;
- **gross error**: the same parameter off by 10 %;
- **kick outside the exact class**: the first row's force terms times ``1 + 2**(-10**6*(t - h/2)**2)``,
  h the horizon: a kick 2e-3 s wide in the middle of every motion, which a state sampled at random
  times rarely meets, analytic with exact numbers, and outside the exact judge's class (a power with
  a non-rational exponent): the motion decides it (issue 45).

Each graded part's deciding evidence is read from the verdict (`lagrade.uses.research.sensitivity.evidence`):
exact arithmetic (`lagrade.compare.exact`, for answers in its class), the sampled states (the box), the states along the motion, the trajectory comparison, the numbers rule,
or "not rejected".
"""

from __future__ import annotations

import argparse
import collections
import tempfile
import time
from pathlib import Path

import sympy as sp

import lagrade
from lagrade.derive.effects import machinery
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem, problem_ids
from lagrade.uses.research.sensitivity import _write, evidence, reference_rows

PRESETS = ("fast", "default", "strict")
CLASSES = ("beyond the box", "small parameter error", "gross error", "kick outside the exact class")
EVIDENCE = ("exact arithmetic", "sampled states", "states along the motion", "trajectories", "the numbers rule", "not rejected")


def beyond_box(rows: list[sp.Expr], mech) -> list[sp.Expr] | None:
    """The first row with force terms (the row at zero accelerations is not 0: a row without them, as
    12.28's first, would stay right) scaled by 1 + (a factor below 1e-13 inside the sampling box); None
    when no row has one."""
    coords = {c.name: c for c in mech.system.coordinates}
    s = sum((qd / sp.nsimplify(max(abs(v) for v in coords[name].velocity))) ** 2
            for name, qd in zip(mech.names, mech.s.qd))
    bump = sp.exp(8 * (s - len(mech.names)) - 30)
    for i, row in enumerate(rows):
        force = sp.simplify(row.xreplace({a: 0 for a in mech.s.qdd}))
        if force != 0:
            return [*rows[:i], row + force * bump, *rows[i + 1:]]
    return None


def kick(rows: list[sp.Expr], mech) -> list[sp.Expr] | None:
    """The first row with force terms plus that force times ``2**(-10**6*(t - h/2)**2)``; None when no
    row has one."""
    from lagrade.problem.symbols import T

    bump = sp.Integer(2) ** (-10**6 * (T - sp.nsimplify(mech.system.horizon) / 2) ** 2)
    for i, row in enumerate(rows):
        force = sp.simplify(row.xreplace({a: 0 for a in mech.s.qdd}))
        if force != 0:
            return [*rows[:i], row + force * bump, *rows[i + 1:]]
    return None


def grade(pid: str, name: str, rows, accuracy: str, folder: Path) -> str:
    path = folder / "answer.toml"
    _write(path, name, rows, False)
    part = next(p for p in lagrade.check(pid, path, accuracy=accuracy).parts if p.part == name)
    return evidence(part)


def scan(ids: list[str]):
    out = []   # (pid, part, class, preset, evidence)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for pid in ids:
            problem = load_problem(pid)
            for part in problem.parts:
                if part.kind != "eom" or part.linearized or part.reference is not None:
                    continue
                mech = references(problem)[part.system]
                if machinery(mech).switching:
                    continue
                try:
                    ref = reference_rows(problem, part)
                except Exception:  # noqa: BLE001
                    continue
                t0 = time.perf_counter()
                params = [p for p in mech.params if any(r.has(p) for r in ref)]
                param = next((p for p in params if grade(pid, part.name, [r.xreplace({p: sp.Rational(11, 10) * p})
                                                                           for r in ref], "fast", folder)
                              != "not rejected"), None)
                bumped = beyond_box(ref, mech)
                answers = {"beyond the box": bumped} if bumped is not None else {}
                if param is not None:
                    answers["small parameter error"] = [r.xreplace({param: (1 + sp.Rational(1, 10**6)) * param})
                                                        for r in ref]
                    answers["gross error"] = [r.xreplace({param: sp.Rational(11, 10) * param}) for r in ref]
                kicked = kick(ref, mech)
                if kicked is not None:
                    answers["kick outside the exact class"] = kicked
                line = []
                for cls, rows in answers.items():
                    for acc in PRESETS:
                        ev = grade(pid, part.name, rows, acc, folder)
                        out.append((pid, part.name, cls, acc, ev))
                        line.append(f"{acc[0]}:{ev.split()[0]}")
                print(f"{pid:>7} {part.name:<12} {' '.join(line)}  ({time.perf_counter() - t0:.1f} s)", flush=True)
    return out


def markdown(out) -> str:
    count = collections.Counter((c, a, e) for _, _, c, a, e in out)
    lines = ["| class of mistake | preset | parts | " + " | ".join(EVIDENCE) + " |",
             "|---|---|---|" + "---|" * len(EVIDENCE)]
    for cls in CLASSES:
        for acc in PRESETS:
            n = sum(count[(cls, acc, e)] for e in EVIDENCE)
            if n:
                lines.append(f"| {cls} | {acc} | {n} | " + " | ".join(str(count[(cls, acc, e)]) for e in EVIDENCE)
                             + " |")
    return "\n".join(lines)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("ids", nargs="*")
    ap.add_argument("--markdown", action="store_true", help="print the table for docs/numerics.md")
    args = ap.parse_args()
    t0 = time.perf_counter()
    out = scan(args.ids or problem_ids())
    print(f"\n{len(out)} gradings in {time.perf_counter() - t0:.0f} s")
    if args.markdown:
        print(markdown(out))


if __name__ == "__main__":
    main()
