"""The PrairieLearn external grader: a public Docker image that holds the lagrade engine alone, its
entry point, and one question per problem whose private ``tests/`` folder holds the problem file.

PrairieLearn runs the image's entry point with the job in ``/grade``: ``data/data.json`` (the
question's ``data``, whose ``params["lagrade"]`` the example ``server.py`` sets: the problem, the
file name, the accuracy), ``student/`` (the submitted files) and ``tests/`` (the question's
``tests/`` folder, which PrairieLearn copies into the job and never serves to students: the
problem file, i.e. the key, comes from there and never from the image, which anyone can pull);
the entry point must leave
``results/results.json``: ``gradable``, ``score`` in [0, 1], ``message``, ``format_errors``,
``tests`` (one per part: ``name``, ``description``, ``points``, ``max_points``, ``message``,
``output``) and ``images`` (the student's motion against the true one, a PNG ``data:`` URL, for
every incorrect dynamics part). A file that cannot be used (a syntax error, nothing assigned, a
file the sandbox stopped) is ``gradable: false`` with the reasons in ``format_errors``: PrairieLearn
then does not count the attempt. The answer runs in lagrade's sandbox as ``lagrade check`` runs it.
"""

from __future__ import annotations

import base64
import hashlib
import json
import os
import re
import sys
import tempfile
import time
import uuid
from pathlib import Path
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError

from lagrade.answer.reading.suffixes import ANSWER_SUFFIXES

#: PrairieLearn's limit on results.json is 1 MB: a plot larger than this is left out (and said)
MAX_IMAGE_BYTES = 600_000
ENTRYPOINT = "/usr/local/bin/lagrade-pl-grade"
#: the folders of the build's output: the image's build context (public), and the questions (private,
#: the course repository); in a question, the folder PrairieLearn copies to ``/grade/tests``
IMAGE_DIR = "image"
TESTS_DIR = "tests"
#: the answer file a question asks for: in the editor, and offered for download (clientFilesQuestion/)
ANSWER_FILE = "answer.py"

#: The registries PrairieLearn pulls grader images from (its docs/dockerImages.md, "Supported
#: registries"): public images, no other host, no port; Docker Hub's are ``org/image[:tag]``.
_NAME = r"[a-z0-9]+(?:(?:[._]|__|-+)[a-z0-9]+)*"
_ACCOUNT = r"[a-z0-9]+(?:(?:_|__|-+)[a-z0-9]+)*"  # no dot: Docker reads "a.b/..." as a registry host
_TAG = r"(?::[A-Za-z0-9_][A-Za-z0-9_.-]{0,127})?(?:@sha256:[0-9a-f]{64})?"
IMAGE_PATTERN = re.compile(
    rf"^(?:(?:docker\.io|index\.docker\.io|registry-1\.docker\.io|ghcr\.io|quay\.io|public\.ecr\.aws)/"
    rf"{_NAME}/{_NAME}|registry\.gitlab\.com/{_NAME}(?:/{_NAME})+|{_ACCOUNT}/{_NAME}){_TAG}$")


class JobParams(BaseModel):
    """``data["params"]["lagrade"]``: what the question asks lagrade to grade."""

    model_config = ConfigDict(extra="forbid")

    problem: str = Field(min_length=1, max_length=100)
    file: str = Field("answer.py", pattern=r"^[A-Za-z0-9_.-]{1,100}\.(py|toml|ipynb)$")
    accuracy: Literal["fast", "default", "strict"] = "default"


def _not_gradable(errors: list[str], message: str) -> dict:
    return {"gradable": False, "score": 0.0, "message": message, "format_errors": errors, "tests": [], "images": []}


