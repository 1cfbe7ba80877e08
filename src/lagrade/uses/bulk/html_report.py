"""The HTML report: a static folder an instructor opens in a browser, nothing to install.

``index.html`` is the class overview (a histogram of total scores, ``totals.png`` with its counts
in the alt text; a histogram per problem, per-part success rates, the most common wrong answers
rendered as math, whose files could not be graded and why, skipped files, every student's points);
``students/<student>.html`` is one feedback page per student with their answers as rendered math
(presentation MathML, which browsers render natively: no script, no network), the feedback of every
part, and the picture of a wrong motion against the true one (``students/<student>-<problem>.png``,
``lagrade check --plot``'s, drawn by ``lagrade grade``). Numbers carry ``data-`` attributes so that
tests can read them back.
"""

from __future__ import annotations

import hashlib
import re
import shutil
from collections import Counter
from html import escape
from pathlib import Path

from lagrade.uses.bulk.assignment import part_points, part_weight
from lagrade.uses.bulk.exports import file_jail, overrides_of, student_feedback
from lagrade.uses.bulk.gradebook import Gradebook, ProblemGrade, StudentGrade
from lagrade.uses.bulk.summary import common_mistakes, common_wrong_answers, failure_counts, problem_stats, to_review

CSS = """
*, *::before, *::after { box-sizing: border-box; }
body { font: 15px/1.45 system-ui, sans-serif; margin: 2em auto; max-width: 70em; padding: 0 1em; color: #222; }
h1, h2, h3 { line-height: 1.2; overflow-wrap: anywhere; }
table { border-collapse: collapse; margin: .5em 0 1.5em; }
th, td { border-bottom: 1px solid #ddd; padding: .3em .6em; text-align: left; vertical-align: top; }
th { background: #f4f4f4; cursor: default; } th.sortable { cursor: pointer; }
.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.correct { color: #166534; } .partial { color: #92400e; } .incorrect, .invalid, .failed { color: #b91c1c; }
.missing { color: #6b7280; } .problems { display: flex; flex-wrap: wrap; gap: 1.5em; }
.card { border: 1px solid #ddd; border-radius: 6px; padding: .8em 1em; min-width: min(20em, 100%); max-width: 100%; }
svg text { font: 11px system-ui, sans-serif; fill: #333; } svg rect.bar { fill: #3b82f6; } svg { max-width: 100%; height: auto; }
pre { background: #f6f8fa; padding: .8em; overflow-x: auto; font-size: 13px; }
math { font-size: 1.1em; } .muted { color: #6b7280; } a { color: #1d4ed8; }
.scroll { overflow-x: auto; max-width: 100%; }
#wrong-answers { width: 100%; table-layout: fixed; } #wrong-answers col.c-problem { width: 5.5em; }
#wrong-answers col.c-part { width: 6em; } #wrong-answers col.c-count { width: 6em; }
td code { overflow-wrap: anywhere; } td { overflow-wrap: anywhere; }
td > .formula { display: block; overflow-x: auto; max-width: 100%; padding-bottom: .2em; }
table.parts { width: 100%; table-layout: fixed; }
table.parts col.c-part { width: 6em; } table.parts col.c-verdict { width: 8em; }
table.parts col.c-points { width: 10em; } table.parts col.c-answer { width: 36%; }
table.parts td.points { white-space: normal; overflow-wrap: anywhere; }
table.parts td.points .weight { display: block; font-size: .85em; }
figure { margin: .5em 0 1.5em; } figure img { max-width: 100%; height: auto; border: 1px solid #eee; }
figcaption { font-size: .9em; color: #444; }
table.parts td.answer > .formula { display: block; overflow-x: auto; max-width: 100%; padding-bottom: .2em; }
table.parts td.feedback { overflow-wrap: anywhere; }
.formula math { display: block; max-width: 100%; padding: .15em 0; }
.formula math > mrow { display: flex; flex-wrap: wrap; align-items: baseline; row-gap: .35em; }
.formula math > mrow > mo { padding: 0 .2em; }
.override { background: #fef9c3; } .why { display: block; font-size: .9em; color: #854d0e; }
.note { border-left: 4px solid #b91c1c; padding: .3em .8em; background: #fef2f2; }
@media (max-width: 700px) {
  body { margin: 1em auto; padding: 0 .6em; font-size: 14px; }
  table.parts, table.parts tbody, table.parts tr, table.parts td { display: block; width: 100%; }
  table.parts colgroup, table.parts thead { display: none; }
  table.parts tr { border: 1px solid #ddd; border-radius: 6px; margin: 0 0 .8em; padding: .3em 0; }
  table.parts td { border: 0; padding: .2em .6em; text-align: left; }
  table.parts td[data-label]::before { content: attr(data-label) ": "; font-weight: 600; color: #444; }
  table.parts td.answer::before { display: block; }
}
"""

