"""What error each accuracy preset catches: every dynamics part, each parameter scaled by (1 + eps).

Run by ``python benchmarks/sensitivity.py`` (the table of docs/numerics.md) and held by
tests/stability/test_sensitivity.py.

For every part of kind lagrangian, eom (not linearized), hamiltonian and hamilton_eqs, the derived
reference is written as an answer.toml with one parameter p replaced by (1 + eps)*p, eps an exact
fraction 1/10**k (a float would be refused outright as an inexact number: docs/answers.md), and graded
under fast, default and strict. For each part and preset, the smallest eps in 1e-3 ... 1e-6 that is
rejected (not full marks) for every parameter that matters is reported (found by bisection: a
larger error is assumed caught when a smaller one is). A parameter whose 10 % change is accepted
does not matter to that part (it cancels) and is left out. "-" means even 1e-3 passed.
"""

from __future__ import annotations

import collections
import sys
import tempfile
import time
from pathlib import Path

import sympy as sp

from lagrade.verdicts.grade import check, references
from lagrade.problem.library import load_problem

#: down to 1e-6: a finer exact fraction (1 + 1/10**7) has a denominator above 10**6 and is refused by the
#: numbers rule whatever the preset (checkers/admit.py), so the sampled evidence is measured above it
EPS = [10.0 ** -k for k in range(3, 7)]
PRESETS = ("fast", "default", "strict")
KINDS = ("lagrangian", "eom", "hamiltonian", "hamilton_eqs")


def reference_rows(problem, part) -> list[sp.Expr] | None:
    """The part's derived reference in state symbols (q, q_d, q_dd, p_q, p_q_d), or None."""
    mech = references(problem)[part.system]
    if part.kind == "lagrangian":
        return [mech.L]
    if part.kind == "eom":
        return list(mech.EL)
    H = mech.hamiltonian_symbolic
    if part.kind == "hamiltonian":
        return [H]
    qd = [sp.diff(H, p) for p in mech.s.p]
    at_qd = dict(zip(mech.s.qd, qd))
    rows = [a - b for a, b in zip(mech.s.qd, qd)]
    rows += [sp.Symbol(f"{p}_d") - (-sp.diff(H, q) + sp.sympify(Q).xreplace(at_qd))
             for p, q, Q in zip(mech.s.p, mech.s.q, mech.Q)]
    return rows


def _write(path: Path, name: str, rows: list[sp.Expr], single: bool) -> None:
    texts = [sp.sstr(r) for r in rows]
    path.write_text(f'{name} = "{texts[0]}"\n' if single else f"{name} = [" + ", ".join(f'"{t}"' for t in texts) + "]\n")


#: the evidence that rejected the last answer graded by `rejected` (what `scan` reports per part)
LAST: dict[str, str] = {}


def rejected(pid: str, name: str, rows, single: bool, param, eps: float, accuracy: str, folder: Path) -> bool:
    factor = 1 + sp.Rational(1, round(1 / eps)) if eps else sp.S.One
    scaled = [r.xreplace({param: factor * param}) for r in rows]
    path = folder / "answer.toml"
    _write(path, name, scaled, single)
    result = check(pid, path, accuracy=accuracy)  # the engine's entry: not the package's, which reaches the server client
    part = next(p for p in result.parts if p.part == name)
    LAST["evidence"] = evidence(part)
    return part.verdict != "correct"


#: the words of a rejection at the states the motion visits (`lagrade.verdicts.checkers.dynamics.ALONG_MOTION`)
MOTION_WORDS = "beyond the range states are sampled from"


def evidence(part) -> str:
    """Which evidence decided a part's rejection, from the verdict's method and words."""
    if part.verdict == "correct":
        return "not rejected"
    return ("exact arithmetic" if part.method == "exact"
            else "the numbers rule" if "cannot be accepted" in part.feedback
            else "trajectories" if part.method == "trajectory"
            else "states along the motion" if MOTION_WORDS in part.feedback
            else "sampled states")


def smallest_rejected(*args) -> float | None:
    """Bisection over EPS (descending): the smallest eps still rejected, None if 1e-3 passes."""
    if not rejected(*args[:5], EPS[0], *args[5:]):
        return None
    lo, hi = 0, len(EPS) - 1  # EPS[lo] rejected; find the last rejected index
    if rejected(*args[:5], EPS[hi], *args[5:]):
        return EPS[hi]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if rejected(*args[:5], EPS[mid], *args[5:]):
            lo = mid
        else:
            hi = mid
    return EPS[lo]


def scan(ids: list[str]):
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for pid in ids:
            problem = load_problem(pid)
            for part in problem.parts:
                if part.kind not in KINDS or part.linearized or part.reference is not None:
                    continue
                try:
                    ref = reference_rows(problem, part)
                except Exception as exc:  # noqa: BLE001
                    print(f"{pid} {part.name}: no reference rows ({exc})", file=sys.stderr)
                    continue
                single = part.kind in ("lagrangian", "hamiltonian")
                mech = references(problem)[part.system]
                params = [p for p in mech.params if any(r.has(p) for r in ref)]
                t0 = time.perf_counter()
                # parameters that matter: a 10 % change is rejected under the loosest preset
                params = [p for p in params if rejected(pid, part.name, ref, single, p, 0.1, "fast", folder)]
                out, by = {}, {}
                for accuracy in PRESETS:
                    worst, evidence = 0.0, set()
                    for p in params:
                        e = smallest_rejected(pid, part.name, ref, single, p, accuracy, folder)
                        if e is not None:  # what rejected it at that eps (and below: the same or the rule)
                            rejected(pid, part.name, ref, single, p, e, accuracy, folder)
                            evidence.add(LAST["evidence"])
                        worst = max(worst, e if e is not None else float("inf"))
                    out[accuracy] = worst if params else None
                    by[accuracy] = evidence
                rows.append((pid, part.name, part.kind, [str(p) for p in params], out, time.perf_counter() - t0, by))
                print(f"{pid:>7} {part.name:<14} " + "  ".join(f"{a} {fmt(out[a]):>6}" for a in PRESETS)
                      + f"   ({len(params)} parameters, {time.perf_counter() - t0:.1f} s)", flush=True)
    return rows


def fmt(e: float | None) -> str:
    if e is None:
        return "n/a"
    return "-" if e == float("inf") else f"{e:.0e}"


def markdown(rows) -> str:
    lines = ["| preset | parts | smallest eps rejected for every parameter: " + ", ".join(fmt(e) for e in EPS)
             + ", none (-) |", "|---|---|---|"]
    for accuracy in PRESETS:
        counts = collections.Counter(fmt(r[4][accuracy]) for r in rows if r[4][accuracy] is not None)
        n = sum(counts.values())
        spread = ", ".join(f"{k}: {counts[k]}" for k in [*(fmt(e) for e in EPS), "-"] if counts[k])
        lines.append(f"| {accuracy} | {n} | {spread} |")
    lines += ["", "| preset | the smallest rejected eps was decided by (parts) |", "|---|---|"]
    for accuracy in PRESETS:
        evidence = collections.Counter(e for r in rows if r[4][accuracy] is not None for e in r[6][accuracy])
        lines.append(f"| {accuracy} | " + ", ".join(f"{k}: {v}" for k, v in sorted(evidence.items())) + " |")
    return "\n".join(lines)
