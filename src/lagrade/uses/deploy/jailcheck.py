"""Whether a platform's container may grade students' files, decided as ``lagrade grade`` decides.

Gradescope's and PrairieLearn's containers may refuse new namespaces and Landlock (Docker's default
seccomp profile does both), so the jail has no file view of its own there. What they do give: the
grader runs as root and each answer as another uid (the jail's ``uid`` layer). That layer hides the
key by itself when the problem files, the reference solutions and the reference cache are readable
by the grader's uid only: ``setup.sh`` installs them so (0700) on Gradescope, ``lagrade prairielearn
grade`` makes the job's ``/grade/tests`` so (PrairieLearn's image holds no key), and this module
checks it before anything is graded. Nothing of the jail itself is changed here: the layers are the
zygote's, and the minimum is :func:`lagrade.answer.jail.kernel.missing_minimum`, with "mount or landlock"
also met by "uid, and every key path private".
"""

from __future__ import annotations

import os
import re
import stat
from dataclasses import dataclass, field
from pathlib import Path


@dataclass
class JailVerdict:
    """``lacking``: why students' files may not run here (None: they may)."""

    active: list[str]
    inactive: dict[str, str] = field(default_factory=dict)
    lacking: str | None = None
    file_view: str = ""    # what keeps the key from the answer: "mount", "landlock", "uid + private files"

    @property
    def ok(self) -> bool:
        return self.lacking is None

    def as_dict(self) -> dict:
        return {"active": self.active, "inactive": self.inactive, "file_view": self.file_view,
                "refused": self.lacking}

    def for_students(self) -> str | None:
        """``lacking`` as a student is shown it: without the grader's paths (where lagrade and the
        problem data are installed, the course's folders); the full reason goes to the instructor's
        log and, on Gradescope, to ``extra_data``."""
        return None if self.lacking is None else without_paths(self.lacking)

    def summary(self) -> str:
        """One line: the layers the answer ran under, and what hid the key."""
        return f"jail: {', '.join(self.active) or 'none'}" + (f"; key hidden by {self.file_view}" if self.file_view
                                                              else "")


_PATH = re.compile(r"(?<![\w.~-])/[^\s'\"(),;:]+")


def without_paths(text: str) -> str:
    """``text`` with every absolute path replaced by "a path of the grader's": what a message shown to
    students may say of the machine it was graded on."""
    return _PATH.sub("a path of the grader's", text)


def probe_layers() -> tuple[list[str], dict[str, str], str | None]:
    """(active layers, why each other one is missing, or a reason the sandbox did not start), from
    a zygote started as the graders start theirs (what ``lagrade grade`` asks before a class)."""
    from lagrade.answer.jail import zygote

    try:
        probe = zygote.Zygote()
        try:
            hello = probe.hello()
        finally:
            probe.close()
    except OSError as exc:
        return [], {}, f"the sandbox could not start ({exc})"
    return list(hello["active"]), dict(hello.get("inactive", {})), None


def exposed(path: Path) -> str | None:
    """Why another uid could read ``path`` (None: it cannot, or it does not exist). Private means
    owned by this uid with no group or other bits, or under a folder that is."""
    p = Path(os.path.realpath(path))
    if not p.exists():
        return None
    me = os.geteuid()
    for q in (p, *p.parents):
        try:
            st = q.stat()
        except OSError:
            return None
        if st.st_uid == me and not st.st_mode & 0o077:
            return None
    return f"{p} is readable by other users (mode {stat.S_IMODE(p.stat().st_mode):04o})"


def key_paths(extra: tuple[Path, ...] = ()) -> list[Path]:
    """What an answer must never read: the reference solutions, the problem files, the reference
    cache (the jail's own list, :func:`lagrade.answer.jail.child.secret_dirs`), and ``extra`` (the
    Gradescope source folder, whose problem-data wheel holds the references)."""
    from lagrade.answer.jail.child import secret_dirs

    return [Path(d) for d in secret_dirs()] + [Path(p) for p in extra]


def decide(extra_keys: tuple[Path, ...] = (), layers: tuple[list[str], dict[str, str], str | None] | None = None
           ) -> JailVerdict:
    """May students' files run here? ``lagrade grade``'s minimum, where the grader-root, answer-
    another-uid layer with private key files stands for the file view (mount or Landlock)."""
    from lagrade.answer.jail import kernel

    active, inactive, failed = layers if layers is not None else probe_layers()
    if failed:
        return JailVerdict([], {}, failed)
    verdict = JailVerdict(active, inactive)
    lacking = kernel.missing_minimum(active)
    if lacking is None:
        verdict.file_view = "mount" if "mount" in active else "landlock"
        return verdict
    rest = kernel.missing_minimum([*active, kernel.MINIMUM_FS[0]])
    if rest is not None:  # seccomp, no_new_privs or limits missing: no stand-in for those
        verdict.lacking = rest
        return verdict
    if "uid" not in active or os.geteuid() != 0 or kernel.in_user_namespace():
        verdict.lacking = (f"{lacking}, and answers do not run as another uid of a root grader "
                           f"({inactive.get('uid', 'the grader is not root')})")
        return verdict
    open_keys = [why for p in key_paths(extra_keys) if (why := exposed(p))]
    if open_keys:
        verdict.lacking = (f"{lacking}, and the answer's uid could read the key: {open_keys[0]}"
                           + (f" (and {len(open_keys) - 1} more)" if len(open_keys) > 1 else "")
                           + "; install them readable by the grader's uid alone (0700), as setup.sh and "
                           "lagrade prairielearn grade do")
        return verdict
    verdict.file_view = "uid + private files"
    return verdict
