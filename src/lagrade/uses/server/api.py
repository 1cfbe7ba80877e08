"""API v1 (JSON, described by the OpenAPI document at /openapi.json): the problems, checking an answer, earlier attempts."""

from __future__ import annotations

import asyncio
from pathlib import Path
from typing import Annotated

from fastapi import APIRouter, HTTPException, Request
from fastapi import Path as PathParameter
from fastapi.responses import JSONResponse, Response
from pydantic import ValidationError

from lagrade.answer.reading.suffixes import ANSWER_SUFFIXES
from lagrade.uses.server.answers import (
    AnswerIn,
    AnswerTextError,
    PreviewIn,
    to_toml,
)

router = APIRouter(prefix="/api/v1", tags=["api v1"])

#: the largest id the database can hold (a signed 64-bit integer): a larger one, like any id that is
#: not a number, is refused with 422 as it is parsed, never handed to the database (which answered 500)
MAX_ID = 2**63 - 1
SubmissionId = Annotated[int, PathParameter(ge=1, le=MAX_ID, description="the id a check answered with")]

_CHECK_BODY = {
    "requestBody": {
        "required": True,
        "content": {
            "application/json": {"schema": AnswerIn.model_json_schema()},
            "multipart/form-data": {"schema": {"type": "object", "required": ["file"], "properties": {
                "file": {"type": "string", "format": "binary", "description": "answer.py or answer.toml"}}}},
        },
    }
}


def _server(request: Request):
    return request.app.state.server


def one_line(exc: ValidationError) -> str:
    e = exc.errors()[0]
    where = ".".join(str(x) for x in e["loc"]) or "body"
    return f"{where}: {e['msg']}; expected {{\"answer\": {{part: text, list of texts or table of texts}}}}"


@router.get("/problems")
def problems(request: Request) -> list[dict]:
    """The assignment's problems: id, title, parts."""
    server = _server(request)
    server.identify(request)
    return [{"id": pid, "title": p.title, "parts": [{"name": f["name"], "kind": f["kind"], "prompt": f["prompt"]}
                                                     for f in server.fields(pid)]}
            for pid, p in server.problems.items()]


@router.get("/problems/{pid}")
def problem(pid: str, request: Request) -> dict:
    """What ``lagrade show`` and ``lagrade template`` print, and the fields of the student page."""
    server = _server(request)
    who = server.identify(request)
    p = server.problem(pid)
    from lagrade.problem.describe import typing_help
    from lagrade.uses.server.rules import standing

    return {"id": pid, "title": p.title, "show": server.text("show", pid), "template": server.text("template", pid),
            "statement_html": server.statement(pid), "figure": f"/api/v1/problems/{pid}/figure.png",
            "fields": server.fields(pid), "typing": typing_help(p), "rules": standing(server, who.student, pid, who.instructor)}


@router.get("/problems/{pid}/figure.png", response_class=Response,
            responses={200: {"content": {"image/png": {}}, "description": "the figure"}})
async def figure(pid: str, request: Request) -> Response:
    """The figure the statement refers to, drawn from the scene: its bodies at a sample state, each
    coordinate's positive direction (``lagrade show --figure`` saves it)."""
    server = _server(request)
    server.identify(request)
    server.problem(pid)
    png = await asyncio.to_thread(server.figure, pid)
    return Response(png, media_type="image/png", headers={
        "Cache-Control": "private, max-age=3600", "X-Content-Type-Options": "nosniff",
        "Content-Security-Policy": "default-src 'none'"})


@router.post("/problems/{pid}/check", openapi_extra=_CHECK_BODY, status_code=200,
             responses={202: {"description": "stored and queued; poll /api/v1/submissions/{id}"}})
async def check(pid: str, request: Request, plot: bool = False) -> JSONResponse:
    """Grade an answer: JSON ``{"answer": {...}}`` (the values answer.toml holds) or an uploaded file.

    Returns what ``lagrade check --json`` prints, plus ``submission_id``. ``plot=true``: also draw
    the picture of a wrong motion (``lagrade check --plot``'s), linked as ``plot`` in the result."""
    server = _server(request)
    who = server.identify(request)
    server.problem(pid)
    suffix, data = await read_answer(request)
    server.require_csrf(who, request.headers.get("x-csrf-token"))
    return await submit(server, who, pid, suffix, data, plot=plot)


async def read_answer(request: Request) -> tuple[str, bytes]:
    """(suffix, bytes) of the answer in a JSON body or a multipart upload; 422 with one line otherwise."""
    kind = request.headers.get("content-type", "")
    if kind.startswith("multipart/form-data"):
        form = await request.form(max_files=1, max_fields=5)
        upload = form.get("file")
        if upload is None or isinstance(upload, str):
            raise HTTPException(422, "no file; expected a multipart field 'file' holding answer.py or answer.toml")
        suffix = Path(upload.filename or "").suffix
        if suffix not in ANSWER_SUFFIXES:
            raise HTTPException(422, f"{upload.filename!r} is neither a .py, a .toml nor a .ipynb file; expected "
                                     "answer.py, answer.toml or answer.ipynb")
        return suffix, await upload.read()
    if not kind.startswith("application/json"):
        raise HTTPException(415, "expected a JSON body {\"answer\": {...}} or a multipart upload of answer.py/answer.toml")
    try:
        body = AnswerIn.model_validate_json(await request.body())
    except ValidationError as exc:
        raise HTTPException(422, one_line(exc)) from None
    try:
        return ".toml", to_toml(body.answer)
    except AnswerTextError as exc:
        raise HTTPException(422, str(exc)) from None


