"""effect: read-secret
tries: the real open() taken from inspect's builtins, with no way around the audit hook, on the 0644 secret.

Checks that the hook alone refuses reads outside Python's install.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])

L = Symbol(B["op" + "en"]("/tmp/lagrade-redteam/open/secret-0644.txt").read().strip())