# The first script of every page: collects errors so that a headless browser can report them.
ERRORS_JS = """window.__lagradeErrors = [];
window.addEventListener('error', function (e) {
  var t = e.target && e.target !== window ? (e.target.src || e.target.href || e.target.tagName) : e.message;
  window.__lagradeErrors.push(String(t));
}, true);
window.addEventListener('load', function () {
  document.body.setAttribute('data-errors', String(window.__lagradeErrors.length));
  document.body.setAttribute('data-loaded', 'yes');
});"""

SORT_JS = """// Click a column heading of a table with class "sortable" to sort by it.
document.querySelectorAll('table.sortable').forEach(function (table) {
  table.querySelectorAll('th').forEach(function (th, col) {
    th.classList.add('sortable');
    th.addEventListener('click', function () {
      var body = table.tBodies[0], rows = Array.prototype.slice.call(body.rows);
      var dir = th.getAttribute('data-dir') === 'asc' ? -1 : 1;
      th.setAttribute('data-dir', dir === 1 ? 'asc' : 'desc');
      rows.sort(function (a, b) {
        var x = a.cells[col].getAttribute('data-value') || a.cells[col].textContent;
        var y = b.cells[col].getAttribute('data-value') || b.cells[col].textContent;
        var nx = parseFloat(x), ny = parseFloat(y);
        return dir * (isNaN(nx) || isNaN(ny) ? x.localeCompare(y) : nx - ny);
      });
      rows.forEach(function (r) { body.appendChild(r); });
    });
  });
});
// A box that scrolls (a formula wider than its cell) is reachable by keyboard: a tab stop each.
document.querySelectorAll('.formula, .scroll, pre').forEach(function (e) {
  if (e.scrollWidth > e.clientWidth || e.scrollHeight > e.clientHeight) e.setAttribute('tabindex', '0');
});
// How wide the page is laid out: wider than the window means a sideways scroll (a test reads it).
document.body.setAttribute('data-page-width', String(document.documentElement.scrollWidth));
document.body.setAttribute('data-window-width', String(window.innerWidth));
document.body.setAttribute('data-scripts', 'ran');"""


def slug(student: str) -> str:
    s = re.sub(r"[^A-Za-z0-9._-]", "_", student).strip(".") or "student"
    if s != student:
        s += "-" + hashlib.sha1(student.encode()).hexdigest()[:6]
    return s


def _n(x: float) -> str:
    return f"{round(x, 4):g}"


def _page(title: str, body: str, depth: int = 0) -> str:
    up = "../" * depth
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<title>{escape(title)}</title><script>{ERRORS_JS}</script>"
            f"<link rel=\"stylesheet\" href=\"{up}style.css\"></head>\n<body>\n{body}\n"
            f"<script src=\"{up}report.js\"></script></body></html>\n")


def _histogram_svg(counts: list[int], possible: float, pid: str) -> str:
    w, h, pad = 320, 140, 24
    peak = max(counts) or 1
    bw = (w - 2 * pad) / len(counts)
    bars = []
    for i, c in enumerate(counts):
        bh = (h - 2 * pad) * c / peak
        x, y = pad + i * bw, h - pad - bh
        lo, hi = possible * i / len(counts), possible * (i + 1) / len(counts)
        label = f"{_n(lo)}–{_n(hi)}" if i < len(counts) - 1 else f"{_n(lo)}–{_n(possible)} (incl. full marks)"
        bars.append(f"<rect class=\"bar\" x=\"{x + 1:.1f}\" y=\"{y:.1f}\" width=\"{bw - 2:.1f}\" height=\"{bh:.1f}\" "
                    f"data-bin=\"{i}\" data-count=\"{c}\"><title>{escape(label)}: {c}</title></rect>")
        if c:
            bars.append(f"<text x=\"{x + bw / 2:.1f}\" y=\"{y - 3:.1f}\" text-anchor=\"middle\">{c}</text>")
    axis = (f"<line x1=\"{pad}\" y1=\"{h - pad}\" x2=\"{w - pad}\" y2=\"{h - pad}\" stroke=\"#999\"/>"
            f"<text x=\"{pad}\" y=\"{h - 6}\">0</text>"
            f"<text x=\"{w - pad}\" y=\"{h - 6}\" text-anchor=\"end\">{_n(possible)}</text>")
    return (f"<svg class=\"histogram\" data-problem=\"{escape(pid)}\" width=\"{w}\" height=\"{h}\" role=\"img\" "
            f"aria-label=\"points for problem {escape(pid)}\">{''.join(bars)}{axis}</svg>")


