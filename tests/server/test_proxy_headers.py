"""Issue 43, item 6: X-Forwarded-For is believed only from a proxy the instructor named
(``--forwarded-allow-ips``), from no one by default. uvicorn's own default believed 127.0.0.1, so a
client on the server's machine (or a tunnel ending there) gave a new address with each refused token
and never reached the failed sign-in bound's 429."""

from __future__ import annotations

import http.client

import pytest
from click.testing import CliRunner
from serverkit import ASSIGNMENT, make_config, on_a_socket

from lagrade.cli import main
from lagrade.cli.serve import proxy_options
from lagrade.uses.server.app import create_app


def _guesses(port: int, n: int) -> list[int]:
    """``n`` refused tokens from 127.0.0.1, each claiming another address in X-Forwarded-For."""
    codes = []
    for i in range(n):
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        conn.request("GET", "/api/v1/problems", headers={"Authorization": f"Bearer lg1.guess{i}.x",
                                                         "X-Forwarded-For": f"198.51.100.{i + 1}"})
        r = conn.getresponse()
        r.read()
        conn.close()
        codes.append(r.status)
    return codes


@pytest.mark.parametrize("allowed, limited", [("", True), ("192.0.2.1", True), ("127.0.0.1", False)])
def test_a_rotated_x_forwarded_for_reaches_the_sign_in_bound(tmp_path, allowed, limited):
    app = create_app(make_config(tmp_path, failed_sign_ins_per_minute=1, failed_sign_in_burst=5), grade=False)
    try:
        with on_a_socket(app, lifespan="auto", **proxy_options(allowed)) as url:
            codes = _guesses(int(url.rsplit(":", 1)[1]), 8)
    finally:
        app.state.server.stop()
    if limited:  # the peer's own address is counted: the sixth guess on is 429
        assert codes == [401] * 5 + [429] * 3, codes
    else:  # a proxy the instructor named: each address it forwards is counted on its own
        assert codes == [401] * 8, codes


def test_lagrade_serve_believes_no_proxy_unless_told(tmp_path, monkeypatch):
    import uvicorn

    seen = []
    monkeypatch.setattr(uvicorn, "run", lambda *a, **kw: seen.append(kw))
    monkeypatch.delenv("LAGRADE_FORWARDED_ALLOW_IPS", raising=False)
    (tmp_path / "hw.toml").write_text(ASSIGNMENT, encoding="utf-8")
    base = ["serve", "--assignment", str(tmp_path / "hw.toml"), "--unsafe-trusted-files", "--port", "1"]
    for i, (extra, env) in enumerate([([], None), (["--forwarded-allow-ips", "127.0.0.1, ::1"], None),
                                      ([], "10.0.0.2"), (["--https"], None)]):
        # uvicorn.run returns at once here: the app (and its claim on its database) stays, so one each
        out = CliRunner().invoke(main, base + ["--db", str(tmp_path / f"s{i}.sqlite")] + extra,
                                 env={"LAGRADE_FORWARDED_ALLOW_IPS": env} if env else None)
        assert out.exit_code == 0, out.output
        if extra == ["--https"]:
            assert "--https without --forwarded-allow-ips" in out.output
    assert [(kw["proxy_headers"], kw.get("forwarded_allow_ips")) for kw in seen] == \
        [(False, None), (True, "127.0.0.1,::1"), (True, "10.0.0.2"), (False, None)]


@pytest.mark.slow
def test_lagrade_serve_counts_the_peer_whatever_x_forwarded_for_says(tmp_path):
    """The same through a real `lagrade serve` with its defaults (on the old code: 401 fourteen times)."""
    import httpx
    from serverkit import start_serve, stop_serve

    proc, base, _ = start_serve(tmp_path)
    try:
        codes = [httpx.get(f"{base}/api/v1/problems", timeout=30, headers={
            "Authorization": f"Bearer lg1.guess{i}.x", "X-Forwarded-For": f"198.51.100.{i + 1}"}).status_code
            for i in range(14)]
    finally:
        stop_serve(proc)
    assert codes == [401] * 10 + [429] * 4, codes  # the bound's burst is 10 (ServerConfig.failed_sign_in_burst)
