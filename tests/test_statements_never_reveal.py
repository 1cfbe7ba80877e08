"""A statement says what the student needs to answer, never the answer (issue 44 §8).

For every problem, what `lagrade show` and `lagrade template` print is checked against every part the
problem counts (extras are the book's answers to questions it does not ask): textually, for the
reference's printed forms (the problem file's text, sympy's ``str`` and the primed notation the
statements use), and mathematically, with the machinery of `leaks` (``test_hints_never_reveal``): every
formula the text quotes (``d/dt(...)`` read as a time derivative) is evaluated at the scene's states
and compared with each counted reference (a Lagrangian, a Hamiltonian, a result, a multiplier, a
constant of the motion), with the pieces of a result (a factor or a sum inside it, up to a constant
factor: 12.21's exp of the inverse map is most of T), and, where equations of motion are counted,
with the equations of the scene. A counted part's own name is never given a formula (``N = ...``),
and the constants of the motion a problem grades are not named (the energy, an angular momentum).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
import sympy as sp
from leaks import _close, _evaluate, _parse, fragments, secrets, squash

from lagrade.problem.describe import show_text, template_text
from lagrade.problem.library import load_problem, problem_ids
from lagrade.verdicts.checkers.values import _reference

#: kinds whose reference is a value that can be quoted (names, yes/no and counts are not formulas)
NOT_VALUES = {"boolean", "integer", "names", "numerical_solution", "trajectory"}
#: words that name a constant of the motion: a problem that grades the constants asks for them unnamed
#: (the momentum conjugate to a cyclic coordinate is what a cyclic coordinate gives: naming it is the question)
CONSTANT_NAMES = re.compile(r"\b(energy|angular momentum|linear momentum|spin|Jacobi)\b", re.IGNORECASE)


def _texts(pid: str) -> str:
    problem = load_problem(pid)
    return show_text(problem) + "\n" + template_text(problem)


def _ddt(text: str) -> list[str]:
    """The X of every ``d/dt(X)`` the text writes (its time derivative is compared too)."""
    out = []
    for start in (m.start() for m in re.finditer(r"d/dt\(", text)):
        depth = 0
        for i in range(start + 4, len(text)):
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            if depth == 0:
                out.append(text[start + 5:i])
                break
    return out


def _along(expr: sp.Expr, mech) -> sp.Expr:
    """The time derivative of ``expr`` (in the state symbols) along the motion."""
    out = sp.diff(expr, sp.Symbol("t"))
    for q, qd, qdd in zip(mech.s.q, mech.s.qd, mech.s.qdd):
        out += sp.diff(expr, q) * qd + sp.diff(expr, qd) * qdd
    return out


def _quoted(text: str, names: set[str], mech) -> list[tuple[str, sp.Expr]]:
    """Every formula the text quotes, parsed, with its pieces that tie two state variables together,
    and the time derivative of each d/dt(X)."""
    out = []
    for frag in fragments(text, names):
        expr = _parse(frag, mech)
        if expr is None or expr.is_Number or expr.is_Symbol or (expr.is_Pow and expr.base.is_Symbol):
            continue
        out.append((frag, expr))
        out += [(f"{frag} (its {node})", node) for node in _pieces(expr, mech)]
    for inner in _ddt(text):
        expr = _parse(inner, mech)
        if expr is not None:
            out.append((f"d/dt({inner})", _along(expr.xreplace(mech.constrained), mech)))
    return out


def _primed(expr: sp.Expr) -> str:
    """The notation of the statements: q' and q'' for the rates."""
    return re.sub(r"\b([A-Za-z]\w*?)_dd\b", r"\1''", re.sub(r"\b([A-Za-z]\w*?)_d\b", r"\1'", str(expr)))


def counted(pid: str) -> list[tuple[str, str, sp.Expr | None, bool]]:
    """(what, system, expression, its pieces too) for every value a counted part is graded against
    (None: a Hamiltonian, compared by its values)."""
    problem = load_problem(pid)
    out = []
    for part in problem.parts:
        if part.extra:
            continue
        for key in dict.fromkeys([part.system, *(a.system for a in part.alternatives if a.system is not None)]):
            mech = secrets(pid)[key].mech
            if part.kind == "lagrangian":
                out.append((f"{part.name} (L of '{key}')", key, mech.L, False))
            elif part.kind == "hamiltonian":  # compared by value (`leaks`' numeric H): the symbolic one is slow
                out.append((f"{part.name} (H of '{key}')", key, None, False))
            elif part.kind not in NOT_VALUES and part.reference is not None and key == part.system:
                refs = [(part.name, part.reference)] + [  # an accepted alternative (12.30's lam, the torque)
                    (f"{part.name} as {a.name or 'an alternative'}", a.reference) for a in part.alternatives
                    if a.reference is not None and (a.system is None or a.system == key)]
                for name, ref in refs:
                    _targets(out, part, name, key, mech, ref)
    return out


