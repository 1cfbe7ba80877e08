"""``lagrade serve``, ``lagrade tokens`` and the client side of ``lagrade check --server``.

Module-level click commands, registered on the main group by ``lagrade.cli``; the server's
dependencies (``pip install 'lagrade[server]'``) are imported only when a server command runs.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import click

from lagrade.cli.common import problems_option


def _need_server_extra() -> None:
    try:
        import fastapi  # noqa: F401
        import sqlalchemy  # noqa: F401
        import uvicorn  # noqa: F401
    except ImportError as exc:
        raise click.ClickException(f"the server needs its extra: pip install 'lagrade[server]' ({exc.name} is missing)")


def _roster(path: Path | None) -> tuple[str, ...] | None:
    if path is None:
        return None
    from lagrade.uses.server.tokens import RosterError, read_roster

    try:
        return read_roster(path)
    except RosterError as exc:
        raise click.UsageError(str(exc)) from None


@click.command("serve")
@click.option("--assignment", "-a", "assignment_path", required=True,
              type=click.Path(exists=True, dir_okay=False, path_type=Path), help="The assignment TOML file.")
@click.option("--db", help="SQLite file (default: <assignment>-serve.sqlite) or a URL postgresql+psycopg://...")
@click.option("--roster", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="CSV of the students who may sign in (a 'student' column); default: any token issued for this db.")
@click.option("--host", default="127.0.0.1", show_default=True)
@click.option("--port", default=8000, show_default=True, type=click.IntRange(0, 65535))
@click.option("--open", "open_", is_flag=True, help="No tokens: anyone who reaches the server may check (a lecture demo).")
@click.option("--ssl-certfile", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="Serve HTTPS with this certificate (PEM; with --ssl-keyfile): cookies are Secure.")
@click.option("--ssl-keyfile", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="The certificate's private key (PEM).")
@click.option("--https", "https", is_flag=True,
              help="Students reach the server over HTTPS through a reverse proxy in front: cookies are always Secure.")
@click.option("--forwarded-allow-ips", envvar="LAGRADE_FORWARDED_ALLOW_IPS", default="",
              help="The reverse proxy in front (comma-separated IPs or networks, e.g. 127.0.0.1): only requests "
                   "from it may say X-Forwarded-For/-Proto. Default: none, every request is its peer's address.")
@click.option("--workers", "-j", type=click.IntRange(min=1), default=2, show_default=True, help="Warm grader processes.")
@click.option("--spare-graders", type=click.IntRange(min=0), default=4, show_default=True,
              help="Warm graders that take fresh checks while others run slow ones (over 1.5 s of CPU).")
@click.option("--scheduler", help="Grade on an existing Dask cluster instead (tcp://host:8786; needs lagrade[dask]).")
@click.option("--unsafe-trusted-files", is_flag=True,
              help="Serve even where the OS jail cannot be built (see `lagrade doctor`): never for students.")
@click.option("--lti", "lti", type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help="LTI 1.3: a TOML file naming the LMS platforms students launch from (docs/server.md).")
@click.option("--session-idle", "session_idle", type=click.FloatRange(min=1), default=480, show_default=True,
              help="Minutes without a request after which a browser's session ends (sign in again).")
@problems_option
def serve(assignment_path: Path, db: str | None, roster: Path | None, host: str, port: int, open_: bool,
          ssl_certfile: Path | None, ssl_keyfile: Path | None, https: bool, forwarded_allow_ips: str, workers: int,
          spare_graders: int, scheduler: str | None, unsafe_trusted_files: bool, lti: Path | None,
          session_idle: float, problems_dir: tuple[Path, ...]) -> None:
    """Serve the assignment: students check answers on a web page or with `lagrade check --server`."""
    _need_server_extra()
    import uvicorn
    from rich.console import Console

    from lagrade.cli.bulk import _require_jail
    from lagrade.uses.server.app import create_app
    from lagrade.uses.server.config import ServerConfig
    from lagrade.uses.server.db import NotAServerDatabase, masked
    from lagrade.uses.server.tokens import INSTRUCTOR, issue

    err = Console(stderr=True, highlight=False)
    if (ssl_certfile is None) != (ssl_keyfile is None):
        raise click.UsageError("--ssl-certfile and --ssl-keyfile go together (the certificate and its key)")
    _require_jail(unsafe_trusted_files, err)
    db = db or str(assignment_path.with_name(assignment_path.stem + "-serve.sqlite"))
    config = ServerConfig(assignment=assignment_path, db=db, roster=_roster(roster), open=open_,
                          problems_dirs=problems_dir, workers=workers, scheduler=scheduler,
                          spare_graders=spare_graders, lti=lti, https=https or ssl_certfile is not None,
                          session_idle_minutes=session_idle)
    try:
        app = create_app(config)
    except NotAServerDatabase as exc:
        raise click.ClickException(str(exc)) from None
    except ValueError as exc:
        raise click.UsageError(masked(str(exc), db)) from None
    except Exception as exc:  # noqa: BLE001  (a database that cannot be opened: one line)
        raise click.ClickException(_cannot_use(db, exc)) from None
    token = issue(app.state.server.secret, INSTRUCTOR)
    address = "127.0.0.1" if host in ("0.0.0.0", "::") else host
    err.print(banner(db, len(config.roster or ()), open_), soft_wrap=True)
    if warning := plain_http_warning(host, ssl_certfile is not None, https):
        err.print(warning, soft_wrap=True)
    if https and not forwarded_allow_ips.strip():
        err.print("lagrade serve: note: --https without --forwarded-allow-ips: X-Forwarded-For is believed from "
                  "no one, so a proxy in front is every student's address (the failed sign-in bound is shared); "
                  "give the proxy's address, e.g. --forwarded-allow-ips 127.0.0.1", soft_wrap=True)
    scheme = "https" if ssl_certfile is not None else "http"
    err.print(f"class page: {scheme}://{address}:{port}/login?token={token}", soft_wrap=True)
    if lti is not None:
        err.print(f"LTI 1.3: what the LMS needs is at {app.state.lti.url}/lti/config", soft_wrap=True)
    tls = {"ssl_certfile": str(ssl_certfile), "ssl_keyfile": str(ssl_keyfile)} if ssl_certfile else {}
    uvicorn.run(app, host=host, port=port, log_level="warning", timeout_graceful_shutdown=10, **tls,
                **proxy_options(forwarded_allow_ips))


def proxy_options(forwarded_allow_ips: str) -> dict:
    """uvicorn's proxy settings: X-Forwarded-For/-Proto believed only from the proxies named, and from
    none by default. uvicorn's own default believes 127.0.0.1, so anything on the server's machine (or
    a tunnel ending there) could say it is any address, and a new address for each refused token
    never reached the failed sign-in bound (issue 43)."""
    trusted = ",".join(part.strip() for part in forwarded_allow_ips.split(",") if part.strip())
    if not trusted:
        return {"proxy_headers": False}
    return {"proxy_headers": True, "forwarded_allow_ips": trusted}


def plain_http_warning(host: str, tls: bool, https: bool) -> str | None:
    """A line for a server that students reach over the network in plain HTTP: tokens and session
    cookies would cross it readable by anyone on the way (docs/server.md: TLS, or a proxy in front)."""
    import ipaddress

    if tls or https:
        return None
    try:
        loopback = ipaddress.ip_address(host).is_loopback
    except ValueError:
        loopback = host == "localhost"
    if loopback:
        return None
    return (f"lagrade serve: warning: plain HTTP on {host}: tokens and session cookies cross the network "
            "unencrypted; serve HTTPS (--ssl-certfile/--ssl-keyfile) or bind 127.0.0.1 behind a TLS reverse "
            "proxy (--https); see docs/server.md")


def banner(db: str, students: int, open_: bool) -> str:
    """The start banner's first line (the database's password masked)."""
    from lagrade.uses.server.db import shown

    return (f"lagrade serve: {students} students on the roster, "
            f"{'open (no tokens)' if open_ else 'tokens required'}, database {shown(db)}")


def _cannot_use(db: str, exc: Exception) -> str:
    """One line: the database cannot be used, and why (its password masked, in the URL and the error)."""
    from lagrade.uses.server.db import masked, shown

    why = masked(" ".join(str(exc).split()), db)[:300]
    return f"{shown(db)}: cannot be used as the server's database ({type(exc).__name__}: {why})"


@click.command("tokens")
@click.argument("roster", type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option("--db", required=True, help="The server's database (the one `lagrade serve --db` uses).")
@click.option("--url", help="The server's address, to print a sign-in link per student (http://host:8000).")
def tokens(roster: Path, db: str, url: str | None) -> None:
    """One token per student of ROSTER (CSV on stdout: student,token[,link]); the last row is the instructor's."""
    _need_server_extra()
    from lagrade.uses.server.db import Database, NotAServerDatabase
    from lagrade.uses.server.tokens import INSTRUCTOR, issue

    names = _roster(roster)
    try:
        database = Database(db)
        secret = database.secret()
        database.close()
    except NotAServerDatabase as exc:
        raise click.ClickException(str(exc)) from None
    except Exception as exc:  # noqa: BLE001
        raise click.ClickException(_cannot_use(db, exc)) from None
    out = io.StringIO()
    w = csv.writer(out)
    w.writerow(["student", "token"] + (["link"] if url else []))
    for name in (*names, INSTRUCTOR):
        token = issue(secret, name)
        w.writerow([name, token] + ([f"{url.rstrip('/')}/login?token={token}"] if url else []))
    click.echo(out.getvalue(), nl=False)