def _bins(possible: float, n: int) -> list[tuple[float, float]]:
    return [(possible * i / n, possible * (i + 1) / n) for i in range(n)]


def totals_histogram(book: Gradebook, png: Path, bins: int = 10) -> str:
    """Draw the histogram of the students' total scores into ``png`` (matplotlib) and return its
    ``<figure>``: the counts per bin are in the alt text and in ``data-counts``, for a screen reader
    and for tests (the same bins as the problems' histograms: the last holds full marks)."""
    from lagrade.uses.bulk.summary import histogram

    possible = book.possible
    totals = [s.points for s in book.students]
    counts = histogram(totals, possible, bins)
    edges = _bins(possible, bins)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 2.6))
    width = possible / bins if possible else 1.0
    ax.bar([lo for lo, _ in edges], counts, width=width, align="edge", color="#3b82f6", edgecolor="white")
    ax.set_xlim(0, possible or 1.0)
    ax.set_xlabel(f"total points (of {_n(possible)})")
    ax.set_ylabel("students")
    ax.yaxis.get_major_locator().set_params(integer=True)
    ax.set_title("Total scores", fontsize=10, loc="left")
    fig.tight_layout()
    fig.savefig(png, format="png", dpi=100, metadata={"Software": None})
    plt.close(fig)
    said = [f"{c} {'student' if c == 1 else 'students'} from {_n(lo)} to {_n(hi)}" for (lo, hi), c in zip(edges, counts)
            if c]
    mean = sum(totals) / len(totals) if totals else 0.0
    alt = (f"Histogram of total scores out of {_n(possible)} points, {len(totals)} students, mean {mean:.2f}: "
           + ("; ".join(said) if said else "no students") + " (the last bin includes full marks).")
    return (f"<figure id=\"totals-histogram\" data-counts=\"{','.join(map(str, counts))}\">"
            f"<img src=\"{escape(png.name)}\" alt=\"{escape(alt)}\" width=\"640\" height=\"260\">"
            f"<figcaption>Total scores: students per tenth of the {_n(possible)} points.</figcaption></figure>")


def _failed_files(book: Gradebook) -> str:
    """Whose files could not be graded, which problem, and why (each student linked to their page)."""
    rows = [(s.student, g) for s in book.students for g in s.problems.values() if g.outcome == "failed"]
    if not rows:
        return ""
    counts = failure_counts(book)
    return ("<h2>Files that could not be graded</h2><p class=\"muted\">" +
            ", ".join(f"{escape(k)}: {v}" for k, v in counts.most_common()) + "</p>"
            "<table id=\"failed\"><thead><tr><th>student</th><th>problem</th><th>file</th><th>status</th><th>why</th>"
            "</tr></thead><tbody>" +
            "".join(f"<tr data-student=\"{escape(who)}\" data-problem=\"{escape(g.problem)}\">"
                    f"<td><a href=\"students/{slug(who)}.html\">{escape(who)}</a></td><td>{escape(g.problem)}</td>"
                    f"<td><code>{escape(g.path)}</code></td><td>{escape(g.status)}</td><td>{escape(g.reason)}</td></tr>"
                    for who, g in rows) + "</tbody></table>")


def _math(text: str | None, mathml: str | None) -> str:
    if mathml:
        return f"<math display=\"inline\">{mathml}</math>" if not mathml.lstrip().startswith("<math") else mathml
    if text:
        return f"<code>{escape(text)}</code>"
    return "<span class=\"muted\">—</span>"


def jail_counts(book: Gradebook) -> Counter:
    """Files per sandbox (``jail``) their grader reported. On the class page only: a student's page
    goes to the student, and would tell them which layers were missing."""
    return Counter(j for s in book.students for g in s.problems.values() if (j := file_jail(g)))