def _targets(out: list, part, name: str, key: str, mech, ref) -> None:
    items = ref.items() if isinstance(ref, dict) else enumerate(ref if isinstance(ref, list) else [ref])
    for k, text in items:
        expr = _reference(part, mech, text)
        expr = expr.xreplace(mech.multiplier_exprs) if expr.free_symbols & set(mech.multipliers) else expr
        if expr.free_symbols & set(mech.s.qdd):
            expr = expr.xreplace(dict(zip(mech.s.qdd, mech.accelerations_symbolic)))
        out.append((f"{name}[{k}]" if isinstance(ref, dict) else name, key, expr, True))


def _state(mech) -> set[sp.Symbol]:
    return {*mech.s.q, *mech.s.qd, *mech.s.qdd, *mech.s.p, *mech.constrained}


def _pieces(expr: sp.Expr, mech) -> list[sp.Expr]:
    """The sums and products inside a result that tie two of the state's variables together (12.21's
    u*sin(phi)**2 + v*cos(phi)**2 inside T's exp): quoting one gives most of the result away, while
    a piece in one coordinate (l - r, k/r) is the scene's own description."""
    return [node for node in sp.preorder_traversal(expr) if node is not expr and isinstance(node, (sp.Add, sp.Mul))
            and len(node.free_symbols & _state(mech)) >= 2]


def _proportional(a: np.ndarray, b: np.ndarray) -> bool:
    with np.errstate(all="ignore"):
        ratio = a / b
    return bool(np.all(np.isfinite(ratio)) and abs(ratio[0]) > 1e-12 and np.allclose(ratio, ratio[0], rtol=1e-9))


def statement_leaks(pid: str, text: str) -> list[str]:
    """What of the counted parts of ``pid`` the text gives away (empty: nothing). The book's own
    statement is not checked, and a quoted value the book's statement gives too (ex12.2's force
    k/r**2, which is also Q_r) is the book's data, not a leak."""
    problem = load_problem(pid)
    text = text.replace(problem.statement.strip(), "")
    found = []
    flat = squash(text)
    values = counted(pid)
    for what, _key, expr, _ in values:  # the printed forms
        for form in {str(expr), _primed(expr)} if expr is not None else ():
            if len(form) >= 4 and not re.fullmatch(r"-?\w+'*", form) and squash(form) in flat:
                found.append(f"prints {what} as {form!r}")
    for part in problem.parts:  # the problem file's own text of a counted reference
        if part.extra or part.kind in NOT_VALUES or part.reference is None:
            continue
        # the part's reference, and each alternative's: an accepted answer printed is the part given away
        for ref in (part.reference, *(a.reference for a in part.alternatives if a.reference is not None)):
            for raw in (ref.values() if isinstance(ref, dict) else ref if isinstance(ref, list) else [ref]):
                raw = str(raw)
                if not re.fullmatch(r"-?\w+", raw.strip()) and squash(raw) in flat.replace("'", "_d"):
                    found.append(f"prints the reference of {part.name} as written, {raw!r}")
    eqs = {part.system for part in problem.parts if not part.extra and part.kind == "eom"}
    for key, sec in secrets(pid).items():
        mech = sec.mech
        names = {*mech.all_names, *(p.name for p in mech.parameters), *(str(m) for m in mech.multipliers)}
        mine = [(w, e, pieces) for w, k, e, pieces in values if k == key]
        targets = []
        for what, expr, pieces in mine:
            if expr is None:  # a Hamiltonian: its values at the states
                v = next(s.values for s in sec.values if s.what == f"H of system '{key}'")
                targets.append((what, v, False))
                continue
            v = _evaluate(expr.xreplace(mech.constrained), sec.pts)
            if v is not None:
                targets.append((what, v, False))
            for piece in (_pieces(expr, mech) if pieces else []):
                v = _evaluate(piece.xreplace(mech.constrained), sec.pts)
                if v is not None:
                    targets.append((f"a piece of {what}", v, True))
        given = [v for _, e in _quoted(problem.statement, names, mech)
                 if (v := _evaluate(e.xreplace(mech.constrained), sec.pts)) is not None]
        for frag, expr in _quoted(text, names, mech):
            reduced = expr.xreplace(mech.constrained)
            a = _evaluate(reduced, sec.pts)
            if a is not None and np.any(a != 0) and not any(_close(a, g) or _close(-a, g) for g in given):
                for what, v, piece in targets:
                    if _proportional(a, v) if piece else _close(a, v):
                        found.append(f"'{frag}' equals {what}")
            if key in eqs and reduced.free_symbols & set(mech.s.qdd):
                on_motion, anywhere = _evaluate(reduced, sec.pts), _evaluate(reduced, sec.raw)
                if on_motion is not None and anywhere is not None and np.any(np.abs(anywhere) > 1e-9) and \
                        np.allclose(on_motion, 0, atol=1e-9 * max(np.abs(anywhere).max(), 1.0)):
                    found.append(f"'{frag}' is an equation of motion of system '{key}'")
    found += _formulas_for_counted_names(problem, text)
    found += _named_constants(problem, text)
    return sorted(set(found))


