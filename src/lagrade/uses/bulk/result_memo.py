"""Results kept by program: a class hands in the same program again and again.

The template with a name in its header comment, a file passed around, a student's resubmission:
running such a file again in the jail and grading it again gives the result it got, since the same
tokens at the same places (`lagrade.answer.reading.program_key`) run with the same limits in an
identical child, and a verdict is a function of the values (`lagrade.verdicts.verdict_memo`). A
grader keeps what it graded (`lagrade.uses.bulk.worker.Grader`), and so does the course server's
queue, across its graders, before it hands an attempt to one.

Only outcomes that are the file's own are kept (:data:`KEPT_STATUSES`), never one a bound or the
machine decided (a timeout, the memory limit, a crash): the next copy runs again.
"""

from __future__ import annotations

import hashlib
import json
from typing import Any

from lagrade.answer.reading.program_key import program_key

#: distinct programs whose results a memo keeps, the least recently used dropped first (a result is about
#: 20 kB of JSON with its read-back: 5 MB)
ENTRIES = 256
#: the statuses that are the file's own doing, the same on every run of its program
KEPT_STATUSES = ("ok", "syntax", "rejected")
#: what a kept result leaves out: whose it was, how long it took, and its picture (kept apart, by the
#: grader that drew it)
_PER_RUN = ("student", "seconds", "plot_png", "server_id")


def content_key(job: dict[str, Any], *more: str) -> bytes:
    """What a job's outcome is a function of, hashed: the problem, the file's program (its bytes but
    its comments) and the grading settings (``more`` names further fields of the job that matter)."""
    settings = (job["problem"], job["suffix"], job["accuracy"], job.get("credit"), job.get("hints"),
                *(job.get(name) for name in more))
    return hashlib.sha256(json.dumps(settings, sort_keys=True, default=repr).encode() + b"\0"
                          + program_key(job["suffix"], job["data"])).digest()


def result_key(job: dict[str, Any]) -> bytes:
    """The key of a job's whole result: its content and every setting a result depends on."""
    return content_key(job, "limits", "read_back")


class ResultMemo:
    """Results by :func:`result_key`, bounded."""

    def __init__(self, entries: int = ENTRIES) -> None:
        self.entries = entries
        self._kept: dict[bytes, str] = {}
        self.hits = 0

    def __len__(self) -> int:
        return len(self._kept)

    def get(self, job: dict[str, Any], key: bytes) -> dict[str, Any] | None:
        """The result kept for ``key``, made the job's own (its student), or None. A job that asks for
        the picture of a wrong motion is not answered from here (drawing it needs its motions)."""
        text = self._kept.get(key)
        if text is None:
            return None
        out = json.loads(text)
        if job.get("plot") and any(p.get("verdict") != "correct" for p in out.get("parts", ())):
            return None
        self._kept[key] = self._kept.pop(key)  # most recently used last
        self.hits += 1
        return {**out, "student": job["student"], "seconds": 0.0}

    def put(self, key: bytes, result: dict[str, Any]) -> None:
        """Keep ``result`` when its status is the file's own doing."""
        if result.get("status") not in KEPT_STATUSES or result.get("outcome") not in ("graded", "failed"):
            return
        self._kept[key] = json.dumps({k: v for k, v in result.items() if k not in _PER_RUN})
        while len(self._kept) > self.entries:
            self._kept.pop(next(iter(self._kept)))
