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


def remote_check(server: str, token: str | None, problem_id: str, answer: Path, plot: bool = False) -> dict:
    """Send ``answer`` for grading; the server's JSON (``lagrade check --json`` plus ``submission_id``).
    ``plot``: ask for the picture of a wrong motion too (the course's feedback level may refuse it)."""
    from lagrade.answer.reading.suffixes import ANSWER_KINDS, ANSWER_SUFFIXES

    if answer.suffix not in ANSWER_SUFFIXES:
        raise ClientError(f"{answer}: {ANSWER_KINDS}")
    try:
        data = answer.read_bytes()
    except OSError as exc:
        raise ClientError(f"{answer}: {exc.strerror or 'cannot be read'}") from None
    if answer.suffix == ".ipynb":
        data = without_outputs(data)
    base = server.rstrip("/")
    if not base.startswith(("http://", "https://")):
        raise ClientError(f"--server {server!r}: expected a URL such as http://127.0.0.1:8000")
    boundary = uuid.uuid4().hex
    body = (f"--{boundary}\r\nContent-Disposition: form-data; name=\"file\"; filename=\"answer{answer.suffix}\"\r\n"
            f"Content-Type: application/octet-stream\r\n\r\n").encode() + data + f"\r\n--{boundary}--\r\n".encode()
    url = f"{base}/api/v1/problems/{urllib.parse.quote(problem_id, safe='')}/check" + ("?plot=true" if plot else "")
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


def without_outputs(data: bytes) -> bytes:
    """A notebook as the server reads it: its outputs (pictures, printed text) are never graded, and
    would count against the server's bound on an upload. Not a notebook: sent as it is, and the
    server says what is wrong with it."""
    try:
        nb = json.loads(data)
        for cell in nb["cells"]:
            if isinstance(cell, dict) and cell.get("cell_type") == "code":
                cell["outputs"], cell["execution_count"] = [], None
    except (ValueError, TypeError, KeyError, RecursionError):
        return data
    return json.dumps(nb, indent=1).encode("utf-8")


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


def remote_plot(server: str, token: str | None, address: str) -> bytes | None:
    """The picture the server drew for an attempt (``plot`` in its result: a path on the server), or
    None when it has none to give (it may not show pictures at this course's feedback level)."""
    url = urllib.parse.urljoin(_base(server) + "/", address.lstrip("/"))
    if not url.startswith(_base(server) + "/"):  # only ever from the server that graded
        return None
    headers = {"User-Agent": "lagrade-check", **({"Authorization": f"Bearer {token}"} if token else {})}
    try:
        with urllib.request.urlopen(urllib.request.Request(url, headers=headers), timeout=60) as resp:
            return resp.read() if resp.headers.get_content_type() == "image/png" else None
    except (urllib.error.URLError, OSError):
        return None


def parts_source(parts: dict) -> str:
    """Parts given as sympy objects, as the text of an ``answer.py`` that binds exactly them (sympy's
    ``srepr``: every symbol with its name and assumptions), for the server to grade in its jail."""
    import sympy

    lines = ['"""Parts given to lagrade.check, as sympy built them."""', "", "from sympy import *", ""]
    for name, value in parts.items():
        if not name.isidentifier():
            raise ClientError(f"{name!r} is not a part name")
        lines.append(f"{name} = {sympy.srepr(value)}")
    return "\n".join(lines) + "\n"


def check_remote(server: str, token: str | None, problem_id: str, answer: Path | str | None, parts: dict,
                 plot: bool = True):
    """``lagrade.check(..., server=, token=)``: the answer file, or the parts given, graded by the course
    server at the course's feedback level; the result a local check returns, with the server's picture
    of a wrong motion when it gives one. :class:`ClientError` with one line when it cannot be had."""
    import tempfile

    if (answer is None) == (not parts):
        raise ClientError("give an answer file or parts (L=..., eom=...), not both" if parts
                          else "give an answer file or parts (L=..., eom=...)")
    with tempfile.TemporaryDirectory(prefix="lagrade-parts-") as tmp:
        if answer is None:
            answer = Path(tmp) / "answer.py"
            answer.write_text(parts_source(parts), encoding="utf-8")
        out = remote_check(server, token, problem_id, Path(answer), plot=plot)
    result = result_of(out)
    address = out.get("plot")
    if plot and isinstance(address, str):
        result._picture = lambda: remote_plot(server, token, address)
    return result


def result_of(out: dict):
    """The server's JSON as the :class:`lagrade.verdicts.result.CheckResult` a local check makes."""
    from lagrade.verdicts.result import CheckResult

    result = CheckResult.model_validate(out)
    shown = out.get("read_as_text") or {}
    for p in result.parts:
        p.read_as_text = shown.get(p.part)
    return result
