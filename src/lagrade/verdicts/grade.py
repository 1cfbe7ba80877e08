"""Grading one answer: every part, each by its checker, into one result.

Nothing a student writes may stop the grading of the other parts: a part that cannot be read is
``invalid`` with the reason, a part not given is ``missing``, and an unexpected failure of the
engine on one part is reported on that part (as a grader error) instead of crashing the run.
"""

from __future__ import annotations

import importlib
import math
import os
import signal
import sys
import threading
import traceback
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

# only what a check needs before the answer's child starts: the engine (checkers, comparison,
# derivation) is imported by `check` while the child runs, so this module loads in sympy's time
from lagrade.answer.jail.screen import AnswerProblem
from lagrade.answer.reading.load import LoadedAnswer, refusal, start_loading
from lagrade.verdicts.credit import Credit
from lagrade.problem.library import SceneFileError, load_problem, scene_message
from lagrade.verdicts.result import CheckResult, PartResult
from lagrade.problem.spec import Problem, SceneError

if TYPE_CHECKING:
    from lagrade.verdicts.checkers import Context
    from lagrade.derive.reference import ReferenceCache
    from lagrade.verdicts.verdict_memo import VerdictMemo

_REFERENCES: dict[int, ReferenceCache] = {}


def references(problem: Problem) -> ReferenceCache:
    """Reference derivations are made once per problem per process, not once per answer, and come
    from the disk cache when an earlier process made them (:mod:`lagrade.derive.cache`)."""
    key = id(problem)
    if key not in _REFERENCES:
        from lagrade.derive import cache
        from lagrade.derive.reference import ReferenceCache

        loaded = cache.load(problem)
        if loaded is not None:
            _FROM_DISK.add(key)
        _REFERENCES[key] = loaded or ReferenceCache(problem)
    return _REFERENCES[key]


#: problems whose references this process loaded from the disk cache (see `keep_references`)
_FROM_DISK: set[int] = set()


def keep_references(problem: Problem, *, update: bool = False) -> bool:
    """Save what this process derived for ``problem`` to the disk cache (if anything is new).

    A check or a class writes an entry only where there was none: it never rewrites one it loaded,
    so an answer, whatever it makes the grader derive (a named mistake's parse, a diagnosis), cannot
    change an existing entry (the red team's poison-cache). ``update``: `lagrade cache build` adds to
    an entry it loaded."""
    from lagrade.derive import cache

    refs = _REFERENCES.get(id(problem))
    if refs is None or (id(problem) in _FROM_DISK and not update):
        return False
    return cache.save(refs)


def _unusable(part, verdict: str, feedback: str, detail: str | None = None) -> PartResult:
    return PartResult(part=part.name, verdict=verdict, score=0.0, max_score=part.weight, method="exact",
                      feedback=feedback, detail=detail)


NOT_GRADED = "not graded: "
"""How the feedback of a part the answer file never reached begins (the file stopped before it)."""

ENGINE_ERROR = ("lagrade could not grade this part: this is an error in lagrade, not a judgement of your "
                "answer; your instructor can see what went wrong")


class GradingOutOfTime(BaseException):
    """Raised by SIGPROF when grading one answer runs out of CPU time; a BaseException so that the
    engine's per-part guards (``except Exception``) do not swallow it."""


def default_grading_seconds() -> float:
    """Bulk grading's default bound (``[limits] grading_seconds``), so a check is bounded alike."""
    from lagrade.problem.limits import GRADING_SECONDS

    return GRADING_SECONDS


def out_of_time(seconds: float) -> str:
    return (f"grading this answer took longer than {seconds:g} s of CPU time "
            f"(the expressions are too large to compare)")


