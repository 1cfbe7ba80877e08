"""Reference derivations kept on disk between runs.

Every check of a problem needs the same reference work: parsing the scene, deriving Lagrange's
equations, compiling them, sampling states and integrating the reference motions. In one process
that is done once (:func:`lagrade.verdicts.grade.references`); this module keeps it across processes, so a
``lagrade check`` costs little more than importing sympy. ``lagrade cache build`` makes the entries
ahead of time; a check that derives something new updates its problem's entry.

An entry is a pickle, and unpickling runs code, so no file is trusted for where it lies or who owns
it: an entry is a header, an HMAC-SHA256 of the header, its name and the pickle under a secret key,
and the pickle. The MAC is checked before anything is unpickled. The key is 32 random bytes in
``<cache>/.key``, made on first use, readable only by this user (a key file anyone else could read
or replace is refused, and the cache is then not used). Whoever cannot read the key cannot write an
entry lagrade will read, even where they can write the directory; the sandbox never lets an answer
file see the cache at all. Entries are also only read from a directory this user owns and nobody
else can write. An entry's name hashes everything that could change its content: the problem as
loaded, lagrade's own source files (size and mtime, so an edited checkout never reads a stale entry),
the versions of Python, sympy and numpy, and the kind of compiled code (machine code through
symengine, or numpy). A corrupt, forged, foreign or unreadable entry is ignored and rebuilt: the cache
can make a check faster, never wrong and never fail.
``LAGRADE_CACHE=off`` turns it off; ``LAGRADE_CACHE=DIR`` moves it.
"""

from __future__ import annotations

import glob
import hashlib
import hmac
import os
import pickle
import secrets
import stat
import sys
import tempfile
from functools import lru_cache
from pathlib import Path

from typing import TYPE_CHECKING

from lagrade._version import __version__
from lagrade.problem.library import cache_dir

if TYPE_CHECKING:  # no heavy imports at module level: a check imports this before the grader
    from lagrade.derive.reference import ReferenceCache
    from lagrade.problem.spec import Problem

_PACKAGE = Path(__file__).resolve().parents[1]  # the lagrade package: every source file counts
HEADER = b"lagrade-reference\x00\x01"  # magic and format version
KEY_FILE = ".key"
KEY_BYTES = 32
_MAC_BYTES = hashlib.sha256().digest_size


class UntrustedKey(Exception):
    """The key file exists but is not this user's secret; the message says why."""


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """lagrade's version and its source files as installed: an edit invalidates every entry."""
    import numpy as np
    import sympy as sp

    from lagrade.numbers.numeric import backend

    versions = f"{__version__} {sys.version} {sp.__version__} {np.__version__} {backend()}"
    h = hashlib.sha256(versions.encode())
    for path in sorted(_PACKAGE.rglob("*.py")):
        st = path.stat()
        h.update(f"{path.relative_to(_PACKAGE)} {st.st_size} {st.st_mtime_ns}\n".encode())
    return h.hexdigest()


def entry_path(problem: Problem, directory: Path | None = None) -> Path | None:
    directory = directory or cache_dir()
    if directory is None:
        return None
    h = hashlib.sha256(code_fingerprint().encode())
    h.update(problem.model_dump_json().encode())
    safe = "".join(c if c.isalnum() or c in ".-_" else "_" for c in problem.id)
    return directory / f"{safe}-{h.hexdigest()[:20]}.pkl"


def _private(path: Path) -> bool:
    """Owned by this user and writable by nobody else."""
    try:
        st = path.stat()
    except OSError:
        return False
    return st.st_uid == os.getuid() and not st.st_mode & (stat.S_IWGRP | stat.S_IWOTH)


def _trusted(path: Path) -> bool:
    """An entry only this user could have written: the file and its directory are private."""
    return _private(path.parent) and _private(path)


def key(directory: Path, create: bool = False) -> bytes | None:
    """The directory's secret key; None if there is none (and ``create`` is false). Raises
    :class:`UntrustedKey` for a key file that is not a regular file of this user's, private to it,
    of the right size: one that others could read or have written authenticates nothing."""
    path = directory / KEY_FILE
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except FileNotFoundError:
        return _new_key(path) if create else None
    except OSError as exc:  # a symbolic link, another user's private file, ...
        raise UntrustedKey(f"{path}: {exc.strerror}") from None
    try:
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode) or st.st_uid != os.getuid():
            raise UntrustedKey(f"{path} is not a file of this user's")
        if st.st_mode & 0o077:
            raise UntrustedKey(f"{path} is readable or writable by others (mode {st.st_mode & 0o777:o})")
        secret = os.read(fd, KEY_BYTES + 1)
    finally:
        os.close(fd)
    if len(secret) != KEY_BYTES:
        raise UntrustedKey(f"{path} is not a key of {KEY_BYTES} bytes")
    return secret


