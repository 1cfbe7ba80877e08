"""The one-screen summary after a run: score distribution per problem and the most common mistakes."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

from rich.console import Console, Group
from rich.table import Table

from lagrade.uses.bulk.gradebook import Gradebook
from lagrade.verdicts.printable import plain

BARS = " ▁▂▃▄▅▆▇█"


@dataclass
class ProblemStats:
    problem: str
    submitted: int
    failed: int
    mean: float
    possible: float
    histogram: list[int]          # counts of points in 10 equal bins of [0, possible] (full marks in the last)
    part_success: dict[str, float]  # part -> share of submissions with the part correct


def histogram(values: list[float], possible: float, bins: int = 10) -> list[int]:
    counts = [0] * bins
    for v in values:
        if possible <= 0 or v >= possible:
            i = bins - 1
        else:
            i = min(bins - 1, max(0, int(bins * v / possible)))
        counts[i] += 1
    return counts


def problem_stats(book: Gradebook) -> list[ProblemStats]:
    out = []
    for ap in book.assignment.problems:
        grades = [s.problems[ap.id] for s in book.students if s.problems[ap.id].submitted]
        possible = book.totals.get(ap.id, 0.0)
        values = [g.points for g in grades]
        parts: dict[str, list[bool]] = {}
        for g in grades:
            for p in g.parts:
                parts.setdefault(p["part"], []).append(p["verdict"] == "correct")
        out.append(ProblemStats(ap.id, len(grades), sum(g.outcome == "failed" for g in grades),
                                sum(values) / len(values) if values else 0.0, possible,
                                histogram(values, possible), {k: sum(v) / len(v) for k, v in parts.items()}))
    return out


def common_mistakes(book: Gradebook, n: int = 8) -> list[tuple[str, str, str, int]]:
    """(problem, part, feedback, count): the most frequent non-correct feedback of files that ran.

    Files that could not be graded at all are counted by ``failure_counts`` instead.
    """
    c: Counter = Counter()
    for s in book.students:
        for g in s.problems.values():
            if g.outcome != "graded":
                continue
            for p in g.parts:
                if p["verdict"] != "correct":
                    c[(g.problem, p["part"], _first_line(p["feedback"]))] += 1
    return [(*k, v) for k, v in c.most_common(n)]


def common_wrong_answers(book: Gradebook, n: int = 10) -> list[tuple[str, str, str, str, int]]:
    """(problem, part, answer as text, answer as MathML, count) for the most frequent wrong answers."""
    c: Counter = Counter()
    mathml: dict = {}
    for s in book.students:
        for g in s.problems.values():
            if g.outcome != "graded":
                continue
            for p in g.parts:
                if p["verdict"] != "correct" and p.get("answer_text"):
                    key = (g.problem, p["part"], p["answer_text"])
                    c[key] += 1
                    mathml.setdefault(key, p.get("answer_mathml"))
    return [(*k, mathml[k], v) for k, v in c.most_common(n)]


def _first_line(text: str, limit: int = 110) -> str:
    line = (text or "").strip().splitlines()[0] if (text or "").strip() else ""
    return line if len(line) <= limit else line[: limit - 1] + "…"


def to_review(book: Gradebook) -> list[tuple[str, str, dict]]:
    """(student, problem, part) of every verdict an instructor should look at: the evidence could not
    decide it (``review``), or lagrade itself failed on the answer (``error``, with its traceback)."""
    return [(s.student, g.problem, p) for s in book.students for g in s.problems.values() for p in g.parts
            if p.get("review") or p.get("verdict") == "error"]


def failure_counts(book: Gradebook) -> Counter:
    return Counter(g.status for s in book.students for g in s.problems.values() if g.outcome == "failed")


def render_summary(book: Gradebook, console: Console) -> None:
    """The summary for a terminal: the feedback quotes students, so every cell is printable and plain text."""
    stats = problem_stats(book)
    t = Table(title=plain(f"{book.assignment.name}: {len(book.students)} students"), title_justify="left")
    for col in ("problem", "handed in", "failed", "mean", "distribution 0 → full", "parts correct"):
        t.add_column(col)
    for st in stats:
        peak = max(st.histogram) or 1
        spark = "".join(BARS[round(8 * c / peak)] for c in st.histogram)
        parts = " ".join(f"{k} {100 * v:.0f}%" for k, v in st.part_success.items())
        t.add_row(plain(st.problem), str(st.submitted), str(st.failed), f"{st.mean:.2f}/{st.possible:g}", spark,
                  plain(parts))
    totals = [s.points for s in book.students]
    mean = sum(totals) / len(totals) if totals else 0.0
    m = Table(title="Most common mistakes", title_justify="left")
    for col in ("problem", "part", "feedback", "count"):
        m.add_column(col, overflow="fold")
    for pid, part, feedback, count in common_mistakes(book, 6):
        m.add_row(plain(pid), plain(part), plain(feedback), str(count))
    fails = failure_counts(book)
    lines = [t, f"class mean {mean:.2f} / {book.possible:g}"]
    if fails:
        lines.append(plain("files that could not be graded: " + ", ".join(f"{k} {v}" for k, v in fails.most_common())))
    if book.skipped:
        lines.append(f"{len(book.skipped)} files skipped (see 'lagrade export --format skipped' or the report)")
    lines.append(m)
    console.print(Group(*lines))
