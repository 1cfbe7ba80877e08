"""Reading an answer file into sympy objects, whatever it holds, without trusting it.

``.py`` files run in the sandbox and come back as text that is rebuilt without eval; ``.toml``
files are parsed without running anything. Either way the result is the same: the values bound
to the problem's part names, and a list of one-line problems naming the file and line.
"""

from __future__ import annotations

from collections.abc import Callable
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp

from lagrade.answer.jail.rebuild import RebuildError, decode_value
from lagrade.answer.jail.screen import AnswerProblem
from lagrade.answer.reading.suffixes import ANSWER_KINDS
from lagrade.answer.reading.text import load_toml_answer
from lagrade.problem.spec import Problem


def answer_names(problem: Problem) -> dict[str, str]:
    """Every name an answer may bind (part names and aliases) -> the part it answers."""
    names = {}
    for part in problem.parts:
        names[part.name] = part.name
        for alias in part.aliases:
            names[alias] = part.name
    return names


@dataclass
class LoadedAnswer:
    """What an answer file gave: values by part name, and what went wrong reading it."""

    values: dict[str, object] = field(default_factory=dict)
    problems: list[AnswerProblem] = field(default_factory=list)
    #: set when the file did not run to its end: parts it never bound are invalid, not missing
    fatal: AnswerProblem | None = None
    #: a problem that concerns one part only (a text answer that does not parse)
    part_problems: dict[str, AnswerProblem] = field(default_factory=dict)
    #: how the sandbox run ended (ok, error, timeout, memory, crashed, rejected); "ok" for text answers
    status: str = "ok"
    #: what the answer printed (truncated)
    stdout: str = ""
    #: versions of a two-version question answered by the shared name: part -> that name
    routed: dict[str, str] = field(default_factory=dict)
    #: the name each part's value was bound to (its own or an alias): an alternative may be selected by
    #: its alias (`Alternative.name`)
    bound_as: dict[str, str] = field(default_factory=dict)


def load_answer(path: Path, problem: Problem, limits=None) -> LoadedAnswer:
    """Read ``answer.py`` (sandboxed) or ``answer.toml`` (parsed) for ``problem``."""
    return start_loading(path, problem, limits)()


def start_loading(path: Path, problem: Problem, limits=None,
                  bound: Callable[[], AbstractContextManager] = nullcontext) -> Callable[[], LoadedAnswer]:
    """Start reading an answer; the returned function finishes it. An ``answer.py`` runs in its
    sandbox child meanwhile, so the caller can do other work (``lagrade check`` imports the grader).
    ``bound``: what this process's own work on the answer (reading the text, rebuilding the child's
    values) runs in: `lagrade.verdicts.grade.check` bounds it by CPU time as it bounds grading."""
    names = answer_names(problem)
    if not path.is_file():
        missing = AnswerProblem(file=str(path), line=None, message="no such answer file")
        return lambda: LoadedAnswer(problems=[missing], fatal=missing)
    if path.suffix == ".toml":
        def read_toml() -> LoadedAnswer:
            with bound():
                return _load_toml(path, problem, names)
        return read_toml
    if path.suffix == ".py":
        from lagrade.answer.jail.sandbox import SandboxLimits, start_answer_file

        running = start_answer_file(path, list(names), limits or SandboxLimits())

        def finish_py() -> LoadedAnswer:
            outcome = running.wait()  # the child is collected first: the bound never cuts into that
            with bound():
                return _finish_py(path, problem, names, outcome)
        return finish_py
    if path.suffix == ".ipynb":
        return _start_notebook(path, problem, names, limits, bound)
    wrong = AnswerProblem(file=str(path), line=None, message=ANSWER_KINDS)
    return lambda: LoadedAnswer(problems=[wrong], fatal=wrong)


