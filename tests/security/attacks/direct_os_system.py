"""effect: run-command
tries: os.system from inspect's os module, no hook bypass.

Checks the hook's 'os.system' refusal.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])

members(os_)["sys" + "tem"]("id > /tmp/lagrade-redteam/drop/pwned-direct_os_system")
L = Symbol("x")
