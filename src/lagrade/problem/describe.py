"""A problem in words, as a student reads it: what ``lagrade show`` and ``lagrade template`` print,
and what the course server's page shows (the same text, from one place)."""

from __future__ import annotations

from lagrade.problem.domains import words
from lagrade.problem.spec import KINDS, GeneralFunction, Problem


def show_text(p: Problem) -> str:
    """Statement, assumptions, symbols to use and the parts asked (never a reference value: only the
    keys of a dict answer)."""
    out = [f"Problem {p.id}: {p.title}", ""]
    if p.statement:
        out += [p.statement.strip(), ""]
    if p.assumptions:
        out += ["Assumptions:"] + [f"  - {a}" for a in p.assumptions] + [""]
    if p.parameters:
        out.append("Parameters (symbols, matched by name):")
        out += [f"  {q.name:<10} {q.description}{' (> 0)' if q.positive else ''}" for q in p.parameters]
        out.append("")
    for s in p.systems:
        label = f"System ({s.key}) {s.title}".rstrip() if s.key else "Coordinates"
        out.append(f"{label}:" if s.key else "Coordinates (functions of t):")
        out += [f"  {c.name + '(t)':<12} {c.description}" for c in s.coordinates]
        for c in s.constraints:
            out.append(f"  constraint: {c.coordinate} = {c.value}" +
                       (f"  (multiplier {c.multiplier})" if c.multiplier else ""))
        for q in s.parameters:
            out.append(f"  parameter {q.name:<10} {q.description}{' (> 0)' if q.positive else ''}")
        for f in s.functions:  # left general by the book: answers may call it, or use the stated one
            out.append(f"  function  {f.name}({', '.join(f.args)}): {f.description or 'a general function'}; "
                       f"{special_cases(f)}")
        out.append(f"  effects: {', '.join(s.effects) or 'none'}")
        out.append("")
    for s in p.systems:  # where each symbol lives: what an answer may rely on (sqrt(m**2) is m)
        out.append(f"Domain{f' ({s.key})' if s.key else ''}: {domain_text(p, s.key)}")
    out.append("")
    out.append("Parts (bind these names in answer.py):")
    for part in p.parts:
        alias = f" (also {', '.join(part.aliases)})" if part.aliases else ""
        sys_note = f" [system {part.system}]" if part.system else ""
        extra = " [extra: not asked by the book; graded and shown, not counted in the total]" if part.extra else ""
        out.append(f"  {part.name:<12} {part.prompt or part.kind}{sys_note}{alias}{extra}")
        detail = KINDS[part.kind].expects
        if part.kind == "expression" and isinstance(part.reference, dict):
            detail = f"dict with keys {', '.join(repr(k) for k in part.reference)}"
        if part.linearized:
            detail += "; linearized about equilibrium"
        if part.symbols:
            detail += f"; may use {', '.join(part.symbols)}"
        if part.accelerations:
            detail += "; may use the accelerations q'', evaluated on the true motion"
        others = [(f"bound to {a.name}, " if a.name else "")
                  + (a.says or ("any Lagrangian L + dF(q, t)/dt (another gauge)" if a.gauge else "")
                     or p.system(a.system if a.system is not None else part.system).title or "another reading")
                  + (f", for {a.credit:.0%} of the part" if a.credit < 1 else "")
                  for a in part.alternatives]
        if others and part.follows is None:  # never a reference value: the formulations' words only
            detail += f"; also accepted: {'; '.join(others)}"
        if part.follows:
            detail += f"; judged for the formulation of your {part.follows}"
        if part.also_answered_by:
            detail += (f"; a motion at these numbers bound to {' or '.join(part.also_answered_by)} is graded "
                       f"as {part.name}")
        if part.version_of and part.version_of in (part.name, *part.aliases):
            others = [v.name for v in p.versions(part.version_of) if v is not part]
            detail += (f"; one version of {part.version_of}, with {', '.join(others)}: both are graded, and a value "
                       f"bound to {part.version_of} counts for the version whose coordinates it uses")
        out.append(f"  {'':<12}   -> {detail}")
    typing = typing_help(p)
    if typing:  # answer.toml and the course page are typed: the spellings before the first try
        out += ["", typing.replace("Typing an answer:", "Typing an answer (answer.toml, the course page):", 1)]
    return "\n".join(out)


def domain_text(p: Problem, key: str = "") -> str:
    """The physical domains of a system's parameters, coordinates and velocities, in the student's
    notation: ``m, M, g > 0; 0 < alpha < pi/2; theta' > 0; x, x' real`` (and t's, where the scene
    holds for a while only: ``0 <= t < pi/(2*omega)``)."""
    return words(d for d in p.domains(key).values() if d.role in ("parameter", "coordinate", "velocity")
                 or (d.role == "time" and d.bounds.text != "real"))  # a scene that holds for a while only


