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
