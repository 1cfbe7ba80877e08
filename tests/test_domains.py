"""Physical domains are data: every symbol of a problem has one, the sampling box lies inside it, and
the judge reads it through `Problem.domains` (issue 42, item 1)."""

from __future__ import annotations

import itertools
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from sympy import Q

from lagrade.compare.sampling import rng_for, sample_points
from lagrade.problem.domains import DomainError, assumed_symbols, parse_domain, predicates, words
from lagrade.problem.library import load_problem, problem_ids
from lagrade.problem.spec import Coordinate, Parameter, SpecError, load_problem_file

IDS = problem_ids()

SCENE = '''
id = "dom"
title = "an incline"
[[parameters]]
name = "m"
[[parameters]]
name = "alpha"
{alpha}
[[systems]]
T = "m*x_d**2/2"
V = "m*g*x*sin(alpha)"
[[systems.coordinates]]
name = "x"
{x}
[[parts]]
name = "L"
kind = "lagrangian"
'''


def write(tmp_path: Path, alpha: str = "", x: str = "", g: bool = True) -> Path:
    text = SCENE.format(alpha=alpha, x=x)
    if g:
        text = text.replace('[[systems]]', '[[parameters]]\nname = "g"\n[[systems]]', 1)
    path = tmp_path / "dom.toml"
    path.write_text(text)
    return path


def test_words_and_intervals_read_exactly():
    assert parse_domain("positive").interval == sp.Interval.open(0, sp.oo)
    assert parse_domain("nonnegative").interval == sp.Interval.Ropen(0, sp.oo)
    assert parse_domain("real").interval == sp.Interval(-sp.oo, sp.oo)
    assert parse_domain("(0, pi/2)").interval == sp.Interval.open(0, sp.pi / 2)
    assert parse_domain("[-pi, pi)").interval == sp.Interval.Ropen(-sp.pi, sp.pi)
    assert parse_domain("(0.5, 2^2]").interval == sp.Interval.Lopen(sp.Rational(1, 2), 4)
    assert parse_domain("(-oo, 0]").interval == sp.Interval(-sp.oo, 0)


@pytest.mark.parametrize("text", ["positve", "(0, pi/2", "0 < x < 1", "(1, 0)", "[0, oo]", "(0, f(1))",
                                  "(0, x.y)", "(0, __import__('os'))", "(0, 2**100)", "(0, 1, 2)", "(0, 1/0)", ""])
def test_a_bad_domain_text_says_what_was_expected(text):
    with pytest.raises(DomainError):
        parse_domain(text)


def test_the_api_gives_sympy_intervals_assumptions_and_predicates():
    p = load_problem("12.35")
    d = p.domains()
    m, theta, theta_d, p_theta, t = sp.symbols("m theta theta_d p_theta t")
    assert set(d) >= {m, theta, theta_d, p_theta, t, sp.Symbol("theta_dd"), sp.Symbol("mu")}
    assert d[m].interval == sp.Interval.open(0, sp.oo) and d[m].assumptions() == {"real": True, "positive": True}
    assert d[theta_d].interval == sp.Interval.open(0, sp.oo), "theta' > 0 while the ring slides"
    assert d[theta_d].contains(0.3) and not d[theta_d].contains(0.0) and not d[theta_d].contains(-1)
    assert d[theta].interval == sp.Interval(-sp.oo, sp.oo) and d[theta].assumptions() == {"real": True}
    assert d[theta_d].sample_box == (0.2, 2.0) and d[p_theta].sample_box is None
    assert d[t].sample_box == (0.0, p.systems[0].horizon)
    assumed = assumed_symbols(d)
    assert assumed[theta_d].is_positive and assumed[theta].is_real and assumed[theta].is_positive is None
    assert sp.sqrt(theta_d**2).xreplace(assumed) == assumed[theta_d]
    assert sp.refine(sp.Abs(theta_d), predicates(d)) == theta_d
    assert sp.sign(theta_d).xreplace(assumed) == 1 and sp.Abs(theta).xreplace(assumed) != assumed[theta]


def test_an_interval_domain_as_predicates_and_assumptions():
    alpha = sp.Symbol("alpha")
    b = parse_domain("(0, pi/2)")
    assert b.assumptions() == {"real": True, "positive": True}
    assert b.predicates(alpha) == Q.real(alpha) & Q.positive(alpha) & Q.positive(sp.pi / 2 - alpha)
    assert b.contains(sp.pi / 3) and not b.contains(sp.pi / 2) and not b.contains(float(sp.pi) / 2 + 1e-12)
    assert list(b.contains(np.array([0.1, 1.6]))) == [True, False]
    assert b.words("alpha") == "0 < alpha < pi/2"
    assert parse_domain("nonnegative").assumptions() == {"real": True, "nonnegative": True}
    assert parse_domain("[-1, 0]").assumptions() == {"real": True, "nonpositive": True}