def _new_key(path: Path) -> bytes | None:
    """Make the key: created exclusively, private from its first byte. A new key invalidates every
    entry made under an old one (they are then rebuilt). Another process may make it first: then
    theirs is read."""
    try:
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW, 0o600)
    except FileExistsError:
        return key(path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(secrets.token_bytes(KEY_BYTES))
    except BaseException:
        path.unlink(missing_ok=True)  # never leave a short key behind: it would be refused forever
        raise
    return key(path.parent)


def _mac(secret: bytes, name: str, data: bytes | memoryview) -> bytes:
    """Over the header, the entry's name (an entry copied to another problem's or version's name
    does not verify) and the pickle."""
    h = hmac.new(secret, HEADER, hashlib.sha256)
    h.update(name.encode() + b"\x00")
    h.update(data)
    return h.digest()


def _verified(blob: bytes, secret: bytes, name: str) -> memoryview | None:
    """The pickle of an entry whose MAC verifies, else None; nothing is unpickled here."""
    start = len(HEADER) + _MAC_BYTES
    if len(blob) < start or not blob.startswith(HEADER):
        return None
    data = memoryview(blob)[start:]
    if not hmac.compare_digest(blob[len(HEADER):start], _mac(secret, name, data)):
        return None
    return data


def load(problem: Problem) -> ReferenceCache | None:
    """The problem's derivations from disk, or None (no entry, stale, forged, foreign or unreadable)."""
    from lagrade.derive.reference import ReferenceCache

    path = entry_path(problem)
    if path is None or not path.is_file() or not _trusted(path):
        return None
    try:
        secret = key(path.parent)
        data = _verified(path.read_bytes(), secret, path.name) if secret else None
        if data is None:
            return None
        refs = pickle.loads(data)  # noqa: S301  (authenticated above: written by lagrade under this user's key)
    except Exception:  # noqa: BLE001  (an untrusted key, an incompatible entry: rebuilt, never fatal)
        return None
    if not isinstance(refs, ReferenceCache):
        return None
    refs.problem = problem
    for mech in refs.systems.values():
        mech.problem = problem
    refs.saved_size = refs.size()
    return refs


def save(refs: ReferenceCache) -> bool:
    """Write the entry if this process derived something it did not hold; atomic, best effort."""
    if refs.size() <= refs.saved_size:
        return False
    path = entry_path(refs.problem)
    if path is None:
        return False
    try:
        path.parent.mkdir(mode=0o700, parents=True, exist_ok=True)
        if not _private(path.parent):
            return False
        secret = key(path.parent, create=True)
        data = pickle.dumps(refs, protocol=pickle.HIGHEST_PROTOCOL)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-", suffix=".pkl")
        try:
            with os.fdopen(fd, "wb") as fh:
                fh.write(HEADER + _mac(secret, path.name, data))
                fh.write(data)
            os.replace(tmp, path)
        except BaseException:
            os.unlink(tmp)
            raise
    except Exception:  # noqa: BLE001  (a read-only home, a full disk or an untrusted key must not fail a check)
        return False
    refs.saved_size = refs.size()
    _prune(path)
    return True


def _prune(kept: Path) -> None:
    """Entries of the same problem id made by another lagrade, sympy or problem version are never
    read again: one entry per problem id stays, so the cache does not grow with every upgrade."""
    prefix = kept.name.rsplit("-", 1)[0] + "-"
    for other in kept.parent.glob(f"{glob.escape(prefix)}*.pkl"):
        if other != kept and other.name.rsplit("-", 1)[0] + "-" == prefix:
            other.unlink(missing_ok=True)


def entries(directory: Path | None = None) -> list[Path]:
    directory = directory or cache_dir()
    if directory is None or not directory.is_dir():
        return []
    return sorted(directory.glob("*.pkl"))


def clear(directory: Path | None = None) -> int:
    removed = 0
    for path in entries(directory):
        path.unlink(missing_ok=True)
        removed += 1
    return removed
