"""The problem as a student reads it on the course server's page: text with math, not a text dump.

The words of ``lagrade show`` (statement, assumptions, symbols, coordinates, parts) as HTML, their
symbols and formulas (``m1``, ``theta1'``, ``-l1*cos(theta1)``) as presentation MathML: the same
markup the live "read as" preview gives a typed answer (:func:`lagrade.uses.bulk.display.show`), read by
the same reader as answers (:func:`lagrade.problem.notation.parse_math`, no eval). A word that does not
read as math stays a word. "Fig. P12.14" links to the figure drawn from the scene
(:mod:`lagrade.verdicts.figure`). Never a reference value: only what ``lagrade show`` prints.
"""

from __future__ import annotations

import re
from html import escape

from lagrade.problem.describe import domain_text
from lagrade.problem.spec import KINDS, Problem

#: a formula written in the notation of answers: operands joined by * / ^ (** too), + or -
_OPERAND = r"-?(?:\d+(?:\.\d+)?|[A-Za-z]\w*(?:\([^()]*\))?'{0,2})"
_FORMULA = re.compile(rf"(?<![\w']){_OPERAND}(?:\s*(?:\*\*|[*/^+\-]|==?)\s*{_OPERAND})+(?![\w(])")
_WORD = re.compile(r"(?<![\w'])[A-Za-z]\w*'{0,2}(?![\w(])")
_FIG = re.compile(r"\bFig\.\s*P?\d+\.\d+\b")


class _Math:
    """Reads the problem's words as math, each text once."""

    def __init__(self, problem: Problem) -> None:
        self.coords = sorted({c.name for s in problem.systems for c in s.coordinates})
        self.params = sorted({q.name for q in problem.parameters} | {q.name for s in problem.systems
                                                                      for q in s.parameters})
        rates = [f"{c}{suffix}" for c in self.coords for suffix in ("_d", "_dd", "_dot", "dot", "_ddot", "ddot")]
        self.names = {*self.coords, *self.params, *rates}
        self.known = [*self.params, "t"]
        self.cache: dict[str, str | None] = {}

    def mathml(self, text: str) -> str | None:
        if text not in self.cache:
            self.cache[text] = self._read(text)
        return self.cache[text]

    def _read(self, text: str) -> str | None:
        from lagrade.uses.bulk.display import show
        from lagrade.problem.notation import parse_math
        from lagrade.uses.server.answers import as_math

        try:
            value = parse_math(text.replace("==", "=").replace("=", "=="), self.coords, self.known)
            return as_math(show(value)[1])
        except Exception:  # noqa: BLE001  (words that are not math stay words)
            return None

    def is_name(self, word: str) -> bool:
        return word.rstrip("'") in self.names

    def html(self, text: str) -> str:
        """``text`` as HTML: formulas and known names as MathML, the rest escaped."""
        out, at = [], 0
        for m in _FORMULA.finditer(text):
            span = m.group(0)
            if not any(self.is_name(w) for w in _WORD.findall(span)):
                continue
            ml = self.mathml(span)
            if ml is None:
                continue
            out.append(self._words(text[at:m.start()]))
            out.append(ml)
            at = m.end()
        out.append(self._words(text[at:]))
        return "".join(out)

    def _words(self, text: str) -> str:
        out, at = [], 0
        for m in _WORD.finditer(text):
            word = m.group(0)
            ml = self.mathml(word) if self.is_name(word) else None
            if ml is None:
                continue
            out.append(_linked(text[at:m.start()]))
            out.append(ml)
            at = m.end()
        out.append(_linked(text[at:]))
        return "".join(out)


def _linked(text: str) -> str:
    """Escaped text, with the book's figure reference a link to the figure drawn here."""
    out, at = [], 0
    for m in _FIG.finditer(text):
        out.append(escape(text[at:m.start()]))
        out.append(f'<a href="#figure" data-fig-ref>{escape(m.group(0))}</a>')
        at = m.end()
    out.append(escape(text[at:]))
    return "".join(out)


def statement_html(p: Problem) -> str:
    """What ``lagrade show`` says, as HTML with MathML (safe to insert: every text is escaped)."""
    m = _Math(p)
    out = []
    for para in re.split(r"\n\s*\n", p.statement.strip()) if p.statement else []:
        out.append(f"<p>{m.html(' '.join(para.split()))}</p>")
    if p.assumptions:
        out.append("<h3>Assumptions</h3><ul>" + "".join(f"<li>{m.html(a)}</li>" for a in p.assumptions) + "</ul>")
    if p.parameters:
        out.append("<h3>Symbols</h3><ul>" + "".join(
            f"<li>{m.html(q.name)}{': ' + m.html(q.description) if q.description else ''}"
            f"{' (&gt; 0)' if q.positive else ''}</li>"
            for q in p.parameters) + "</ul>")
    for s in p.systems:
        head = f"System ({escape(s.key)}) {escape(s.title)}" if s.key else "Coordinates (functions of t)"
        items = [f"<li>{m.html(c.name)}: {m.html(c.description)}</li>" for c in s.coordinates]
        items += [f"<li>constraint: {m.html(f'{c.coordinate} = {c.value}')}</li>" for c in s.constraints]
        items += [f"<li>{m.html(q.name)}: {m.html(q.description)}</li>" for q in s.parameters]
        items.append(f"<li>domain: {escape(domain_text(p, s.key))}</li>")  # what an answer may rely on
        out.append(f"<h3>{head}</h3><ul>{''.join(items)}</ul>")
    out.append("<h3>Parts</h3><ul>")
    for part in p.parts:
        extra = " <i>(extra: not asked by the book; graded and shown, not counted)</i>" if part.extra else ""
        out.append(f"<li><code>{escape(part.name)}</code>: {m.html(part.prompt or part.kind)} "
                   f"<span class=\"hint\">({escape(KINDS[part.kind].expects)})</span>{extra}</li>")
    out.append("</ul>")
    return "\n".join(out)
