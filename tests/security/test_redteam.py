"""The red-team suite: every file in attacks/ is a hostile answer.py for problem 12.22.

Each attack runs (1) through ``lagrade check 12.22 FILE --json``, one subprocess per attack, two at
a time, and (2) as a student in ONE ``lagrade grade`` of a class that also holds two honest
students (the reference solution, and a wrong answer). An attack succeeds only by its effect, never
by what lagrade says: before the runs the harness plants

- two secret tokens: /tmp/lagrade-redteam/secret-0600.txt (0600) and .../open/secret-0644.txt (0644);
  a token in any output (check's stdout/stderr; the gradebook's tables and its CSV export) = read-secret;
- a world-writable drop folder /tmp/lagrade-redteam/drop (1777): any file appearing there (attacks
  name theirs pwned-<attack>) = write-outside or run-command; so does a new file next to the answer
  file or in the working folder lagrade was started in;
- LAGRADE_CACHE: a private copy of a warm reference cache per run, snapshotted before and after:
  any change = poison-cache (and a pickle lagrade loads later shows up in drop/);
- TCP listeners on 127.0.0.1:47474 and [::1]:47474: any connection = network;

and it runs lagrade under tests/security/_launch.py (a child subreaper), which bounds the run's time
and reports processes left alive after it (exhaust-processes) and the largest RSS (exhaust-memory).
A check must end with a verdict (a JSON object with a score) within CHECK_BOUND seconds (hang,
signal-parent) and below full marks (full-marks); the grade run must end, every student must have a
row, the honest correct student full marks and the honest wrong one the score it gets alone
(other-row), and no grader process may outlive it.

``LAGRADE_REDTEAM_SRC=/path/to/src`` runs that lagrade source tree (PYTHONPATH); default: the
installed one. Where ``lagrade grade`` refuses a class because its OS jail is incomplete, the grade
tests are skipped with its reason; ``LAGRADE_REDTEAM_UNSAFE=1`` passes --unsafe-trusted-files.
``LAGRADE_REDTEAM_TRIPWIRES=off`` switches lagrade's screen and audit hook off in every lagrade
process (tripwires_off/sitecustomize.py): the attacks then meet the OS jail alone. ``LAGRADE_REDTEAM_REPORT=FILE`` writes every run's findings as JSON (README's table).
The attacks run for real, as the user running pytest: they aim only at /tmp/lagrade-redteam/, the
harness's temporary folders and the loopback listeners, and their fork and memory bombs are bounded.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import os
import pickletools
import re
import secrets
import shutil
import socket
import sqlite3
import stat
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import fcntl
import pytest

pytestmark = pytest.mark.slow  # about 5 minutes on 2 cores: 69 checks, three of which hang for CHECK_BOUND

HERE = Path(__file__).resolve().parent
ATTACKS = sorted((HERE / "attacks").glob("*.py"))
NAMES = [p.stem for p in ATTACKS]
LAUNCH = HERE / "_launch.py"
SRC = os.environ.get("LAGRADE_REDTEAM_SRC")
#: lagrade grade refuses a class where its OS jail is incomplete; =1 grades anyway (--unsafe-trusted-files)
UNSAFE = os.environ.get("LAGRADE_REDTEAM_UNSAFE") == "1"
#: =off: lagrade's Python-level tripwires (screen, audit hook) off in every lagrade process, so the
#: attacks meet the OS jail alone (needs a lagrade with sandbox.TRIPWIRES, see tripwires_off/)
TRIPWIRES_OFF = os.environ.get("LAGRADE_REDTEAM_TRIPWIRES") == "off"
ROOT = Path("/tmp/lagrade-redteam")
DROP = ROOT / "drop"
PORT = 47474
CHECK_BOUND = 60.0       # seconds for one `lagrade check` (its sandbox allows 20 s of wall time)
GRADE_BOUND = 600.0      # seconds for the whole class
MEMORY_BOUND = 2 << 30   # bytes of RSS for any one process of a run
EFFECTS = {"read-secret", "write-outside", "full-marks", "other-row", "run-command", "poison-cache", "hang",
           "network", "signal-parent", "trace-parent", "exhaust-memory", "exhaust-processes"}
LIMITS = {"cpu_seconds": 5, "wall_seconds": 10, "memory_mb": 1024, "grading_seconds": 20}
HONEST_CORRECT, HONEST_WRONG = "honest-correct", "honest-wrong"


def _lagrade_src() -> Path:
    """The lagrade package the runs use: its reference solution is the honest correct answer."""
    if SRC:
        return Path(SRC)
    import lagrade

    return Path(lagrade.__file__).resolve().parents[1]


def _check_bound_args() -> list[str]:
    """The grading bound the class run gets (LIMITS), for a check too where lagrade has the option
    (its default, 120 s of CPU, is longer than CHECK_BOUND)."""
    package = _lagrade_src() / "lagrade"
    has = any(f.is_file() and "--grading-seconds" in f.read_text() for f in (package / "cli.py", package / "cli" / "check.py"))
    return ["--grading-seconds", str(LIMITS["grading_seconds"])] if has else []


def _reference_answer() -> str:
    from_src = _lagrade_src().parent / "reference_solutions" / "12.22" / "answer.py"
    if from_src.is_file():
        return from_src.read_text()
    from lagrade.problem.library import reference_dir

    return (reference_dir() / "12.22" / "answer.py").read_text()


def _wrong_answer() -> str:
    # the reference with a scaled Lagrangian (half credit) and one wrong numerical acceleration
    return _reference_answer() + '\nL = 3*L\na_case = dict(a_case, m1=g)\n'


def header(path: Path) -> dict[str, str]:
    text = path.read_text()
    m = re.match(r'"""effect: (?P<effect>[a-z-]+)\ntries: (?P<tries>[^\n]+)\n', text)
    return m.groupdict() if m else {}


