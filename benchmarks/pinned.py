"""Issue 48's table: this checkout against the pinned older commit, every row measured in one run.

    python benchmarks/pinned.py                     # against the pin (check_against.PIN), the table printed
    python benchmarks/pinned.py --against ad7372a --markdown

Runs, one after the other (so that all of them see the same machine; run it on an idle one):
``check_against.py`` (a check of 12.14's, 12.22's and 12.43's reference against the import floor, the
old commit interleaved), ``bulk.py`` on the 200-submission class of 12.14 by this checkout and by the
old commit's sources (``--lagrade-src``), then the same with ``--distinct`` (every file a program of
its own; no baseline, whose per-file checks the row does not need), and ``serve_load.py`` with 200
students at once (with and without ``--distinct``), by this checkout only: the older server's API
differs. Each script writes its figures with ``--json``; this one prints them as a Markdown table
with the goals beside them.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from check_against import PIN, worktree  # noqa: E402


def figures(script: str, *args: str) -> dict:
    """Run ``benchmarks/<script>`` with ``args`` and ``--json``; its figures (its own output passes through)."""
    with tempfile.NamedTemporaryFile(suffix=".json", delete=False) as f:
        out = Path(f.name)
    try:
        print(f"$ python benchmarks/{script} {' '.join(args)}", flush=True)
        subprocess.run([sys.executable, str(HERE / script), *args, "--json", str(out)], check=True)
        return json.loads(out.read_text())
    finally:
        out.unlink(missing_ok=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--against", default=PIN, help=f"the older commit (default: the pin, {PIN})")
    ap.add_argument("--repeats", type=int, default=3, help="check_against.py's repeats")
    ap.add_argument("--worktrees", type=Path, default=Path(tempfile.gettempdir()))
    args = ap.parse_args()
    old = worktree(args.against, args.worktrees)
    label = args.against if not Path(args.against).is_dir() else old.name

    check = figures("check_against.py", "--against", str(old), "--repeats", str(args.repeats), "12.14", "12.22", "12.43")
    bulk_new = figures("bulk.py", "--repeats", "1", "--no-memory")
    bulk_old = figures("bulk.py", "--repeats", "1", "--no-memory", "--lagrade-src", str(old / "src"))
    distinct_new = figures("bulk.py", "--repeats", "1", "--no-memory", "--no-baseline", "--distinct")
    distinct_old = figures("bulk.py", "--repeats", "1", "--no-memory", "--no-baseline", "--distinct",
                           "--lagrade-src", str(old / "src"))
    serve = figures("serve_load.py", "--students", "200", "--spread", "0", "--hostile", "0", "--no-probe")
    serve_distinct = figures("serve_load.py", "--students", "200", "--spread", "0", "--hostile", "0", "--no-probe",
                             "--distinct")

    def bulk(b: dict) -> str:
        return (f"{b['seconds']:.1f} s ({b['cpu']:.1f} s of CPU, {b['idle_cores']:.1f} s over two idle cores), "
                f"{b['ratio']:.1f}x one check per file ({b['cpu_ratio']:.1f}x of CPU)")

    def per_file(b: dict) -> str:
        return (f"{b['seconds']:.1f} s; lagrade {b['lagrade_ms_per_file']:.0f} ms of CPU a file, the answers' "
                f"own code {b['own'] / b['n'] * 1000:.0f} ms")

    def served(s: dict) -> str:
        return (f"p95 {s['p95']:.1f} s, {s['throughput']:.1f}/s, {s['server_cpu_ms'] + s['graders_cpu_ms']:.0f} ms CPU "
                f"a submission (web process {s['server_cpu_ms']:.0f} ms), {s['burst_idle']:.1f} s of CPU over two "
                f"idle cores; the simulated students' own {s['clients_cpu']:.1f} s on the same cores")

    w = check["wall"]
    rows = [
        ("`lagrade check` of 12.14's, 12.22's and 12.43's reference / import floor (wall; CPU of its own process)",
         f"{w['old']:.2f}x; {check['own_cpu']['old']:.2f}x",
         f"{w['new']:.2f}x ({w['new_over_old']:.2f}x the old); {check['own_cpu']['new']:.2f}x", "<= 1.1x"),
        ("`python benchmarks/bulk.py` (200 submissions, 22 distinct files)", bulk(bulk_old), bulk(bulk_new),
         "< 8 s, >= 20x"),
        ("`bulk.py --distinct` (every file a program of its own)", per_file(distinct_old), per_file(distinct_new),
         "<= 50 ms of lagrade CPU a file"),
        ("`serve_load.py --students 200 --spread 0 --hostile 0`", "not run (the server's API differs)", served(serve),
         "p95 < 3 s"),
        ("the same, `--distinct`", "", served(serve_distinct), ""),
    ]
    print(f"\n(The floor: {w['floor_seconds']:.2f} s of wall time a run; graded unexpectedly: "
          f"{bulk_new['unexpected']} and {distinct_new['unexpected']} here, {bulk_old['unexpected']} and "
          f"{distinct_old['unexpected']} by {label}.)\n")
    print(f"| what | {label} | this checkout | goal |")
    print("|---|---|---|---|")
    for row in rows:
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
