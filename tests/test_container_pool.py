"""A Gradescope submission's answers are graded at once only as far as the container's memory holds
them (issue 43, item 6: three large answers peaked at 1070 MiB in Gradescope's 768 MB container).
The container's memory is read from fake cgroup v2 / v1 trees and /proc files here."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.uses.deploy.pool import BASE_MB, GRADER_MB, memory_limit, pool_size

MB = 10**6
GIB = 2**30


def _fake(tmp: Path, *, v2: dict[str, str] | None = None, v1: dict[str, str] | None = None,
          cgroup: str = "0::/\n", ram_kib: int | None = 16 * 2**20) -> dict[str, Path]:
    """A /sys/fs/cgroup tree with ``memory.max`` (v2) or ``memory/memory.limit_in_bytes`` (v1) files at
    the given cgroup paths, a /proc/self/cgroup and a /proc/meminfo."""
    root = tmp / "cgroup"
    root.mkdir(parents=True)
    for where, value in (v2 or {}).items():
        (root / where.strip("/")).mkdir(parents=True, exist_ok=True)
        (root / where.strip("/") / "memory.max").write_text(value + "\n")
    for where, value in (v1 or {}).items():
        d = root / "memory" / where.strip("/")
        d.mkdir(parents=True, exist_ok=True)
        (d / "memory.limit_in_bytes").write_text(value + "\n")
    (tmp / "self-cgroup").write_text(cgroup)
    (tmp / "meminfo").write_text(f"MemTotal:       {ram_kib} kB\nMemFree:  1000 kB\n" if ram_kib else "")
    return {"cgroup_root": root, "proc_cgroup": tmp / "self-cgroup", "meminfo": tmp / "meminfo"}


def test_a_cgroup_v2_limit_is_the_containers_memory(tmp_path):
    """Docker's cgroup namespace: the container's own limit at the root of /sys/fs/cgroup."""
    assert memory_limit(**_fake(tmp_path, v2={"/": str(768 * MB)})) == 768 * MB


def test_the_smallest_limit_on_the_way_up_counts(tmp_path):
    """A process in a cgroup under a limited parent (systemd slices): the parent's limit binds."""
    paths = _fake(tmp_path, v2={"/": "max", "/grading.slice": str(2 * GIB), "/grading.slice/job": "max"},
                  cgroup="0::/grading.slice/job\n")
    assert memory_limit(**paths) == 2 * GIB


def test_a_cgroup_v1_limit_is_read_and_its_no_limit_ignored(tmp_path):
    paths = _fake(tmp_path, v1={"/": "9223372036854771712", "/docker/abc": str(768 * MB)},
                  cgroup="12:memory:/docker/abc\n11:cpu,cpuacct:/docker/abc\n")
    assert memory_limit(**paths) == 768 * MB


def test_no_limit_falls_back_to_the_machines_ram(tmp_path):
    assert memory_limit(**_fake(tmp_path, v2={"/": "max"}, ram_kib=4 * 2**20)) == 4 * GIB
    assert memory_limit(**_fake(tmp_path / "n", ram_kib=None)) is None  # nothing readable: unknown


def test_a_limit_above_the_ram_is_the_ram(tmp_path):
    assert memory_limit(**_fake(tmp_path, v2={"/": str(64 * GIB)}, ram_kib=2 * 2**20)) == 2 * GIB


def test_gradescopes_default_container_grades_one_answer_at_a_time():
    """768 MB, answers bounded at 384 MB (lagrade's Gradescope default): two graders would be
    2 x (200 + 384) + 100 MiB, over the container; three were measured at 1070 MiB."""
    assert pool_size(3, 384, 768 * MB, cores=4) == 1
    assert 2 * (GRADER_MB + 384) + BASE_MB > 768 * MB / 2**20


@pytest.mark.parametrize("jobs, answer_mb, memory, cores, expected", [
    (3, 384, 3 * GIB, 4, 3),            # room for all three: the cores and the answers bound it
    (3, 384, 3 * GIB // 2, 4, 2),       # (1536 - 100) // (200 + 384) = 2
    (8, 1024, 4 * GIB, 8, 3),           # (4096 - 100) // 1224 = 3
    (8, 384, 64 * GIB, 2, 2),           # a big machine: the cores bound it
    (1, 384, 64 * GIB, 8, 1),           # one answer: one grader
    (5, 384, 100 * MB, 4, 1),           # too small even for one: one, as the bound of each answer says
    (5, 384, None, 4, 4),               # memory unknown: the cores
    (0, 384, 3 * GIB, 4, 1),
])
def test_the_pool_is_what_the_memory_holds(jobs, answer_mb, memory, cores, expected):
    assert pool_size(jobs, answer_mb, memory, cores) == expected


@pytest.mark.slow  # the jail's probe and three problems loaded: 6 s
def test_gradescope_run_sizes_its_pool_to_the_container(tmp_path, monkeypatch):
    """`lagrade gradescope run` without -j: three answers in a 768 MB container go one at a time (it
    used to start one grader per core, up to three here); -j still says how many."""
    import lagrade.uses.bulk.runner as runner
    import lagrade.uses.deploy.pool as pool
    from click.testing import CliRunner

    from lagrade.cli.bulk import gradescope

    class Stop(Exception):
        pass

    asked = []

    def fake_grade_folder(root, assignment, db, *, workers=None, **kwargs):
        asked.append((workers, assignment.limits.memory_mb))
        raise Stop

    monkeypatch.setattr(runner, "grade_folder", fake_grade_folder)
    monkeypatch.setattr(pool, "memory_limit", lambda: 768 * MB)
    monkeypatch.setattr("os.cpu_count", lambda: 4)
    repo = Path(__file__).resolve().parents[1]
    (tmp_path / "submission").mkdir()
    ids = ("12.14", "12.22", "12.43")
    for pid in ids:
        answer = (repo / "reference_solutions" / pid / "answer.py").read_text()
        (tmp_path / "submission" / f"{pid}.py").write_text(answer)
    (tmp_path / "hw.toml").write_text('name = "hw"\n' + "".join(f'[[problems]]\nid = "{p}"\n' for p in ids))
    args = ["run", "--submission", str(tmp_path / "submission"), "--assignment", str(tmp_path / "hw.toml"),
            "--results", str(tmp_path / "results.json")]
    res = CliRunner().invoke(gradescope, args)
    if asked == []:  # a machine where the jail check refuses (not Linux): nothing to size
        pytest.skip(res.output)
    assert isinstance(res.exception, Stop) and asked == [(1, 384)], (res.output, asked)
    assert "1 grader(s) at once: 384 MB an answer in 732 MiB" in res.output
    asked.clear()
    res = CliRunner().invoke(gradescope, [*args, "-j", "3"])
    assert asked == [(3, 384)]