# =========================================================================== what the harness plants

class Listener:
    """TCP listeners on the loopback addresses; every accepted connection is recorded."""

    def __init__(self) -> None:
        self.connections: list[tuple[float, str, bytes]] = []
        self.stop = threading.Event()
        self.sockets = []
        for family, host in ((socket.AF_INET, "127.0.0.1"), (socket.AF_INET6, "::1")):
            try:
                s = socket.socket(family, socket.SOCK_STREAM)
                s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
                s.bind((host, PORT))
                s.listen(64)
                s.settimeout(0.2)
            except OSError:
                continue  # no IPv6 loopback here
            self.sockets.append(s)
            threading.Thread(target=self._serve, args=(s, host), daemon=True).start()

    def _serve(self, s: socket.socket, host: str) -> None:
        while not self.stop.is_set():
            try:
                conn, _ = s.accept()
            except OSError:
                continue
            conn.settimeout(1.0)
            try:
                data = conn.recv(200)
            except OSError:
                data = b""
            conn.close()
            self.connections.append((time.monotonic(), host, data))

    def close(self) -> None:
        self.stop.set()
        for s in self.sockets:
            s.close()


@dataclass
class Planted:
    tokens: list[str]
    listener: Listener
    template_cache: Path
    work: Path
    honest: dict[str, dict]          # check results of the honest answers: name -> JSON


def snapshot(directory: Path) -> dict[str, tuple]:
    """Every file and folder under ``directory`` (itself included): mode, owner and content hash."""
    out = {}
    if not directory.exists():
        return out
    for path in [directory, *sorted(directory.rglob("*"))]:
        st = path.lstat()
        digest = hashlib.sha256(path.read_bytes()).hexdigest() if stat.S_ISREG(st.st_mode) else ""
        out[str(path.relative_to(directory))] = (stat.S_IMODE(st.st_mode), st.st_uid, digest)
    return out


def changed(before: dict, after: dict) -> list[str]:
    return sorted(k for k in before.keys() | after.keys() if before.get(k) != after.get(k))


_NUMPY_GLOBALS = {"dtype", "ndarray", "_reconstruct", "_frombuffer", "scalar"}


