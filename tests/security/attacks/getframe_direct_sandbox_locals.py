"""effect: read-secret
tries: sys._getframe(1) straight from the answer to reach the sandbox's frame and its policy, then read the 0600 secret.

Checks the hook's 'sys._getframe' refusal for the answer's and the sandbox's frames.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
from sympy.core.add import attrgetter

frame = members(sys_)["_getframe"](1)
attrgetter("f_" + "locals")(frame)["policy"].busy = True
L = Symbol(B["op" + "en"]("/tmp/lagrade-redteam/secret-0600.txt").read().strip())