def test_a_system_of_a_lettered_problem_has_its_own_symbols():
    p = load_problem("12.8")  # theta: (a)'s incline angle, (b)'s coordinate
    theta = sp.Symbol("theta")
    assert p.domains("a")[theta].role == "parameter"
    assert p.domains("a")[theta].interval == sp.Interval.open(0, sp.pi / 2)
    assert p.domains("b")[theta].role == "coordinate"


def test_a_parts_extra_symbols_get_their_domain(tmp_path):
    path = write(tmp_path)
    path.write_text(path.read_text() + '[[parts]]\nname = "x_t"\nkind = "expression"\nreference = "v0*t"\n'
                    'symbols = ["v0", "x0"]\nsymbol_domain = { v0 = "positive" }\nsymbol_ranges = { x0 = [-1, 1] }\n')
    d = load_problem_file(path).domains("", part="x_t")
    assert d[sp.Symbol("v0")].interval == sp.Interval.open(0, sp.oo) and d[sp.Symbol("v0")].sample_box == (0.5, 1.5)
    assert d[sp.Symbol("x0")].interval == sp.Interval(-sp.oo, sp.oo) and d[sp.Symbol("x0")].role == "symbol"
    path.write_text(path.read_text().replace("x0 = [-1, 1]", "v0 = [-1, 1]"))
    with pytest.raises(SpecError, match=r"symbol v0: the sampling range \[-1.0, 1.0\] is not inside its domain"):
        load_problem_file(path)


def test_a_good_domain_loads(tmp_path):
    p = load_problem_file(write(tmp_path, alpha='domain = "(0, pi/2)"\nsample = [0.2, 1.3]',
                                x='domain = "positive"\nsample = [0.5, 2.0]\nvelocity_domain = "real"'))
    d = p.domains()
    assert d[sp.Symbol("alpha")].interval == sp.Interval.open(0, sp.pi / 2)
    assert p.parameters[1].positive, "a domain inside x > 0 is positive, as the checkers read it"
    assert words(d[s] for s in sp.symbols("m g alpha x x_d")) == "m, g, x > 0; 0 < alpha < pi/2; x' real"


@pytest.mark.parametrize("alpha, x, expect", [
    ('domain = "(0, pi/2"', "", r"parameter alpha: domain '\(0, pi/2': cannot read the domain"),
    ('domain = "acute"', "", r"parameter alpha: domain 'acute'.*expected 'real', 'positive'"),
    ('domain = "(0, pi/2)"\nsample = [0.2, 2.0]', "",
     r"parameter alpha: the sampling range \[0.2, 2.0\] is not inside its domain '\(0, pi/2\)' \(0 < alpha < pi/2\)"),
    ("", 'domain = "positive"', r"coordinate x: the sampling range \[-1.0, 1.0\] is not inside its domain 'positive'"),
    ("", 'velocity_domain = "positive"\nvelocity = [0.0, 1.0]',
     r"velocity x': the sampling range \[0.0, 1.0\] is not inside its domain 'positive' \(x' > 0\)"),
    ('domain = "real"\npositive = true', "", r"parameter alpha: positive = true contradicts domain 'real'"),
    ('domain = 3', "", r"domain: Input should be a valid string"),
])
def test_a_bad_problem_file_is_one_line_naming_file_symbol_box_and_domain(tmp_path, alpha, x, expect):
    path = write(tmp_path, alpha=alpha, x=x)
    with pytest.raises(SpecError, match=expect) as err:
        load_problem_file(path)
    assert str(err.value).startswith(str(path)) and "\n" not in str(err.value)