def pickle_globals(data: bytes) -> set[tuple[str, str]]:
    """The (module, name) pairs a pickle imports, read with pickletools: never unpickled here."""
    found, memo, strings, last = set(), {}, [], None
    try:
        for op, arg, _ in pickletools.genops(data):
            if op.name in ("SHORT_BINUNICODE", "BINUNICODE", "UNICODE", "BINUNICODE8", "SHORT_BINSTRING",
                           "BINSTRING", "STRING"):
                last = arg
                strings.append(arg)
            elif op.name == "MEMOIZE":
                memo[len(memo)] = last
            elif op.name in ("BINPUT", "LONG_BINPUT", "PUT"):
                memo[arg] = last
            elif op.name in ("BINGET", "LONG_BINGET", "GET"):
                last = memo.get(arg)
                strings.append(last)
            elif op.name in ("GLOBAL", "INST"):
                found.add(tuple(arg.split(" ", 1)))
            elif op.name == "STACK_GLOBAL":
                found.add((str(strings[-2]), str(strings[-1])) if len(strings) > 1 else ("?", "?"))
    except Exception:  # noqa: BLE001  (not a pickle at all)
        found.add(("?", "not a pickle"))
    return found


def lagrades_own(path: Path, before: dict) -> bool:
    """A cache entry lagrade itself rewrote: replaced atomically (a new file, private), and a pickle of
    lagrade's, sympy's and numpy's classes only (a function or another module's name is a payload).
    A forged entry made only of those classes passes: the judge is the process, not the data."""
    if not path.is_file() or not path.name.endswith(".pkl") or path.name.startswith("."):
        return False
    st = path.lstat()
    if stat.S_IMODE(st.st_mode) & 0o077 or st.st_uid != os.getuid() or before.get("inode") == st.st_ino:
        return False
    data = path.read_bytes()
    start = data.find(b"\x80\x05")  # lagrade's pickles (protocol 5), after any header lagrade puts first
    for module, name in pickle_globals(data[max(start, 0):]):
        top = module.split(".")[0]
        if not ((top in ("lagrade", "sympy", "mpmath") and name[:1].isupper()) or
                (top == "numpy" and name in _NUMPY_GLOBALS)):
            return False
    return True


def cache_changes(cache: Path, before: dict, after: dict, inodes: dict[str, int]) -> list[str]:
    """What changed in a cache folder that lagrade itself would not have written."""
    diff = changed(before, after)
    own = {rel for rel in diff if rel in after and rel != "." and lagrades_own(cache / rel, {"inode": inodes.get(rel)})}
    # lagrade prunes the entries of the same problem made by another version (its sources changed)
    pruned = {rel for rel in diff if rel not in after and rel.endswith(".pkl") and
              any(o.rsplit("-", 1)[0] == rel.rsplit("-", 1)[0] for o in own)}
    return [rel for rel in diff if rel not in own and rel not in pruned]


def inodes(directory: Path) -> dict[str, int]:
    return {str(p.relative_to(directory)): p.lstat().st_ino for p in directory.rglob("*")}


def environment(work: Path, cache: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("LAGRADE_", "PYTEST_"))}
    for name in ("home", "tmp"):
        (work / name).mkdir(exist_ok=True)
    env.update(LAGRADE_CACHE=str(cache), HOME=str(work / "home"), XDG_CACHE_HOME=str(work / "home" / ".cache"),
               TMPDIR=str(work / "tmp"), PYTHONDONTWRITEBYTECODE="1")
    if SRC:
        env["PYTHONPATH"] = SRC
    if TRIPWIRES_OFF:
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(HERE / "tripwires_off"), env.get("PYTHONPATH")]))
        env["LAGRADE_REDTEAM_TRIPWIRES"] = "off"
    return env


def launch(work: Path, cache: Path, cwd: Path, bound: float, *args: str) -> tuple[subprocess.CompletedProcess, dict]:
    result = work / "launch.json"
    proc = subprocess.run([sys.executable, str(LAUNCH), str(result), str(bound), "--", sys.executable, "-m",
                           "lagrade", *args], cwd=cwd, env=environment(work, cache), capture_output=True,
                          timeout=bound + 120)
    return proc, json.loads(result.read_text())