def _index(book: Gradebook, totals_figure: str = "") -> str:
    a = book.assignment
    totals = [s.points for s in book.students]
    mean = sum(totals) / len(totals) if totals else 0.0
    out = [f"<h1>{escape(a.title or a.name)}</h1>",
           f"<p><span id=\"students\" data-value=\"{len(book.students)}\">{len(book.students)}</span> students, "
           f"class mean <span id=\"mean\" data-value=\"{mean:.6f}\">{mean:.2f}</span> / "
           f"<span id=\"possible\" data-value=\"{book.possible:g}\">{_n(book.possible)}</span> points. "
           f"<span class=\"muted\">Graded by lagrade {escape(book.grader_version)}, accuracy {escape(a.accuracy)}.</span></p>",
           totals_figure, "<h2>Problems</h2><div class=\"problems\">"]
    for st in problem_stats(book):
        rows = "".join(f"<tr data-part=\"{escape(k)}\"><td>{escape(k)}</td><td class=\"num\" data-value=\"{v:.6f}\">"
                       f"{100 * v:.0f}%</td></tr>" for k, v in st.part_success.items())
        out.append(f"<section class=\"card\" id=\"problem-{escape(st.problem)}\" data-problem=\"{escape(st.problem)}\">"
                   f"<h3>Problem {escape(st.problem)}</h3>"
                   f"<p>{st.submitted} handed in, {st.failed} could not be graded; mean "
                   f"<span class=\"mean\" data-value=\"{st.mean:.6f}\">{st.mean:.2f}</span> / {_n(st.possible)}</p>"
                   f"{_histogram_svg(st.histogram, st.possible, st.problem)}"
                   f"<table class=\"part-success\"><thead><tr><th>part</th><th>correct</th></tr></thead>"
                   f"<tbody>{rows}</tbody></table></section>")
    out.append("</div>")
    wrong = common_wrong_answers(book, 12)
    if wrong:
        out.append("<h2>Most common wrong answers</h2><table id=\"wrong-answers\"><colgroup><col class=\"c-problem\">"
                   "<col class=\"c-part\"><col><col class=\"c-count\"></colgroup><thead><tr><th>problem</th>"
                   "<th>part</th><th>answer</th><th class=\"num\">students</th></tr></thead><tbody>")
        out += [f"<tr><td>{escape(p)}</td><td>{escape(part)}</td><td><div class=\"formula\">{_math(text, ml)}</div></td>"
                f"<td class=\"num\">{c}</td></tr>" for p, part, text, ml, c in wrong]
        out.append("</tbody></table>")
    mistakes = common_mistakes(book, 12)
    if mistakes:
        out.append("<h2>Most common feedback</h2><table id=\"mistakes\"><thead><tr><th>problem</th><th>part</th>"
                   "<th>feedback</th><th class=\"num\">students</th></tr></thead><tbody>")
        out += [f"<tr><td>{escape(p)}</td><td>{escape(part)}</td><td>{escape(fb)}</td><td class=\"num\">{c}</td></tr>"
                for p, part, fb, c in mistakes]
        out.append("</tbody></table>")
    review = to_review(book)
    if review:
        out.append("<h2>Verdicts to review</h2><p class=\"muted\">Where the evidence could not decide, or "
                   "lagrade itself failed on a readable answer (its traceback is here, never on a student's "
                   "page).</p><table id=\"review\"><thead><tr><th>student</th><th>problem</th><th>part</th>"
                   "<th>verdict</th><th>why</th></tr></thead><tbody>")
        for student, problem, p in review:
            why = escape(p.get("review") or p.get("feedback") or "")
            if p.get("detail"):
                why += f"<details><summary>traceback</summary><pre>{escape(p['detail'])}</pre></details>"
            out.append(f"<tr><td>{escape(student)}</td><td>{escape(problem)}</td><td>{escape(p['part'])}</td>"
                       f"<td>{escape(p['verdict'])}</td><td>{why}</td></tr>")
        out.append("</tbody></table>")
    failed = _failed_files(book)
    if failed:
        out.append(failed)
    jails = jail_counts(book)
    if jails:
        out.append("<h2>Sandbox</h2><p class=\"muted\">The sandbox layers each file ran under, as its grader "
                   "reported them.</p><table id=\"jails\"><thead><tr><th>layers</th><th class=\"num\">files</th>"
                   "</tr></thead><tbody>" +
                   "".join(f"<tr data-jail=\"{escape(j)}\"><td><code>{escape(j)}</code></td>"
                           f"<td class=\"num\">{c}</td></tr>" for j, c in jails.most_common()) + "</tbody></table>")
    out.append("<h2>Students</h2><div class=\"scroll\"><table id=\"students-table\" class=\"sortable\"><thead><tr><th>student</th>" +
               "".join(f"<th class=\"num\">{escape(p)}</th>" for p in a.ids) +
               "<th class=\"num\">total</th></tr></thead><tbody>")
    for s in book.students:
        cells = "".join(f"<td class=\"num{' failed' if s.problems[p].outcome == 'failed' else ''}\" "
                        f"data-problem=\"{escape(p)}\" data-value=\"{s.problems[p].points:.6f}\">"
                        f"{_n(s.problems[p].points) if s.problems[p].submitted else '—'}</td>" for p in a.ids)
        out.append(f"<tr data-student=\"{escape(s.student)}\"><td><a href=\"students/{slug(s.student)}.html\">"
                   f"{escape(s.student)}</a></td>{cells}<td class=\"num total\" data-value=\"{s.points:.6f}\">"
                   f"{_n(s.points)}</td></tr>")
    out.append("</tbody></table></div>")
    changed = [(st.student, o) for st in book.students for o in overrides_of(st)]
    if changed:
        out.append("<h2>Scores set by the instructor</h2><table id=\"overrides\"><thead><tr><th>student</th>"
                   "<th>part, score, reason</th></tr></thead><tbody>" +
                   "".join(f"<tr><td>{escape(who)}</td><td>{escape(o)}</td></tr>" for who, o in changed) +
                   "</tbody></table>")
    if book.skipped:
        out.append("<h2>Skipped files</h2><table id=\"skipped\"><thead><tr><th>file</th><th>reason</th></tr></thead><tbody>" +
                   "".join(f"<tr><td><code>{escape(p)}</code></td><td>{escape(r)}</td></tr>" for p, r in book.skipped) +
                   "</tbody></table>")
    return _page(f"{a.title or a.name}: class report", "\n".join(out))


