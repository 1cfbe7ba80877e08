"""effect: read-secret
tries: os.symlink in the sandbox's working folder to the 0644 secret, then open the link by its relative name.

Symlink tricks in the working folder (the hook resolves real paths, and refuses os.symlink).
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
members(os_)["symlink"]("/tmp/lagrade-redteam/open/secret-0644.txt", "innocent.txt")
L = Symbol(B["op" + "en"]("innocent.txt").read().strip())
