"""effect: signal-parent
tries: os.kill(os.getppid(), SIGKILL) with inspect's os, no hook bypass.

Checks the hook's 'os.kill' refusal.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
members(os_)["kill"](os_.getppid(), 9)
L = Symbol("x")
