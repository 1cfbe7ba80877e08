"""Plain-text answers (``answer.toml``) for students who do not write Python.

Each value is read in the notation of problem files (:mod:`lagrade.problem.notation`: ``q_d``, ``q_dd``, ``^``,
``==``; nothing is evaluated), and a bad part is a problem for the student while the others load.

In ``answer.toml`` a string value (or list item, or dict value) is read as **LaTeX** instead when
it contains a control sequence (a backslash followed by a letter: ``\\frac``, ``\\dot``,
``\\theta``...) or is wrapped in ``$...$``; see ``lagrade.answer.reading.latex`` (``\\dot``, ``\\ddot`` and
primes are time derivatives, ``=`` makes an equation, ``,`` separates the items of a list).
Plain text never contains a backslash, so nothing written for ``parse_math`` changes meaning.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import sympy as sp

from lagrade.answer.jail.screen import AnswerProblem
from lagrade.problem.limits import MAX_LATEX_FILE_CHARS, MAX_TOML_BYTES, MAX_TOML_DEPTH
from lagrade.problem.notation import YES_NO, TextAnswerError, parse_math  # noqa: F401  (re-exported: answers read with it)


def load_toml_answer(path: Path, coordinates: Sequence[str], known_names: Iterable[str] | None,
                     functions: Mapping[str, int] | None = None) -> tuple[dict[str, object], list[AnswerProblem]]:
    """Read ``answer.toml``: every key is a part; a bad part is a problem, the others still load.
    ``functions``: the general functions of the problem (``V`` -> 1 argument) answers may call."""
    path = Path(path)
    fname = path.name
    known = None if known_names is None else list(known_names)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        return {}, [AnswerProblem(file=fname, line=None, message=f"cannot read the file: {exc}")]
    if len(text) > MAX_TOML_BYTES:
        return {}, [AnswerProblem(file=fname, line=None,
                                  message=f"the file is larger than {MAX_TOML_BYTES // 1000} kB")]
    too_deep = [AnswerProblem(file=fname, line=None,
                              message=f"arrays or tables nested more than {MAX_TOML_DEPTH} levels deep; "
                                      f"an answer needs 2 (a list or a table in the file)")]
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        m = re.search(r"line (\d+)", str(exc))
        return {}, [AnswerProblem(file=fname, line=int(m.group(1)) if m else None,
                                  message=f"not valid TOML: {exc}")]
    except RecursionError:  # Python's TOML parser recurses once a level: far beyond MAX_TOML_DEPTH
        return {}, too_deep
    if _depth(data) > MAX_TOML_DEPTH:
        return {}, too_deep
    latex_chars = sum(len(v) for v in _strings(data) if _looks_latex(v))
    if latex_chars > MAX_LATEX_CHARS:  # sympy's LaTeX parser takes about 2 ms per character
        return {}, [AnswerProblem(file=fname, line=None,
                                  message=f"{latex_chars} characters of LaTeX; at most {MAX_LATEX_CHARS} per file")]
    lines = text.splitlines()
    values: dict[str, object] = {}
    problems: list[AnswerProblem] = []
    for key, raw in data.items():
        line = _key_line(lines, key)
        try:
            values[key] = _toml_value(raw, coordinates, known, key, lines, line, functions)
        except TextAnswerError as exc:
            where, message = exc.args if len(exc.args) == 2 else (line, str(exc))
            problems.append(AnswerProblem(file=fname, line=where, message=f"{key}: {message}"))
    return values, problems


MAX_LATEX_CHARS = MAX_LATEX_FILE_CHARS  # the name this module has always given it


def _depth(raw: Any) -> int:
    """Levels of arrays and tables in a parsed TOML document (the document itself is one), counted
    to one past ``MAX_TOML_DEPTH`` at most."""
    level, layer = 0, [raw]
    while level <= MAX_TOML_DEPTH:
        containers = [v for v in layer if isinstance(v, (list, dict))]
        if not containers:
            break
        level += 1
        layer = [item for v in containers for item in (v.values() if isinstance(v, dict) else v)]
    return level


def _strings(raw: Any):
    if isinstance(raw, str):
        yield raw
    elif isinstance(raw, list):
        for item in raw:
            yield from _strings(item)
    elif isinstance(raw, dict):
        for item in raw.values():
            yield from _strings(item)


def _looks_latex(text: str) -> bool:
    from lagrade.answer.reading.latex import is_latex

    return is_latex(text)


def _parse_text(text: str, coordinates: Sequence[str], known: list[str] | None,
                functions: Mapping[str, int] | None = None) -> Any:
    """One TOML string: LaTeX (a ``\\command`` or ``$...$``) or plain text. Text that is not well
    formed as plain text but reads as LaTeX is LaTeX (``x_0 + v_{x0} t``, with no backslash)."""
    from lagrade.answer.reading.latex import is_latex, parse_latex_answer

    if is_latex(text):
        return parse_latex_answer(text, coordinates, known, functions)
    try:
        return parse_math(text, coordinates, known, functions)
    except TextAnswerError as plain:
        if "not well formed" not in str(plain):
            raise
        try:
            return parse_latex_answer(text, coordinates, known, functions)
        except TextAnswerError:
            raise plain from None


def _toml_value(raw: Any, coordinates: Sequence[str], known: list[str] | None,
                key: str, lines: list[str], line: int | None, functions: Mapping[str, int] | None = None) -> object:
    if isinstance(raw, bool) or isinstance(raw, int):
        return raw
    if isinstance(raw, float):
        return sp.Float(repr(raw))
    if isinstance(raw, str):
        if raw.strip().lower() in YES_NO and raw.strip() not in (known or ()):
            return YES_NO[raw.strip().lower()]
        return _parse_text(raw, coordinates, known, functions)
    if isinstance(raw, list):
        out = []
        for i, item in enumerate(raw):
            if not isinstance(item, str):
                raise TextAnswerError(f"item {i + 1} of the list should be a string formula")
            try:
                out.append(_parse_text(item, coordinates, known, functions))
            except TextAnswerError as exc:
                raise TextAnswerError(line, f"item {i + 1}: {exc}") from None
        return out
    if isinstance(raw, dict):
        out_d: dict[str, object] = {}
        for sub, item in raw.items():
            sub_line = _key_line(lines, sub, start=(line or 1) - 1) or line
            if isinstance(item, bool) or isinstance(item, int):
                out_d[sub] = item
                continue
            if not isinstance(item, str):
                raise TextAnswerError(sub_line, f"{sub} should be a string formula")
            try:
                out_d[sub] = _parse_text(item, coordinates, known, functions)
            except TextAnswerError as exc:
                raise TextAnswerError(sub_line, f"{sub}: {exc}") from None
        return out_d
    raise TextAnswerError(f"unsupported value of type {type(raw).__name__}")




def _key_line(lines: list[str], key: str, start: int = 0) -> int | None:
    """1-based line where ``key = ...`` (or the table ``[key]``) is written, for error messages."""
    k = re.escape(key)
    assign = re.compile(rf"""^\s*(?:{k}|"{k}"|'{k}')\s*=""")
    table = re.compile(rf"""^\s*\[\s*(?:{k}|"{k}"|'{k}')\s*\]""")
    for pattern in (assign, table):
        for i in range(max(start, 0), len(lines)):
            if pattern.match(lines[i]):
                return i + 1
    return None
