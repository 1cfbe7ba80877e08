"""Where lagrade finds the bundled problems and references (lagrade.problem.library.data_root): the checkout
of an editable install, else an installed ``lagrade.problem_data`` package (lagrade-chapter12), else
nowhere, and then a check says so in one line. The installed case is laid out here as pip lays out a
wheel (a package folder and a dist-info with its entry point), so no install is needed."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
from serverkit import REPO

from lagrade.problem import library
from lagrade.problem.spec import SpecError


@pytest.fixture
def no_checkout(monkeypatch, tmp_path):
    """lagrade as if installed from its wheel: no checkout around its package."""
    fake = tmp_path / "site" / "lagrade"
    fake.mkdir(parents=True)
    monkeypatch.setattr(library, "_PACKAGE", fake)
    monkeypatch.setattr(library, "_NOWHERE", fake / "_no_problem_data")
    monkeypatch.delenv("LAGRADE_PROBLEMS", raising=False)
    library.data_root.cache_clear()
    library._index.cache_clear()
    yield tmp_path
    library.data_root.cache_clear()
    library._index.cache_clear()


def _install_data(site: Path, name: str, ids: list[str]) -> Path:
    package = site / name
    (package / "problems").mkdir(parents=True)
    (package / "reference_solutions").mkdir()
    (package / "__init__.py").write_text("")
    for pid in ids:
        (package / "problems" / f"{pid}.toml").write_text((REPO / "problems" / f"{pid}.toml").read_text())
    info = site / f"{name}-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(f"[{library.DATA_GROUP}]\n{name} = {name}\n")
    return package


def test_the_checkout_comes_first():
    library.data_root.cache_clear()
    assert library.data_root() == REPO
    assert library.reference_dir() == REPO / "reference_solutions"


def test_an_installed_data_package_is_found_by_its_entry_point(no_checkout, monkeypatch):
    site = no_checkout / "site"
    package = _install_data(site, "lagrade_testdata", ["12.22"])
    monkeypatch.syspath_prepend(str(site))
    assert library.data_root() == package.resolve()
    assert library.reference_dir() == package.resolve() / "reference_solutions"
    assert library.problem_ids() == ["12.22"] and library.load_problem("12.22").id == "12.22"
    assert "lagrade_testdata" not in sys.modules  # found, not imported: a data package runs no code


def test_without_data_a_check_says_what_to_do(no_checkout):
    assert library.data_root() is None and library.problem_ids() == []
    assert not library.reference_dir().exists()
    with pytest.raises(SpecError, match="no problem data is installed") as exc:
        library.load_problem("12.22")
    assert "--server" in str(exc.value) and len(str(exc.value).splitlines()) == 1