def read_job(root: Path) -> tuple[JobParams, Path] | dict:
    """The job's parameters and the student's file, or the results that say why there are none."""
    try:
        data = json.loads((root / "data" / "data.json").read_text(encoding="utf-8"))
        params = JobParams.model_validate((data.get("params") or {}).get("lagrade"))
    except (OSError, ValueError, AttributeError) as exc:
        what = "; ".join(f"{'.'.join(map(str, e['loc'])) or 'lagrade'}: {e['msg']}" for e in exc.errors()) \
            if isinstance(exc, ValidationError) else str(exc)
        return _not_gradable([f"the question is set up wrongly (data.json params.lagrade: {what})"],
                             "This question's grader is misconfigured; please tell your instructor.")
    student = root / "student"
    path = student / params.file
    if not path.is_file() or path.is_symlink():
        found = sorted(p.name for p in student.glob("*") if p.suffix in ANSWER_SUFFIXES and p.is_file()
                       and not p.is_symlink()) if student.is_dir() else []
        if len(found) != 1:
            return _not_gradable([f"no file {params.file} was submitted"], f"Submit your answer as {params.file}.")
        path = student / found[0]
    return params, path


def _image(result) -> list[dict]:
    from lagrade.verdicts.plot import plot_result

    with tempfile.TemporaryDirectory(prefix="lagrade-pl-plot-") as tmp:
        png = Path(tmp) / "motion.png"
        if not plot_result(result, png):
            return []
        data = png.read_bytes()
    if len(data) > MAX_IMAGE_BYTES:
        return []
    return [{"label": "Your motion (dashed) against the true one",
             "url": "data:image/png;base64," + base64.b64encode(data).decode()}]


def hide_tree(folder: Path) -> None:
    """Make ``folder`` and all below it the grader's own (root's, when the grader is root) and
    unreadable to other uids: where the container gives the jail no file view of its own, the
    answer's other uid is what keeps it from the problem files (:mod:`lagrade.uses.deploy.jailcheck`)."""
    root = os.geteuid() == 0
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in [None, *dirnames, *filenames]:
            p = dirpath if name is None else os.path.join(dirpath, name)
            try:
                st = os.lstat(p)
                if os.path.islink(p):
                    continue
                if root and (st.st_uid, st.st_gid) != (0, 0):
                    os.lchown(p, 0, 0)
                os.chmod(p, st.st_mode & 0o700)
            except OSError:  # what stays readable, the jail check before grading finds and refuses
                continue


def grade_job(root: Path = Path("/grade")) -> dict:
    """Grade the job in ``root`` and return PrairieLearn's results (see the module's docstring).

    The problem data are ``root/tests`` (the question's private ``tests/`` folder), made private to
    the grader first, and used as the data root (``LAGRADE_DATA``) for this job alone."""
    from lagrade.problem.library import DATA_ENV

    data = root / TESTS_DIR
    if not (data / "problems").is_dir():
        return _not_gradable([f"the question is set up wrongly: its {TESTS_DIR}/ folder holds no problems/ "
                              "(rebuild it with lagrade prairielearn build and copy the whole question folder)"],
                             "This question's grader is misconfigured; please tell your instructor.")
    hide_tree(data)
    before = os.environ.get(DATA_ENV)
    os.environ[DATA_ENV] = str(data.resolve())
    try:
        return _grade_job(root)
    finally:
        if before is None:
            os.environ.pop(DATA_ENV, None)
        else:
            os.environ[DATA_ENV] = before


