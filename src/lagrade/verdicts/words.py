"""Feedback as a student reads it: the evidence in words, the integrator's settings left out.

The engine's feedback (``PartResult.feedback``) keeps every figure of the evidence, for the
instructor's report and ``lagrade check --json``: "trajectories agree over t in [0, 2] (DOP853 at
rtol 1e-10) (compared within rtol 1e-06, atol 1e-06, 1545 evaluations, 0.09 s)". A student reads "your
Lagrangian gives the same motion as the true one over t in [0, 2]": what ``lagrade check`` prints
and what the course server shows a student (:func:`in_words`). And the assignment's feedback level
(:func:`at_level`): ``hints``, ``named`` (the hints left out) or ``verdict`` (the verdict alone).
"""

from __future__ import annotations

import re

#: what "your ..." is, by the part's kind
_WHAT = {"lagrangian": "Lagrangian", "eom": "equations", "hamiltonian": "Hamiltonian",
         "hamilton_eqs": "Hamilton's equations"}

#: a parenthesis that holds the integrator's or the comparison's settings
_SETTINGS = re.compile(r"\s*\((?:[^()]*?\b(?:rtol|atol|evaluations|DOP853|LSODA|Radau|RK45|BDF)\b[^()]*)\)")
_AGREE = re.compile(r"equal at every sampled state and trajectories agree over t in \[0, ([^\]]+)\]")
_AGREE_ALONE = re.compile(r"trajectories agree over t in \[0, ([^\]]+)\]")
_CLOSE = re.compile(r"agrees with the right one at every sampled state to about \S+ \(relative\), but not exactly")


def in_words(feedback: str, kind: str = "") -> str:
    """``feedback`` with its evidence in words: no integrator, tolerance, count or timing."""
    if not feedback:
        return feedback
    what = f"your {_WHAT.get(kind, 'answer')}"
    gives = "give" if what.endswith(("equations", "s'")) else "gives"
    text = _SETTINGS.sub("", feedback)
    text = _AGREE.sub(lambda m: f"equal to the true one at every sampled state, and {what} {gives} the same motion "
                                f"as the true one over t in [0, {m.group(1)}]", text)
    text = _AGREE_ALONE.sub(lambda m: f"{what} {gives} the same motion as the true one over t in [0, {m.group(1)}]",
                            text)
    text = _CLOSE.sub("agrees closely with the right one at every sampled state, but not exactly", text)
    return re.sub(r"\s+([.,;])", r"\1", text)


#: feedback levels, as the assignment's ``[rules] feedback`` names them
LEVELS = ("hints", "named", "verdict")

_SAID = {"correct": "Correct.", "partial": "Partly right.", "incorrect": "Incorrect.", "error": ""}


def at_level(feedback: str, verdict: str, level: str) -> str:
    """What a student reads at ``level``: ``hints`` everything; ``named`` the named mistake without
    its hint (``Hint: ...``); ``verdict`` the verdict alone. A part that could not be read
    (``invalid``, ``missing``) keeps its reason at every level: it says what to fix in the file, not
    what is wrong in the physics."""
    if level == "hints" or verdict in ("invalid", "missing"):
        return feedback
    if level == "verdict":
        return _SAID.get(verdict, "") or feedback
    return re.sub(r"\s*Hint: .*?\.(?=\s+[A-Z]|\s*$)", "", feedback, flags=re.S)