@contextmanager
def cpu_time_bound(seconds: float | None) -> Iterator[None]:
    """Raise :class:`GradingOutOfTime` once the enclosed code has used ``seconds`` of this process's
    CPU time (``ITIMER_PROF``: the engine's own proofs use ``ITIMER_REAL``, and time spent waiting on
    the sandbox child is not the grader's work). Signals reach only the main thread, so elsewhere,
    and for ``None`` or ``math.inf``, nothing is bounded. A timer armed before (a profiler's) is
    paused meanwhile and resumed after.

    The timer keeps firing every :data:`RAISE_AGAIN` s of CPU until the block is left: an exception
    raised inside a gc callback or a ``__del__`` is printed and dropped by Python, and a bare
    ``except:`` in a library swallows it, so one signal alone may not end the grading (CI saw a
    2 s bound run for 570 s that way). A raise Python dropped is raised again at the next call of
    Python code (a one-shot profile hook), since while collections of a large heap take most of
    the time every signal lands in them (a 0.3 s bound once ran 14.6 s in the test suite's heap)."""
    if seconds is not None and not seconds > 0:  # setitimer(0) would mean no bound at all
        raise ValueError(f"grading_seconds must be positive, not {seconds!r}")
    if (seconds is None or math.isinf(seconds) or not hasattr(signal, "setitimer")
            or threading.current_thread() is not threading.main_thread()):
        yield
        return

    state = {"expired": False, "leaving": False}

    def _expired(signum, frame):  # noqa: ARG001
        if not state["leaving"]:
            state["expired"] = True
            raise GradingOutOfTime(out_of_time(seconds))

    hook, profiler = sys.unraisablehook, sys.getprofile()

    def _raise_at_next_call(frame, event, arg) -> None:  # noqa: ARG001
        if frame.f_code is _dropped.__code__:  # the hook's own return
            return
        sys.setprofile(profiler)
        if not state["leaving"]:
            raise GradingOutOfTime(out_of_time(seconds))

    def _dropped(unraisable) -> None:
        # Python dropped a raise (in a gc callback or a __del__). Not reported: formatting its
        # traceback, as the default hook and pytest's do, can take longer than RAISE_AGAIN, so the
        # next raise would land in the report and be dropped too. Raised again at the next call
        # of Python code: a collection of a large heap hands every signal that arrives during it to
        # its callbacks, and the timer's ticks may never fall in the code between collections.
        if not isinstance(unraisable.exc_value, GradingOutOfTime):
            hook(unraisable)
        elif not state["leaving"]:
            sys.setprofile(_raise_at_next_call)

    alarm = signal.getsignal(signal.SIGALRM)
    previous = signal.signal(signal.SIGPROF, _expired)
    sys.unraisablehook = _dropped
    outer = signal.setitimer(signal.ITIMER_PROF, seconds, RAISE_AGAIN)  # a profiler's: paused meanwhile
    try:
        yield
    finally:
        state["leaving"] = True
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)
        if sys.unraisablehook is _dropped:
            sys.unraisablehook = hook
        if sys.getprofile() is _raise_at_next_call:
            sys.setprofile(profiler)
        if state["expired"] and signal.getsignal(signal.SIGALRM) is not alarm:
            signal.setitimer(signal.ITIMER_REAL, 0)  # cut off inside the engine's own time bound,
            signal.signal(signal.SIGALRM, alarm)     # before it could disarm its alarm
        signal.setitimer(signal.ITIMER_PROF, *outer)


RAISE_AGAIN = 0.05
"""CPU seconds between repeated :class:`GradingOutOfTime` raises once the bound is spent."""


def _check(ctx: Context, part, value, gauge: bool = False) -> tuple[PartResult, bool]:
    """The part's grade, and whether it is the value's own (not an error of the engine's). ``gauge``:
    graded as the H of any admissible Lagrangian L + dF(q, t)/dt (`lagrade.verdicts.checkers.gauge`)."""
    from lagrade.verdicts.checkers import CHECKERS, InvalidAnswer
    from lagrade.verdicts.checkers.gauge import GAUGE_CHECKERS

    try:
        return (GAUGE_CHECKERS if gauge else CHECKERS)[part.kind](ctx, part, value), True
    except InvalidAnswer as exc:
        return _unusable(part, "invalid", str(exc)), True
    except SceneError as exc:  # the scene derived before any part: this is the part's own text (its
        # reference, a mistake, its initial values), so the instructor is told which part to fix
        raise SceneError(f"part '{part.name}': {exc}", exc.system, exc.field) from exc
    except Exception:  # noqa: BLE001  (a grader bug must not sink the other parts)
        if os.environ.get("LAGRADE_DEBUG"):
            raise
        # an ``error``, never ``invalid``: the answer was readable. The traceback (whose messages may
        # quote reference expressions) is for instructors only, never in what a student is shown
        return _unusable(part, "error", ENGINE_ERROR, detail=traceback.format_exc(limit=-8)), False