def _grade_job(root: Path) -> dict:
    from lagrade.uses.bulk.exports import readable, student_feedback
    from lagrade.verdicts.grade import check
    from lagrade.problem.spec import SpecError

    from lagrade.uses.deploy.jailcheck import decide, without_paths

    t0 = time.monotonic()
    job = read_job(root)
    if isinstance(job, dict):
        return job
    params, path = job
    jail = decide()
    if not jail.ok:  # not gradable: PrairieLearn does not count the attempt, and the reason is said
        print(f"lagrade: refusing to run students' files: {jail.lacking}", file=sys.stderr)  # the staff's job log
        return _not_gradable([f"the grader refused to run students' files in this container: {jail.for_students()}"],
                             "This submission was not graded: the grader's sandbox is incomplete here; "
                             "please tell your instructor.")
    try:
        result = check(params.problem, path, accuracy=params.accuracy)
    except SpecError as exc:
        print(f"lagrade: the question is set up wrongly: {exc}", file=sys.stderr)
        return _not_gradable([f"the question is set up wrongly: {without_paths(str(exc))}"],
                             "This question's grader is misconfigured; please tell your instructor.")
    if result.parts and all(p.verdict == "invalid" for p in result.parts) and result.problems:
        return _not_gradable(list(result.problems), "Your file could not be graded; fix it and submit again.\n"
                             f"(sandbox {jail.summary()})")
    tests = []
    for p in result.parts:
        shown = {"part": p.part, "verdict": p.verdict, "feedback": p.feedback}
        out = f"Read as: {readable(p.read_as_text)}" if p.read_as_text else ""
        tests.append({"name": p.part, "description": p.verdict, "points": round(p.score, 6),
                      "max_points": round(p.max_score, 6), "message": student_feedback(shown, params.problem),
                      "output": out})
    score = result.score / result.max_score if result.max_score else 0.0
    lines = [f"Problem {result.problem}: {result.score:g} / {result.max_score:g}"] + list(result.problems)
    lines.append(f"(sandbox {jail.summary()})")
    return {"gradable": True, "score": min(1.0, max(0.0, score)), "message": "\n".join(lines),
            "format_errors": [], "tests": tests, "images": _image(result),
            "output": f"graded in {time.monotonic() - t0:.1f} s"}


def write_results(root: Path = Path("/grade")) -> dict:
    """Grade and write ``root/results/results.json``; lagrade failing still leaves a result."""
    try:
        results = grade_job(root)
    except Exception as exc:  # noqa: BLE001 - the student must get a result, never a hung job
        results = _not_gradable([f"the grader failed ({type(exc).__name__})"],
                                "The grader failed on this submission; please tell your instructor.")
    out = root / "results"
    out.mkdir(parents=True, exist_ok=True)
    (out / "results.json").write_text(json.dumps(results), encoding="utf-8")
    return results


# ------------------------------------------------------------------------------------- the build

class BuildError(ValueError):
    """What ``lagrade prairielearn build`` was given cannot make a question PrairieLearn runs."""


def check_image(image: str) -> str:
    """``image`` if PrairieLearn can pull it (a public image on a registry it supports), else
    :class:`BuildError` saying what it takes."""
    if not IMAGE_PATTERN.match(image):
        raise BuildError(
            f"--image {image!r}: PrairieLearn pulls grader images only from Docker Hub (YOURACCOUNT/NAME:TAG), "
            "ghcr.io/ORG/NAME:TAG, quay.io/ORG/NAME:TAG, registry.gitlab.com/GROUP/PROJECT/NAME:TAG or "
            "public.ecr.aws/ALIAS/NAME:TAG (lower case, no port); a name with no account, like "
            "lagrade-prairielearn, names no image you can push")
    return image


def question_uuid(seed: str, problem_id: str) -> str:
    """The question's UUID drawn from ``seed`` and the problem: a version 4 UUID (what PrairieLearn's
    schema asks for), the same for the same seed and problem."""
    digest = hashlib.sha256(f"lagrade-prairielearn:{seed}:{problem_id}".encode()).digest()
    return str(uuid.UUID(bytes=digest[:16], version=4))