def special_cases(f: GeneralFunction) -> str:
    """What an answer written for the stated function or for 0 earns: the promise the grader keeps
    (`lagrade.verdicts.checkers.general`), said from the one field both read."""
    cases = " or ".join(dict.fromkeys(f"{f.name} = {c}" for c in (f.concrete, "0")))
    call = f"{f.name}({', '.join(f.args)})"
    if f.special_case == "full":
        return (f"general, or {cases}: an answer is checked for the one it states, and a right one earns "
                "full marks")
    return (f"the problem asks a general {call}; an answer right only for {cases} earns partial credit")


def template_text(p: Problem) -> str:
    """A skeleton answer.py with every part as a name to fill."""
    lines = [f'"""Answer to problem {p.id}: {p.title}."""', "", "from lagrade.answer import *", ""]
    params = " ".join(q.name for q in p.parameters)
    if params:
        lines.append(f"{', '.join(q.name for q in p.parameters)} = parameters(\"{params}\")")
    for s in p.systems:
        if s.parameters:
            names = [q.name for q in s.parameters]
            lines.append(f"# system ({s.key}) only: {', '.join(names)} = parameters(\"{' '.join(names)}\")")
    declared: set[str] = {q.name for q in p.parameters}  # each name once: 12.41's (b) and (b_small) share theta
    for s in p.systems:
        names = [c.name for c in s.coordinates]
        if s.key:
            lines.append(f"# system ({s.key}) {s.title}")
        new = [n for n in names if n not in declared]
        if new:
            lines.append(f"{', '.join(new)} = coordinates(\"{' '.join(new)}\")")
        if len(new) < len(names):
            lines.append(f"# ({', '.join(n for n in names if n not in new)} as above)")
        declared.update(names)
        for f in s.functions:
            line = f"{f.name} = Function(\"{f.name}\")  # {f.name}({', '.join(f.args)}), general"
            if line not in lines:  # several systems may share one function (12.39's frames)
                lines.append(line)
        if any(part.kind in ("hamiltonian", "hamilton_eqs")
               and s.key in {part.system, *(a.system for a in part.alternatives)} for part in p.parts):
            moms = [f"p_{n}" for n in names if f"p_{n}" not in declared]
            if moms:
                lines.append(f"{', '.join(moms)} = momenta(\"{' '.join(moms)}\")")
            declared.update(f"p_{n}" for n in names)
    lines.append("")
    for part in p.parts:
        lines.append(f"# {part.prompt or part.kind}: {KINDS[part.kind].expects}")
        if part.kind == "expression" and isinstance(part.reference, dict):
            lines.append(f"# {part.name} = {{{', '.join(f'{k!r}: ...' for k in part.reference)}}}")
        else:
            lines.append(f"# {part.name} = ")
        lines.append("")
    return "\n".join(lines).rstrip() + "\n"


def typing_help(p: Problem) -> str:
    """How a typed answer (the course page, answer.toml) writes a coordinate's rates, for this
    problem's coordinates: said before a student types, not only in the error after."""
    from lagrade.problem.notation import spellings

    coords = list(dict.fromkeys(c.name for s in p.systems for c in s.coordinates))
    if not coords:
        return ""
    first = coords[0]
    others = f"; likewise {', '.join(c + chr(39) for c in coords[1:])}" if len(coords) > 1 else ""
    return (f"Typing an answer: the rates of {first} are written {spellings(first)}{others}; a power is x^2 or x**2; "
            "an equation is Eq(lhs, rhs) or lhs == rhs.")


#: words of the statements that are names of symbols too: left as words, not set as math
_WORDS = frozenset({"a", "A", "I"})


def _with_math(text: str, names: list[str]) -> str:
    """``text`` with each symbol name set as inline math (``m1`` -> ``$m_{1}$``), for Markdown."""
    import re

    import sympy as sp

    names = sorted((n for n in set(names) if n not in _WORDS), key=len, reverse=True)
    if not names:
        return text
    pattern = re.compile(r"(?<![\w$'.])(" + "|".join(map(re.escape, names)) + r")(\(t\))?(?![\w'$])")
    return pattern.sub(lambda m: f"${sp.latex(sp.Symbol(m.group(1)))}{m.group(2) or ''}$", text)