def grade_values(problem: Problem, answer: LoadedAnswer, accuracy: str = "default",
                 only: list[str] | None = None, hints: bool = False, credit: Credit | None = None,
                 read_as: tuple[str, ...] = ("latex", "unicode"), memo: VerdictMemo | None = None,
                 grading_seconds: float | None = None) -> CheckResult:
    """Grade every part; ``read_as`` says which echoes of the answer to render (pretty-printing a
    long expression can cost a tenth of a second, so a caller asks only for what it shows). A process
    that grades many answers passes a ``memo``: a value graded before gets the verdict it got.

    ``grading_seconds`` bounds the CPU time of the whole grading (:func:`cpu_time_bound`): a part
    not graded by then is ``invalid`` with the reason, so a huge expression gets a verdict, not a
    hang. None leaves any bound to the caller (the bulk grader sets its own around loading too)."""
    from lagrade.verdicts.checkers import Context
    from lagrade.compare.trajectory import ACCURACY

    ctx = Context(problem, references(problem), ACCURACY[accuracy], hints=hints, credit=credit or Credit())
    asked = [part for part in problem.parts if not only or part.name in only]
    parts: list[PartResult] = []
    answer, moved = _motions_bound_elsewhere(ctx, answer)
    used = Formulations(ctx, answer)
    try:
        with cpu_time_bound(grading_seconds):
            for part in asked:
                parts.append(_ungradable(part, answer) or used.grade(part, answer.values[part.name], read_as, memo))
    except GradingOutOfTime as exc:
        parts += [_ungradable(part, answer) or _unusable(part, "invalid", str(exc)) for part in asked[len(parts):]]
    for graded_part in parts:  # say where a moved value went, on both parts
        for target, source in moved.items():
            if graded_part.part in (target, source):
                graded_part.feedback = (f"{graded_part.feedback.rstrip()} (Your {source} is a motion at {target}'s "
                                        f"numbers, so it is graded as {target}.)")
    extras = {part.name for part in asked if part.extra}
    for graded_part in parts:
        graded_part.extra = graded_part.part in extras
    counted = [p for p in parts if not p.extra]  # the book's parts: extras are graded and shown, not counted
    return CheckResult(problem=problem.id, score=round(sum(p.score for p in counted), 6),
                       max_score=sum(p.max_score for p in counted), parts=parts,
                       problems=[str(p) for p in answer.problems])


def _motions_bound_elsewhere(ctx, answer: LoadedAnswer) -> tuple[LoadedAnswer, dict[str, str]]:
    """The answer with a motion at a numerical_solution part's numbers, bound to a part that part is
    ``also_answered_by`` (12.41's catalogue name ``solution_b``), graded as that part when it has no
    value of its own; and which moved (part -> the name it was bound to). The caller's answer is kept."""
    from lagrade.verdicts.checkers.numerical import reads_as_motion

    moved: dict[str, str] = {}
    for part in ctx.problem.parts:
        for source in part.also_answered_by:
            if part.name in answer.values or part.name in answer.part_problems or source not in answer.values:
                continue
            if part.name not in moved and reads_as_motion(ctx, part, answer.values[source]):
                moved[part.name] = source
    if not moved:
        return answer, moved
    values = dict(answer.values)
    for target, source in moved.items():
        values[target] = values.pop(source)
    return replace(answer, values=values, routed={**answer.routed, **moved}), moved


def _ungradable(part, answer: LoadedAnswer) -> PartResult | None:
    """The verdict of a part with no usable value (nothing to compare, so nothing to bound)."""
    if part.name in answer.part_problems:
        return _unusable(part, "invalid", str(answer.part_problems[part.name]))
    if part.name not in answer.values:
        if answer.fatal is not None:
            return _unusable(part, "invalid", f"{NOT_GRADED}{answer.fatal}")
        return _unusable(part, "missing", f"not answered: no value for '{part.name}'{_other_version(part, answer)}")
    return None


def _other_version(part, answer: LoadedAnswer) -> str:
    """For a missing version of a two-version question: where the shared name's value went instead, and
    in any case that the problem asks both versions (every two-version id says it alike)."""
    if part.version_of is None:
        return ""
    for graded_as, name in answer.routed.items():
        if name == part.version_of and graded_as != part.name:
            return (f" (your {name} is written in the other version's coordinates and is graded as {graded_as}; "
                    f"the problem asks both versions)")
    return f" (the problem asks both versions of {part.version_of}: this one is {part.name})"