DOCKERFILE = """# lagrade's PrairieLearn external grader: the lagrade engine alone. PrairieLearn pulls grader images
# from a public registry, so this image holds no problem file, no reference solution and no reference
# cache: each question's tests/ folder holds its problem file, and PrairieLearn copies it to
# /grade/tests for each job and never serves it to students (lagrade prairielearn build refuses to put
# a key into this folder). PrairieLearn runs linux/amd64 images: build and push with
#   docker buildx build --platform linux/amd64 -t {image} --push .
# (the question's info.json names this image in externalGradingOptions.image)
# The base is an exact release (lagrade.uses.deploy.pins.BASE_IMAGE), and requirements.txt pins every
# dependency to the version this build was made with: a rebuild installs the same ones.
FROM {base}
COPY requirements.txt /tmp/
COPY {wheel} /tmp/
RUN pip install --no-cache-dir -r /tmp/requirements.txt && pip install --no-cache-dir --no-deps /tmp/{wheel} \
 && pip check && rm /tmp/{wheel} /tmp/requirements.txt
COPY lagrade-pl-grade {entrypoint}
RUN chmod 0755 {entrypoint}
"""

ENTRY_SCRIPT = """#!/bin/sh
# PrairieLearn runs this in the grading container: /grade/data/data.json, /grade/student/ and the
# question's private files /grade/tests/ (the problem) in, /grade/results/results.json out.
exec python -m lagrade prairielearn grade --root "${LAGRADE_GRADE_ROOT:-/grade}"
"""

SERVER_PY = '''"""PrairieLearn question {qid}: lagrade grades the submitted {file} externally."""


def generate(data):
    data["params"]["lagrade"] = {{"problem": {problem!r}, "file": {file!r}, "accuracy": "default"}}
'''


def _text(s: str) -> str:
    """``s`` for question.html: HTML-escaped, and no brace left for PrairieLearn's Mustache pass
    (question.html is a Mustache template: ``{{`` in a problem's text would be read as a tag)."""
    from html import escape

    return escape(s).replace("{", "&#123;").replace("}", "&#125;")


def question_html(problem) -> str:
    """The question's page: the statement, then what ``lagrade show`` prints (the assumptions, the
    symbols to use, the parts), the answer template to download, an editor that starts from it."""
    from lagrade.problem.describe import show_text, template_text

    statement = problem.statement.strip()
    rest = "\n".join(show_text(problem).split("\n")[1:]).strip()  # the title is the page's
    if statement and rest.startswith(statement):  # the statement is said as prose above
        rest = rest[len(statement):].strip()
    return (
        "<pl-question-panel>\n"
        + (f"  <p>{_text(statement)}</p>\n" if statement else "")
        + f"  <p>Write your answer in <code>{ANSWER_FILE}</code> with sympy: bind each part below to its name, "
        "with the symbols below (the template declares them). Download the template, or edit it below.</p>\n"
        f"  <pre class=\"lagrade-problem\">{_text(rest)}</pre>\n"
        f"  <p><pl-file-download file-name=\"{ANSWER_FILE}\" label=\"Download the answer template ({ANSWER_FILE})\">"
        "</pl-file-download></p>\n"
        "</pl-question-panel>\n\n"
        f"<pl-file-editor file-name=\"{ANSWER_FILE}\" ace-mode=\"ace/mode/python\">\n"
        f"{_text(template_text(problem))}</pl-file-editor>\n\n"
        "<pl-submission-panel>\n  <pl-external-grader-results></pl-external-grader-results>\n"
        "  <pl-file-preview></pl-file-preview>\n</pl-submission-panel>\n")


