"""The integrator's order and step control (`method_check`), as a test of its own."""

from .method_check import check_the_method


def test_the_integrator_keeps_its_order_and_shrinks_rejected_steps():
    """Reason: a tableau error or a step control that never shrinks makes the integrator slow, not
    wrong, and a slow integrator hangs the suite; this fails in milliseconds instead (the session
    fixture in conftest.py runs the same check before every other test of the suite)."""
    problems = check_the_method()
    assert not problems, "\n".join(problems)