class Formulations:
    """Which formulation each part was graded in, for one answer: a part with ``alternatives`` (the book
    allows either: a frame, a gauge, planar or 3-D coordinates) is right when it is right in any of them;
    a part that ``follows`` another is judged in the formulation the student's answer to that one used
    (H conserved? for the student's own H), or in its primary one when that answer was right in none.

    The choice is made here, above the checkers: each formulation is an ordinary part (another system,
    another reference), so every checker grades it unchanged."""

    #: the formulation of a part right only as the H of another gauge L + dF/dt: no system states
    #: answers for it, so a part following it is judged in the primary formulation
    GAUGE = "<gauge>"

    def __init__(self, ctx: Context, answer: LoadedAnswer) -> None:
        self.ctx, self.answer = ctx, answer
        #: part name -> the system key its answer was right in (None: right in none, or not given)
        self.chosen: dict[str, str | None] = {}
        #: id of a formulation that earns part of the credit only (an approximation) -> (share, formulation)
        self.credit: dict[int, tuple[float, object]] = {}

    def variants(self, part) -> list[tuple[object, str, bool]]:
        """The part as graded in each formulation it may be judged in, primary first, each with the words
        that name it to the student ("" for the primary, when no alternative changes the system) and
        whether it is graded up to a gauge term."""
        forms = [(part, self._words(part.system, "") if any(a.system not in (None, part.system)
                                                             for a in part.alternatives) else "", False)]
        alternatives = part.alternatives
        if any(alt.name is not None for alt in alternatives):  # selected by the name the value is bound to
            bound = self.answer.bound_as.get(part.name, part.name)
            chosen = [alt for alt in alternatives if alt.name == bound]
            if chosen:
                forms, alternatives = [], chosen
            else:
                alternatives = [alt for alt in alternatives if alt.name is None]
        for alt in alternatives:
            system = alt.system if alt.system is not None else part.system
            update = {"system": system, "alternatives": [], "follows": None, "mistakes": alt.mistakes}
            if alt.reference is not None:
                update["reference"] = alt.reference
            if alt.initial is not None:
                update["initial"] = alt.initial
            words = alt.says or ("" if alt.gauge else self._words(system, ""))
            form = part.model_copy(update=update)
            if alt.credit < 1:
                self.credit[id(form)] = (alt.credit, form)  # the form too: its id stays its own while kept
            forms.append((form, words, alt.gauge))
        if part.follows is None:
            return forms
        system = self._chosen(part.follows)
        same = [form for form in forms if system is not None and form[0].system == system and not form[2]]
        return [same[0] if same else forms[0]]

    def _words(self, system: str, says: str) -> str:
        return says or self.ctx.problem.system(system).title

    def _chosen(self, name: str) -> str | None:
        """The formulation of part ``name``, grading it first (silently) if it has not been graded."""
        if name not in self.chosen:
            part = self.ctx.problem.part(name)
            if _ungradable(part, self.answer) is None:
                self.grade(part, self.answer.values[part.name], (), None)
            else:
                self.chosen[name] = None
        return self.chosen[name]

    def grade(self, part, value, read_as: tuple[str, ...], memo: VerdictMemo | None) -> PartResult:
        forms = self.variants(part)
        key = memo.key(self.ctx, part, value) if memo is not None else None
        if key is not None and any(alt.name is not None for alt in part.alternatives):
            key = (key, self.answer.bound_as.get(part.name, part.name))  # the name chooses the formulation
        if key is not None and part.follows is not None:
            key = (key, self.chosen.get(part.follows))  # the verdict depends on that choice too
        graded_part = memo.get(key) if key is not None else None
        if graded_part is not None:  # a memoized verdict carries the formulation it was right in
            self.chosen[part.name] = graded_part._formulation
            return _echo(graded_part, value, read_as)
        graded_part, own, system = self._fresh(part, forms, value)
        self.chosen[part.name] = graded_part._formulation = system
        if key is not None and own:
            memo.put(key, graded_part)
        return _echo(graded_part, value, read_as)

    def _fresh(self, part, forms, value) -> tuple[PartResult, bool, str | None]:
        """Grade in the formulations; a following part whose leader matched none (or only up to a gauge
        term) is judged in the primary one, and told why."""
        theirs = self.chosen.get(part.follows) if part.follows is not None else None
        if part.follows is None or theirs not in (None, self.GAUGE):
            return self._first_right(forms, value, part.follows)
        graded_part, own, system = self._first_right([(form, "", gauge) for form, _, gauge in forms], value, None)
        graded_part.feedback += (
            f" It is judged in the problem's stated formulation: your {part.follows} comes from another admissible "
            f"Lagrangian (a gauge term dF(q, t)/dt), for which the problem states no answer." if theirs == self.GAUGE
            else f" It is judged in the problem's stated formulation, since your {part.follows} is missing or right "
                 f"in none the problem accepts.")
        return graded_part, own, system

    def _first_right(self, forms, value, follows: str | None) -> tuple[PartResult, bool, str | None]:
        """The verdict in the first formulation the value is right in; else the first it is right in for
        a special case of a general function only (partial, and the formulation a following part is
        judged in); else the primary's, or, when the primary cannot even read it (names of another
        formulation), the first formulation that can."""
        fallback, own_all, approximate, special = None, True, None, None
        for form, words, gauge in forms:
            graded_part, own = _check(self.ctx, form, value, gauge)
            own_all = own_all and own
            if graded_part._special_case:  # right for a special case in this formulation: keep looking for a
                special = special or (graded_part, form.system)  # fully right one, else it is the formulation
                continue
            share = self.credit.get(id(form), (1.0, None))[0]
            if graded_part.verdict == "correct" and share < 1:  # right only as an approximation: a share
                if approximate is None:
                    approximate = _approximation(graded_part, share, words)
                continue
            if words and follows:  # one formulation, the followed part's: say which, right or wrong
                graded_part.feedback += f" Judged for the formulation of your {follows}: {words}."
            elif words and graded_part.verdict == "correct":
                graded_part.feedback += f" You used this formulation: {words}."
            if graded_part.verdict == "correct":
                return graded_part, own_all, self.GAUGE if gauge else form.system
            if approximate is not None:
                continue
            if fallback is None or (fallback.verdict == "invalid" and graded_part.verdict != "invalid"):
                if fallback is not None and words:
                    graded_part.feedback += f" (Read in this formulation: {words}.)"
                fallback = graded_part
        if special is not None:
            return special[0], own_all, special[1]
        return approximate or fallback, own_all, None