def question_files(problem_id: str, problems_dirs: tuple[Path, ...] = (), *, image: str,
                   uuid_seed: str | None = None, question_id: str | None = None) -> dict[str, bytes]:
    """``info.json``, ``question.html``, ``server.py``, ``clientFilesQuestion/answer.py`` (the
    template, served to students) and ``tests/problems/<id>.toml`` (the problem file, the key: private,
    copied to ``/grade/tests`` for the grader) of a question graded by lagrade in ``image``. Its UUID:
    ``question_id`` if given, else drawn from ``uuid_seed`` (:func:`question_uuid`), else a random UUID4."""
    from lagrade.problem.describe import template_text
    from lagrade.problem.library import load_problem, problem_path

    check_image(image)
    problem = load_problem(problem_id, problems_dirs)
    source = Path(problem_id) if Path(problem_id).suffix == ".toml" and Path(problem_id).exists() \
        else problem_path(problem.id, problems_dirs)
    qid = f"lagrade-{problem.id}"
    if question_id is None:
        question_id = question_uuid(uuid_seed, problem.id) if uuid_seed is not None else str(uuid.uuid4())
    # no externalGradingOptions.enabled: PrairieLearn's schema marks it "[DEPRECATED, DO NOT USE]"
    info = {"uuid": question_id, "type": "v3",
            "title": f"{problem.id}: {problem.title}", "topic": "Lagrangian and Hamiltonian dynamics",
            "tags": ["lagrade"], "gradingMethod": "External", "singleVariant": True, "partialCredit": True,
            "externalGradingOptions": {"image": image, "entrypoint": ENTRYPOINT, "timeout": 120}}
    return {"info.json": (json.dumps(info, indent=2) + "\n").encode(), "question.html": question_html(problem).encode(),
            "server.py": SERVER_PY.format(qid=qid, problem=problem.id, file=ANSWER_FILE).encode(),
            f"clientFilesQuestion/{ANSWER_FILE}": template_text(problem).encode(),
            f"{TESTS_DIR}/problems/{problem.id}.toml": source.read_bytes()}


#: what PrairieLearn shows or serves to students, of a question's files
def _served(name: str) -> bool:
    return name == "question.html" or name.startswith("clientFilesQuestion/")


def _kept_uuid(info: Path) -> str | None:
    """The UUID of the question an earlier build wrote here (a rebuild keeps it: PrairieLearn knows a
    question by it, and a new one would make another question, without the old one's history)."""
    try:
        value = json.loads(info.read_text(encoding="utf-8")).get("uuid")
    except (OSError, ValueError, AttributeError):
        return None
    ok = isinstance(value, str) and re.fullmatch(r"[0-9a-fA-F]{8}(-[0-9a-fA-F]{4}){3}-[0-9a-fA-F]{12}", value)
    return value if ok else None


def _old_layout(output: Path) -> list[Path]:
    """What builds before the image had its own folder wrote at the top of ``output``: the Dockerfile
    that installed the problem data, both wheels, the entry script (removed, so that the old
    ``docker build`` of ``output`` finds no Dockerfile and cannot push the key again)."""
    from lagrade.uses.deploy.wheel import DATA_WHEEL

    old = [*output.glob("lagrade-*.whl"), *output.glob(DATA_WHEEL), output / "lagrade-pl-grade"]
    docker = output / "Dockerfile"
    try:
        if docker.read_text(encoding="utf-8").startswith("# lagrade's PrairieLearn external grader"):
            old.append(docker)
    except (OSError, UnicodeDecodeError):
        pass
    return [p for p in old if p.is_file()]