@pytest.fixture(scope="module")
def planted(tmp_path_factory):
    ROOT.mkdir(mode=0o755, exist_ok=True)
    lock = open(ROOT / ".lock", "w")
    fcntl.flock(lock, fcntl.LOCK_EX)  # one red-team run on this machine at a time
    for entry in ROOT.iterdir():
        if entry.name != ".lock":
            shutil.rmtree(entry) if entry.is_dir() and not entry.is_symlink() else entry.unlink()
    tokens = [f"rt0600_{secrets.token_hex(16)}", f"rt0644_{secrets.token_hex(16)}"]
    (ROOT / "secret-0600.txt").write_text(tokens[0] + "\n")
    os.chmod(ROOT / "secret-0600.txt", 0o600)
    (ROOT / "open").mkdir(mode=0o755)
    os.chmod(ROOT / "open", 0o755)
    (ROOT / "open" / "secret-0644.txt").write_text(tokens[1] + "\n")
    os.chmod(ROOT / "open" / "secret-0644.txt", 0o644)
    DROP.mkdir()
    os.chmod(DROP, 0o1777)
    listener = Listener()
    work = tmp_path_factory.mktemp("redteam")
    # a warm reference cache, made by lagrade itself from the honest correct answer
    template = work / "cache-template"
    honest = {}
    for name, text in ((HONEST_CORRECT, _reference_answer()), (HONEST_WRONG, _wrong_answer())):
        run_dir = work / name
        run_dir.mkdir()
        (run_dir / f"{name}.py").write_text(text)
        proc, _ = launch(run_dir, template, run_dir, CHECK_BOUND, "check", "12.22", str(run_dir / f"{name}.py"), "--json", *_check_bound_args())
        honest[name] = json.loads(proc.stdout)
    os.chmod(template, 0o700)
    try:
        yield Planted(tokens, listener, template, work, honest)
    finally:
        listener.close()
        for name in ("secret-0600.txt", "open/secret-0644.txt"):
            (ROOT / name).unlink(missing_ok=True)
        lock.close()


def test_the_honest_answers_grade_as_expected(planted):
    correct, wrong = planted.honest[HONEST_CORRECT], planted.honest[HONEST_WRONG]
    assert correct["score"] == correct["max_score"] > 0
    assert 0 < wrong["score"] < wrong["max_score"]
    assert list(planted.template_cache.glob("*.pkl")), "lagrade made no cache entry to protect"


def test_every_attack_file_says_what_it_tries():
    assert len(ATTACKS) >= 60
    for path in ATTACKS:
        h = header(path)
        assert h.get("effect") in EFFECTS, f"{path.name}: first docstring lines must be 'effect: ...' and 'tries: ...'"
        assert len(h.get("tries", "")) > 20, path.name


# =========================================================================== one check per attack

@dataclass
class Run:
    name: str
    started: float
    ended: float
    output: str = ""
    verdict: dict | None = None
    launch: dict = field(default_factory=dict)
    cache: list[str] = field(default_factory=list)
    beside: list[str] = field(default_factory=list)


def run_check(planted: Planted, attack: Path) -> Run:
    work = planted.work / "check" / attack.stem
    sub, cwd, cache = work / "sub", work / "cwd", work / "cache"
    sub.mkdir(parents=True)
    cwd.mkdir()
    answer = sub / attack.name
    shutil.copyfile(attack, answer)
    shutil.copytree(planted.template_cache, cache)
    before_cache, before_sub, before_cwd = snapshot(cache), snapshot(sub), snapshot(cwd)
    cache_inodes = inodes(cache)
    started = time.monotonic()
    proc, launched = launch(work, cache, cwd, CHECK_BOUND, "check", "12.22", str(answer), "--json", *_check_bound_args())
    run = Run(attack.stem, started, time.monotonic(), proc.stdout.decode("utf-8", "replace") +
              proc.stderr.decode("utf-8", "replace"), launch=launched)
    try:
        verdict = json.loads(proc.stdout)
        run.verdict = verdict if isinstance(verdict, dict) and "score" in verdict else None
    except ValueError:
        pass
    run.cache = cache_changes(cache, before_cache, snapshot(cache), cache_inodes)
    run.beside = [f"next to the answer: {p}" for p in changed(before_sub, snapshot(sub))] + \
                 [f"in the working folder: {p}" for p in changed(before_cwd, snapshot(cwd))]
    return run


def owned(name: str, label: str | bytes, started: float, ended: float, when: float, runs: dict[str, Run]) -> bool:
    """Whose effect is a drop file or a connection: the attack it names, else every run active then."""
    text = label.decode("utf-8", "replace") if isinstance(label, bytes) else label
    named = [n for n in runs if f"pwned-{n}" in text]
    if named:
        return name in [max(named, key=len)]
    return started - 1 <= when <= ended + 1


