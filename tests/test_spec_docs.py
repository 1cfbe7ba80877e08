"""One table of part kinds and one description per field: the problem-file format is documented
from the models, and the checkers cover exactly the kinds the format allows."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path
from typing import get_args

from lagrade.problem.spec import KINDS, PartKind, Problem, markdown_tables

DOCS = Path(__file__).resolve().parents[1] / "docs" / "authoring-problems.md"


def test_the_docs_tables_are_the_models():
    text = DOCS.read_text()
    generated = re.search(r"<!-- generated: lagrade show --schema markdown -->\n(.*)\n<!-- end generated -->",
                          text, re.DOTALL)
    assert generated, "docs/authoring-problems.md lost its generated block"
    assert generated.group(1) == markdown_tables(), "regenerate it with: lagrade show --schema markdown"


def test_every_field_says_what_it_holds():
    def models(schema):
        return schema["$defs"].values()

    schema = Problem.model_json_schema()
    for model in [schema, *models(schema)]:
        for name, field in model["properties"].items():
            assert field.get("description"), f"{model['title']}.{name} has no description"


def test_one_table_of_kinds_drives_validation_and_the_checkers():
    from lagrade.verdicts.checkers import CHECKERS

    assert set(get_args(PartKind)) == set(KINDS) == set(CHECKERS)


def test_show_schema_prints_the_json_schema():
    out = subprocess.run([sys.executable, "-m", "lagrade", "show", "--schema", "json"], capture_output=True,
                         text=True, check=True)
    assert json.loads(out.stdout) == json.loads(json.dumps(Problem.model_json_schema()))
