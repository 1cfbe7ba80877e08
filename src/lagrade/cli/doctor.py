"""``lagrade doctor``: which layers of the answer jail this machine gives, and a proof that they hold.

An instructor should not have to trust that the jail is there: the command starts the zygote the
graders use, prints each layer and why it is missing where it is, and runs a probe answer (lagrade's
own, with the Python-level tripwires off) that tries what a hostile file would and reports what
the kernel stopped.
"""

from __future__ import annotations

import json
import os
import platform
import sys
import tempfile
from pathlib import Path

import click

#: the probe: tries, from inside the jail, what the layers are there to stop
_PROBE = '''
import json, os
seen = {"uid": os.getuid(), "ppid": os.getppid()}
def attempt(name, action):
    try:
        action()
        seen[name] = "done"
    except BaseException as exc:
        seen[name] = type(exc).__name__
attempt("read the reference solutions", lambda: open(REFERENCE).read())
attempt("list the root directory", lambda: os.listdir("/"))
attempt("write a file", lambda: open("probe.txt", "w").write("x"))
attempt("start a process", lambda: os.posix_spawn("/bin/true", ["true"], {}))
attempt("open a socket", lambda: __import__("socket").socket())
attempt("see /proc", lambda: os.listdir("/proc"))
attempt("signal the grader", lambda: os.kill(GRADER, 0))
print(json.dumps(seen))
L = 0
'''


@click.command()
@click.option("--json", "as_json", is_flag=True, help="Print one JSON object.")
def doctor(as_json: bool) -> None:
    """Which layers of the answer jail are active on this machine, and a probe that they hold."""
    from lagrade.answer.jail import kernel, zygote
    from lagrade.problem.library import reference_dir

    if not sys.platform.startswith("linux"):
        message = (f"{platform.system()}: there is no OS jail here (the layers are Linux kernel features); "
                   "answer files would run with only lagrade's Python-level tripwires: do not grade "
                   "other people's files on this machine")
        click.echo(json.dumps({"os": platform.system(), "active": [], "error": message}) if as_json else message)
        sys.exit(1)
    zyg = zygote.start()
    try:
        hello = zyg.hello()
        probe = _run_probe(str(reference_dir() / "12.22" / "answer.py"))
    finally:
        zygote.stop()
    active, inactive = hello["active"], hello["inactive"]
    lacking = kernel.missing_minimum(active)
    if as_json:
        click.echo(json.dumps({"os": f"Linux {platform.release()}", "euid": os.geteuid(), "active": active,
                               "inactive": inactive, "probe": probe, "can_grade": lacking is None}))
    else:
        click.echo(f"The answer jail on Linux {platform.release()}, running as uid {os.geteuid()}:")
        for layer in kernel.LAYERS:
            state = "active" if layer in active else "MISSING"
            detail = kernel.DESCRIPTIONS[layer] if layer in active else inactive.get(layer, "not requested")
            click.echo(f"  {layer:<13} {state:<8} {detail}")
        click.echo("")
        if "error" in probe:
            click.echo(f"probe: {probe['error']}")
        else:
            stopped = [k for k, v in probe.items() if k not in ("uid", "ppid") and v != "done"]
            allowed = [k for k, v in probe.items() if k not in ("uid", "ppid") and v == "done"]
            click.echo(f"probe: an answer ran as uid {probe['uid']} (the grader is uid {os.geteuid()}), "
                       f"its parent is pid {probe['ppid']}")
            click.echo(f"  stopped: {', '.join(stopped) or 'nothing'}")
            if allowed:
                click.echo(f"  NOT stopped: {', '.join(allowed)}")
        click.echo("")
        click.echo("lagrade grade will grade classes here." if lacking is None else
                   f"lagrade grade will refuse to grade classes here ({lacking}) unless given --unsafe-trusted-files.")
    sys.exit(0 if lacking is None else 1)


def _run_probe(reference: str) -> dict:
    """Run the probe answer in the jail, with the tripwires off (it is lagrade's own code)."""
    from lagrade.answer.jail import sandbox

    source = _PROBE.replace("REFERENCE", repr(reference)).replace("GRADER", str(os.getpid()))
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "probe.py"
        path.write_text(source)
        saved, sandbox.TRIPWIRES = sandbox.TRIPWIRES, False
        try:
            out = sandbox.run_answer_file(path, ["L"])
        finally:
            sandbox.TRIPWIRES = saved
    try:
        return json.loads(out.stdout.strip().splitlines()[-1])
    except (ValueError, IndexError):
        return {"error": f"the probe did not run ({out.status}: {'; '.join(str(p) for p in out.problems)})"}
