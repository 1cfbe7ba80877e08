"""What a student installs holds no answer: the lagrade wheel is built apart from the problem data
(lagrade-chapter12), holds no problem file, no reference solution and no reference value, and,
installed alone in a fresh virtual environment, checks against a course server and prints the report.

Slow: it builds both wheels and makes a venv (about 30 s); the dependencies are not downloaded but
lent from this environment (a folder of links to its packages, every lagrade distribution left out).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pytest
from serverkit import GOLDEN, REPO

from lagrade.uses.deploy.wheel import build_data_wheel, build_wheel
from lagrade.problem.library import load_problem
from lagrade.uses.server.tokens import issue

pytestmark = pytest.mark.slow

SAMPLES = ("12.14", "12.22")
#: shorter texts ("g", "m*l**2") turn up in any file of a physics grader
MIN_CHARS = 14


def _texts(value) -> list[str]:
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [t for v in value.values() for t in _texts(v)]
    if isinstance(value, list | tuple):
        return [t for v in value for t in _texts(v)]
    return []


def _squash(text: str) -> str:
    return re.sub(r"\s+", "", text)


def reference_values(pid: str) -> set[str]:
    """The sample problem's reference values as text: its problem file's references and the
    right-hand sides of its reference solution's assignments (whitespace removed, long enough to mean it)."""
    problem = load_problem(pid)
    found = {_squash(t) for part in problem.parts for t in _texts(part.reference)}
    solution = (REPO / "reference_solutions" / pid / "answer.py").read_text(encoding="utf-8")
    found |= {_squash(line.split("=", 1)[1]) for line in solution.splitlines()
              if re.match(r"\s*\w+\s*=[^=]", line) and "symbols(" not in line and "Function(" not in line}
    return {t for t in found if len(t) >= MIN_CHARS}


def leaks(wheel: Path) -> list[str]:
    """Every (file, reference value) of the wheel where a sample problem's value appears as text,
    and every problem or reference file it holds."""
    values = {pid: reference_values(pid) for pid in SAMPLES}
    out = []
    with zipfile.ZipFile(wheel) as z:
        for name in z.namelist():
            if re.search(r"(^|/)(problems|reference_solutions|_data)/", name) or re.fullmatch(r".*/12\.\d+\.toml", name):
                out.append(f"{name}: a problem or reference file")
            text = _squash(z.read(name).decode("utf-8", "replace"))
            out += [f"{name}: {pid} {v[:40]}" for pid, vs in values.items() for v in vs if v in text]
    return out


@pytest.fixture(scope="module")
def wheels(tmp_path_factory) -> tuple[Path, Path]:
    out = tmp_path_factory.mktemp("wheels")
    return build_wheel(out), build_data_wheel(out)


def test_the_client_wheel_holds_no_problem_and_no_reference(wheels):
    client, data = wheels
    assert leaks(client) == []
    # not vacuous: the data wheel is caught on every count, and the values searched for are there
    found = leaks(data)
    assert all(reference_values(pid) for pid in SAMPLES)
    assert any("12.14.toml: a problem" in f for f in found) and any("reference_solutions/12.22/answer.py: 12.22" in f
                                                                   for f in found)
    assert any(f.startswith("lagrade_chapter12/problems/12.14.toml: 12.14 ") for f in found)
    with zipfile.ZipFile(client) as z:
        assert "lagrade/uses/server/client.py" in z.namelist()  # the client is in it


def _fresh_venv(root: Path, client: Path) -> Path:
    """A venv with the client wheel alone; lagrade's dependencies lent from this environment by
    links (every lagrade distribution and its editable hook left out). Its ``bin`` folder."""
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(root)], check=True)
    py = root / "bin" / "python"
    site = Path(subprocess.run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                               capture_output=True, text=True, check=True).stdout.strip())
    subprocess.run([sys.executable, "-m", "pip", "--python", str(py), "install", "--quiet", "--no-deps",
                    "--no-index", str(client)], check=True)
    lent = root / "lent"
    lent.mkdir()
    ours = sysconfig.get_paths()["purelib"]
    for entry in os.listdir(ours):
        if re.match(r"(_?editable_impl_)?_?lagrade", entry, re.IGNORECASE) or entry.endswith(".pth"):
            continue
        (lent / entry).symlink_to(Path(ours) / entry)
    (site / "zz_lent_dependencies.pth").write_text(f"{lent}\n", encoding="utf-8")
    return root / "bin"


def test_the_client_alone_checks_against_the_server(wheels, graded, live_url, tmp_path):
    client, _ = wheels
    bin_ = _fresh_venv(tmp_path / "venv", client)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "LAGRADE_PROBLEMS")}
    env["PATH"] = f"{bin_}{os.pathsep}{env.get('PATH', '')}"
    probe = "import lagrade, lagrade.problem.library as l; print(lagrade.__file__); print(l.data_root()); print(l.problem_ids())"
    where = subprocess.run([str(bin_ / "python"), "-c", probe],
                           capture_output=True, text=True, env=env, cwd=tmp_path)
    assert where.returncode == 0, where.stderr
    file, root, ids = where.stdout.splitlines()
    assert file.startswith(str(tmp_path / "venv")) and root == "None" and ids == "[]"

    token = issue(graded[0].state.server.secret, "installed-client")
    answer = tmp_path / "answer.toml"
    shutil.copyfile(GOLDEN / "12.14" / "wrong_plain_potential_sign.toml", answer)
    remote = subprocess.run([str(bin_ / "lagrade"), "check", "12.14", "answer.toml", "--server", live_url,
                             "--token", token], capture_output=True, text=True, env=env, cwd=tmp_path, timeout=600)
    print(remote.stdout, remote.stderr, sep="\n")  # the report, for whoever runs this with -s
    assert remote.returncode == 1, remote.stderr
    assert "Problem 12.14" in remote.stdout and "incorrect" in remote.stdout and "submission " in remote.stderr

    right = tmp_path / "right.py"
    shutil.copyfile(GOLDEN / "12.14" / "correct_cartesian_and_solve.py", right)
    ok = subprocess.run([str(bin_ / "lagrade"), "check", "12.14", "right.py", "--server", live_url, "--token", token],
                        capture_output=True, text=True, env=env, cwd=tmp_path, timeout=600)
    assert ok.returncode == 0, ok.stdout + ok.stderr

    # without the server, the client says what is missing in one line
    local = subprocess.run([str(bin_ / "lagrade"), "check", "12.14", "answer.toml"], capture_output=True, text=True,
                           env=env, cwd=tmp_path, timeout=300)
    assert local.returncode == 2 and "no problem data is installed" in local.stderr + local.stdout
