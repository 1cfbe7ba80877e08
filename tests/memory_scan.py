"""An answer that searches its own memory for another student's text (issue 43, item 1).

Used by ``test_zygote`` and ``test_jail_grade`` with the tripwires off (the OS jail alone). The jail
has no /proc, so the answer finds its memory as an attacker would: the malloc heap from ``sbrk(0)``
down and every region holding an object ``gc`` knows, each page probed with a system call that
copies from it (``rt_sigprocmask`` reads its set before it checks ``how``: EINVAL for a readable
page, EFAULT otherwise) and searched in place with libc's ``memmem``. The marker is never in the
answer's source (it is stored xor 0x5A and decoded byte by byte into a buffer whose address the
search skips), and a control copy planted in a 4 kB malloc'd buffer proves the search reaches the
heap. It binds ``found`` and ``control`` and ends with ``RuntimeError: memory scan: N found, C
control``, which reaches the student's feedback through any grading path.
"""

from __future__ import annotations

import secrets

_SCANNER = r'''
import bisect, ctypes, gc
libc = ctypes.CDLL(None, use_errno=True)
libc.memmem.restype = ctypes.c_void_p
libc.memmem.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p, ctypes.c_size_t]
libc.syscall.restype = ctypes.c_long
libc.sbrk.restype = ctypes.c_void_p
PAGE = 4096

def decoded(xored, size):
    buf = ctypes.create_string_buffer(size)
    for i, b in enumerate(xored):
        buf[i] = bytes([b ^ 0x5A])
    return buf

def readable(page):
    return libc.syscall(14, 99, ctypes.c_void_p(page), None, 8) == -1 and ctypes.get_errno() == 22

regions = []

def add(addr):
    if not addr:
        return
    starts = [r[0] for r in regions]
    i = bisect.bisect_right(starts, addr) - 1
    if i >= 0 and regions[i][0] <= addr < regions[i][1]:
        return
    page = addr & ~(PAGE - 1)
    if not readable(page):
        return
    lo, hi = page, page + PAGE
    while readable(lo - PAGE):
        lo -= PAGE
    while readable(hi):
        hi += PAGE
    regions.append((lo, hi))
    regions.sort()

def count(needle, size):
    own, hits = ctypes.addressof(needle), 0
    for lo, hi in regions:
        at = lo
        while at < hi:
            hit = libc.memmem(ctypes.c_void_p(at), hi - at, ctypes.c_void_p(own), size)
            if not hit:
                break
            hits += hit != own
            at = hit + 1
    return hits

XORED, CONTROL = MARKER_XOR, CONTROL_XOR
needle = decoded(XORED, len(XORED))
control_needle = decoded(CONTROL, len(CONTROL))
planted = decoded(CONTROL, 4096)  # malloc'd: in the heap, where a freed source would be
add(libc.sbrk(0) - 1)
for obj in gc.get_objects():
    add(id(obj))
found = count(needle, len(XORED))
control = count(control_needle, len(CONTROL))
raise RuntimeError(f"memory scan: {found} found, {control} control")
'''


def marker() -> str:
    return f"student-alice-wrote-this-{secrets.token_hex(8)}"


def scanner(text: str) -> str:
    """The source of an answer that counts the copies of ``text`` in its memory (never its own)."""
    control = f"planted-control-{secrets.token_hex(8)}"
    return (_SCANNER.replace("MARKER_XOR", repr(bytes(c ^ 0x5A for c in text.encode())))
            .replace("CONTROL_XOR", repr(bytes(c ^ 0x5A for c in control.encode()))))


def victim(text: str, answer: str = "L = 1\n", lines: int = 1500) -> str:
    """``answer`` with ``text`` in ``lines`` comment lines: a file of ~80 kB, so that its freed copies
    in a process that received it are not all reused before the next answer looks."""
    return answer + "".join(f"# {i} {text}\n" for i in range(lines))