def build_grader(output: Path, problem_id: str = "12.43", problems_dirs: tuple[Path, ...] = (),
                 wheel: Path | None = None, *, image: str, uuid_seed: str | None = None) -> list[str]:
    """Write the image's build context (``image/``: Dockerfile, the lagrade engine wheel, entry
    script) and one question (``questions/lagrade-<id>/``) into ``output``; the files written,
    relative to it.

    The image is public (PrairieLearn pulls it without credentials), so it holds the engine alone:
    :func:`lagrade.uses.deploy.keycheck.refuse_keys` checks the whole context once written, and a
    ``--wheel`` before anything is written; the problem file goes to the question's ``tests/``.

    The question's UUID: drawn from ``uuid_seed`` if given; else the one an earlier build left in
    ``output`` (a rebuild is the same question); else a fresh random UUID4, so that two builds never
    collide in one course."""
    import shutil

    from lagrade.uses.deploy.keycheck import KeyInPublic, known_keys, refuse_keys, what_key
    from lagrade.uses.deploy.wheel import build_wheel, check_wheel

    check_image(image)
    known = known_keys(problems_dirs)
    if wheel is not None:
        check_wheel(wheel)
        why = what_key(wheel.name, wheel.read_bytes(), known)
        if why is not None:
            raise KeyInPublic(f"refusing to put the key into the public image {image}: --wheel {wheel} holds {why}; "
                              "give the lagrade engine wheel (pip wheel --no-deps . in a checkout), which holds none")
    question = output / "questions" / f"lagrade-{problem_id}"
    kept = _kept_uuid(question / "info.json") if uuid_seed is None else None
    files = question_files(problem_id, problems_dirs, image=image, uuid_seed=uuid_seed, question_id=kept)
    context = output / IMAGE_DIR
    context.mkdir(parents=True, exist_ok=True)
    for old in _old_layout(output):
        if wheel is None or old.resolve() != wheel.resolve():  # the wheel given may be one it left
            old.unlink()
    with tempfile.TemporaryDirectory(prefix="lagrade-pl-build-") as tmp:
        engine = wheel if wheel is not None else build_wheel(Path(tmp) / "wheel")
        for old in context.glob("lagrade-*.whl"):
            if old.resolve() != engine.resolve():
                old.unlink()
        if engine.resolve() != (context / engine.name).resolve():
            shutil.copyfile(engine, context / engine.name)
    from lagrade.uses.deploy.pins import BASE_IMAGE, requirements_txt

    (context / "requirements.txt").write_text(requirements_txt())
    (context / "Dockerfile").write_text(DOCKERFILE.format(image=image, wheel=engine.name, entrypoint=ENTRYPOINT,
                                                          base=BASE_IMAGE))
    (context / "lagrade-pl-grade").write_text(ENTRY_SCRIPT)
    (context / "lagrade-pl-grade").chmod(0o755)
    try:
        refuse_keys(context, f"the public image {image} (its build context {context})", problems_dirs, known)
    except KeyInPublic:
        (context / "Dockerfile").unlink()  # no context left that docker could build and push
        raise
    written = [f"{IMAGE_DIR}/{name}" for name in (engine.name, "requirements.txt", "Dockerfile", "lagrade-pl-grade")]
    _write_question(output, question, files, written, known)
    return written


def write_question(output: Path, problem_id: str, problems_dirs: tuple[Path, ...] = (), *, image: str,
                   uuid_seed: str | None = None) -> list[str]:
    """One more question graded by the same grader (an assignment's other problems), its UUID chosen as
    `build_grader` chooses the example's (``uuid_seed`` is made the problem's own)."""
    from lagrade.uses.deploy.keycheck import known_keys

    check_image(image)
    question = output / "questions" / f"lagrade-{problem_id}"
    kept = _kept_uuid(question / "info.json") if uuid_seed is None else None
    files = question_files(problem_id, problems_dirs, image=image,
                           uuid_seed=f"{uuid_seed}/{problem_id}" if uuid_seed is not None else None, question_id=kept)
    written: list[str] = []
    _write_question(output, question, files, written, known_keys(problems_dirs))
    return written


def _write_question(output: Path, question: Path, files: dict[str, bytes], written: list[str],
                    known: dict[str, str]) -> None:
    """Write the question's files; what PrairieLearn serves to students is checked for a key first."""
    from lagrade.uses.deploy.keycheck import KeyInPublic, what_key

    for name, data in files.items():
        why = what_key(name, data, known) if _served(name) else None
        if why is not None:
            raise KeyInPublic(f"refusing to serve the key to students: {question / name} would be {why}")
    for name, data in files.items():
        (question / name).parent.mkdir(parents=True, exist_ok=True)
        (question / name).write_bytes(data)
        written.append(str((question / name).relative_to(output)))
