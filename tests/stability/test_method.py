"""The integrator's order, step control, stage times, singularity guard and events (`method_check`),
as tests of their own."""

from .method_check import check_the_events, check_the_guard, check_the_method, check_the_time_dependence


def test_the_integrator_keeps_its_order_and_shrinks_rejected_steps():
    """Reason: a tableau error or a step control that never shrinks makes the integrator slow, not
    wrong, and a slow integrator hangs the suite; this fails in milliseconds instead (the session
    fixture in conftest.py runs the same check before every other test of the suite)."""
    problems = check_the_method()
    assert not problems, "\n".join(problems)


def test_a_time_dependent_problem_keeps_the_order():
    """Reason: the stage times c_s are read only where the rates depend on t; every other problem of the
    suite is autonomous, so a wrong c_s passed it (issue 45). y' = w cos(w t) y against exp(sin(w t))."""
    problems = check_the_time_dependence()
    assert not problems, "\n".join(problems)


def test_the_singularity_guard_sees_only_states_of_the_motion():
    """Reason: a rejected trial's end is no state of the motion (its rates can be a millionfold the
    motion's); a guard that watched it stopped correct runs (caught before only by tests/test_dop853.py)."""
    problems = check_the_guard()
    assert not problems, "\n".join(problems)


def test_an_event_is_found_where_it_is_known_exactly():
    """Reason: an event state interpolated at the wrong fraction of its step was caught only after 85 s
    of the suite (issue 45); x = cos(w t) reaches 0 at pi / (2 w) with v = -w, in milliseconds."""
    problems = check_the_events()
    assert not problems, "\n".join(problems)
