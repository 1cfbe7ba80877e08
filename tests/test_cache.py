"""The disk cache of reference derivations: faster, never different, never fatal, never shared."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from lagrade.derive import cache
from lagrade.answer.reading.load import load_answer
from lagrade.verdicts.grade import grade_values
from lagrade.problem.library import load_problem
from lagrade.derive.reference import ReferenceCache

ROOT = Path(__file__).resolve().parents[1]


def _check(pid: str, env: dict[str, str], answer: Path | None = None) -> dict:
    answer = answer or ROOT / "reference_solutions" / pid / "answer.py"
    out = subprocess.run([sys.executable, "-m", "lagrade", "check", pid, str(answer), "--json"],
                         capture_output=True, text=True, env=env, timeout=300)
    return json.loads(out.stdout)


def _comparable(result: dict) -> list:
    # timings differ between runs; verdicts, scores and feedback must not
    return [(p["part"], p["verdict"], p["score"], p["method"]) for p in result["parts"]]


@pytest.mark.parametrize("pid", ["12.14", "12.22", "12.46"])
def test_warm_check_grades_exactly_like_a_cold_one(pid, tmp_path):
    env = {**os.environ, "LAGRADE_CACHE": str(tmp_path / "c")}
    cold = _check(pid, env)
    assert len(cache.entries(tmp_path / "c")) == 1
    warm = _check(pid, env)
    off = _check(pid, {**os.environ, "LAGRADE_CACHE": "off"})
    assert _comparable(cold) == _comparable(warm) == _comparable(off)
    assert warm["score"] == warm["max_score"]


def test_warm_check_still_catches_a_wrong_answer(tmp_path):
    env = {**os.environ, "LAGRADE_CACHE": str(tmp_path / "c")}
    wrong = ROOT / "tests" / "answers" / "12.14"
    files = sorted(wrong.glob("wrong_*.py"))
    assert files
    _check("12.14", env)  # warms the cache with the reference solution
    result = _check("12.14", env, files[0])
    assert result["score"] < result["max_score"]


def test_a_check_never_rewrites_an_entry_it_loaded_but_cache_build_does(tmp_path, monkeypatch):
    """What an answer makes the grader derive (here: a wrong L whose diagnosis parses the problem's
    named mistakes) must not change an existing entry: the red team's poison-cache."""
    env = {**os.environ, "LAGRADE_CACHE": str(tmp_path / "c")}
    _check("12.22", env)  # makes the entry
    [entry] = cache.entries(tmp_path / "c")
    before = entry.read_bytes()
    wrong = tmp_path / "wrong.py"
    wrong.write_text((ROOT / "reference_solutions" / "12.22" / "answer.py").read_text() + "\nL = L**3\n")
    result = _check("12.22", env, wrong)
    assert result["score"] < result["max_score"]
    assert entry.read_bytes() == before
    # `lagrade cache build` grades the reference solution into the entry it loads, and may add to it
    from lagrade.verdicts import grade

    monkeypatch.setenv("LAGRADE_CACHE", str(tmp_path / "c"))
    monkeypatch.setattr(grade, "_REFERENCES", {})  # as in a fresh process: loaded from the entry
    monkeypatch.setattr(grade, "_FROM_DISK", set())
    problem = load_problem("12.22")
    grade.references(problem)[problem.systems[0].key].parse("x_d**7")
    assert not grade.keep_references(problem)
    assert entry.read_bytes() == before
    assert grade.keep_references(problem, update=True)
    assert entry.read_bytes() != before


def _warm(problem) -> ReferenceCache:
    from lagrade.verdicts.grade import references

    grade_values(problem, load_answer(ROOT / "reference_solutions" / problem.id / "answer.py", problem), read_as=())
    return references(problem)


def test_entry_round_trips_and_is_rewritten_only_when_something_new(tmp_path, monkeypatch):
    monkeypatch.setenv("LAGRADE_CACHE", str(tmp_path))
    problem = load_problem("12.43")
    refs = _warm(problem)
    refs.saved_size = 0
    assert cache.save(refs)
    assert not cache.save(refs)  # nothing new
    loaded = cache.load(problem)
    assert loaded is not None and loaded.problem is problem
    assert set(loaded.systems) == set(refs.systems)
    mech, back = refs[problem.systems[0].key], loaded[problem.systems[0].key]
    assert back.runs.keys() == mech.runs.keys() and back.runs
    import numpy as np

    q = np.array([[0.3, -0.2]])
    p = np.array([[0.1, 0.5]])
    params = np.ones((len(mech.params), 2))
    t = np.zeros(2)
    assert np.allclose(back.hamilton_rates(q, p, t, params), mech.hamilton_rates(q, p, t, params))