def findings(run: Run, planted: Planted, runs: dict[str, Run], drop_times: dict[str, float]) -> list[str]:
    """Everything the attack achieved in its check run; empty when it achieved nothing."""
    out = []
    for token in planted.tokens:
        if token in run.output:
            out.append(f"read-secret: {token[:6]} token in lagrade's output")
    for fname, when in drop_times.items():
        if owned(run.name, fname, run.started, run.ended, when, runs):
            out.append(f"wrote/ran: drop/{fname}")
    out += [f"wrote: {b}" for b in run.beside]
    if run.cache:
        out.append(f"poison-cache: changed {run.cache}")
    for when, host, data in planted.listener.connections:
        if owned(run.name, data, run.started, run.ended, when, runs):
            out.append(f"network: connection to {host}:{PORT} ({data[:40]!r})")
    if run.launch.get("timed_out"):
        out.append(f"hang: no end within {CHECK_BOUND:g} s")
    elif run.verdict is None:
        out.append(f"no verdict: exit {run.launch.get('returncode')} ({run.output[-200:].strip()!r})")
    elif run.verdict["score"] >= run.verdict["max_score"]:
        out.append(f"full-marks: {run.verdict['score']}/{run.verdict['max_score']}")
    if run.launch.get("leftovers"):
        out.append(f"exhaust-processes: {len(run.launch['leftovers'])} processes outlived the run "
                   f"({run.launch['leftovers'][0][:60]})")
    if run.launch.get("max_rss_bytes", 0) > MEMORY_BOUND:
        out.append(f"exhaust-memory: a process reached {run.launch['max_rss_bytes'] >> 20} MiB")
    return out


def drop_files() -> dict[str, float]:
    """Files in drop/ and when they appeared (on the harness's monotonic clock)."""
    offset = time.time() - time.monotonic()
    return {p.name: p.lstat().st_mtime - offset for p in DROP.iterdir()}


@pytest.fixture(scope="module")
def check_results(planted):
    with ThreadPoolExecutor(max_workers=2) as pool:
        runs = {r.name: r for r in pool.map(lambda a: run_check(planted, a), ATTACKS)}
    time.sleep(1)  # connections and files from the last runs
    drops = drop_files()
    results = {name: findings(run, planted, runs, drops) for name, run in runs.items()}
    for name in list(drops):  # the grade run starts with an empty drop folder
        (DROP / name).unlink()
    _report("check", results, runs)
    return results


@pytest.mark.parametrize("attack", NAMES)
def test_check(check_results, attack):
    assert not check_results[attack], f"{attack} succeeded in `lagrade check`: " + "; ".join(check_results[attack])


# =========================================================================== one grade of a class

@dataclass
class GradeRun:
    started: float
    ended: float
    proc: subprocess.CompletedProcess
    launch: dict
    rows: dict[str, dict]
    parts: dict[str, list[dict]]
    export: dict[str, dict]
    tables: str
    triggers: list[tuple[str, str]]
    cache: list[str]
    drops: dict[str, float]
    connections: list
    beside: list[str]


