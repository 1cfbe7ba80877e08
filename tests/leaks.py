"""Does a feedback text give a reference away? Textually, and mathematically.

Used by ``test_hints_never_reveal``. Every expression quoted in a message (primes ``x'``, ``x''``
read as time derivatives) is parsed with the text-answer parser and evaluated at the problem's
sampled states; it reveals the answer when it equals a reference value there: a part's reference
(derived accelerations and multipliers at their true values), a system's L, T, V, H, an
acceleration, a multiplier, or, for an equation, a multiple of a Lagrange equation of the scene.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cache

import numpy as np
import sympy as sp

from lagrade.answer.reading.text import parse_math
from lagrade.verdicts.checkers.dynamics import split_energy
from lagrade.verdicts.checkers.values import _reference
from lagrade.verdicts.grade import references
from lagrade.problem.library import load_problem
from lagrade.numbers.numeric import evaluate
from lagrade.compare.sampling import (
    rng_for,
    sample_points,
    state_arrays,
    with_reference_dynamics,
)
from lagrade.problem.symbols import T, to_state

K = 12
_FUNCS = {"sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "acot", "atan2", "sinh", "cosh", "tanh",
          "coth", "exp", "log", "sqrt", "Abs", "sign"}


def squash(text: str) -> str:
    return re.sub(r"\s+", "", text)


@dataclass
class Secret:
    what: str
    values: np.ndarray  # (K,) at the system's points
    bare: bool  # the reference is a bare name (x_dd, lam): a bare name in a message is not its value


@dataclass
class SystemSecrets:
    mech: object
    pts: object  # with the reference dynamics
    raw: object  # random accelerations (for equations)
    values: list[Secret] = field(default_factory=list)
    derived: set = field(default_factory=set)


def _evaluate(expr: sp.Expr, pts) -> np.ndarray | None:
    syms = [s for s in expr.free_symbols]
    if any(s not in pts.values for s in syms):
        return None
    with np.errstate(all="ignore"):
        try:
            out = evaluate([expr], syms, pts.args(syms))[0]
        except Exception:  # noqa: BLE001
            return None
    out = np.broadcast_to(np.asarray(out, dtype=complex if np.iscomplexobj(out) else float), (pts.K,))
    return out if np.all(np.isfinite(out)) else None


@cache
def secrets(pid: str) -> dict[str, SystemSecrets]:
    problem = load_problem(pid)
    out = {}
    for system in problem.systems:
        mech = references(problem)[system.key]
        extra = sorted({s for part in problem.parts for s in part.symbols})
        pts = with_reference_dynamics(mech, sample_points(mech, K, rng_for("leaks", pid, system.key), extra=extra))
        raw = sample_points(mech, K, rng_for("leaks", pid, system.key), extra=extra)
        for sym, v in pts.values.items():  # same states; only the accelerations stay random
            if sym not in mech.s.qdd:
                raw.values.setdefault(sym, v)
        q, p = np.array(pts.args(mech.s.q)), np.array(pts.args(mech.s.p))
        _, _, t, params = state_arrays(mech, pts)
        sec = SystemSecrets(mech, pts, raw)
        sec.derived = {*mech.s.qdd, *mech.multipliers}
        kin, pot = split_energy(mech.L, mech)
        for what, expr in (("L", mech.L), ("T", kin), ("V", -pot)):
            v = _evaluate(expr, pts)
            if v is not None and np.any(v != 0):
                sec.values.append(Secret(f"{what} of system '{system.key}'", v, False))
        sec.values.append(Secret(f"H of system '{system.key}'", mech.hamiltonian(q, p, t, params), False))
        for sym in [*mech.s.qdd, *mech.multipliers]:
            sec.values.append(Secret(f"{sym}", np.asarray(pts[sym]), True))
        for term in sp.Add.make_args(sp.expand(mech.L)):
            if term.free_symbols & {*mech.s.q, *mech.s.qd, T} and len(sp.Add.make_args(mech.L)) > 1:
                v = _evaluate(term, pts)
                if v is not None:
                    sec.values.append(Secret(f"a term of the L of system '{system.key}'", v, False))
        out[system.key] = sec
    for part in problem.parts:
        if part.kind in ("boolean", "integer", "names") or part.reference is None:
            continue
        sec = out[part.system]
        ref = part.reference
        items = ref.items() if isinstance(ref, dict) else enumerate(ref if isinstance(ref, list) else [ref])
        for key, text in items:
            expr = _reference(part, sec.mech, text)
            v = _evaluate(expr, sec.pts)
            if v is not None:
                sec.values.append(Secret(f"{part.name}[{key}]" if key else part.name, v, expr.is_Symbol))
    return out


def reference_texts(pid: str) -> list[tuple[str, str]]:
    """(what, squashed text) of every reference written in the problem file that is a value, not a name."""
    problem = load_problem(pid)
    texts = []
    for system in problem.systems:
        calls = {squash(f"{f.name}({','.join(f.args)})") for f in system.functions}
        for what in ("L", "T", "V"):
            raw = getattr(system, what)
            if raw and squash(raw).lstrip("-") not in calls:  # V = V(r): the general function, named by show
                texts.append((f"{what} of system '{system.key}'", raw))
    for part in problem.parts:
        if part.kind in ("boolean", "integer", "names") or part.reference is None:
            continue
        ref = part.reference
        items = ref.values() if isinstance(ref, dict) else (ref if isinstance(ref, list) else [ref])
        for text in items:
            text = str(text)
            if re.fullmatch(r"-?[A-Za-z_][A-Za-z0-9_]*|-?\d+", text.strip()):
                continue  # a bare name (x_dd, lam) or number: compared by value below
            texts.append((part.name, text))
    return [(w, squash(t)) for w, t in texts]


def _primes(text: str) -> str:
    text = re.sub(r"([A-Za-z_][A-Za-z0-9_]*)''", r"\1_dd", text)
    return re.sub(r"([A-Za-z_][A-Za-z0-9_]*)'", r"\1_d", text)


def fragments(message: str, names: set[str]) -> list[str]:
    """Every run of mathematics in a message: text between English words and punctuation, and each
    side of an ``=``; an equation ``a = b`` also as ``a - (b)``."""
    text = _primes(message)
    pieces = re.split(r"[:;,]|(?<![<>!=])=(?!=)|\.(?=\s|$)|\b(?:not|is|and|or|with|the|of|so|than|which|by|in|"
                      r"for|at|to|from|as|gives|has|here|then|when|i\.e\.|e\.g\.)\b", text)
    out = []
    for piece in pieces:
        if not piece:
            continue
        run: list[str] = []
        for word in re.split(r"(\s+)", piece):
            token = word.strip().strip(".")
            if not token:
                run.append(word)
                continue
            if re.fullmatch(r"[A-Za-z]{3,}", token) and token not in names and token not in _FUNCS:
                if run:
                    out.append("".join(run))
                run = []
            else:
                run.append(word)
        if run:
            out.append("".join(run))
    for eq in re.finditer(r"([^:;,=]+?)\s=\s([^:;,=]+)", text):
        out.append(f"({eq.group(1)}) - ({eq.group(2)})")
    cleaned = []
    for f in out:
        f = f.strip().strip(".").strip()
        while f.count("(") > f.count(")") and f.startswith("("):
            f = f[1:].strip()
        while f.count(")") > f.count("(") and f.endswith(")"):
            f = f[:-1].strip()
        if f and f.count("(") == f.count(")"):
            cleaned.append(f)
    return cleaned


def _parse(fragment: str, mech) -> sp.Expr | None:
    try:
        expr = parse_math(fragment, list(mech.all_names))
        expr = sp.sympify(to_state(expr, mech.all_names, momenta_too=True))
    except Exception:  # noqa: BLE001  (prose that is not mathematics)
        return None
    if isinstance(expr, sp.Equality):
        expr = expr.lhs - expr.rhs
    return expr if isinstance(expr, sp.Expr) else None


def _close(a: np.ndarray, b: np.ndarray) -> bool:
    return bool(np.allclose(a, b, rtol=1e-9, atol=1e-12 * max(np.abs(b).max(), 1e-300)))


def reveals(pid: str, message: str) -> list[str]:
    """What of the references of ``pid`` the message gives away (empty: nothing)."""
    found = []
    message = re.sub(r"your term \S+", "your term", message)  # the student's own term, quoted back
    flat = squash(message)
    for what, text in reference_texts(pid):
        if text in flat or squash(_primes(message)).find(text) >= 0:
            found.append(f"quotes the reference {what} textually")
    for sec in secrets(pid).values():
        mech = sec.mech
        names = {*mech.all_names, *(p.name for p in mech.parameters), *(str(m) for m in mech.multipliers)}
        for frag in fragments(message, names):
            expr = _parse(frag, mech)
            if expr is None or expr.is_Number and expr == 0:
                continue
            a = _evaluate(expr, sec.pts)
            if a is not None:
                for s in sec.values:
                    if (s.bare or expr.is_Symbol) and (expr.free_symbols & sec.derived or expr.is_Symbol):
                        continue  # naming x'' or lam is not giving its value
                    if _close(a, s.values):
                        found.append(f"'{frag}' equals the reference {s.what}")
            # An equation: it holds on the true motion but not at random accelerations.
            reduced = expr.xreplace(mech.constrained) if mech.constrained else expr
            if reduced.free_symbols & set(mech.s.qdd):
                on_motion, anywhere = _evaluate(reduced, sec.pts), _evaluate(reduced, sec.raw)
                if on_motion is not None and anywhere is not None and np.any(np.abs(anywhere) > 1e-9) and \
                        np.allclose(on_motion, 0, atol=1e-9 * max(np.abs(anywhere).max(), 1.0)):
                    found.append(f"'{frag}' is an equation of motion of the scene")
    return sorted(set(found))