def notebook_text(p: Problem) -> str:
    """A Jupyter notebook to answer ``p`` in (``lagrade template ID --notebook``): the statement as
    Markdown with math, how to write the answer, the symbols' cell, one code cell per part (None: not
    answered yet) and a last cell, tagged ``lagrade-check``, that checks the answer where it is
    written. The grader reads the code cells and leaves that cell out
    (`lagrade.answer.reading.notebook`). nbformat 4.5, written as JSON: no Jupyter needed to make it."""
    import json

    coords = list(dict.fromkeys(c.name for s in p.systems for c in s.coordinates))
    names = [q.name for s in p.systems for q in p.parameters_of(s.key)] + coords
    math = lambda text: _with_math(text, names)  # noqa: E731
    intro = [f"# Problem {p.id}: {p.title}", ""]
    if p.statement:
        intro += [math(" ".join(p.statement.split())), ""]
    if p.assumptions:
        intro += ["**Assumptions**", ""] + [f"- {math(a)}" for a in p.assumptions] + [""]
    if p.parameters:
        intro += ["**Parameters** (symbols, matched by name)", "", "| symbol | name | meaning |", "|---|---|---|"]
        intro += [f"| {math(q.name) if q.name not in _WORDS else '$' + q.name + '$'} | `{q.name}` | "
                  f"{q.description}{' (> 0)' if q.positive else ''} |" for q in p.parameters]
        intro.append("")
    for s in p.systems:
        label = f"**System ({s.key})** {s.title}".rstrip() if s.key else "**Coordinates** (functions of $t$)"
        intro += [label, ""] + [f"- {math(c.name + '(t)')} (`{c.name}`): {c.description}" for c in s.coordinates]
        intro += [f"- parameter {math(q.name)} (`{q.name}`): {q.description}" for q in s.parameters]
        intro += [f"- function `{f.name}({', '.join(f.args)})`: {f.description or 'a general function'}; "
                  f"{special_cases(f)}" for f in s.functions]
        intro += [f"- domain: {domain_text(p, s.key)}", ""]
    how = ["## How to answer", "",
           f"Fill in one cell per part below (`None` means not answered yet), then run the last cell: it checks "
           f"your answer here. `lagrade check {p.id} answer.ipynb` grades the saved notebook from a terminal, "
           f"and your course may collect the notebook itself. Only the code cells are read, never their "
           f"outputs; Markdown cells and IPython's `%` and `!` lines are left out.", "",
           f"- A coordinate such as `{coords[0] if coords else 'q'}` stands for a function of time: its rate is "
           f"`{coords[0] if coords else 'q'}.diff(t)` (or `dot({coords[0] if coords else 'q'})`), its acceleration "
           f"`{coords[0] if coords else 'q'}.diff(t, 2)`.",
           "- An equation is `Eq(lhs, rhs)`, or an expression meaning `= 0`; a power is `x**2`.",
           "- `from lagrade.answer import *` gives sympy's names and `t`, `coordinates`, `parameters`, "
           "`momenta`, `dot`."]
    typing = typing_help(p)
    if typing:
        how += ["", typing.replace("Typing an answer:", "Typed as text (answer.toml, the course page):", 1)]
    setup = template_text(p).split("\n")
    first_part = next((i for i, line in enumerate(setup) if line.startswith("# ") and i > 3
                       and any(line.startswith(f"# {part.prompt or part.kind}:") for part in p.parts)), len(setup))
    cells = [_cell("markdown", "\n".join(intro).rstrip()), _cell("markdown", "\n".join(how)),
             _cell("code", "\n".join(line for line in setup[2:first_part]).strip())]
    for part in p.parts:
        extra = " (extra: not asked by the book; graded and shown, not counted in the total)" if part.extra else ""
        expects = KINDS[part.kind].expects
        if part.kind == "expression" and isinstance(part.reference, dict):
            expects = f"dict with keys {', '.join(repr(k) for k in part.reference)}"
        cells.append(_cell("markdown", f"**`{part.name}`**: {math(part.prompt or part.kind)}{extra}  \n{expects}"))
        shape = (f"  # {{{', '.join(f'{k!r}: ...' for k in part.reference)}}}"
                 if part.kind == "expression" and isinstance(part.reference, dict) else "")
        cells.append(_cell("code", f"{part.name} = None{shape}"))
    call = ", ".join(f"{part.name}={part.name}" for part in p.parts)
    cells.append(_cell("markdown", "## Check your answer"))
    cells.append(_cell("code", f"import lagrade\nlagrade.check({p.id!r}, {call})", tags=["lagrade-check"]))
    for i, cell in enumerate(cells):
        cell["id"] = f"lagrade-{i}"
    nb = {"cells": cells, "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python",
                                                      "name": "python3"},
                                       "language_info": {"name": "python"}},
          "nbformat": 4, "nbformat_minor": 5}
    return json.dumps(nb, indent=1, ensure_ascii=False) + "\n"


def _cell(kind: str, text: str, tags: list[str] | None = None) -> dict:
    cell = {"cell_type": kind, "metadata": {"tags": tags} if tags else {},
            "source": text.splitlines(keepends=True)}
    if kind == "code":
        cell.update(execution_count=None, outputs=[])
    return cell