def _start_notebook(path: Path, problem: Problem, names: dict[str, str], limits,
                    bound: Callable[[], AbstractContextManager]) -> Callable[[], LoadedAnswer]:
    """A notebook's code cells run as an ``answer.py`` would (`lagrade.answer.reading.notebook`): the same
    screen and jail. Its problems name the cell and the line in it; what was left out is said once each;
    a part bound to None (the template's placeholder) is not answered yet, not invalid."""
    from lagrade.answer.jail.sandbox import SandboxLimits, start_answer_source
    from lagrade.answer.reading.notebook import NotebookError, read_notebook

    try:
        nb = read_notebook(path)
    except NotebookError as exc:
        unreadable = AnswerProblem(file=path.name, line=None, message=str(exc))
        return lambda: LoadedAnswer(problems=[unreadable], fatal=unreadable, status="error")
    running = start_answer_source(nb.source, path, list(names), limits or SandboxLimits())

    def finish_notebook() -> LoadedAnswer:
        outcome = running.wait()
        placeholders = tuple(f"'{name}' is a NoneType" for name in names)
        held = [p for p in outcome.problems if p.message.startswith(placeholders)]
        outcome = outcome.model_copy(update={"problems": [
            p.model_copy(update={"file": f"{path.name} ({nb.where(p.line)})", "line": None}) if nb.where(p.line)
            else p for p in outcome.problems if p not in held]})
        with bound():
            out = _finish_py(path, problem, names, outcome)
        if held:  # the template's names, none filled in yet: no "did you mean 'L' for 'L'"
            out.problems = [p for p in out.problems if not p.message.startswith("no expected name found")]
        out.problems[:0] = [AnswerProblem(file=path.name, line=None, message=note) for note in nb.notes]
        return out
    return finish_notebook


def _load_toml(path: Path, problem: Problem, names: dict[str, str]) -> LoadedAnswer:
    out = LoadedAnswer()
    coords = sorted({c.name for s in problem.systems for c in s.coordinates})
    # momenta are functions of t too, so that Derivative(p_q(t), t) reads in Hamilton's equations
    functions = coords + [f"p_{c}" for c in coords]
    known = sorted({p.name for s in problem.systems for p in problem.parameters_of(s.key)}) + \
        [f"delta_{c}" for c in coords] + \
        [s for part in problem.parts for s in part.symbols] + ["t"] + _equation_names(problem, coords)
    general = {f.name: len(f.args) for s in problem.systems for f in s.functions}
    raw, problems = load_toml_answer(path, functions, known, general)
    text = path.read_text(encoding="utf-8", errors="replace")
    for prob in problems:
        for name in names:  # the part a problem is about: its line binds it, or (a table) it names it first
            if (prob.line is not None and _binds(text, prob.line, name)) or prob.message.startswith(f"{name}: "):
                out.part_problems[names[name]] = prob
    if any(prob.line is None for prob in problems):
        out.fatal = next(prob for prob in problems if prob.line is None)
    syntax = next((prob for prob in problems if "not valid TOML" in prob.message), None)
    if syntax is not None or (not raw and problems and not out.part_problems):  # not TOML at all: nothing in it
        out.fatal, out.status = syntax or problems[0], "error"                  # can be graded (exit 2, as .py)
        out.part_problems.clear()
    return _bind(out, raw, problems, path, problem, names)


def _equation_names(problem: Problem, coords: list[str]) -> list[str]:
    """Names an equation of motion may use besides the problem's: Lagrange multipliers (the problem's
    own, and lam, lambda_1, mu2 ... as students name them) and generalized forces Q_q left as symbols.
    The checker decides what they mean; a name the problem gives a parameter stays that parameter."""
    own = [c.multiplier for s in problem.systems for c in s.constraints if c.multiplier]
    usual = [f"{base}{suffix}" for base in ("lam", "lamda", "mu", "nu")
             for suffix in ("", *(f"{sep}{i}" for sep in ("", "_") for i in range(1, 5)))]
    usual += [f"lambda_{i}" for i in range(1, 5)]
    return sorted({*own, *usual, *(f"Q_{c}" for c in coords)})


def _finish_py(path: Path, problem: Problem, names: dict[str, str], outcome) -> LoadedAnswer:
    out = LoadedAnswer()
    problems = [p for p in outcome.problems if not _about_sympys_own(p, names)]
    out.status, out.stdout = outcome.status, outcome.stdout
    if outcome.status != "ok" and problems:
        out.fatal = problems[0]
    for prob in problems:  # what the child would not send ("'L' is an integer too large to grade"):
        for name in names:         # the part is invalid for it, not missing
            if prob.message.startswith(f"'{name}' "):
                out.part_problems.setdefault(names[name], prob)
    raw = {}
    for name, encoded in outcome.values.items():
        try:
            raw[name] = decode_value(encoded)
        except RebuildError as exc:  # the part is invalid for it (not missing): the file did bind it
            refused = AnswerProblem(file=path.name, line=None, message=f"{name}: {exc}")  # no grader path
            problems.append(refused)
            if name in names:
                out.part_problems.setdefault(names[name], refused)
    return _bind(out, raw, problems, path, problem, names)


