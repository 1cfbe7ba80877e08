"""Nothing in the reference cache is unpickled unless lagrade wrote it under this user's key.

Unpickling runs code: a pickle that anything else could put at an entry's path (a student's code
running as the same user, before the sandbox ran as another one) ran as the grader."""

from __future__ import annotations

import json
import os
import pickle
import subprocess
import sys
from pathlib import Path

import pytest

from lagrade.derive import cache
from lagrade.answer.reading.load import load_answer
from lagrade.verdicts.grade import grade_values, references
from lagrade.problem.library import load_problem

ROOT = Path(__file__).resolve().parents[1]
PROBLEM = load_problem("12.43")


class _Payload:
    """Makes ``marker`` when unpickled."""

    def __init__(self, marker: Path) -> None:
        self.marker = marker

    def __reduce__(self):
        return os.mkdir, (str(self.marker),)


@pytest.fixture(scope="module")
def refs():
    grade_values(PROBLEM, load_answer(ROOT / "reference_solutions" / "12.43" / "answer.py", PROBLEM), read_as=())
    return references(PROBLEM)


@pytest.fixture
def entry(refs, tmp_path, monkeypatch) -> Path:
    """A valid entry of 12.43 in a fresh cache (its key made with it)."""
    directory = tmp_path / "c"
    monkeypatch.setenv("LAGRADE_CACHE", str(directory))
    refs.saved_size = 0
    assert cache.save(refs)
    return cache.entry_path(PROBLEM)


def _check(directory: Path) -> dict:
    out = subprocess.run([sys.executable, "-m", "lagrade", "check", "12.43",
                          str(ROOT / "reference_solutions" / "12.43" / "answer.py"), "--json"],
                         capture_output=True, text=True, env={**os.environ, "LAGRADE_CACHE": str(directory)},
                         timeout=300)
    return json.loads(out.stdout)


def test_a_valid_entry_round_trips(entry):
    assert entry.read_bytes().startswith(cache.HEADER)
    assert (entry.parent / cache.KEY_FILE).stat().st_mode & 0o777 == 0o600
    assert entry.parent.stat().st_mode & 0o777 == 0o700
    loaded = cache.load(PROBLEM)
    assert loaded is not None and loaded.problem is PROBLEM and loaded.systems.keys() == references(PROBLEM).systems.keys()


@pytest.mark.parametrize("form", ["bare pickle", "header and a made-up MAC"])
def test_a_forged_entry_is_never_unpickled_and_is_rebuilt(entry, tmp_path, form):
    marker = tmp_path / "unpickled"
    payload = pickle.dumps(_Payload(marker))
    entry.write_bytes(payload if form == "bare pickle" else cache.HEADER + bytes(32) + payload)
    os.chmod(entry, 0o600)  # as private as a real entry: only the MAC can tell
    assert cache.load(PROBLEM) is None
    result = _check(entry.parent)
    assert result["score"] == result["max_score"]
    assert not marker.exists()
    assert cache.load(PROBLEM) is not None  # the check wrote a valid entry in its place


@pytest.mark.parametrize("where", ["header", "mac", "pickle"])
def test_a_tampered_entry_is_rebuilt(entry, where):
    blob = bytearray(entry.read_bytes())
    at = {"header": 0, "mac": len(cache.HEADER) + 5, "pickle": len(blob) // 2}[where]
    blob[at] ^= 0x01
    entry.write_bytes(bytes(blob))
    assert cache.load(PROBLEM) is None
    result = _check(entry.parent)
    assert result["score"] == result["max_score"]
    assert cache.load(PROBLEM) is not None


def test_an_entry_copied_under_another_name_does_not_verify(entry):
    other = PROBLEM.model_copy(update={"title": PROBLEM.title + " (edited)"})
    cache.entry_path(other).write_bytes(entry.read_bytes())
    assert cache.load(other) is None


def _refused(entry: Path, refs) -> None:
    with pytest.raises(cache.UntrustedKey):
        cache.key(entry.parent)
    assert cache.load(PROBLEM) is None  # even a valid entry: its key may be known to others
    refs.saved_size = 0
    assert not cache.save(refs)


def test_a_key_others_can_read_is_refused(entry, refs):
    key = entry.parent / cache.KEY_FILE
    key.chmod(0o644)
    _refused(entry, refs)
    assert key.stat().st_mode & 0o777 == 0o644  # refused, not silently replaced
    info = subprocess.run([sys.executable, "-m", "lagrade", "cache", "info"], capture_output=True, text=True,
                          env={**os.environ, "LAGRADE_CACHE": str(entry.parent)}, timeout=120)
    assert "key: refused" in info.stdout and "mode 644" in info.stdout


def test_a_key_of_another_user_is_refused(entry, refs, monkeypatch):
    key = entry.parent / cache.KEY_FILE
    if os.getuid() == 0:
        os.chown(key, 65534, 65534)
        _refused(entry, refs)
    else:  # only root can give a file away: here the key is the other user's because we are not its owner
        real = os.getuid()
        monkeypatch.setattr(os, "getuid", lambda: real + 1)
        with pytest.raises(cache.UntrustedKey, match="not a file of this user's"):
            cache.key(entry.parent)


@pytest.mark.parametrize("bad", ["short", "symlink"])
def test_a_key_of_the_wrong_size_or_a_link_is_refused(entry, refs, bad):
    key = entry.parent / cache.KEY_FILE
    if bad == "short":
        key.write_bytes(key.read_bytes()[:16])
    else:
        elsewhere = entry.parent.parent / "key"
        key.rename(elsewhere)
        key.symlink_to(elsewhere)
    _refused(entry, refs)


def test_a_lost_key_is_made_again_and_old_entries_are_rebuilt(entry, refs):
    (entry.parent / cache.KEY_FILE).unlink()
    assert cache.load(PROBLEM) is None
    refs.saved_size = 0
    assert cache.save(refs)
    assert cache.load(PROBLEM) is not None
