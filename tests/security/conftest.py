"""The red-team suite's marker (the project registers no other)."""


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: takes minutes (the red-team suite: about 5)")