def _approximation(graded_part: PartResult, share: float, words: str) -> PartResult:
    """Right only under an approximation the question does not make: that share, and why not all."""
    out = graded_part.model_copy()
    out.verdict, out.score, out.method = "partial", round(out.max_score * share, 6), graded_part.method
    out.feedback = f"Partly right: your answer is right for {words}, an approximation the question does not make."
    return out


def _echo(graded_part: PartResult, value, read_as: tuple[str, ...]) -> PartResult:
    from lagrade.verdicts.readback import as_latex, as_unicode

    if "latex" in read_as:
        graded_part.read_as = as_latex(value)
    if "unicode" in read_as:
        graded_part.read_as_text = as_unicode(value)
    return graded_part


#: what grading imports, loaded by `check` while an answer's child runs rather than before it starts
ENGINE = ("lagrade.verdicts.checkers", "lagrade.verdicts.checkers.gauge", "lagrade.compare.trajectory", "lagrade.verdicts.readback")


class UnknownPartError(TypeError):
    """A check asked for a part the problem does not have (a value given for it, or ``only``)."""


def check(problem: str | Path | Problem, answer: str | Path | None = None, *, problem_dirs: tuple[Path, ...] = (),
          accuracy: str = "default", only: list[str] | None = None, hints: bool = False, credit: Credit | None = None,
          read_as: tuple[str, ...] = ("latex", "unicode"), grading_seconds: float | None = None, limits=None,
          meanwhile: Callable[[], object] | None = None, **parts: object) -> CheckResult:
    """Grade an answer file, or parts given directly as sympy objects (``check("12.43", H=...)``):
    the one way a single answer is graded, for ``lagrade check`` and the Python API alike.

    ``problem`` is an id (looked up in ``problem_dirs`` first), a problem file's path or a
    :class:`Problem`. The start is staged for speed: an ``answer.py`` runs in its jailed child while
    this process imports the engine, derives (or loads) the references and runs ``meanwhile`` (the
    caller's own warm-up, such as the imports of what shows the result); docs/performance.md.

    Grading is bounded like bulk grading's: ``grading_seconds`` of CPU time (default
    :func:`default_grading_seconds`, ``math.inf`` for none; only on the main thread).

    Raises :class:`lagrade.problem.spec.SpecError` for a problem that cannot be loaded,
    :class:`lagrade.problem.library.SceneFileError` (a SpecError too) for one whose scene cannot be derived,
    with the one line ``FILE:LINE: ...`` naming where, and :class:`UnknownPartError` for a part the
    problem does not have. An unusable answer file is not an error: its parts are invalid, with why
    (:func:`unusable`)."""
    path = Path(answer) if answer is not None else None
    if path is not None and path.suffix in (".py", ".ipynb"):
        from lagrade.answer.jail import zygote

        zygote.current()  # started by the console script already (lagrade.__main__), or now: it imports sympy
    dirs = tuple(Path(d) for d in problem_dirs)
    if isinstance(problem, Problem):
        prob = problem
    else:
        prob = load_problem(problem, dirs)
        if Path(problem).suffix == ".toml" and Path(problem).is_file():
            dirs = (Path(problem).parent, *dirs)  # where a scene error is told to be
    unknown = [name for name in only or () if name not in {part.name for part in prob.parts}]
    if unknown:
        raise UnknownPartError(f"problem {prob.id} has no part {', '.join(unknown)}")
    given, routed, bound_as = {}, {}, {}
    for name, value in parts.items():
        try:
            part_name = prob.part(name).name
        except KeyError:
            raise UnknownPartError(f"problem {prob.id} has no part '{name}'") from None
        if not prob.versions(name):
            if part_name in given:
                raise TypeError(f"'{bound_as[part_name]}' and '{name}' answer the same part {part_name}: "
                                f"give one of them")
            given[part_name], bound_as[part_name] = value, name
    for name, value in parts.items():  # a two-version question's shared name: the version it is written in
        if prob.versions(name):
            from lagrade.answer.reading.load import version_for

            target = version_for(prob, name, value, taken=set(given))
            if target is not None:
                given[target], routed[target] = value, name
    if grading_seconds is None:
        grading_seconds = default_grading_seconds()
    # this process's own work on the answer (its text parsed, its child's values rebuilt) is bounded as grading is
    finish = start_loading(path, prob, limits, bound=lambda: cpu_time_bound(grading_seconds)) if path is not None \
        else LoadedAnswer
    try:  # meanwhile, on the other core: the engine and the references
        for module in ENGINE:
            importlib.import_module(module)
        refs = references(prob)
        for system in prob.systems:
            refs[system.key]
        if meanwhile is not None:
            meanwhile()
    except SceneError as exc:  # the problem file's fault, not the answer's: its file and line
        finish()  # the child is collected, not left behind
        raise SceneFileError(scene_message(prob, exc, dirs), exc.system, exc.field) from exc
    except BaseException:
        finish()  # any other failure (or an interrupt) still collects the child and closes its pipes
        raise
    try:
        loaded = finish()
    except GradingOutOfTime:  # the reading, like the grading, within the CPU bound: then every part is invalid
        stopped = AnswerProblem(file=path.name, line=None, message=f"reading this answer took longer than "
                                f"{grading_seconds:g} s of CPU time (the expressions are too large)")
        loaded = LoadedAnswer(problems=[stopped], fatal=stopped)
    for name, value in given.items():
        reason = refusal(value, prob.part(name).kind)
        if reason is None:
            loaded.values[name] = value
        else:
            loaded.part_problems[name] = AnswerProblem(file=name, line=None, message=reason)
    loaded.routed.update(routed)
    loaded.bound_as.update(bound_as)
    try:
        return grade_values(prob, loaded, accuracy, only, hints=hints, credit=credit, read_as=read_as,
                            grading_seconds=grading_seconds)
    except SceneError as exc:
        raise SceneFileError(scene_message(prob, exc, dirs), exc.system, exc.field) from exc


def unusable(result: CheckResult) -> bool:
    """Whether the answer file gave nothing to grade (it did not run, or not to any part): every part
    is invalid for the file's own reason, at least one because the file stopped. What the result
    carries says so; ``lagrade check`` exits with 2 then."""
    own = set(result.problems)
    return (any(p.feedback.startswith(NOT_GRADED) for p in result.parts)
            and all(p.verdict == "invalid" and (p.feedback.startswith(NOT_GRADED) or p.feedback in own)
                    for p in result.parts))