def _bind(out: LoadedAnswer, raw: dict, problems: list, path: Path, problem: Problem,
          names: dict[str, str]) -> LoadedAnswer:
    _bind_values(out, raw, problems, path, problem, names)
    if not out.values and not out.part_problems and out.fatal is None:  # said once, for every name it binds
        out.problems = [p for p in out.problems if not p.message.endswith("; ignored")]
        out.problems.append(AnswerProblem(file=str(path), line=None, message=no_expected_name(path, problem)))
    return out


#: what students write for the answer names (a "did you mean" beyond spelling)
USUAL_WORDS = {"lagrangian": "L", "lagrange": "L", "hamiltonian": "H", "equations": "eom", "equation": "eom",
               "equations_of_motion": "eom", "motion": "eom", "eqs": "eom", "hamilton_equations": "hamilton",
               "hamiltons_equations": "hamilton", "hamilton_eqs": "hamilton", "generalized_force": "Q",
               "force": "Q", "forces": "Q", "tension": "S_t", "period": "period", "frequency": "omega",
               "virtual_work": "dW", "acceleration": "a", "conserved_quantities": "conserved",
               "constants_of_motion": "conserved", "trajectory": "solution", "degrees_of_freedom": "dof"}


def no_expected_name(path: Path, problem: Problem) -> str:
    """The one line for an answer that binds no name of the problem: which names it should bind, and the
    closest of them to each name it does bind ("did you mean 'L' for 'Lagrangian'?")."""
    import difflib

    expected = list(answer_names(problem))
    # the problem's own symbols (a template's `m, l1 = parameters(...)`, its coordinates and momenta) are
    # not attempts at an answer name: no "did you mean 'L' for 'l1'"
    coords = {c.name for s in problem.systems for c in s.coordinates}
    own = {q.name for s in problem.systems for q in problem.parameters_of(s.key)} | coords \
        | {f"p_{c}" for c in coords} | {f.name for s in problem.systems for f in s.functions} \
        | {c.multiplier for s in problem.systems for c in s.constraints if c.multiplier} \
        | {sym for part in problem.parts for sym in part.symbols}
    hints = []
    for name in bound_names(path):
        if name in own:  # ex12.4's parameter a is also its part's name: bound as the symbol, not an answer
            continue
        guess = USUAL_WORDS.get(name.lower())
        if guess not in expected:
            close = difflib.get_close_matches(name, expected, n=1, cutoff=0.6) or \
                difflib.get_close_matches(name.lower(), [n.lower() for n in expected], n=1, cutoff=0.6)
            guess = next((n for n in expected if close and n.lower() == close[0].lower()), None)
        if guess is not None:
            hints.append(f"'{guess}' for '{name}'")
    mean = f" (did you mean {', '.join(hints)}?)" if hints else ""
    parts = ", ".join(p.name for p in problem.parts)
    return f"no expected name found: problem {problem.id} asks {parts}{mean}"


def bound_names(path: Path) -> list[str]:
    """The names a file binds at its top level, read without running it (``ast`` for .py, TOML keys)."""
    import ast
    import tomllib

    try:
        text = path.read_text(encoding="utf-8", errors="replace")
        if path.suffix == ".toml":
            return list(tomllib.loads(text))
        if path.suffix == ".ipynb":
            from lagrade.answer.reading.notebook import notebook_source

            text = notebook_source(text).source
        tree = ast.parse(text)
    except (OSError, ValueError, SyntaxError):
        return []
    out: list[str] = []
    for node in tree.body:
        targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(
            node, (ast.AnnAssign, ast.AugAssign)) else []
        for target in targets:
            for leaf in ast.walk(target):
                if isinstance(leaf, ast.Name) and leaf.id not in out:
                    out.append(leaf.id)
    return out


