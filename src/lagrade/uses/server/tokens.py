"""Student tokens: ``lg1.<student, base64url>.<HMAC>``, signed with the server database's secret.

Signed rather than stored, so that ``lagrade tokens`` can issue tokens before or after the server
starts, for a roster or for one late student, without a table to keep in step; the roster (when
given) says who may sign in. The instructor's token is the one issued for ``@instructor``.
"""

from __future__ import annotations

import base64
import binascii
import csv
import hashlib
import hmac
import io
from pathlib import Path

INSTRUCTOR = "@instructor"
PREFIX = "lg1"
#: how long a browser session lasts (a term), unless signed out before; older session rows are deleted
SESSION_SECONDS = 120 * 24 * 3600
#: an --open server's guest session: a cookie this server signed, never a row written per visit
GUEST_PREFIX = "g1"


def issue(secret: bytes, student: str) -> str:
    name = base64.urlsafe_b64encode(student.encode()).decode().rstrip("=")
    return f"{PREFIX}.{name}.{_mac(secret, name)}"


def student_of(secret: bytes, token: str) -> str | None:
    """The student a token was issued to, or None if this server did not sign it."""
    try:
        prefix, name, mac = token.strip().split(".")
    except ValueError:
        return None
    if prefix != PREFIX or not hmac.compare_digest(mac, _mac(secret, name)):
        return None
    try:
        return base64.urlsafe_b64decode(name + "=" * (-len(name) % 4)).decode()
    except (binascii.Error, UnicodeDecodeError):
        return None


def _mac(secret: bytes, name: str) -> str:
    return hmac.new(secret, f"student:{name}".encode(), hashlib.sha256).hexdigest()[:40]


def csrf_token(secret: bytes, session: str) -> str:
    """The token the HTML forms of one session carry (tied to it: another site cannot know it)."""
    return hmac.new(secret, f"csrf:{session}".encode(), hashlib.sha256).hexdigest()[:32]


class RosterError(ValueError):
    """The roster file cannot be used; the message names it and says what was expected."""


def read_roster(path: Path) -> tuple[str, ...]:
    """Student ids from a CSV: the column ``student`` (any case), else a Canvas export's ``SIS Login ID``
    or ``ID``, else the first column; one header line."""
    try:
        text = Path(path).read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise RosterError(f"{path}: cannot be read ({exc}); expected a CSV file with a 'student' column") from None
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        raise RosterError(f"{path}: empty; expected a CSV file with a header line and a 'student' column")
    header = [h.strip().lower() for h in rows[0]]
    col = next((header.index(h) for h in ("student", "sis login id", "id") if h in header), 0)
    names = []
    for r in rows[1:]:
        name = r[col].strip() if col < len(r) else ""
        if name and name != "Points Possible" and not name.startswith("@") and name not in names:
            if any(ord(ch) < 32 for ch in name) or "/" in name or len(name) > 200 or name.startswith("guest-"):
                raise RosterError(f"{path}: student id {name!r} cannot be used (no '/', no control characters, "
                                  "not beginning with 'guest-', at most 200 characters)")
            names.append(name)
    if not names:
        raise RosterError(f"{path}: no student ids in it; expected a CSV file with a 'student' column")
    return tuple(names)


def login_csrf(secret: bytes, nonce: str) -> str:
    """The sign-in form's token, tied to the nonce in the browser's sign-in cookie: a page of another
    site cannot sign a browser in (as the attacker, to read what the student then types)."""
    return hmac.new(secret, f"login:{nonce}".encode(), hashlib.sha256).hexdigest()[:32]


def guest_session(secret: bytes, now: float) -> tuple[str, str]:
    """A new guest of an ``--open`` server: (the session cookie's value, the guest's name).

    Signed, not stored: a browser, a crawler or a script that keeps no cookie gets a new guest on
    every visit, and a row for each was written and never deleted (issue 43). The cookie holds no
    student token (it signs nobody in with a Bearer header, nor on another server, nor on this one
    once it is not --open) and its time of issue, so that it ends with :data:`SESSION_SECONDS`;
    sign-out keeps a row of the ended session until then (:meth:`Database.end_session`)."""
    import secrets

    name, issued = secrets.token_hex(8), str(int(now))
    return f"{GUEST_PREFIX}.{name}.{issued}.{_guest_mac(secret, name, issued)}", f"guest-{name}"


def guest_of(secret: bytes, sid: str, now: float) -> tuple[str, float] | None:
    """(The guest's name, when its cookie was issued) for a guest cookie this server signed that has
    not expired; None for anything else."""
    try:
        prefix, name, issued, mac = sid.split(".")
        when = float(int(issued))
    except ValueError:
        return None
    if prefix != GUEST_PREFIX or len(name) != 16 or not hmac.compare_digest(mac, _guest_mac(secret, name, issued)):
        return None
    return (f"guest-{name}", when) if 0 <= now - when < SESSION_SECONDS else None


def _guest_mac(secret: bytes, name: str, issued: str) -> str:
    return hmac.new(secret, f"guest:{name}.{issued}".encode(), hashlib.sha256).hexdigest()[:32]