async def submit(server, who, pid: str, suffix: str, data: bytes, plot: bool = False) -> JSONResponse:
    """Store the attempt (before grading it), queue it, wait for its grade; idempotent per content
    (the same file again is the same attempt, with or without its picture as it was first graded)."""
    from lagrade.uses.bulk.layout import file_hash

    from lagrade.uses.server.db import AttemptsUsed
    from lagrade.uses.server.rules import view

    rules = server.assignment.rules
    plot = plot and (rules.feedback != "verdict" or who.instructor)  # verdict only: no picture of the motion
    key = {"student": who.student, "problem": pid, "file_hash": file_hash(data), "grading_hash": server.plan.keys[pid],
           "version": server.plan.version}
    # the same file again is the attempt stored before: it costs no grading, so only the rate of
    # requests bounds it (a student who resubmits after a long grading gets it back, not a 429)
    admitted = await asyncio.to_thread(server.db.stored, **key) is None
    server.limit(who, admit=admitted)  # admitted by the queue: counted as in flight until queued or settled
    try:
        sid, new = await asyncio.to_thread(
            server.db.submit, suffix=suffix, data=data, max_attempts=None if who.instructor else rules.attempts, **key)
    except BaseException as exc:
        if server.queue is not None and admitted:
            server.queue.settle(who.student)
        if isinstance(exc, AttemptsUsed):
            raise HTTPException(403, str(exc)) from None
        raise
    if server.queue is not None:
        if new:
            server.queue.put(sid, who.student, plot)
        elif admitted:
            server.queue.settle(who.student)
    att = await server.queue.wait(sid, server.config.wait_seconds) if server.queue is not None else None
    if att is None or not att.graded:
        att = att or await asyncio.to_thread(server.db.attempt, sid)
        return JSONResponse({**view(server, att, who),
                             "detail": f"stored and queued; GET /api/v1/submissions/{sid} for the grade"}, 202)
    return JSONResponse(view(server, att, who))


@router.post("/problems/{pid}/preview")
async def read_as(pid: str, body: PreviewIn, request: Request) -> dict:
    """How a part's text will be read (as answer.toml is read): sympy text and presentation MathML."""
    server = _server(request)
    who = server.identify(request)
    p = server.problem(pid)
    server.require_csrf(who, request.headers.get("x-csrf-token"))
    server.limit(who, preview=True)
    # read in the preview process, one at a time and bounded: never in this one (docs/server.md)
    out = await asyncio.to_thread(server.previews, p.id, body.part, body.value)
    out.pop("seconds", None)
    return out


@router.get("/submissions/{sid}")
def submission(sid: SubmissionId, request: Request) -> JSONResponse:
    """One of your attempts: its grade, or ``queued``."""
    server = _server(request)
    who = server.identify(request)
    att = server.db.attempt(sid)
    if att is None or (att.student != who.student and not who.instructor):
        raise HTTPException(404, f"no submission {sid} of yours")
    from lagrade.uses.server.rules import view

    return JSONResponse(view(server, att, who), 200 if att.graded else 202)


@router.get("/submissions/{sid}/plot.png", response_class=Response,
            responses={200: {"content": {"image/png": {}}, "description": "the picture"},
                       404: {"description": "no such attempt of yours, or no picture"}})
def plot(sid: SubmissionId, request: Request) -> Response:
    """The picture of an attempt's wrong dynamics parts: your motion against the true one, as
    ``lagrade check --plot`` draws it. A PNG, pixels only: no number of the true motion as text."""
    server = _server(request)
    who = server.identify(request)
    att = server.db.attempt(sid)
    if att is None or (att.student != who.student and not who.instructor):
        raise HTTPException(404, f"no submission {sid} of yours")
    png = server.db.plot(sid) if server.assignment.rules.feedback != "verdict" or who.instructor else None
    if png is None:
        raise HTTPException(404, f"submission {sid} has no picture (not graded yet, or no dynamics part is wrong)")
    return Response(png, media_type="image/png", headers={
        "Cache-Control": "private, max-age=86400", "X-Content-Type-Options": "nosniff",
        "Content-Security-Policy": "default-src 'none'"})


@router.get("/problems/{pid}/submissions")
def submissions(pid: str, request: Request) -> list[dict]:
    """Your earlier attempts at a problem, newest first, stored but not graded yet too (``state``:
    ``queued``); ``file_hash`` (sha256 of the file) finds an attempt whose answer a crash cut off."""
    server = _server(request)
    who = server.identify(request)
    server.problem(pid)
    from lagrade.uses.server.rules import rows

    return [{"submission_id": r["id"], "state": r["state"], "created_at": r["created_at"], "file_hash": r["file_hash"],
             "score": r["result"]["score"] if r["result"] else None,
             "max_score": r["result"]["max_score"] if r["result"] else None, "late": r["late"]}
            for r in rows(server, server.db.attempts(who.student, pid), who)]