def _bind_values(out: LoadedAnswer, raw: dict, problems: list, path: Path, problem: Problem,
                 names: dict[str, str]) -> LoadedAnswer:
    out.problems = problems
    shared = {p.version_of for p in problem.parts if p.version_of is not None}
    for name, value in raw.items():
        if name in names:
            part = names[name]
            if _is_own_symbol(value, name) or is_sympys_own(value, name):
                continue  # ``lam = symbols("lam")``, sympy's ``Q``: not an answer to the part
            reason = refusal(value, problem.part(part).kind)
            if reason is not None:
                refused = AnswerProblem(file=path.name, line=None, message=f"{name}: {reason}")
                out.problems.append(refused)
                out.part_problems.setdefault(part, refused)
                continue
            if name not in shared:
                if part in out.values and out.bound_as.get(part, name) != name:
                    # two names of one part (an alias and the name, 12.30's lam and N): the part's own name
                    # wins, as a version's own name wins over the shared one; else the first bound
                    graded, ignored = (name, out.bound_as[part]) if name == part else (out.bound_as[part], name)
                    out.problems.append(AnswerProblem(
                        file=path.name, line=None, message=f"'{ignored}' and '{graded}' answer the same part "
                        f"{part}: '{graded}' is graded, '{ignored}' ignored"))
                    if name != part:
                        continue
                    out.values[part], out.bound_as[part] = value, name
                    continue
                out.values.setdefault(part, value)
                out.bound_as.setdefault(part, name)
        elif path.suffix == ".toml":
            out.problems.append(AnswerProblem(file=str(path), line=None,
                                              message=f"'{name}' is not a part of problem {problem.id}; ignored"))
    # a two-version question's shared name answers the version it is written in, once the versions'
    # own names are bound (those win)
    for name, value in raw.items():
        if name in shared and not _is_own_symbol(value, name) and not is_sympys_own(value, name):
            target = version_for(problem, name, value, taken=set(out.values))
            if target is not None:
                out.values[target] = value
                out.routed[target] = name
    return out


def version_for(problem: Problem, name: str, value: object, taken: set[str] = frozenset()) -> str | None:
    """The version of the two-version question ``name`` that ``value`` answers: the one whose system's
    coordinates it uses (fewest coordinates of another version's, then fewest of its own left out),
    else the version that has ``name`` as name or alias. None when that version is in ``taken`` (bound by
    a name of its own, which wins): the value is not graded as another version it is not written in."""
    versions = problem.versions(name)
    coords = {p.name: {c.name for c in problem.system(p.system).coordinates} for p in versions}
    every = set().union(*coords.values())
    used = _coordinates_used(value, every)

    def fit(part) -> tuple[int, int, bool]:
        own = coords[part.name]
        return len(used - own), len(own - used), name not in (part.name, *part.aliases)

    best = min(versions, key=fit).name
    return None if best in taken else best


def _coordinates_used(value: object, coords: set[str]) -> set[str]:
    """The coordinates a value is written in: a dict's coordinate keys, else its virtual displacements'
    (delta_q), else every coordinate, momentum (p_q) or velocity it names."""
    if isinstance(value, dict):
        keys = {_base(_name_of(k)) for k in value} & coords
        if keys:
            return keys
    names = {_name_of(n) for n in _names_in(value)}
    deltas = {n[len("delta_"):] for n in names if n.startswith("delta_")} & coords
    if deltas:
        return deltas
    return {_base(n) for n in names} & coords


def _base(name: str) -> str:
    if name.startswith("p_"):
        name = name[2:]
    for suffix in ("_dd", "_d"):
        if name.endswith(suffix):
            return name[: -len(suffix)]
    return name


def _name_of(thing: object) -> str:
    if isinstance(thing, str):
        return thing
    func = getattr(thing, "func", None)
    if getattr(thing, "is_Function", False) and func is not None:
        return getattr(func, "__name__", "")
    return str(getattr(thing, "name", ""))


def _names_in(value: object) -> set:
    """Symbols and applied undefined functions anywhere in a value (dicts, lists, sympy objects)."""
    if isinstance(value, dict):
        return set().union(set(value), *(_names_in(v) for v in value.values()))
    if isinstance(value, (list, tuple, set)):
        return set().union(*(_names_in(v) for v in value))
    try:
        from sympy import Basic
        from sympy.core.function import AppliedUndef
    except ImportError:  # pragma: no cover
        return set()
    if isinstance(value, Basic):
        return set(value.free_symbols) | set(value.atoms(AppliedUndef))
    return set()


