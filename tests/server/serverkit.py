"""Helpers of the server tests: the small assignment, configs, tokens and golden answers (a module
of its own: tests/bulk has a conftest too, and one name would shadow the other)."""

from __future__ import annotations

import contextlib
import re
import time
import struct
import tomllib
import zlib
from pathlib import Path

import pytest

pytest.importorskip("fastapi")
pytest.importorskip("sqlalchemy")
pytest.importorskip("httpx")


from lagrade.uses.server.config import ServerConfig
from lagrade.uses.server.tokens import issue

REPO = Path(__file__).resolve().parents[2]
GOLDEN = REPO / "tests" / "answers"
PROBLEMS = ("12.22", "12.14")
ASSIGNMENT = 'name = "hw-serve"\ntitle = "Serve test"\n[limits]\ncpu_seconds = 10\nwall_seconds = 20\n' + \
    "".join(f'[[problems]]\nid = "{pid}"\n' for pid in PROBLEMS)


#: golden answers (tests/answers) used here, by name: that folder grows (other suites add files to it)
GOLDEN_NAMES = {
    "12.22": ["correct_plain.toml", "correct_latex.toml", "correct_solved_accelerations.py", "wrong_S3_equals_S1.py",
              "wrong_sign_of_V.py", "wrong_case_upward.toml", "wrong_ignores_pulley_motion.py"],
    "12.14": ["correct_plain.toml", "correct_latex.toml", "correct_cartesian_and_solve.py", "wrong_missing_cross_term.py",
              "wrong_uncoupled_frequencies.toml", "wrong_V_upper_mass_only.py", "wrong_centrifugal_sign_exact.py"],
}


def golden(pid: str) -> list[Path]:
    return [GOLDEN / pid / name for name in GOLDEN_NAMES[pid]]


def make_config(tmp: Path, **kw) -> ServerConfig:
    path = tmp / "hw.toml"
    if not path.exists():
        path.write_text(ASSIGNMENT, encoding="utf-8")
    kw.setdefault("db", str(tmp / "serve.sqlite"))
    kw.setdefault("workers", 1)
    kw.setdefault("spare_graders", 0)  # each warms up for seconds: only the tests that need them
    return ServerConfig(assignment=path, **kw)


def sign_in(app, client, student: str) -> str:
    """Sign a browser (a TestClient) in as ``student`` as a person does: the sign-in link's page, then
    its button (a POST with the page's login-CSRF token). Returns the session's CSRF token."""
    from lagrade.uses.server.state import SESSION_COOKIE
    from lagrade.uses.server.tokens import csrf_token

    token = issue(app.state.server.secret, student)
    page = client.get("/login", params={"token": token})
    assert page.status_code == 200, page.text
    form = re.search(r'name="login_csrf" value="([^"]+)"', page.text).group(1)
    r = client.post("/login", data={"token": token, "login_csrf": form}, follow_redirects=False)
    assert r.status_code == 303, r.text
    return csrf_token(app.state.server.secret, client.cookies[SESSION_COOKIE])


def graded(client, headers, sid: int, seconds: float):
    """The attempt's response (GET /api/v1/submissions/<id>) once graded, or the last one after ``seconds``."""
    end = time.monotonic() + seconds
    while True:
        r = client.get(f"/api/v1/submissions/{sid}", headers=headers)
        if r.status_code != 202 or time.monotonic() > end:
            return r
        time.sleep(0.1)


def bearer(app, student: str) -> dict[str, str]:
    return {"Authorization": f"Bearer {issue(app.state.server.secret, student)}"}


def expectations(path: Path) -> dict[str, str]:
    """The ``# expect: L=correct, eom=partial`` line of a golden answer file."""
    first = path.read_text(encoding="utf-8").splitlines()[0]
    m = re.match(r"#\s*expect:\s*(.*)", first)
    return dict(item.strip().split("=") for item in m.group(1).split(",")) if m else {}


def toml_answer(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


#: what a PNG needs to be a picture; tEXt, iTXt, zTXt (text) and eXIf would be words and numbers
PICTURE_CHUNKS = {"IHDR", "PLTE", "IDAT", "IEND", "pHYs", "sRGB", "gAMA", "cHRM", "bKGD", "tRNS"}


def png_chunks(data: bytes) -> list[str]:
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    kinds, at = [], 8
    while at < len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind = data[at + 4:at + 8].decode("ascii")
        assert zlib.crc32(data[at + 4:at + 8 + length]) == struct.unpack(">I", data[at + 8 + length:at + 12 + length])[0]
        kinds.append(kind)
        at += 12 + length
    return kinds


def free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_serve(tmp: Path, *extra: str, db: Path | None = None, ready: float = 300.0):
    """``lagrade serve`` as a process of its own on 127.0.0.1 (one grader, no spare), in a session of its
    own (``os.killpg`` ends it and its graders): ``(process, base URL, log file)`` once /healthz answers 200."""
    import subprocess
    import sys

    import httpx

    if not (tmp / "hw.toml").exists():
        (tmp / "hw.toml").write_text(ASSIGNMENT, encoding="utf-8")
    port = free_port()
    log_path = tmp / f"serve-{port}.log"
    with open(log_path, "wb") as log:  # the child keeps its own descriptor
        proc = subprocess.Popen([sys.executable, "-m", "lagrade", "serve", "--assignment", str(tmp / "hw.toml"),
                                 "--db", str(db or tmp / "serve.sqlite"), "--port", str(port), "--workers", "1",
                                 "--spare-graders", "0", *extra],
                                stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    base = f"http://127.0.0.1:{port}"
    end = time.monotonic() + ready
    while time.monotonic() < end:
        try:
            if httpx.get(f"{base}/healthz", timeout=1).status_code == 200:
                return proc, base, log_path
        except httpx.HTTPError:
            pass
        if proc.poll() is not None:
            raise AssertionError(log_path.read_text())
        time.sleep(0.1)
    stop_serve(proc)
    raise AssertionError(f"the server did not become ready in {ready:g} s: {log_path.read_text()[-2000:]}")


def stop_serve(proc, kill: bool = False) -> None:
    """SIGINT (a graceful stop), or ``kill``: SIGKILL to the server and its graders at once (kill -9)."""
    import os
    import signal
    import subprocess

    if proc.poll() is not None:
        return
    if not kill:
        proc.send_signal(signal.SIGINT)
        try:
            proc.wait(timeout=30)
            return
        except subprocess.TimeoutExpired:
            pass
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()


@contextlib.contextmanager
def on_a_socket(app, **config):
    """``app`` served by uvicorn on a free port of 127.0.0.1 in a thread (lifespan off unless
    ``config`` says otherwise: the caller's graders), yielding its URL (https with a certificate);
    stopped on exit. ``config``: more of uvicorn's options (proxy headers, TLS)."""
    import socket
    import threading
    import time

    import uvicorn

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    config = {"lifespan": "off", **config}
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning", **config))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    for _ in range(200):
        if server.started:
            break
        time.sleep(0.05)
    try:
        yield f"{'https' if config.get('ssl_certfile') else 'http'}://127.0.0.1:{port}"
    finally:
        server.should_exit = True
        thread.join(timeout=10)
