"""effect: exhaust-memory
tries: allocate 3 GB in the answer itself (a bytearray, then a list), bounded.

The sandbox's RLIMIT_AS should stop it with a 'memory' verdict.
"""

from lagrade.answer import *

hoard = [bytearray(256 * 1024 * 1024) for _ in range(12)]
L = Symbol("x")