def _about_sympys_own(prob: AnswerProblem, names: dict[str, str]) -> bool:
    """A complaint of the sandbox about a part name bound to sympy's own object (``Q`` after
    ``from sympy import *``): not the student's binding, so the part is unanswered, not in error."""
    import sympy

    for name in names:
        own = getattr(sympy, name, None)
        if own is not None and prob.message.startswith(f"'{name}' is a {type(own).__name__},"):
            return True
    return False


def is_sympys_own(value: object, name: str) -> bool:
    """Whether ``value`` is the very object sympy exports under ``name`` (``Q``, the assumptions; ``N``,
    a function), bound by ``from sympy import *``, not by the student: the part is unanswered."""
    import sympy

    own = getattr(sympy, name, None)
    return own is not None and not isinstance(own, (int, float, str, bool)) and (
        value is own or (type(value) is type(own) and _same_object(value, own)))


def _same_object(value: object, own: object) -> bool:
    try:
        return bool(value == own) and type(own).__module__.startswith("sympy")
    except Exception:  # noqa: BLE001 - an unusual value is simply not sympy's
        return False


def _is_own_symbol(value: object, name: str) -> bool:
    return getattr(value, "is_Symbol", False) and getattr(value, "name", None) == name


def _binds(text: str, line: int, name: str) -> bool:
    lines = text.splitlines()
    return 0 < line <= len(lines) and lines[line - 1].split("=", 1)[0].strip() == name


#: what no physical quantity is: refused where an answer is read, since the engine has no number for it
NOT_A_VALUE = {
    "AccumulationBounds": "AccumBounds (a range of limits) is not a value a physical quantity can take",
    "DiracDelta": ("DiracDelta is not a value a physical quantity can take (differentiating Max, Min, Abs, "
                   "sign or Heaviside makes it)"),
    "Order": "an order term O(...) is not a value a physical quantity can take; leave it out",
    "Integral": "an unevaluated Integral cannot be graded; evaluate it (doit()) or write its result",
}
#: what the engine differentiates twice (Lagrange's equations) or once (Hamilton's): no function of
#: the state (of t: coordinates, velocities and momenta are functions of t) whose derivative is a
#: DiracDelta, or is not defined, may be in it (``Abs(eps)`` of a parameter may)
DIFFERENTIATED = ("lagrangian", "hamiltonian")
NOT_SMOOTH = frozenset("Abs sign Heaviside Max Min floor ceiling".split())
#: the kinds whose value may be a Matrix as a whole: a column of equations (`checkers.base.equation_rows`)
EQUATION_LISTS = ("eom", "hamilton_eqs", "reduced")
_TIME = sp.Symbol("t")


def refusal(value: object, kind: str) -> str | None:
    """Why ``value`` cannot be graded as a part of ``kind`` (one sentence), or None: a value no
    physical quantity takes, a function the engine cannot differentiate in what it differentiates,
    or an expression that multiplies out to more terms than the limit, or holds a number with more digits
    than the limit (``lagrade.problem.limits``)."""
    from lagrade.problem.notation import check_expansion, check_numbers, expressions_in

    if isinstance(value, sp.MatrixBase) and kind in EQUATION_LISTS:
        value = list(value)  # a column of equations: the checkers take its rows
    for expr in expressions_in(value):
        for node in sp.preorder_traversal(expr):
            name = type(node).__name__
            if name in NOT_A_VALUE:
                return NOT_A_VALUE[name]
            if isinstance(node, sp.MatrixBase):
                return (f"a Matrix cannot be graded as {kind.replace('_', ' ')}"
                        + ("; give the rows as a list" if kind in EQUATION_LISTS else
                           "; give an expression (or a list or a dict of them, as the problem asks)"))
            if kind in DIFFERENTIATED and name in NOT_SMOOTH and _TIME in node.free_symbols:  # of the state
                return (f"{name} is not differentiable everywhere, and a {kind.capitalize()} is differentiated "
                        f"to give the equations of motion; write it for the case at hand, without {name}")
    try:
        check_numbers(value)
        check_expansion(value)
    except RebuildError as exc:
        return str(exc)
    return None