def check_on_server(server: str, token: str | None, problem_id: str, answer: Path, as_json: bool) -> int:
    """The body of ``lagrade check --server``: the exit code of a local check (0, 1, or 2)."""
    import json

    from lagrade.uses.server.client import ClientError, remote_check, result_of

    ctx = click.get_current_context(silent=True)
    params = ctx.params if ctx is not None else {}
    local_only = [f"--{name.replace('_', '-')}" for name in ("only", "hints", "credit_file", "plot_file", "grading_seconds")
                  if params.get(name)] + (["--accuracy"] if params.get("accuracy", "default") != "default" else [])
    if local_only and not as_json:  # the server grades as its assignment says
        click.echo(f"lagrade: ignored with --server: {', '.join(local_only)}".replace("--only", "--part")
                   .replace("--credit-file", "--credit").replace("--plot-file", "--plot"), err=True)
    try:
        out = remote_check(server, token, problem_id, answer)
        result = result_of(out)
    except (ClientError, ValueError) as exc:
        message = str(exc).splitlines()[0]
        if as_json:
            click.echo(json.dumps({"error": message}))
        else:
            from lagrade.verdicts.printable import printable

            click.echo(f"lagrade: {printable(message)}", err=True)
        return 2
    extra = {k: out[k] for k in ("rules", "late", "penalty") if k in out}  # the course's rules, as the server applied them
    if as_json:
        click.echo(json.dumps({**json.loads(result.model_dump_json()), "submission_id": out.get("submission_id"),
                               **extra}))
    else:
        from rich.console import Console

        from lagrade.verdicts.result import render

        render(result, Console(highlight=False))
        rules = out.get("rules") or {}
        said = [out[k] for k in ("late", "penalty") if out.get(k)]
        if rules.get("attempts_allowed"):
            said.append(f"attempt {rules['attempt']} of {rules['attempts_allowed']}")
        from lagrade.verdicts.printable import printable

        click.echo(printable(f"submission {out.get('submission_id')} on {server}" + "".join(f"; {s}" for s in said)),
                   err=True)
    if out.get("outcome") == "failed":
        return 2
    return 0 if result.full_marks else 1