def _problem_section(book: Gradebook, g: ProblemGrade, picture: str | None = None,
                     problems_dirs: tuple[Path, ...] = ()) -> str:
    """One problem of a student's page: each part's points with the weight the total uses, the answer
    as math (a wide one scrolls in its own cell), the feedback; a message every part shares (a file
    that could not be used) is said once, above the table; ``picture``: the file name of its wrong
    motion's picture, shown below the table."""
    head = (f"<section class=\"problem\" data-problem=\"{escape(g.problem)}\"><h2>Problem {escape(g.problem)}: "
            f"<span class=\"points\" data-value=\"{g.points:.6f}\">{_n(g.points)}</span> / {_n(g.possible)}</h2>")
    if not g.submitted:
        return head + "<p class=\"missing\">No file was handed in for this problem.</p></section>"
    out = [head]
    feedbacks = {(p["verdict"], p["feedback"]) for p in g.parts}
    shared = len(g.parts) > 1 and len(feedbacks) == 1 and g.parts[0]["verdict"] != "correct"
    if g.outcome == "failed":
        out.append(f"<p class=\"failed note\">This file could not be graded: {escape(g.reason)}</p>")
    elif shared:
        out.append(f"<p class=\"note shared-feedback\">{escape(g.parts[0]['feedback'])}</p>")
    said = {g.reason, g.parts[0]["feedback"] if shared else None}
    listed = [p for p in g.problems if p not in said]  # the reason above is not said a second time
    if listed:
        out.append("<ul class=\"file-problems\">" + "".join(f"<li>{escape(p)}</li>" for p in listed) + "</ul>")
    ap = book.assignment.problem(g.problem)
    weights = {p["part"]: part_weight(ap, p) for p in g.parts}
    total_w = sum(weights.values()) or 1.0
    out.append("<table class=\"parts\"><colgroup><col class=\"c-part\"><col class=\"c-verdict\">"
               "<col class=\"c-points\"><col class=\"c-answer\"><col class=\"c-feedback\"></colgroup>"
               "<thead><tr><th>part</th><th>verdict</th><th class=\"num\">points</th>"
               "<th>your answer</th><th>feedback</th></tr></thead><tbody>")
    for p, (earned, possible) in zip(g.parts, part_points(ap, g.parts, g.possible)):
        o = p.get("override")
        feedback = "" if shared or g.outcome == "failed" else escape(student_feedback(p, g.problem, problems_dirs))
        verdict, verdict_class = p["verdict"], p["verdict"]
        if o:
            feedback = (f"<span class=\"why\">Score set by your instructor: {escape(o['reason'])} (lagrade's "
                        f"verdict: {escape(p['verdict'])}, {_n(o['engine_score'])} / {_n(p['max_score'])})</span>"
                        + feedback)
            verdict, verdict_class = "set by instructor", "partial"
        weight = f"weight {_n(weights[p['part']])} of {_n(total_w)}"
        row_class = ' class="override"' if o else ""
        feedback = feedback or '<span class="muted">see above</span>'
        out.append(f"<tr data-part=\"{escape(p['part'])}\"{row_class}>"
                   f"<td data-label=\"part\">{escape(p['part'])}</td>"
                   f"<td data-label=\"verdict\" class=\"{escape(verdict_class)}\">{escape(verdict)}</td>"
                   f"<td data-label=\"points\" class=\"num points\" data-value=\"{p['score']:.6f}\" data-points=\"{earned:.4f}\" "
                   f"data-possible=\"{possible:.4f}\" title=\"{weight}\">{_n(earned)} / {_n(possible)}"
                   f"<span class=\"muted weight\">{weight}</span></td>"
                   f"<td data-label=\"your answer\" class=\"answer\"><div class=\"formula\">"
                   f"{_math(p.get('answer_text'), p.get('answer_mathml'))}</div></td>"
                   f"<td data-label=\"feedback\" class=\"feedback\">{feedback}"
                   f"</td></tr>")
    out.append("</tbody></table>")
    if picture:
        wrong = [p["part"] for p in g.parts if p["verdict"] not in ("correct", "invalid", "missing")]
        alt = (f"Your motion (red, dashed) against the true one (black) for problem {g.problem}"
               + (f", parts {', '.join(wrong)}" if wrong else "") + ": both start from the same state; a dotted "
               "orange line marks the time where they separate, as the feedback says.")
        out.append(f"<figure class=\"motion\" data-problem=\"{escape(g.problem)}\"><img src=\"{escape(picture)}\" "
                   f"alt=\"{escape(alt)}\"><figcaption>Your motion against the true one, one panel per "
                   "coordinate (the picture <code>lagrade check --plot</code> draws).</figcaption></figure>")
    if g.source:
        out.append(f"<details><summary>the file as graded ({escape(g.path)})</summary><pre>{escape(g.source)}</pre></details>")
    out.append("</section>")
    return "".join(out)