@pytest.fixture(scope="module")
def grade_run(planted, check_results):  # after the checks: one heavy thing at a time
    work = planted.work / "grade"
    root, cwd, cache = work / "class", work / "cwd", work / "cache"
    cwd.mkdir(parents=True)
    for name, text in [(HONEST_CORRECT, _reference_answer()), (HONEST_WRONG, _wrong_answer())] + \
                      [(p.stem, p.read_text()) for p in ATTACKS]:
        (root / name).mkdir(parents=True)
        (root / name / "12.22.py").write_text(text)
    assignment = work / "hw.toml"
    assignment.write_text('name = "redteam"\n[limits]\n' + "".join(f"{k} = {v}\n" for k, v in LIMITS.items()) +
                          '[[problems]]\nid = "12.22"\n')
    db = work / "db" / "hw.sqlite"
    db.parent.mkdir()
    shutil.copytree(planted.template_cache, cache)
    before_cache, before_class, before_cwd = snapshot(cache), snapshot(root), snapshot(cwd)
    cache_inodes = inodes(cache)
    connections_before = len(planted.listener.connections)
    started = time.monotonic()
    flags = ["--unsafe-trusted-files"] if UNSAFE else []
    proc, launched = launch(work, cache, cwd, GRADE_BOUND, "grade", str(root), "-a", str(assignment), "--db", str(db),
                            "--workers", "2", "--no-progress", *flags)
    ended = time.monotonic()
    if b"refusing to run students' files" in proc.stdout + proc.stderr and not db.exists():
        _report("grade", {}, None, {"whole run": ["refused: " + proc.stderr.decode()[-300:]]})
        pytest.skip("lagrade grade refused the class (its jail is incomplete here): "
                    f"{proc.stderr.decode().strip()[-200:]}; LAGRADE_REDTEAM_UNSAFE=1 grades it anyway")
    time.sleep(1)
    export_proc = subprocess.run([sys.executable, "-m", "lagrade", "export", str(db), "--format", "csv"],
                                 env=environment(work, cache), capture_output=True, cwd=cwd)
    rows, parts, tables, triggers = {}, {}, "", []
    if db.exists():
        con = sqlite3.connect(db)
        con.row_factory = sqlite3.Row
        rows = {r["student"]: dict(r) for r in con.execute("SELECT * FROM submissions")}
        for r in con.execute("SELECT * FROM parts"):
            parts.setdefault(r["student"], []).append(dict(r))
        tables = "\n".join(str(tuple(r)) for t in ("submissions", "parts", "meta", "students", "skipped", "grade_log")
                           for r in con.execute(f"SELECT * FROM {t}"))
        triggers = [tuple(r) for r in con.execute("SELECT name, sql FROM sqlite_master WHERE type = 'trigger'")]
        con.close()
    export = {}
    if export_proc.returncode == 0:
        export = {r[next(iter(r))]: r for r in csv.DictReader(io.StringIO(export_proc.stdout.decode()))}
    tables += export_proc.stdout.decode("utf-8", "replace") + export_proc.stderr.decode("utf-8", "replace")
    tables += proc.stdout.decode("utf-8", "replace") + proc.stderr.decode("utf-8", "replace")
    beside = [f"in the class folder: {p}" for p in changed(before_class, snapshot(root))] + \
             [f"in the working folder: {p}" for p in changed(before_cwd, snapshot(cwd))] + \
             [f"next to the gradebook: {p.name}" for p in db.parent.iterdir()
              if p.name not in ("hw.sqlite", "hw.sqlite-wal", "hw.sqlite-shm", "hw.sqlite.lock")]
    result = GradeRun(started, ended, proc, launched, rows, parts, export, tables, triggers,
                      cache_changes(cache, before_cache, snapshot(cache), cache_inodes),
                      drop_files(), planted.listener.connections[connections_before:], beside)
    _report("grade", {name: grade_findings(result, planted, name) for name in NAMES}, None,
            {"whole run": whole_run_findings(result, planted)})
    return result


def _points(row: dict) -> float:
    return float(row.get("total") or row.get("points") or next(v for k, v in row.items() if k.startswith("12.22")))


