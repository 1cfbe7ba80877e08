"""Validate one problem: every check of ``lagrade validate``, and a report of each.

Generated answers are trusted sympy objects, so they are graded in this process, but through the
one entry a student's answer reaches after its jail (:func:`lagrade.verdicts.grade.check`: the
readers' refusals, the formulations, the checkers); text and LaTeX forms go through an
``answer.toml``, as a typed answer does.
"""

from __future__ import annotations

import json
import random
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import sympy as sp

from lagrade.uses.validate.forms import _leaves, as_latex, as_text, bounded, right_forms
from lagrade.uses.validate.proofs import proved_equal
from lagrade.uses.validate.slips import wrong_answers
from lagrade.uses.validate.states import to_answer_form

#: kinds whose reference this module derives from the scene or the part's `reference`
DERIVED = ("lagrangian", "eom", "hamiltonian", "hamilton_eqs", "expression", "expression_set", "equation_root",
           "boolean", "integer", "names", "conserved")


@dataclass
class Case:
    """One check: what it is, whether it holds, and why not."""

    check: str      # schema, render, reference, solution, mistake, right, wrong, dropped
    part: str
    label: str
    ok: bool
    verdict: str = ""
    detail: str = ""


@dataclass
class Report:
    """Every check of one problem."""

    problem: str
    title: str = ""
    cases: list[Case] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return all(c.ok for c in self.cases)

    def count(self, check: str, ok: bool | None = None) -> int:
        return sum(1 for c in self.cases if c.check == check and (ok is None or c.ok == ok))

    @property
    def false_accepts(self) -> list[Case]:
        return [c for c in self.cases if c.check == "wrong" and not c.ok]

    @property
    def false_rejects(self) -> list[Case]:
        return [c for c in self.cases if c.check == "right" and not c.ok]

    def summary(self) -> dict:
        return {"problem": self.problem, "title": self.title, "ok": self.ok, "seconds": round(self.seconds, 2),
                "right": self.count("right"), "wrong": self.count("wrong"), "dropped": self.count("dropped"),
                "false_accepts": len(self.false_accepts), "false_rejects": len(self.false_rejects),
                "failed": [asdict(c) for c in self.cases if not c.ok]}

    def as_json(self) -> dict:
        return {**self.summary(), "cases": [asdict(c) for c in self.cases]}


def solution_path(target: str, problem) -> Path | None:
    """The hand-written reference solution of a problem: ``reference_solutions/<id>/answer.py`` (or
    .toml) beside the problem file's folder, or the bundled one for a chapter id."""
    from lagrade.problem.library import reference_dir

    path = Path(target)
    folders = [path.resolve().parent.parent / "reference_solutions"] if path.suffix == ".toml" and path.is_file() \
        else [reference_dir()]
    for folder in folders:
        for name in ("answer.py", "answer.toml"):
            if (folder / problem.id / name).is_file():
                return folder / problem.id / name
    return None


def validate(target: str, problem_dirs: tuple[Path, ...] = (), seed: int = 0, count: int = 8,
             grading_seconds: float = 60.0) -> Report:
    """Every check of one problem (an id or a problem file's path); ``count``: at most this many
    generated right and this many wrong answers per part (a seeded sample when there are more)."""
    from lagrade.problem.library import load_problem
    from lagrade.problem.spec import SpecError

    start = time.monotonic()
    report = Report(problem=target)
    try:
        problem = load_problem(target, problem_dirs)
    except (SpecError, FileNotFoundError, KeyError, OSError) as exc:
        report.cases.append(Case("schema", "", "the file loads: schema and domains", False, detail=_line(exc)))
        report.seconds = time.monotonic() - start
        return report
    report.problem, report.title = problem.id, problem.title
    report.cases.append(Case("schema", "", "the file loads: schema and domains (sampling boxes inside)", True))
    dirs = (Path(target).parent, *problem_dirs) if Path(target).suffix == ".toml" else problem_dirs
    _Validation(problem, report, random.Random(seed), count, grading_seconds, dirs).run(solution_path(target, problem))
    report.seconds = time.monotonic() - start
    return report


def _line(exc: BaseException) -> str:
    text = str(exc).strip() or type(exc).__name__
    return text.splitlines()[0] if len(text.splitlines()) == 1 else " ".join(text.split())[:400]