def _student(book: Gradebook, s: StudentGrade, pictures: dict[str, str] | None = None,
             problems_dirs: tuple[Path, ...] = ()) -> str:
    a = book.assignment
    pictures = pictures or {}
    body = ["<p><a href=\"../index.html\">class report</a></p>",
            f"<h1>{escape(a.title or a.name)}: {escape(s.student)}</h1>",
            f"<p>Total <span id=\"total\" data-value=\"{s.points:.6f}\">{_n(s.points)}</span> / {_n(s.possible)} points.</p>"]
    body += [_problem_section(book, g, pictures.get(g.problem), problems_dirs) for g in s.problems.values()]
    return _page(f"{s.student}: {a.title or a.name}", "\n".join(body), depth=1)


def write_report(book: Gradebook, folder: Path, problems_dirs: tuple[Path, ...] = ()) -> Path:
    """Write the report into ``folder`` (created; an earlier report's student pages are replaced);
    ``problems_dirs``: where a course's own problem files are (`--problems`), whose part kinds word
    the feedback ("your Hamiltonian")."""
    folder = Path(folder)
    students = folder / "students"
    if students.is_dir():
        shutil.rmtree(students)
    students.mkdir(parents=True)
    (folder / "style.css").write_text(CSS, encoding="utf-8")
    (folder / "report.js").write_text(SORT_JS, encoding="utf-8")
    figure = totals_histogram(book, folder / "totals.png") if book.students else ""
    (folder / "index.html").write_text(_index(book, figure), encoding="utf-8")
    for s in book.students:
        pictures = {}
        for g in s.problems.values():
            if g.plot_png:  # the student's own page only: a picture of their equations' motion
                name = f"{slug(s.student)}-{slug(g.problem)}.png"
                (students / name).write_bytes(g.plot_png)
                pictures[g.problem] = name
        (students / f"{slug(s.student)}.html").write_text(_student(book, s, pictures, problems_dirs), encoding="utf-8")
    return folder / "index.html"
