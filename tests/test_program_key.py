"""The key a grader reuses a file's result by: the same program, whatever its comments say."""

from __future__ import annotations

import ast

import pytest

from lagrade.answer.reading.program_key import MAX_TOKENIZED, program_key

ANSWER = b'''"""My answer."""
from lagrade.answer import *

theta = coordinates("theta")  # the angle
m, l, g = parameters("m l g")
L = m * l**2 * dot(theta)**2 / 2 + m * g * l * cos(theta)
if True:
    eom = [Eq(diff(L, dot(theta)).diff(t), diff(L, theta))]
'''


@pytest.mark.parametrize("other", [
    ANSWER + b"\n# student 17\n",                             # a line after the code
    ANSWER.replace(b"# the angle", b"# Alice's angle"),         # another comment's text
    ANSWER.replace(b"  # the angle", b""),                      # a comment removed from the end of a line
    ANSWER.replace(b"cos(theta)\n", b"cos(theta)   \n"),        # trailing blanks
])
def test_the_same_program_with_other_comments_has_one_key(other):
    assert program_key(".py", other) == program_key(".py", ANSWER)


@pytest.mark.parametrize("other", [
    ANSWER.replace(b"m * g * l", b"m * g * l * 2"),             # another value
    b"# Alice\n" + ANSWER,                                      # every line moved: f_lineno differs
    ANSWER.replace(b"m * l**2", b"m*l**2"),                     # columns moved on a line
    ANSWER.replace(b'"""My answer."""', b'"""Her answer."""'),  # a docstring is a value
    ANSWER.replace(b"    eom", b"\teom"),                       # another indentation
])
def test_another_program_or_the_same_at_other_places_has_another_key(other):
    assert program_key(".py", other) != program_key(".py", ANSWER)


def test_files_that_do_not_tokenize_large_files_and_text_answers_are_keyed_by_their_bytes():
    for bad in (b"x = '''never closed\n", b"\xff\xfe not utf-8", b"def f(:\n  )(\n"):
        assert program_key(".py", bad) == program_key(".py", bad)
        assert program_key(".py", bad) != program_key(".py", bad + b"# x\n")
    big = ANSWER + b"\n" + b"x = 1\n" * (MAX_TOKENIZED // 6)
    assert program_key(".py", big) != program_key(".py", big + b"# x\n")
    toml = b'L = "m*l**2*dot(theta)**2/2"\n'
    assert program_key(".toml", toml) != program_key(".py", toml)
    assert program_key(".ipynb", b"{}") != program_key(".ipynb", b"{} ")


TEXT = b'''# Alice, problem 12.14
L = "m*l**2*dot(theta)**2/2 + m*g*l*cos(theta)"  # my L
# what follows is the Hamiltonian
H = "p_theta**2/(2*m*l**2) - m*g*l*cos(theta)"
'''


@pytest.mark.parametrize("other", [
    TEXT.replace(b"# Alice", b"# Bob"),      # a comment line's text
    TEXT + b"\n# student 17\n\n",            # lines after the last line of content
    TEXT.rstrip(b"\n"),                      # no newline at the end
])
def test_a_text_answer_with_other_comment_lines_has_one_key(other):
    assert program_key(".toml", other) == program_key(".toml", TEXT)


@pytest.mark.parametrize("other", [
    TEXT.replace(b"# my L", b"# your L"),              # after content on its line: left as it is
    b"\n" + TEXT,                                      # every line moved: messages name lines
    TEXT.replace(b"cos(theta)", b"sin(theta)"),
    TEXT.replace(b'L = "', b'L = "0 + '),
    TEXT + b"x = \n",                                 # does not parse: its bytes
])
def test_a_text_answer_with_other_content_or_lines_has_another_key(other):
    assert program_key(".toml", other) != program_key(".toml", TEXT)


def test_one_key_means_one_syntax_tree_with_its_positions():
    # the claim the grader's reuse rests on, tried on the variants above: equal keys, equal trees
    # (every node at the same line and column), so the child runs the same code
    variants = [ANSWER, ANSWER + b"# end\n", ANSWER.replace(b"# the angle", b"# x"), b"# top\n" + ANSWER,
                ANSWER.replace(b"m * l**2", b"m*l**2")]
    for a in variants:
        for b in variants:
            if program_key(".py", a) == program_key(".py", b):
                assert ast.dump(ast.parse(a), include_attributes=True) == \
                       ast.dump(ast.parse(b), include_attributes=True)


def test_a_line_that_only_looks_like_a_comment_keeps_a_text_answer_keyed_by_its_bytes():
    # inside a multi-line string a line beginning with # is part of a value
    text = b'L = "m*g*l"\nnotes = """\n# not a comment\n"""\n'
    assert program_key(".toml", text) != program_key(".toml", text.replace(b"# not", b"# never"))
    assert program_key(".toml", text) != program_key(".toml", text + b"# x\n")