@pytest.mark.parametrize("damage", ["garbage", "truncated", "foreign"])
def test_a_damaged_or_foreign_entry_is_ignored(damage, tmp_path, monkeypatch):
    monkeypatch.setenv("LAGRADE_CACHE", str(tmp_path))
    problem = load_problem("12.43")
    refs = _warm(problem)
    refs.saved_size = 0
    assert cache.save(refs)
    path = cache.entry_path(problem)
    if damage == "garbage":
        path.write_bytes(b"not a pickle")
    elif damage == "truncated":
        path.write_bytes(path.read_bytes()[:100])
    else:
        path.chmod(0o666)  # anyone could have written it: never unpickled
    assert cache.load(problem) is None
    result = _check("12.43", {**os.environ, "LAGRADE_CACHE": str(tmp_path)})
    assert result["score"] == result["max_score"]


def test_an_unwritable_cache_never_fails_a_check(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    result = _check("12.43", {**os.environ, "LAGRADE_CACHE": str(blocker / "cache")})
    assert result["score"] == result["max_score"]


def test_an_edited_problem_gets_its_own_entry(tmp_path, monkeypatch):
    monkeypatch.setenv("LAGRADE_CACHE", str(tmp_path))
    original = load_problem("12.43")
    text = (ROOT / "problems" / "12.43.toml").read_text()
    edited_file = tmp_path / "12.43.toml"
    edited_file.write_text(text.replace("horizon", "# edited\nhorizon", 1) if "horizon" in text else text + "\n# edited\n")
    edited = load_problem(edited_file)
    assert cache.entry_path(original) == cache.entry_path(load_problem(ROOT / "problems" / "12.43.toml"))
    if edited.model_dump_json() != original.model_dump_json():
        assert cache.entry_path(edited) != cache.entry_path(original)
    changed = original.model_copy(update={"title": original.title + " (edited)"})
    assert cache.entry_path(changed) != cache.entry_path(original)


def test_cache_off(monkeypatch):
    monkeypatch.setenv("LAGRADE_CACHE", "off")
    assert cache.cache_dir() is None and cache.entry_path(load_problem("12.43")) is None


def test_answers_can_never_read_the_cache(monkeypatch, tmp_path):
    from lagrade.answer.jail import child

    monkeypatch.setenv("LAGRADE_CACHE", str(tmp_path / "c"))
    child.secret_dirs.cache_clear()
    try:
        assert str((tmp_path / "c").resolve()) in child.secret_dirs()
    finally:
        child.secret_dirs.cache_clear()


def test_cache_commands(tmp_path):
    env = {**os.environ, "LAGRADE_CACHE": str(tmp_path / "c")}
    run = lambda *a: subprocess.run([sys.executable, "-m", "lagrade", "cache", *a], capture_output=True,  # noqa: E731
                                    text=True, env=env, timeout=300)
    built = run("build", "12.43", "12.4")
    assert built.returncode == 0, built.stderr
    assert "12.43: built" in built.stdout and "12.4: built" in built.stdout
    again = run("build", "12.43")
    assert "12.43: up to date" in again.stdout
    info = run("info")
    assert "entries: 2" in info.stdout
    assert "removed 2 entries" in run("clear").stdout
    assert "entries: 0" in run("info").stdout
    bad = run("build", "no-such-problem")
    assert bad.returncode == 1 and "no-such-problem: skipped" in bad.stderr


def test_cache_build_byte_compiles_lagrade_even_where_python_would_not_write_bytecode(tmp_path):
    """A check imports ~40 lagrade modules: with PYTHONDONTWRITEBYTECODE (or an editable install
    never imported yet) each would be compiled from source by every check."""
    import importlib.util

    import lagrade

    package = Path(lagrade.__file__).parent
    compiled = Path(importlib.util.cache_from_source(str(package / "verdicts" / "readback.py")))
    compiled.unlink(missing_ok=True)
    env = {**os.environ, "LAGRADE_CACHE": str(tmp_path / "c"), "PYTHONDONTWRITEBYTECODE": "1"}
    done = subprocess.run([sys.executable, "-m", "lagrade", "cache", "build", "12.4"], capture_output=True,
                          text=True, env=env, timeout=300)
    assert done.returncode == 0, done.stderr
    assert compiled.is_file()


def test_an_entry_replaces_the_stale_ones_of_its_problem(tmp_path, monkeypatch):
    monkeypatch.setenv("LAGRADE_CACHE", str(tmp_path))
    tmp_path.chmod(0o700)
    problem = load_problem("12.43")
    stale = tmp_path / "12.43-0123456789abcdef0123.pkl"
    other = tmp_path / "12.4-0123456789abcdef0123.pkl"  # another problem whose id is a prefix
    stale.write_bytes(b"old")
    other.write_bytes(b"old")
    refs = _warm(problem)
    refs.saved_size = 0
    assert cache.save(refs)
    assert not stale.exists() and other.exists()
    assert cache.entries(tmp_path) == sorted([cache.entry_path(problem), other])
