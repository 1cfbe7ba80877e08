"""Answers as the server receives them: JSON values become ``answer.toml`` text, and the preview.

A JSON answer (``{"L": "...", "eom": ["...", "..."], "a": {"m1": "..."}}``) is written as the
``answer.toml`` a student could have uploaded, canonically (sorted keys), so that it is graded by
the same path and the same content is the same attempt. Nothing here runs student code: text is
parsed by :mod:`lagrade.answer.reading.text` (``ast``, no eval); an ``answer.py`` only ever runs in the jail.
"""

from __future__ import annotations

import json
import tempfile
import tomllib
from pathlib import Path

from pydantic import BaseModel, ConfigDict, Field

Scalar = bool | int | str
Value = bool | int | str | list[str] | dict[str, Scalar]


class AnswerIn(BaseModel):
    """The JSON body of ``POST /api/v1/problems/{id}/check``."""

    model_config = ConfigDict(extra="forbid")

    answer: dict[str, Value] = Field(min_length=1, max_length=50)


class PreviewIn(BaseModel):
    model_config = ConfigDict(extra="forbid")

    part: str = Field(max_length=100)
    #: what the part's field holds: a string, a list of strings (equations), a dict (keyed values)
    value: Value


class AnswerTextError(ValueError):
    pass


def _sorted(v):
    return {k: _sorted(x) for k, x in sorted(v.items())} if isinstance(v, dict) else v


def to_toml(answer: dict) -> bytes:
    """``answer.toml`` text holding exactly these values, written by tomli-w with sorted keys (the
    same content, the same bytes), and checked by reading it back."""
    import tomli_w

    try:
        json.dumps(answer, ensure_ascii=False).encode("utf-8")
    except UnicodeEncodeError:
        raise AnswerTextError("a value holds an unpaired surrogate; send UTF-8 text") from None
    text = tomli_w.dumps(_sorted(answer))
    if tomllib.loads(text) != answer:  # pragma: no cover  (a guard: what is graded is what was sent)
        raise AnswerTextError("the answer could not be written as answer.toml")
    return text.encode("utf-8")


def preview(problem, part: str, value) -> dict:
    """How the grader will read ``value`` as ``part``: sympy text and presentation MathML, or the
    one-line error ``answer.toml`` would give. Parsed exactly as that answer.toml line would be."""
    from lagrade.answer.reading.load import load_answer
    from lagrade.uses.bulk.display import show

    names = {p.name for p in problem.parts}
    if part not in names:
        return {"part": part, "error": f"problem {problem.id} has no part '{part}' (its parts: {', '.join(sorted(names))})"}
    if len(json.dumps(value)) > MAX_PREVIEW_CHARS:
        return {"part": part, "error": f"longer than {MAX_PREVIEW_CHARS} characters; no preview (a check still reads it)"}
    from lagrade.answer.reading.latex import is_latex

    latex = sum(len(t) for t in _texts(value) if is_latex(t))
    if latex > MAX_PREVIEW_LATEX:
        return {"part": part, "error": f"{latex} characters of LaTeX; the preview reads at most {MAX_PREVIEW_LATEX} "
                                       "(a check reads up to 8000)"}
    with tempfile.TemporaryDirectory(prefix="lagrade-preview-") as tmp:
        path = Path(tmp) / "answer.toml"
        try:
            path.write_bytes(to_toml({part: value}))
        except AnswerTextError as exc:
            return {"part": part, "error": str(exc)}
        loaded = load_answer(path, problem)
    if part not in loaded.values:
        lines = [p.message for p in loaded.problems]
        return {"part": part, "error": lines[0] if lines else "nothing could be read"}
    shown_text, mathml = show(loaded.values[part])
    return {"part": part, "text": shown_text, "mathml": as_math(mathml), "error": None}


def as_math(mathml: str | None) -> str | None:
    """A ``<math>`` element around the printer's presentation MathML, as the HTML report shows it."""
    if not mathml or mathml.lstrip().startswith("<math"):
        return mathml
    return f'<math display="inline">{mathml}</math>'


#: a preview is parsed (in the preview process, lagrade.uses.server.preview) as often as a student types: bounded so that one
#: preview costs at most about a second (sympy's LaTeX parser takes ~2 ms a character)
MAX_PREVIEW_CHARS = 2000
MAX_PREVIEW_LATEX = 500


def _texts(value):
    if isinstance(value, str):
        yield value
    elif isinstance(value, list):
        yield from (v for v in value if isinstance(v, str))
    elif isinstance(value, dict):
        yield from (v for v in value.values() if isinstance(v, str))