def test_an_end_may_name_a_parameter(tmp_path):
    """12.17's r lies in (0, l), a string's length; 12.30's Cartesian wire holds while omega*t < pi/2."""
    p = load_problem_file(write(tmp_path, x='domain = "(0, 2*m)"\nsample = [0.2, 0.9]'))
    x, m = sp.symbols("x m")
    d = p.domains()[x]
    assert d.interval == sp.Interval.open(0, 2 * m) and d.bounds.parameters == {m}
    assert d.contains(0.9, {m: 0.5}) and not d.contains(1.0, {m: 0.5}) and d.contains(1.5, {m: 1.0})
    assert list(d.contains(np.array([0.9, 0.9]), {m: np.array([0.5, 0.4])})) == [True, False]
    with pytest.raises(ValueError, match="names m: give their values"):
        d.contains(np.array([0.9]))
    assert d.assumptions() == {"real": True, "positive": True} and d.words() == "0 < x < 2*m"
    with pytest.raises(SpecError, match=r"coordinate x: the sampling range \[0.2, 1.2\] is not inside its domain "
                                        r"'\(0, 2\*m\)' \(0 < x < 2\*m\) at m = 0.5"):
        load_problem_file(write(tmp_path, x='domain = "(0, 2*m)"\nsample = [0.2, 1.2]'))
    with pytest.raises(SpecError, match=r"coordinate x: its domain '\(0, L\)' names L, which is not a parameter"):
        load_problem_file(write(tmp_path, x='domain = "(0, L)"\nsample = [0.2, 0.9]'))
    for pid, key, text in [("12.30", "xy", "[0, pi/(2*omega))"), ("12.12", "", "[0, pi/(2*omega))"),
                           ("12.49", "", "[0, l0/k)"), ("12.17", "", None)]:
        t = load_problem(pid).domains(key)[sp.Symbol("t")]
        assert t.bounds.text == (text or "real"), pid
    r = load_problem("12.17").domains()[sp.Symbol("r")]
    assert r.interval == sp.Interval.open(0, sp.Symbol("l")), "m2 hangs l - r below the hole: 1/(l - r)**2 in H"


def test_positive_false_is_the_real_line_and_the_models_default_inside_their_domains():
    assert Parameter(name="q", positive=False).domain == "real"
    assert Parameter(name="q").domain == "positive" and Parameter(name="q").positive
    assert not Parameter(name="q", domain="nonnegative", sample=(0.0, 1.0)).positive
    c = Coordinate(name="x")
    assert parse_domain(c.domain).encloses(c.sample) and parse_domain(c.velocity_domain).encloses(c.velocity)


@pytest.mark.parametrize("pid", IDS)
def test_every_problem_has_its_boxes_inside_its_domains(pid):
    p = load_problem(pid)
    for s in p.systems:
        for part in [None, *(q.name for q in p.parts if q.system == s.key and q.symbols)]:
            domains = p.domains(s.key, part)
            rng = np.random.default_rng(0)
            for sym, d in domains.items():
                if d.sample_box is None:
                    continue
                # the ends' parameters at their ranges' corners and at random points of them
                names = sorted(d.bounds.parameters, key=str)
                boxes = [domains[n].sample_box for n in names]
                draws = [dict(zip(names, c)) for c in itertools.product(*boxes)]
                draws += [{n: rng.uniform(*b) for n, b in zip(names, boxes)} for _ in range(10 if names else 0)]
                for at in draws:
                    assert d.bounds.encloses(d.sample_box, at), (pid, s.key, sym, at)


@pytest.mark.parametrize("pid", ["12.35", "12.8", "12.22", "12.17", "12.30", "12.49"])
def test_the_sampled_points_lie_in_the_physical_domain(pid):
    from lagrade.verdicts.grade import references

    p = load_problem(pid)
    for s in p.systems:
        mech = references(p)[s.key]
        pts = sample_points(mech, 64, rng_for(pid, "domains"))
        for sym, d in p.domains(s.key).items():
            if sym in pts.values and d.role != "momentum":
                assert d.contains(pts[sym], at=pts.values).all(), (pid, s.key, sym)


def test_show_prints_the_domains_in_the_students_notation():
    out = subprocess.run([sys.executable, "-m", "lagrade", "show", "12.35"], capture_output=True, text=True,
                         check=True).stdout
    assert "Domain: m, a, c, mu, rho, theta' > 0; rho', theta real" in out
    out = subprocess.run([sys.executable, "-m", "lagrade", "show", "12.30"], capture_output=True, text=True,
                         check=True).stdout
    assert "Domain (xy): m, omega > 0; 0 <= t < pi/(2*omega); x, x', y, y' real" in out


def test_the_course_page_shows_the_domains_too():
    from lagrade.uses.server.statement import statement_html

    html = statement_html(load_problem("12.35"))
    assert "<li>domain: m, a, c, mu, rho, theta&#x27; &gt; 0; rho&#x27;, theta real</li>" in html
