"""`lagrade serve` under a class: simulated students submitting 12.14 answers to a server on 127.0.0.1.

    python benchmarks/serve_load.py                       # 200 students, arrivals spread over 60 s
    python benchmarks/serve_load.py --spread 0            # all 200 at once
    python benchmarks/serve_load.py --hostile 0           # no hostile answer (the ordinary p95 to compare with)
    python benchmarks/serve_load.py --mix light           # hostile answers that cost nothing (the jail refuses them)
    python benchmarks/serve_load.py --probe-only          # the head-of-line probe alone
    python benchmarks/serve_load.py --spread 0 --distinct # a real burst: 200 answers at once, no two values alike

Starts ``lagrade serve`` (a fresh database in a temporary folder, tokens required), issues a token
per student, and has each student submit one 12.14 answer by upload: right (the reference solution,
the golden right files), wrong (the golden wrong files), broken (a syntax error, an empty file) and
hostile, in proportions 40/30/15/``--hostile`` (15). The hostile answers of ``--mix costly`` (the
default) really cost grader time: an infinite loop, a memory bomb (both spend the answer's CPU and
memory bounds in the jail), a power bomb (``((3*g*l1)^2)^2...`` thirty squarings, as text and as
``Pow(..., 2**30, evaluate=False)`` in answer.py: built by the reader in the grader itself) and a
4000-term sum; ``--mix light`` are the old ones (imports os, opens a file, walks
``__subclasses__``), refused by the jail at no cost; ``--mix bounded`` the costly ones but the
power bombs (whose cost is the reader's, bounded by another change). Each request waits for its grade (a 202, or
a 429 of the fair queue, is asked again). Bounded: ``--students`` submissions, and everything
still unanswered at ``--deadline`` seconds counts as an error.

Then (unless ``--no-probe``) the head-of-line probe, on the same server once the load is over: one
student sends ten infinite loops at once, then another student sends the right answer; it prints
how long that right answer took, and how many of the loops the server took (the rest get 429).

Says what it does as it goes, on stderr (the server's pid and address, the graders warm, every 5 s
the grades received so far); SIGINT (Ctrl-C), SIGTERM or an error stops the server it started, its
graders with it, and removes its temporary folder.

Prints p50 / p95 / max latency (send to grade received) of all answers and of the ordinary ones
(all but the hostile), throughput (grades per second over the run), the CPU time the server
process and its graders used during the run (where a burst's time goes; benchmarks/serve_profile.py
splits a submission into its stages), errors (anything but a grade), lost (attempts a student was
given an id for that are not graded in the database when the run ends, plus submissions the
database does not hold at all) and graded twice (a file with more than one line in the grade log).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import random
import shutil
import signal
import socket
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import httpx

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "tests" / "answers" / "12.14"


LOOP = b"while True:\n    pass\n"
POWER_TEXT = ("L = \"" + "(" * 30 + "3*g*l1" + ")^2" * 30 + "\"\n").encode()
POWER_PY = (b"from lagrade.answer import *\nfrom sympy import Pow\nm1, m2, l1, l2, g = parameters('m1 m2 l1 l2 g')\n"
            b"L = Pow(3*g*l1, 2**30, evaluate=False)\n")
SUM_4000 = (b"from lagrade.answer import *\nm1, m2, l1, l2, g = parameters('m1 m2 l1 l2 g')\n"
            b"theta1, theta2 = coordinates('theta1 theta2')\n"
            b"L = sum(cos(k*theta1)*m1*g*l1/k for k in range(1, 4001))\n")
MEMORY = b"chunks = []\nwhile True:\n    chunks.append(bytearray(50_000_000))\n"
COSTLY = [("answer.py", LOOP), ("answer.py", MEMORY), ("answer.toml", POWER_TEXT), ("answer.py", POWER_PY),
          ("answer.py", SUM_4000)]


def answers(mix: str = "costly") -> dict[str, list[tuple[str, bytes]]]:
    right = [("answer.py", (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes())]
    right += [(f"answer{p.suffix}", p.read_bytes()) for p in sorted(GOLDEN.glob("correct_*"))]
    wrong = [(f"answer{p.suffix}", p.read_bytes()) for p in sorted(GOLDEN.glob("wrong_*"))]
    broken = [("answer.py", b"from sympy import *\nL = (m1*\n"), ("answer.py", b""), ("answer.toml", b'L = "m1*\n')]
    hostile = [("answer.py", b"import os\nos.system('true')\nL = 1\n"), ("answer.py", b"L = open('/etc/passwd').read()\n"),
               ("answer.py", b"x = ().__class__.__bases__[0].__subclasses__()\nL = len(x)\n")]
    costly = {"costly": COSTLY, "bounded": [c for c in COSTLY if c[1] not in (POWER_TEXT, POWER_PY)]}
    return {"right": right, "wrong": wrong, "broken": broken, "hostile": costly.get(mix, hostile)}


def pick(rng: random.Random, pool: dict, i: int, hostile: float, distinct=None) -> tuple[str, str, bytes]:
    """A student's answer. ``distinct`` (the problem, :func:`distinct_answers`): every right or wrong
    answer.py gets values of its own (benchmarks/bulk.py's rewrite, with the same grade), so that no
    grader memo or content cache serves one student's values to another, and every other file is a
    program of its own (its text answers' values are shared: a class's text answers often are)."""
    kind = rng.choices(["right", "wrong", "broken", "hostile"], weights=[40, 30, 15, hostile])[0]
    name, data = rng.choice(pool[kind])
    if distinct is not None and kind in ("right", "wrong") and name.endswith(".py"):
        from bulk import distinct_source

        data = distinct_source(data.decode("utf-8", "replace"), distinct, i + 2).encode()
    # each student's own file (a comment, in .py and .toml alike): no two attempts share their bytes.
    # A comment after the last line leaves the program as it is (a server grades it once,
    # lagrade.uses.bulk.result_memo); with ``distinct``, every file is a program of its own: the
    # comment comes first, moving every line
    if distinct is not None:
        return kind, name, f"# student {i}\n".encode() + data
    return kind, name, data + f"\n# student {i}\n".encode()


def distinct_answers():
    """The problem the answers are to, for :func:`pick`'s ``distinct``."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from lagrade.problem.library import load_problem

    return load_problem("12.14")


def cpu_seconds(root: int) -> tuple[float, float]:
    """CPU seconds used so far by process ``root`` itself, and by all its descendants (the grader
    processes, their zygotes and, through those, the answers' children once reaped); Linux /proc."""
    tick = os.sysconf("SC_CLK_TCK")
    parent, used = {}, {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            fields = Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        parent[int(entry)] = int(fields[1])
        used[int(entry)] = sum(int(x) for x in fields[11:15]) / tick  # utime stime cutime cstime
    own = (sum(int(x) for x in Path(f"/proc/{root}/stat").read_text().rsplit(")", 1)[1].split()[11:13]) / tick)
    below = 0.0
    for pid in used:
        p = parent.get(pid)
        while p and p != root:
            p = parent.get(p)
        if p == root and pid != root:
            below += used[pid]
    return own, below


T_START = time.monotonic()


def say(message: str) -> None:
    """A progress line on stderr, at once (the results go to stdout at the end)."""
    print(f"[{time.monotonic() - T_START:7.1f} s] {message}", file=sys.stderr, flush=True)


class Stopped(Exception):
    """SIGTERM: the run stops as on Ctrl-C, through every ``finally``."""


def _on_sigterm(signum, frame) -> None:
    raise Stopped(f"signal {signum}")


def stop_server(server: subprocess.Popen) -> None:
    """SIGINT (uvicorn's graceful stop, which stops the graders), then SIGKILL to the server's whole
    process group (it was started in a session of its own): nothing of it is left running."""
    if server.poll() is None:
        server.send_signal(signal.SIGINT)
        try:
            server.wait(timeout=60)
        except subprocess.TimeoutExpired:
            pass
    try:
        os.killpg(server.pid, signal.SIGKILL)  # a grader or an answer left behind, or the server itself
    except ProcessLookupError:
        pass
    server.wait()


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


async def student(client, base, token, kind, name, data, start_at, t0, deadline, out):
    await asyncio.sleep(max(0.0, t0 + start_at - time.monotonic()))
    h = {"Authorization": f"Bearer {token}"}
    sent = time.monotonic()
    sid = None
    try:
        while True:
            r = await client.post(f"{base}/api/v1/problems/12.14/check", headers=h, files={"file": (name, data)},
                                  timeout=max(1.0, t0 + deadline - time.monotonic()))
            if r.status_code != 429 or time.monotonic() > t0 + deadline:
                break
            await asyncio.sleep(float(r.headers.get("retry-after", "1")))
        body = r.json()
        sid = body.get("submission_id")
        while r.status_code == 202 and time.monotonic() < t0 + deadline:
            await asyncio.sleep(0.5)
            r = await client.get(f"{base}/api/v1/submissions/{sid}", headers=h, timeout=10)
            body = r.json()
        ok = r.status_code == 200 and body.get("state") == "graded"
        out.append({"kind": kind, "ok": ok, "seconds": time.monotonic() - sent, "sid": sid,
                    "error": None if ok else f"{r.status_code} {str(body)[:120]}"})
    except Exception as exc:  # noqa: BLE001
        out.append({"kind": kind, "ok": False, "seconds": time.monotonic() - sent, "sid": sid,
                    "error": f"{type(exc).__name__}: {exc}"})


async def run(base: str, tokens: list[str], spread: float, deadline: float, seed: int, mix: str,
              hostile: float, distinct: bool = False) -> list[dict]:
    rng = random.Random(seed)
    pool = answers(mix)
    problem = distinct_answers() if distinct else None
    jobs = [(tokens[i], *pick(rng, pool, i, hostile, problem), rng.uniform(0, spread)) for i in range(len(tokens))]
    out: list[dict] = []
    limits = httpx.Limits(max_connections=len(tokens), max_keepalive_connections=len(tokens))
    async def progress():
        while True:
            await asyncio.sleep(5)
            ok = sum(1 for r in out if r["ok"])
            say(f"{ok} graded, {len(out) - ok} errors, {len(jobs) - len(out)} waiting, of {len(jobs)}")

    async with httpx.AsyncClient(limits=limits) as client:
        t0 = time.monotonic()
        ticker = asyncio.create_task(progress())
        try:
            await asyncio.gather(*(student(client, base, tok, kind, name, data, at, t0, deadline, out)
                                   for tok, kind, name, data, at in jobs))
        finally:
            ticker.cancel()
    return out


async def probe(base: str, looper: str, other: str, deadline: float = 120.0) -> dict:
    """The head-of-line probe: ten infinite loops from one student at once, then another's right answer."""
    right = (REPO / "reference_solutions" / "12.14" / "answer.py").read_bytes() + b"\n# the probe\n"
    async with httpx.AsyncClient() as client:
        url = f"{base}/api/v1/problems/12.14/check"
        h = {"Authorization": f"Bearer {looper}"}
        loops = [asyncio.create_task(client.post(url, headers=h, files={"file": ("answer.py", LOOP + b"#%d" % i)},
                                                 timeout=deadline)) for i in range(10)]
        await asyncio.sleep(1.0)  # all ten are in
        out: list = []
        t0 = time.monotonic()
        await student(client, base, other, "right", "answer.py", right, 0.0, t0, deadline, out)
        codes = [r.status_code for r in await asyncio.gather(*loops, return_exceptions=True)
                 if isinstance(r, httpx.Response)]
    return {"seconds": out[0]["seconds"], "ok": out[0]["ok"], "error": out[0]["error"],
            "taken": sum(c in (200, 202) for c in codes), "refused": sum(c == 429 for c in codes)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--students", type=int, default=200)
    ap.add_argument("--spread", type=float, default=60.0, help="seconds over which students arrive (0: all at once)")
    ap.add_argument("--workers", type=int, default=2, help="grader processes of the server")
    ap.add_argument("--spares", type=int, help="spare graders of the server (lagrade serve --spare-graders)")
    ap.add_argument("--deadline", type=float, default=600.0, help="seconds after which the run stops waiting")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--mix", choices=["costly", "bounded", "light"], default="costly",
                    help="what the hostile answers are (bounded: the costly ones but the power bombs)")
    ap.add_argument("--hostile", type=float, default=15.0, help="share of hostile answers, in %% (right 40, wrong 30, "
                                                                  "broken 15)")
    ap.add_argument("--distinct", action="store_true", help="every right or wrong answer.py with values of its own "
                                                              "(a real class's burst: no two students send one value)")
    ap.add_argument("--no-probe", action="store_true", help="skip the head-of-line probe")
    ap.add_argument("--probe-only", action="store_true", help="only the head-of-line probe")
    ap.add_argument("--json", type=Path, help="also write the figures to this file (benchmarks/pinned.py reads it)")
    args = ap.parse_args()
    if args.probe_only:
        args.students = 0

    signal.signal(signal.SIGTERM, _on_sigterm)
    work = Path(tempfile.mkdtemp(prefix="lagrade-serve-load-"))
    try:
        measure(args, work)
    except (KeyboardInterrupt, Stopped) as exc:
        say(f"stopped ({type(exc).__name__}{': ' + str(exc) if str(exc) else ''}); the server is stopped")
        sys.exit(130)
    except RuntimeError as exc:
        sys.exit(f"serve_load: {exc}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


def measure(args, work: Path) -> None:
    (work / "hw.toml").write_text('name = "load"\n[[problems]]\nid = "12.14"\n', encoding="utf-8")
    db = work / "serve.sqlite"
    roster = work / "roster.csv"
    roster.write_text("student\n" + "".join(f"s{i:03d}\n" for i in range(args.students)) + "looper\nprober\n",
                      encoding="utf-8")
    say(f"issuing {args.students + 2} tokens in {work}")
    tokens_csv = subprocess.run([sys.executable, "-m", "lagrade", "tokens", str(roster), "--db", str(db)],
                                check=True, capture_output=True, text=True).stdout
    issued = dict(line.split(",")[:2] for line in tokens_csv.splitlines()[1:] if not line.startswith("@"))
    looper, prober = issued.pop("looper"), issued.pop("prober")
    tokens = list(issued.values())
    port = free_port()
    with open(work / "serve.log", "wb") as log:  # the server keeps its own descriptor
        server = subprocess.Popen([sys.executable, "-m", "lagrade", "serve", "--assignment", str(work / "hw.toml"),
                                   "--db", str(db), "--roster", str(roster), "--port", str(port),
                                   "--workers", str(args.workers)]
                                  + ([] if args.spares is None else ["--spare-graders", str(args.spares)]),
                                  stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    base = f"http://127.0.0.1:{port}"
    say(f"server pid {server.pid} starting on {base} (log {work / 'serve.log'})")
    try:
        t = time.monotonic()
        while True:  # /healthz is 200 once a grader is warm
            try:
                if httpx.get(f"{base}/healthz", timeout=1).status_code == 200:
                    break
            except httpx.HTTPError:
                pass
            if server.poll() is not None or time.monotonic() - t > 300:
                raise RuntimeError(f"the server did not start: {(work / 'serve.log').read_text()[-2000:]}")
            time.sleep(0.2)
        warmup = float(os.environ.get("LAGRADE_LOAD_WARMUP", "15"))
        say(f"server ready (a grader warm) in {time.monotonic() - t:.1f} s; {warmup:g} s more for the others")
        time.sleep(warmup)  # let the other graders warm up too
        cpu0 = cpu_seconds(server.pid)
        own0 = time.process_time()
        t0 = time.monotonic()
        say(f"{len(tokens)} students submit, arriving over {args.spread:g} s")
        results = asyncio.run(run(base, tokens, args.spread, args.deadline, args.seed, args.mix, args.hostile,
                                  args.distinct)) \
            if tokens else []
        wall = time.monotonic() - t0
        cpu1 = cpu_seconds(server.pid)
        clients = time.process_time() - own0  # the simulated students' own CPU, on the same cores
        if not args.no_probe:
            say("head-of-line probe: ten infinite loops, then another student's right answer")
        probed = None if args.no_probe else asyncio.run(probe(base, looper, prober))
    finally:
        say(f"stopping the server (pid {server.pid})")
        stop_server(server)
    con = sqlite3.connect(db)
    states = dict(con.execute("SELECT id, state FROM server_submissions").fetchall())
    graded_seconds = con.execute("SELECT sum(seconds) FROM submissions").fetchone()[0] or 0.0
    twice = con.execute("SELECT count(*) FROM (SELECT 1 FROM grade_log GROUP BY student, problem, file_hash, "
                        "grading_hash, grader_version HAVING count(*) > 1)").fetchone()[0]
    con.close()
    given = [r["sid"] for r in results if r["sid"] is not None]
    lost = sum(1 for sid in given if states.get(sid) != "graded") + (len(results) - len(given))
    ok = sorted(r["seconds"] for r in results if r["ok"])
    ordinary = sorted(r["seconds"] for r in results if r["ok"] and r["kind"] != "hostile")
    errors = [r for r in results if not r["ok"]]
    q = statistics.quantiles(ok, n=100) if len(ok) >= 2 else [float("nan")] * 99
    qo = statistics.quantiles(ordinary, n=100) if len(ordinary) >= 2 else [float("nan")] * 99
    print(f"students {args.students}, arrivals over {args.spread:g} s, {args.workers} grader processes, "
          f"{'' if args.spares is None else f'{args.spares} spare, '}{os.cpu_count()} cores, "
          f"hostile {args.hostile:g} % ({args.mix})")
    by_kind = {}
    for r in results:
        by_kind.setdefault(r["kind"], []).append(r["seconds"])
    print("  kinds: " + ", ".join(f"{k} {len(v)}" for k, v in sorted(by_kind.items())))
    print(f"  latency p50 {q[49]:.2f} s, p95 {q[94]:.2f} s, max {max(ok, default=float('nan')):.2f} s")
    print(f"  ordinary answers (not hostile): p50 {qo[49]:.2f} s, p95 {qo[94]:.2f} s, "
          f"max {max(ordinary, default=float('nan')):.2f} s")
    print(f"  throughput {len(ok) / wall:.2f} grades/s over {wall:.1f} s")
    print(f"  grading time in the graders: {graded_seconds:.1f} s in all ({graded_seconds / max(1, len(ok)):.3f} s a file)")
    n = max(1, len(results))
    print(f"  CPU during the run: server process {cpu1[0] - cpu0[0]:.1f} s ({(cpu1[0] - cpu0[0]) / n * 1e3:.0f} ms a "
          f"submission), graders and answers {cpu1[1] - cpu0[1]:.1f} s ({(cpu1[1] - cpu0[1]) / n * 1e3:.0f} ms a "
          f"submission), on {os.cpu_count()} cores in {wall:.1f} s")
    burst = ((cpu1[0] - cpu0[0]) + (cpu1[1] - cpu0[1])) / (os.cpu_count() or 1)
    print(f"  the run's CPU spread over {os.cpu_count()} idle cores: {burst:.1f} s (what the burst's last grade would "
          f"wait for on an idle machine at best; on a loaded one the wall times above include the other load)")
    print(f"  the simulated students' own CPU during the run (this process: HTTP clients on the same cores as the "
          f"server): {clients:.1f} s")
    print(f"  errors {len(errors)}, lost {lost}, graded twice {twice}")
    if args.json is not None:
        args.json.write_text(json.dumps({
            "p50": q[49], "p95": q[94], "max": max(ok, default=float("nan")), "throughput": len(ok) / wall,
            "wall": wall, "server_cpu_ms": (cpu1[0] - cpu0[0]) / n * 1e3, "graders_cpu_ms": (cpu1[1] - cpu0[1]) / n * 1e3,
            "burst_idle": burst, "clients_cpu": clients, "errors": len(errors), "lost": lost, "twice": twice}))
    if probed is not None:
        print(f"  head-of-line probe: the right answer behind another student's ten infinite loops "
              f"{'graded' if probed['ok'] else 'NOT graded'} in {probed['seconds']:.2f} s "
              f"(loops taken {probed['taken']}, refused with 429 {probed['refused']})"
              + (f"; {probed['error']}" if probed["error"] else ""))
    for r in errors[:5]:
        print(f"    {r['kind']}: {r['error']}")


if __name__ == "__main__":
    main()