class _Validation:
    def __init__(self, problem, report: Report, rng: random.Random, count: int, grading_seconds: float,
                 dirs: tuple[Path, ...] = ()):
        self.problem, self.report, self.rng, self.count, self.dirs = problem, report, rng, count, dirs
        self.grading_seconds = grading_seconds
        self.positive = frozenset(p.name for s in problem.systems for p in problem.parameters_of(s.key)
                                  if p.positive)

    def add(self, *args, **kwargs) -> Case:
        case = Case(*args, **kwargs)
        self.report.cases.append(case)
        return case

    # ------------------------------------------------------------------ the checks

    def run(self, solution: Path | None) -> None:
        from lagrade.problem.library import scene_message
        from lagrade.problem.spec import SceneError

        self._render()
        try:
            derived = {part.name: self._derived(part) for part in self.problem.parts}
        except SceneError as exc:  # the file's line that says which scene and field
            self.add("reference", "", "the scene derives", False, detail=_line(ValueError(scene_message(self.problem, exc, self.dirs))))
            return
        solved = self._solution(solution)
        for part in self.problem.parts:
            base = None
            ref = derived[part.name]
            if ref is not None:
                graded = self.grade(part, ref)
                ok = graded.verdict == "correct"
                self.add("reference", part.name, "the reference, derived from the problem file, gets full marks", ok,
                         graded.verdict, "" if ok else f"the reference of {part.name} is not graded correct: "
                         f"{_line_text(graded.feedback)}")
                base = ref if ok else None
            if part.name in solved:
                base = solved[part.name]
            if base is None:
                continue
            self.others = self._other_references(part, ref)
            for step in (self._mistakes, self._right, self._wrong):
                try:
                    step(part, base)
                except Exception as exc:  # noqa: BLE001 (one part's failure is reported, the others go on)
                    self.add("error", part.name, step.__name__.strip("_"), False,
                             detail=f"validate could not finish {part.name}: {type(exc).__name__}: {_line(exc)}")

    def _render(self) -> None:
        from lagrade.problem.describe import show_text, template_text, typing_help

        for label, make, good in (
                ("the statement (lagrade show)", lambda: show_text(self.problem), lambda v: bool(v.strip())),
                ("the answer template (lagrade template)", lambda: template_text(self.problem), lambda v: bool(v.strip())),
                ("the typing help", lambda: typing_help(self.problem), lambda v: isinstance(v, str)),
                ("the figure (lagrade show --figure)", self._figure, lambda v: v[:8] == b"\x89PNG\r\n\x1a\n")):
            try:
                ok, detail = good(make()), ""
            except Exception as exc:  # noqa: BLE001 (reported, not raised: the other checks go on)
                ok, detail = False, f"{type(exc).__name__}: {_line(exc)}"
            self.add("render", "", label, ok, detail=detail if not ok and detail else ("" if ok else "empty"))

    def _figure(self) -> bytes:
        from lagrade.verdicts.figure import draw

        return draw(self.problem, dpi=40)

    def _solution(self, path: Path | None) -> dict[str, object]:
        """The hand-written reference solution, graded: every part full marks. Its values are the
        base of the generated answers (they are in a student's own form)."""
        if path is None:
            self.add("solution", "", "reference solution: none found (reference_solutions/<id>/answer.py); "
                     "generated answers start from the derived reference", True)
            return {}
        from lagrade.answer.reading.load import load_answer
        from lagrade.verdicts import grade

        result = grade.check(self.problem, path, read_as=(), grading_seconds=self.grading_seconds * 4)
        for p in result.parts:
            ok = p.verdict == "correct"
            self.add("solution", p.part, f"the reference solution {path.name} gets full marks", ok, p.verdict,
                     "" if ok else f"the reference solution's {p.part} is graded {p.verdict}: the problem's reference "
                     f"or the solution is wrong ({_line_text(p.feedback)})")
        loaded = load_answer(path, self.problem)
        right = {p.part for p in result.parts if p.verdict == "correct"}
        return {name: v for name, v in loaded.values.items() if name in right}

    # ------------------------------------------------------------------ references

    def mech(self, system: str):
        from lagrade.verdicts.grade import references

        return references(self.problem)[system]

    def _derived(self, part) -> object | None:
        value = self._derive(part)
        general = {f.name for f in self.problem.system(part.system).functions}
        if general and part.kind in ("lagrangian", "eom", "hamiltonian", "hamilton_eqs") and value is not None and not any(
                getattr(getattr(x, "func", None), "__name__", None) in general
                for leaf in _leaves(value) for x in leaf.atoms(sp.core.function.AppliedUndef)):
            return None  # derived with the concrete function: not the general answer the part asks
        return value

    def _derive(self, part) -> object | None:
        """The part's reference as a student would write it, derived from the file (None: this kind,
        or this part, has none to derive here: a motion, a table, conditions, a linearization)."""
        if part.kind not in DERIVED or (part.kind == "eom" and part.linearized):
            return None
        mech = self.mech(part.system)  # a SceneError is the file's: run() reports its line
        names = mech.all_names
        if part.kind == "lagrangian":
            return to_answer_form(mech.L, names) if part.reference is None else self._from_text(part, part.reference)
        if part.kind == "eom" and part.reference is None:
            acc = bounded(lambda: mech.accelerations_symbolic, 20.0)
            return None if acc is None else [
                sp.Eq(to_answer_form(a, names), to_answer_form(v, names)) for a, v in zip(mech.s.qdd, acc)]
        if part.kind == "hamiltonian" and part.reference is None:
            H = bounded(lambda: mech.hamiltonian_symbolic, 20.0)
            return None if H is None else to_answer_form(H, names)
        if part.kind == "hamilton_eqs" and part.reference is None:
            if any(sp.sympify(q) != 0 for q in mech.Q):
                return None
            H = bounded(lambda: mech.hamiltonian_symbolic, 20.0)
            if H is None:
                return None
            rows = [sp.Eq(qd, sp.diff(H, p)) for qd, p in zip(mech.s.qd, mech.s.p)]
            rows += [sp.Eq(pd, -sp.diff(H, q)) for pd, q in zip(mech.s.pd, mech.s.q)]
            return [to_answer_form(r, names) for r in rows]
        if part.reference is None:
            return None
        return self._from_text(part, part.reference)

    def _from_text(self, part, ref, system: str | None = None) -> object:
        """A reference or mistake in the notation of problem files, as an answer's value."""
        if isinstance(ref, bool | int | float) and not isinstance(ref, str):
            return ref if not isinstance(ref, float) else sp.Float(ref)
        if isinstance(ref, dict):
            return {k: self._from_text(part, v, system) for k, v in ref.items()}
        if isinstance(ref, list):
            if part.kind == "names":
                return [str(v) for v in ref]
            return [self._from_text(part, v, system) for v in ref]
        from lagrade.verdicts.checkers.values import _symbolic_reference

        mech = self.mech(part.system if system is None else system)
        extra = [*part.symbols, *(str(m) for m in mech.multipliers), *(str(p) for p in mech.s.p),
                 *(f"delta_{n}" for n in mech.all_names)]
        expr = mech.parse(str(ref), extra)
        derived = set(mech.multipliers) | set(mech.constrained)
        if part.kind not in ("eom",) and expr.free_symbols & (derived | set(mech.s.qdd)):
            expr = _symbolic_reference(expr, mech, 60.0)
        return to_answer_form(expr, mech.all_names)

    # ------------------------------------------------------------------ grading

    def grade(self, part, value, bound: str | None = None):
        """``value`` graded as ``part`` (bound to ``bound``: an alias may choose a formulation) by the
        entry a student's values reach."""
        from lagrade.verdicts import grade

        try:
            result = grade.check(self.problem, only=[part.name], read_as=(), grading_seconds=self.grading_seconds,
                                 **{bound or part.name: value})
        except TypeError as exc:  # the value is refused before grading (a kind's reading)
            from lagrade.verdicts.result import PartResult

            return PartResult(part=part.name, verdict="invalid", score=0.0, max_score=part.weight, method="exact",
                              feedback=str(exc))
        return result.parts[0]

    def grade_text(self, part, text: object):
        """``text`` (a str, a list or a table of them) as an answer.toml's value for ``part``."""
        from lagrade.verdicts import grade

        with tempfile.TemporaryDirectory(prefix="lagrade-validate-") as folder:
            path = Path(folder) / "answer.toml"
            path.write_text(f"{part.name} = {_toml(text)}\n", encoding="utf-8")
            result = grade.check(self.problem, path, only=[part.name], read_as=(),
                                 grading_seconds=self.grading_seconds)
        return result.parts[0]

    # ------------------------------------------------------------------ generated and named answers

    def _mistakes(self, part, base) -> None:
        lists = [(part.system, part.mistakes, "", part.name)]
        lists += [(alt.system or part.system, alt.mistakes, " (an alternative's)", alt.name or part.name)
                  for alt in part.alternatives]
        all_messages = [m.message for _, ms, _, _ in lists for m in ms]
        for system, mistakes, whose, bound in lists:
            for k, mistake in enumerate(mistakes):
                label = f"mistake {k + 1}{whose}: {_short(mistake.answer)}"
                try:
                    value = self._from_text(part, mistake.answer, system)
                except Exception as exc:  # noqa: BLE001 (a mistake that cannot be read is the file's fault)
                    self.add("mistake", part.name, label, False, detail=f"cannot be read: {_line(exc)}")
                    continue
                proof = proved_equal(part.kind, value, base, self.positive, self._mech_or_none(part)) \
                    if system == part.system else None
                graded = self.grade(part, value, bound)
                others = [m for m in all_messages if m != mistake.message and m in graded.feedback]
                problems = []
                if proof is not None:
                    problems.append(f"the mistake equals the reference ({proof})")
                if graded.verdict == "correct":
                    problems.append("it gets full marks")
                if mistake.message not in graded.feedback:
                    problems.append("its message is not in the feedback")
                if others:
                    problems.append("another mistake's message is in the feedback")
                self.add("mistake", part.name, label, not problems, graded.verdict,
                         f"mistake {k + 1}{whose} of {part.name}: " + "; ".join(problems) if problems else "")

    def _other_references(self, part, derived) -> list[tuple[object, str]]:
        """Values besides the base that are right too: the derived reference, each alternative's
        reference (another formulation, another reading), and, for a system with a general function whose
        special case earns full marks, the reference with the function 0 or its concrete form."""
        out = [(derived, "the derived reference")] if derived is not None else []
        for k, alt in enumerate(part.alternatives):
            if alt.reference is not None and not alt.gauge:
                try:
                    out.append((self._from_text(part, alt.reference, alt.system), f"alternative {k + 1}'s reference"))
                except Exception:  # noqa: BLE001
                    pass
        return out

    def _special_cases(self, part, value) -> list[tuple[object, str]]:
        """``value`` with each general function of the part's system that earns full marks when
        answered for a special case (`special_case = "full"`) put to 0 and to its concrete form."""
        out = []
        try:
            system = self.problem.system(part.system)
        except KeyError:
            return out
        for f in system.functions:
            if f.special_case != "full":
                continue
            mech = self.mech(part.system)
            concrete = mech.parse(f.concrete)
            dummies = [sp.Dummy(a) for a in f.args]
            body = concrete.xreplace({sp.Symbol(a): d for a, d in zip(f.args, dummies)})
            for what, put in (("0", lambda *a: sp.Integer(0)), (f.concrete, sp.Lambda(tuple(dummies), body))):
                try:
                    out.append((_put_function(value, f.name, put), f"right for {f.name} = {what} (special_case = full)"))
                except Exception:  # noqa: BLE001
                    pass
        return out

    def _proof(self, part, value, base) -> str | None:
        """A proof that ``value`` is right for the part: equal to the base, or to another right value."""
        mech = self._mech_or_none(part) if part.kind == "lagrangian" else None
        proof = proved_equal(part.kind, value, base, self.positive, mech)
        if proof is not None:
            return proof
        for other, what in [*getattr(self, "others", []), *self._special_cases(part, base)]:
            proof = proved_equal(part.kind, value, other, self.positive, mech)
            if proof is not None:
                return f"{what}: {proof}"
        if part.kind == "hamiltonian" and any(alt.gauge for alt in part.alternatives):
            from lagrade.uses.validate.proofs import same_motion

            proof = same_motion(value, base, self.mech(part.system), self.positive)
            if proof is not None:
                return f"the part's gauge alternative: {proof}"
        return None

    def _mech_or_none(self, part):
        try:
            return self.mech(part.system)
        except Exception:  # noqa: BLE001
            return None

    def _sample(self, items: list) -> list:
        return items if len(items) <= self.count else self.rng.sample(items, self.count)

    def _right(self, part, base) -> None:
        params = [p.name for p in self.problem.parameters_of(part.system)]
        try:
            intervals = {str(sym): d.interval for sym, d in self.problem.domains(part.system, part.name).items()}
        except Exception:  # noqa: BLE001 (no domains: no half-angle forms)
            intervals = {}
        forms = right_forms(part.kind, base, params, intervals=intervals)
        typed = []
        text = as_text(base) if part.kind in ("lagrangian", "eom", "hamiltonian", "hamilton_eqs", "expression",
                                              "expression_set", "equation_root") else None
        if text is not None:
            typed.append(("as text (answer.toml)", text))
        # not in LaTeX where the value calls a general function (V(x)): its echo, V{\left(x \right)}, does
        # not read back (a limit of the LaTeX reader, docs/answers.md), and the text form covers it
        general = {f.name for s in self.problem.systems for f in s.functions}
        calls = any(getattr(getattr(x, "func", None), "__name__", None) in general
                    for leaf in _leaves(base) for x in leaf.atoms(sp.core.function.AppliedUndef))
        latex = as_latex(base) if text is not None and not calls else None
        if latex is not None:
            typed.append(("as LaTeX (answer.toml)", latex))
        chosen = self._sample(forms)
        for label, value in chosen:
            graded = self.grade(part, value)
            self.add("right", part.name, label, graded.verdict == "correct", graded.verdict,
                     "" if graded.verdict == "correct" else f"{part.name} {label}: graded {graded.verdict}: "
                     f"{_line_text(graded.feedback)} [value: {_short(value, 300)}]")
        for label, text_value in typed:
            graded = self.grade_text(part, text_value)
            self.add("right", part.name, label, graded.verdict == "correct", graded.verdict,
                     "" if graded.verdict == "correct" else f"{part.name} {label}: graded {graded.verdict}: "
                     f"{_line_text(graded.feedback)} [text: {_short(text_value, 300)}]")

    def _wrong(self, part, base) -> None:
        params = [p.name for p in self.problem.parameters_of(part.system)]
        slips = wrong_answers(part.kind, base, params)
        kept = 0
        for label, value in self.rng.sample(slips, len(slips)):
            if kept >= self.count:
                break
            proof = self._proof(part, value, base)
            if proof is not None:
                self.add("dropped", part.name, label, True, detail=f"proved right: {proof}")
                continue
            kept += 1
            graded = self.grade(part, value)
            refused = graded.verdict != "correct"
            self.add("wrong", part.name, label, refused, graded.verdict,
                     "" if refused else f"{part.name} {label}: a wrong answer gets full marks [value: {_short(value, 300)}]")


def _put_function(value: object, name: str, put) -> object:
    """``value`` with every call of the function ``name`` replaced by ``put`` (a Lambda, or a callable)."""
    if isinstance(value, dict):
        return {k: _put_function(v, name, put) for k, v in value.items()}
    if isinstance(value, list):
        return [_put_function(v, name, put) for v in value]
    if not isinstance(value, sp.Basic):
        return value
    calls = [x for x in value.atoms(sp.core.function.AppliedUndef) if x.func.__name__ == name]
    out = value.replace(lambda x: isinstance(x, sp.core.function.AppliedUndef) and x.func.__name__ == name,
                        lambda x: put(*x.args)) if calls else value
    return out.doit() if calls else out


def _short(value: object, n: int = 60) -> str:
    text = sp.sstr(value) if isinstance(value, sp.Basic) else str(value)
    text = " ".join(text.split())
    return text if len(text) <= n else text[: n - 3] + "..."


def _line_text(text: str) -> str:
    return _short(text, 240)


def _toml(value: object) -> str:
    if isinstance(value, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {_toml(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return json.dumps(str(value))
