"""``lagrade check ID answer.py --server URL --token T``: the course server grades, this prints.

Standard library only (urllib), and nothing of the problem: no problem file, no reference is read,
so a student's install needs neither. The report is the one a local check prints.
"""

from __future__ import annotations

import hashlib
import http.client
import json
import time
import urllib.error
import urllib.parse
import urllib.request
import uuid
from pathlib import Path

POLL_SECONDS = 600


class ClientError(RuntimeError):
    """One line for the student: what went wrong talking to the server, and what to do."""


class _CutOff(ClientError):
    """The connection ended after the request was sent, before the answer came: the server may have
    stored the attempt (it stores before it grades) and crashed, or a proxy cut the line."""


def _request(url: str, token: str | None, data: bytes | None = None, kind: str | None = None) -> tuple[int, dict]:
    headers = {"Accept": "application/json", "User-Agent": "lagrade-check"}
    if token:
        headers["Authorization"] = f"Bearer {token}"
    if kind:
        headers["Content-Type"] = kind
    req = urllib.request.Request(url, data=data, headers=headers, method="POST" if data is not None else "GET")
    try:
        with urllib.request.urlopen(req, timeout=POLL_SECONDS) as resp:
            return resp.status, json.loads(resp.read() or b"{}")
    except urllib.error.HTTPError as exc:
        try:
            detail = json.loads(exc.read()).get("detail", exc.reason)
        except (ValueError, AttributeError):
            detail = exc.reason
        raise ClientError(f"the server answered {exc.code}: {detail}") from None
    except urllib.error.URLError as exc:
        raise ClientError(f"cannot reach the server at {url} ({exc.reason}); check --server") from None
    except (ConnectionError, http.client.HTTPException, TimeoutError) as exc:
        raise _CutOff(f"the connection to {url} was cut before the server answered ({exc or type(exc).__name__})") \
            from None
    except OSError as exc:
        reason = getattr(exc, "reason", exc)
        raise ClientError(f"cannot reach the server at {url} ({reason}); check --server") from None
    except ValueError:
        raise ClientError(f"{url} did not answer JSON; is --server a lagrade server?") from None


def remote_check(server: str, token: str | None, problem_id: str, answer: Path) -> dict:
    """Send ``answer`` for grading; the server's JSON (``lagrade check --json`` plus ``submission_id``)."""
    if answer.suffix not in (".py", ".toml"):
        raise ClientError(f"{answer}: an answer file must be a .py or a .toml file")
    try:
        data = answer.read_bytes()
    except OSError as exc:
        raise ClientError(f"{answer}: {exc.strerror or 'cannot be read'}") from None
    base = server.rstrip("/")
    if not base.startswith(("http://", "https://")):
        raise ClientError(f"--server {server!r}: expected a URL such as http://127.0.0.1:8000")
    boundary = uuid.uuid4().hex
    body = (f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"answer{answer.suffix}\"\r\n"
            f"Content-Type: application/octet-stream\r\n\r\n").encode() + data + f"\r\n--{boundary}--\r\n".encode()
    url = f"{base}/api/v1/problems/{urllib.parse.quote(problem_id, safe='')}/check"
    try:
        status, out = _request(url, token, body, f"multipart/form-data; boundary={boundary}")
    except _CutOff as exc:
        # the server stores an attempt before it grades it: find this file among the attempts
        sid = _stored(base, token, problem_id, hashlib.sha256(data).hexdigest())
        if sid is None:
            raise ClientError(f"{exc}, and the server holds no attempt with this file; send it again") from None
        status, out = 202, {"submission_id": sid}
    deadline = time.monotonic() + POLL_SECONDS
    while status == 202 and time.monotonic() < deadline:  # stored and queued: ask again
        time.sleep(1.0)
        status, out = _request(f"{base}/api/v1/submissions/{out['submission_id']}", token)
    if status == 202:
        raise ClientError(f"submission {out.get('submission_id')} is stored but not graded yet; ask again later")
    return out


def _base(server: str) -> str:
    base = server.rstrip("/")
    if not base.startswith(("http://", "https://")):
        raise ClientError(f"--server {server!r}: expected a URL such as http://127.0.0.1:8000")
    return base


def remote_problem(server: str, token: str | None, problem_id: str) -> dict:
    """The problem as the server's API gives it: what ``lagrade show`` and ``template`` print (``show``,
    ``template``), its statement as HTML, its figure's address and the assignment's rules."""
    base = _base(server)
    return _request(f"{base}/api/v1/problems/{urllib.parse.quote(problem_id, safe='')}", token)[1]


def remote_figure(server: str, token: str | None, problem_id: str) -> bytes:
    """The problem's figure (a PNG), drawn by the server from the scene."""
    base = _base(server)
    url = f"{base}/api/v1/problems/{urllib.parse.quote(problem_id, safe='')}/figure.png"
    headers = {"User-Agent": "lagrade-show", **({"Authorization": f"Bearer {token}"} if token else {})}
    try:
        with urllib.request.urlopen(urllib.request.Request(url, headers=headers), timeout=60) as resp:
            return resp.read()
    except urllib.error.HTTPError as exc:
        raise ClientError(f"the server answered {exc.code} for the figure") from None
    except (urllib.error.URLError, OSError) as exc:
        raise ClientError(f"cannot reach the server at {url} ({getattr(exc, 'reason', exc)}); check --server") from None


def _stored(base: str, token: str | None, problem_id: str, sha256: str) -> int | None:
    """The id of the newest attempt at ``problem_id`` holding exactly this file, if the server stored one."""
    try:
        status, attempts = _request(f"{base}/api/v1/problems/{urllib.parse.quote(problem_id, safe='')}/submissions",
                                    token)
    except ClientError:
        return None
    return next((a["submission_id"] for a in attempts or [] if a.get("file_hash") == sha256), None)


def result_of(out: dict):
    """The server's JSON as the :class:`lagrade.verdicts.result.CheckResult` a local check makes."""
    from lagrade.verdicts.result import CheckResult

    result = CheckResult.model_validate(out)
    shown = out.get("read_as_text") or {}
    for p in result.parts:
        p.read_as_text = shown.get(p.part)
    return result