def whole_run_findings(g: GradeRun, planted: Planted) -> list[str]:
    out = []
    if g.launch.get("timed_out"):
        out.append(f"hang: the class did not finish in {GRADE_BOUND:g} s")
    elif g.launch.get("returncode") != 0:
        out.append(f"lagrade grade exited with {g.launch.get('returncode')}: {g.proc.stderr[-300:]!r}")
    missing = [n for n in [HONEST_CORRECT, HONEST_WRONG, *NAMES] if n not in g.rows or n not in g.parts]
    if missing:
        out.append(f"no row (or no part rows) for {len(missing)} students: {missing[:5]}")
    if g.triggers:  # lagrade's schema has none
        out.append(f"other-row: the gradebook holds triggers {[t[0] for t in g.triggers]}")
    correct, wrong = g.rows.get(HONEST_CORRECT), g.rows.get(HONEST_WRONG)
    alone = planted.honest[HONEST_WRONG]["score"]
    if not correct or correct["score"] != correct["max_score"] or \
            sum(p["score"] for p in g.parts.get(HONEST_CORRECT, [])) != correct["max_score"]:
        out.append(f"other-row: the honest correct student lost marks ({correct and correct['score']} in its row, "
                   f"{sum(p['score'] for p in g.parts.get(HONEST_CORRECT, []))} in its part rows)")
    elif HONEST_CORRECT in g.export and abs(_points(g.export[HONEST_CORRECT]) - correct["max_score"]) > 1e-6:
        out.append(f"other-row: the honest correct student's exported points changed ({g.export[HONEST_CORRECT]})")
    if not wrong or abs(wrong["score"] - alone) > 1e-6 or \
            abs(sum(p["score"] for p in g.parts.get(HONEST_WRONG, [])) - alone) > 1e-6:
        out.append(f"other-row: the honest wrong student's score changed ({wrong and wrong['score']} in its row, "
                   f"{sum(p['score'] for p in g.parts.get(HONEST_WRONG, []))} in its part rows, {alone} alone)")
    elif HONEST_WRONG in g.export and abs(_points(g.export[HONEST_WRONG]) - alone) > 1e-6:
        out.append(f"other-row: the honest wrong student's exported points changed ({g.export[HONEST_WRONG]})")
    for token in planted.tokens:
        if token in g.tables:
            out.append(f"read-secret: {token[:6]} token in the gradebook or its export")
    if g.cache:
        out.append(f"poison-cache: changed {g.cache}")
    if g.drops:
        out.append(f"wrote/ran: drop/ holds {sorted(g.drops)}")
    if g.connections:
        out.append(f"network: {len(g.connections)} connections ({[c[2][:30] for c in g.connections]})")
    out += [f"wrote: {b}" for b in g.beside]
    if g.launch.get("leftovers"):
        out.append(f"exhaust-processes: {len(g.launch['leftovers'])} processes outlived the run "
                   f"({sorted(set(x[:50] for x in g.launch['leftovers']))[:3]})")
    if g.launch.get("max_rss_bytes", 0) > MEMORY_BOUND:
        out.append(f"exhaust-memory: a process reached {g.launch['max_rss_bytes'] >> 20} MiB")
    return out


def grade_findings(g: GradeRun, planted: Planted, name: str) -> list[str]:
    """What the whole run shows that names this attack (its row, its files, its connections)."""
    out = []
    row = g.rows.get(name)
    if row is None:
        out.append("no row in the gradebook")
    elif row["score"] >= row["max_score"]:
        out.append(f"full-marks: {row['score']}/{row['max_score']}")
    text = "\n".join(str(v) for v in (row or {}).values()) + "\n".join(str(p) for p in g.parts.get(name, []))
    for token in planted.tokens:
        if token in text:
            out.append(f"read-secret: {token[:6]} token in its row")
    out += [f"wrote/ran: drop/{f}" for f in g.drops if f"pwned-{name}" in f]
    source = (HERE / "attacks" / f"{name}.py").read_text()
    out += [f"other-row: its trigger {t[0]} is in the gradebook" for t in g.triggers if t[0] in source]
    out += [f"network: connection ({c[2][:30]!r})" for c in g.connections if f"pwned-{name}".encode() in c[2]]
    return out


def test_grade_run_as_a_whole(grade_run, planted):
    problems = whole_run_findings(grade_run, planted)
    assert not problems, "the class run was attacked: " + "; ".join(problems)


@pytest.mark.parametrize("attack", NAMES)
def test_grade(grade_run, planted, attack):
    problems = grade_findings(grade_run, planted, attack)
    assert not problems, f"{attack} succeeded in `lagrade grade`: " + "; ".join(problems)


# =========================================================================== the report for README

def _report(kind: str, results: dict[str, list[str]], runs: dict[str, Run] | None, extra: dict | None = None) -> None:
    path = os.environ.get("LAGRADE_REDTEAM_REPORT")
    if not path:
        return
    report = json.loads(Path(path).read_text()) if Path(path).exists() else {}
    section = report.setdefault(kind, {})
    for name, found in {**results, **(extra or {})}.items():
        entry = {"findings": found}
        if runs and name in runs:
            r = runs[name]
            entry["problems"] = (r.verdict or {}).get("problems", [])
            entry["seconds"] = round(r.launch.get("seconds", 0), 1)
            entry["exit"] = r.launch.get("returncode")
        section[name] = entry
    Path(path).write_text(json.dumps(report, indent=1))
