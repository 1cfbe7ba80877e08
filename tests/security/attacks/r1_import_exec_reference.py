"""effect: full-marks
tries: route 1 (str subclass in the hook's import check) reads and execs the reference solution, then binds its values.

Full marks through route 1.
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
    # the reference solution, wherever the installed lagrade keeps it, run with the real exec
    library = members(sys_)["modules"]["lagrade.problem.library"]
    source = (library.reference_dir() / "12.22" / "answer.py").read_text()
    namespace = {}
    B["ex" + "ec"](source, namespace)
    box.append(namespace)

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1: the hook does str(args[0]) for "import" events while it has set self.busy; a str
# subclass whose __str__ is ours runs with every check off. sys.audit calls the hook directly.
def hook_str(self):
    once()
    return "sympy"


Evil = type("Evil", (str,), {"_" + "_str_" + "_": hook_str})
sys_.audit("import", Evil("anything"))
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway

stolen = box[0] if box else {}
L, eom, a, S_t, a_case = (stolen.get(k) for k in ("L", "eom", "a", "S_t", "a_case"))
