"""benchmarks/serve_load.py says what it does as it goes, and stopped (SIGTERM here; Ctrl-C alike)
it stops the `lagrade serve` it started, graders and all, and removes its folder (issue 43: it
printed nothing until the end and left its server running)."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time

import pytest
from serverkit import REPO


@pytest.mark.slow
def test_a_stopped_benchmark_stops_its_server():
    env = {**os.environ, "LAGRADE_LOAD_WARMUP": "0"}
    bench = subprocess.Popen([sys.executable, str(REPO / "benchmarks" / "serve_load.py"), "--students", "4",
                              "--spread", "30", "--no-probe", "--workers", "1", "--spares", "0", "--mix", "light"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    said, server, work = [], None, None
    try:
        end = time.monotonic() + 300
        while time.monotonic() < end:
            line = bench.stderr.readline()
            assert line, f"the benchmark ended early: {''.join(said)}{bench.stdout.read()}"
            said.append(line)
            if m := re.search(r"issuing \d+ tokens in (\S+)", line):
                work = m.group(1)
            if m := re.search(r"server pid (\d+) starting", line):
                server = int(m.group(1))
            if "students submit" in line:
                break
        assert server is not None and work and os.path.isdir(work), said
        time.sleep(1)
        bench.send_signal(signal.SIGTERM)
        rest, _ = bench.communicate(timeout=120)
    finally:
        if bench.poll() is None:
            bench.kill()
            bench.wait()
    assert bench.returncode == 130, said
    with pytest.raises(ProcessLookupError):
        os.killpg(server, 0)  # neither the server nor any grader of its process group is left
    assert not os.path.exists(work)