def _formulas_for_counted_names(problem, text: str) -> list[str]:
    """``N = m*a*theta'**2`` for a counted part N: a formula in the problem's symbols (not a definition
    in other quantities, such as L = T - V)."""
    symbols = {p.name for p in problem.parameters} | {c.name for s in problem.systems for c in s.coordinates} | \
              {q.name for s in problem.systems for q in s.parameters}
    out = []
    for part in problem.parts:
        if part.extra or part.kind in ("boolean", "integer", "names"):
            continue
        for name in (part.name, *part.aliases):
            for m in re.finditer(rf"(?<![\w'])({re.escape(name)})[ \t]*=(?!=)[ \t]*([^,;\n]+)", text):
                rhs = re.split(r"\s(?:with|where|for|is|and|the)\s|\.\s|\.$", m.group(2))[0]
                line = text[text.rfind("\n", 0, m.start()) + 1:text.find("\n", m.end()) % (len(text) + 1)]
                if "..." in line:  # the template's placeholder {'r': ..., 'theta': ...}
                    continue
                words = set(re.findall(r"[A-Za-z_]\w*", rhs.replace("'", "")))
                if words & symbols:
                    out.append(f"gives the counted part {part.name} a formula: '{m.group(0)[:60]}'")
    return out


def _named_constants(problem, text: str) -> list[str]:
    """Where the constants of the motion are graded, the statement asks for them without naming them,
    and does not name a coordinate as the cyclic one."""
    out = []
    graded = [p for p in problem.parts if not p.extra and p.kind in ("conserved", "names")]
    if not graded:
        return out
    lines = [ln for ln in text.splitlines() if re.search(r"conserved|constants? of (the )?motion|cyclic", ln)]
    for ln in lines:
        for m in CONSTANT_NAMES.finditer(ln):
            out.append(f"names a graded constant of the motion ({m.group(0)}): {ln.strip()[:80]!r}")
    for part in graded:
        if part.kind != "names":
            continue
        for name in part.reference:
            if re.search(rf"cyclic (coordinate )?{re.escape(name)}\b|\b{re.escape(name)} is cyclic|"
                         rf"(?<![\w']){re.escape(name)}'? (is )?eliminated", text):
                out.append(f"names the cyclic coordinate {name}")
    return out


@pytest.mark.parametrize("pid", problem_ids())
def test_show_and_template_never_give_a_counted_part_away(pid):
    assert statement_leaks(pid, _texts(pid)) == []


# The texts the problem files used to print (issue 44): each gave a counted part away.
OLD_LEAKS = [
    ("12.35", "Gravity is ignored, so the normal reaction is horizontal, toward the centre, N = m*a*theta'**2."),
    ("12.21", "Inverse: ln(r/a) = u*sin(phi)**2 + v*cos(phi)**2, theta = (v - u)*sin(phi)*cos(phi)."),
    ("12.21", "write r through u and v (r = a*exp(u*sin(phi)**2 + v*cos(phi)**2))."),
    ("12.30", "the constraint is theta = omega*t, with multiplier lam = d/dt(m*r**2*theta') - dL/dtheta"),
    ("12.30", "lam: the torque the wire exerts about the axis, d/dt(m*r**2*theta')"),
    ("12.38", "(For the vertical spring of 12.1(b): H = p_y**2/(2*m) + k*y**2/2 - m*g*y, y' = p_y/m.)"),
    ("12.13", "conserved: the quantity conserved because of the cyclic coordinate (the disk's spin)"),
    ("12.16", "conserved: the constants of the motion (the vertical angular momentum and the energy)"),
    ("ex12.7", "conserved asks for the constants of the motion (the angular momentum about the origin and the energy)"),
    ("12.32", "R_theta = m*a*theta'' on the motion"),
    ("12.16", "L = m*R**2*(theta'**2 + sin(theta)**2*phi'**2)/2 + m*g*R*cos(theta)"),
    ("12.43", "theta'' = -g*sin(theta)/l, the equation of motion"),
    ("12.38", "the energy p_r**2/(2*m) + p_theta**2/(2*m*r**2) - m*g*r*cos(theta) + k*(r - l0)**2/2"),
]


@pytest.mark.parametrize("pid, text", OLD_LEAKS, ids=[f"{p}-{i}" for i, (p, _) in enumerate(OLD_LEAKS)])
def test_the_check_catches_an_old_leaking_statement(pid, text):
    assert statement_leaks(pid, text), text


def test_describing_the_scene_is_not_a_leak():
    assert statement_leaks("12.32", "potential c*(r**2 + z**2)/2; the constraints r = a and z = k*theta") == []
    assert statement_leaks("12.26", "L = T - U with T the inertial kinetic energy written in xp, yp.") == []
    assert statement_leaks("12.16", "conserved asks for the constants of the motion, in the coordinates "
                                    "and velocities.") == []
